// Output files: a write the system refuses is an IoError with the file and the system's reason.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "hpcontact/core/error.hpp"
#include "hpcontact/post/output_file.hpp"

using namespace hpcontact;

namespace {
std::string temp_folder(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("hpc-output-file-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}
}  // namespace

// A full disk (/dev/full: every write fails with ENOSPC) is reported at close even when the
// text fits in the buffer, so nothing is written before close() itself.
TEST(OutputFile, FullDiskIsAnErrorNamingTheFileAndTheReason) {
  post::OutputFile file("/dev/full");
  file.stream() << "a short summary";
  try {
    file.close();
    FAIL() << "close() accepted a write to /dev/full";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/full: cannot write the file: No space left on device"),
              std::string::npos)
        << e.what();
  }
}

TEST(OutputFile, WritesTheWholeTextAndRefusesALink) {
  const std::string dir = temp_folder("link");
  std::string text(200000, 'x');  // more than one buffer
  post::write_text_file(dir + "/a.txt", text);
  std::ifstream in(dir + "/a.txt");
  const std::string back((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(back, text);
  std::filesystem::create_symlink(dir + "/a.txt", dir + "/link.txt");
  EXPECT_THROW(post::write_text_file(dir + "/link.txt", "through the link"), IoError);
  std::ifstream again(dir + "/a.txt");
  const std::string kept((std::istreambuf_iterator<char>(again)), std::istreambuf_iterator<char>());
  EXPECT_EQ(kept, text);
  std::filesystem::remove_all(dir);
}
