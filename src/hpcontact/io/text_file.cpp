// Input files read through a file descriptor: fstat first (type and size), then read at most
// one byte beyond the limit, so a file that grows while read is refused too.
#include "hpcontact/io/text_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <iomanip>
#include <sstream>

#include "hpcontact/core/error.hpp"

namespace hpcontact::io {

std::string in_megabytes(std::size_t bytes) {
  std::ostringstream os;
  os << std::setprecision(3) << static_cast<double>(bytes) / (1 << 20) << " MB";
  return os.str();
}

std::string read_bounded_file(const std::string& path, const std::string& what,
                              std::size_t max_bytes, bool follow_link) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | (follow_link ? 0 : O_NOFOLLOW));
  if (fd < 0)
    throw IoError(path + ": cannot open " + what + ": " +
                  (errno == ELOOP && !follow_link ? "it is a symbolic link, which is not followed"
                                                  : std::strerror(errno)));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st;
  if (::fstat(fd, &st) != 0) throw IoError(path + ": cannot read " + what + ": " + std::strerror(errno));
  if (S_ISDIR(st.st_mode))
    throw IoError(path + ": cannot read " + what + ": " + std::strerror(EISDIR));
  if (!S_ISREG(st.st_mode))
    throw IoError(path + ": cannot read " + what +
                  ": not a regular file (a device, a pipe or a socket, which may never end)");
  const std::string too_large = path + ": the " + what + " is larger than the " +
                                in_megabytes(max_bytes) + " it may have";
  if (static_cast<std::size_t>(st.st_size) > max_bytes)
    throw IoError(too_large + " (" + in_megabytes(static_cast<std::size_t>(st.st_size)) + ")");
  // One byte more than the file has, so that the read that finds its end needs no larger buffer
  // (growing the string would double its memory).
  std::string text(static_cast<std::size_t>(st.st_size) + 1, '\0');
  std::size_t got = 0;
  for (;;) {
    if (got == text.size()) {
      if (text.size() > max_bytes) throw IoError(too_large + " (it grew while it was read)");
      text.resize(std::min(max_bytes + 1, text.size() + (1 << 16)));
    }
    const ssize_t n = ::read(fd, text.data() + got, text.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw IoError(path + ": cannot read " + what + ": " + std::strerror(errno));
    if (n == 0) break;
    got += static_cast<std::size_t>(n);
  }
  text.resize(got);
  return text;
}

}  // namespace hpcontact::io
