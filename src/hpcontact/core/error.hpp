// Error types and checks: input errors always on, programming errors in debug builds only.
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>

namespace hpcontact {

/// Base of every error the library reports to a user; what() is the full one-line message.
class Error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// Bad input: a key, value or reference in a problem file or an API argument.
/// The message names the file, line and key path when they are known.
class InputError : public Error {
public:
  using Error::Error;
};

/// Bad input that came from the command line (a --set override: a key path that does not exist,
/// a value of the wrong type or range): the program exits with status 2 and its usage.
class CommandLineError : public InputError {
public:
  using InputError::InputError;
};

/// A mesh that cannot be used: inverted or degenerate element, inconsistent topology.
class MeshError : public Error {
public:
  using Error::Error;
};

/// A file that cannot be read or written.
class IoError : public Error {
public:
  using Error::Error;
};

/// An adaptive step (rp relocation, hp refinement) that cannot be carried out: Γ* not found, a
/// node that cannot move along its curve, a mesh change that would invert an element.
class AdaptError : public Error {
public:
  using Error::Error;
};

/// The machine's resources ran out: memory for a factorisation, or a size beyond a library's
/// integers. The message says how large the problem is and what it needed.
class ResourceError : public Error {
public:
  using Error::Error;
};

/// A numerical failure that ends a computation (singular matrix, NaN in a residual).
class NumericalError : public Error {
public:
  using Error::Error;
};

/// An error's text with every "file: " removed: for a message that names the file once and
/// quotes a cause that names it again (the refinement of an hp step quoting the mesh check).
std::string without_file_name(std::string what, const std::string& file);

namespace detail {
template <class... Args>
std::string concat(const Args&... args) {
  std::ostringstream os;
  os.precision(10);
  (os << ... << args);
  return os.str();
}
}  // namespace detail

}  // namespace hpcontact

/// Always-on check of a user-facing precondition: throws ErrorType with the streamed message.
#define HPC_REQUIRE(cond, ErrorType, ...)                                  \
  do {                                                                     \
    if (!(cond)) throw ErrorType(::hpcontact::detail::concat(__VA_ARGS__)); \
  } while (false)

#ifndef NDEBUG
/// Debug-only check of an internal invariant; the message shows the offending values.
#define HPC_ASSERT(cond, ...)                                                         \
  do {                                                                                \
    if (!(cond))                                                                      \
      throw std::logic_error(::hpcontact::detail::concat(__FILE__, ":", __LINE__,      \
                                                         ": assertion '" #cond "' failed: ", \
                                                         __VA_ARGS__));               \
  } while (false)
#else
#define HPC_ASSERT(cond, ...) \
  do {                        \
  } while (false)
#endif
