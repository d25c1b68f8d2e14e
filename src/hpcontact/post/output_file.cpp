// Output files on a file descriptor: a buffer whose writes report errno, and a checked close.
#include "hpcontact/post/output_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <streambuf>
#include <vector>

#include "hpcontact/core/error.hpp"

namespace hpcontact::post {

/// A stream buffer over a file descriptor that remembers the first failed write's errno; after
/// a failure it drops further output (the file is refused at close anyway).
class OutputFile::Buffer : public std::streambuf {
public:
  explicit Buffer(int fd) : fd_(fd), data_(1 << 16) { setp(data_.data(), data_.data() + data_.size()); }
  int fd() const { return fd_; }
  int error() const { return error_; }
  void fail(int e) {
    if (!error_) error_ = e;
  }

protected:
  int_type overflow(int_type c) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return drain() ? 0 : -1; }

private:
  /// Writes out the buffer; false (and the error kept) if the system refused a write.
  bool drain() {
    const char* p = pbase();
    std::size_t n = static_cast<std::size_t>(pptr() - pbase());
    while (n > 0 && !error_) {
      const ssize_t w = ::write(fd_, p, n);
      if (w < 0) {
        if (errno == EINTR) continue;
        fail(errno);
      } else {
        p += w;
        n -= static_cast<std::size_t>(w);
      }
    }
    setp(data_.data(), data_.data() + data_.size());
    return !error_;
  }

  int fd_;
  int error_ = 0;
  std::vector<char> data_;
};

OutputFile::OutputFile(const std::string& path) : path_(path) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd < 0) {
    const int e = errno;
    throw IoError(path + ": cannot create the file: " +
                  (e == ELOOP ? std::string("it is a symbolic link, which is not followed")
                              : std::strerror(e)));
  }
  buffer_ = std::make_unique<Buffer>(fd);
  stream_ = std::make_unique<std::ostream>(buffer_.get());
}

OutputFile::~OutputFile() {
  if (buffer_) ::close(buffer_->fd());
}

std::ostream& OutputFile::stream() { return *stream_; }

void OutputFile::close() {
  HPC_REQUIRE(buffer_, IoError, path_, ": closed twice");
  stream_->flush();
  const int fd = buffer_->fd();
  // fsync: the data is on the disk before the file is renamed into place. A special file
  // (/dev/null) cannot be synchronised; that is no failure of the output.
  if (::fsync(fd) != 0 && errno != EINVAL && errno != EROFS) buffer_->fail(errno);
  if (::close(fd) != 0 && errno != EINTR) buffer_->fail(errno);
  const int error = buffer_->error();
  const bool stream_bad = !stream_->good();
  stream_->rdbuf(nullptr);  // a write after close() fails the stream instead of reaching a closed fd
  buffer_.reset();
  HPC_REQUIRE(!error, IoError, path_, ": cannot write the file: ", std::strerror(error));
  HPC_REQUIRE(!stream_bad, IoError, path_, ": cannot write the file (the output stream failed)");
}

void write_text_file(const std::string& path, const std::string& text) {
  OutputFile file(path);
  file.stream() << text;
  file.close();
}

}  // namespace hpcontact::post
