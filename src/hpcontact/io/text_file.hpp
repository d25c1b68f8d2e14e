// Reading an input file whole, bounded: only regular files, only up to a size.
#pragma once

#include <cstddef>
#include <string>

namespace hpcontact::io {

/// Largest compare.reference curve read (bytes): a pressure.csv has some thousand rows.
constexpr std::size_t kMaxReferenceBytes = 64u << 20;

/// A size for messages: "19.6 MB" (MB of 2^20 bytes, three digits).
std::string in_megabytes(std::size_t bytes);

/// The whole of the regular file at `path`, at most `max_bytes` long. IoError naming the path,
/// `what` it is ("problem file") and the reason if it is not a regular file (a folder, a device
/// such as /dev/zero, a pipe), is longer, or cannot be read; with `follow_link` false also if it
/// is a symbolic link.
std::string read_bounded_file(const std::string& path, const std::string& what,
                              std::size_t max_bytes, bool follow_link = true);

}  // namespace hpcontact::io
