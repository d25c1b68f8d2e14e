// A file written with every step checked: open, each write, flush, fsync and close.
#pragma once

#include <memory>
#include <ostream>
#include <string>

namespace hpcontact::post {

/// An output file written through std::ostream. Opening refuses a symbolic link at `path`
/// (O_NOFOLLOW) and truncates an existing file. close() flushes, fsyncs and closes; it throws
/// IoError naming the file and the system's error text ("No space left on device", "File too
/// large") if that or any earlier write failed, so a file that close() accepted is on disk whole.
class OutputFile {
public:
  /// IoError if the file cannot be created.
  explicit OutputFile(const std::string& path);
  /// Without close(): closes without checking (the caller is unwinding from another error).
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  std::ostream& stream();
  const std::string& path() const { return path_; }
  /// Flushes, fsyncs and closes; IoError on any failure since the file was opened.
  void close();

private:
  class Buffer;
  std::string path_;
  std::unique_ptr<Buffer> buffer_;
  std::unique_ptr<std::ostream> stream_;
};

/// Writes `text` to `path` through an OutputFile; IoError on failure.
void write_text_file(const std::string& path, const std::string& text);

}  // namespace hpcontact::post
