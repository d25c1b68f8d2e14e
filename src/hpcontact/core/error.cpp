// Anchor translation unit for the core module.
#include "hpcontact/core/error.hpp"

namespace hpcontact {

std::string without_file_name(std::string what, const std::string& file) {
  if (file.empty()) return what;
  const std::string prefix = file + ": ";
  std::string out;
  size_t from = 0;
  for (size_t at = what.find(prefix); at != std::string::npos; at = what.find(prefix, from)) {
    out.append(what, from, at - from);
    from = at + prefix.size();
  }
  out.append(what, from, std::string::npos);
  return out;
}

}  // namespace hpcontact
