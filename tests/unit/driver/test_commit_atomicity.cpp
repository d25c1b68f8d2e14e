// The output folder's commit fails half way — the N-th rename of its files refused, for every N —
// and leaves no summary.json that claims a finished run: the marker is either the earlier run's,
// with all its files as they were, or the new one's, with all of the new files; and the next run
// takes the folder over (nothing it finds is a stranger's file).
#include <gtest/gtest.h>

#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "hpcontact/core/error.hpp"
#include "hpcontact/driver/output_folder.hpp"
#include "hpcontact/driver/run.hpp"
#include "hpcontact/post/output_file.hpp"

using namespace hpcontact;
namespace fs = std::filesystem;

namespace {

/// Renames still to let through before one fails (with EIO); < 0: none fails.
std::atomic<int> renames_before_failure{-1};
std::atomic<int> renames_seen{0};  ///< every rename, for the count of one commit's

}  // namespace

// Every renameat of this test program (the output folder's, on its file descriptors) comes here.
extern "C" int renameat(int from_dir, const char* from, int to_dir, const char* to) {
  ++renames_seen;
  if (renames_before_failure.load() == 0) {
    renames_before_failure = -1;
    errno = EIO;
    return -1;
  }
  if (renames_before_failure.load() > 0) --renames_before_failure;
  return static_cast<int>(::syscall(SYS_renameat2, from_dir, from, to_dir, to, 0));
}

namespace {

using Files = std::map<std::string, std::string>;  // relative path -> content

/// The folder's files but the bookkeeping (lock, manifest), with their content.
Files files_in(const fs::path& dir) {
  Files files;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const auto rel = fs::relative(e.path(), dir).string();
    if (rel.rfind(".hpcontact-", 0) == 0 || !e.is_regular_file()) continue;
    std::ifstream in(e.path());
    files[rel] = {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  return files;
}

/// Stages `files` into `folder` and commits them (into last-good/ if `sub`).
void commit(driver::OutputFolder& folder, const Files& files, const std::string& sub = "") {
  const std::string stage = folder.begin();
  for (const auto& [path, text] : files) {
    fs::create_directories(fs::path(stage + "/" + path).parent_path());
    post::write_text_file(stage + "/" + path, text);
  }
  if (sub.empty()) folder.commit();
  else folder.commit_subfolder(sub);
}

Files under(const std::string& prefix, const Files& files) {
  Files out;
  for (const auto& [path, text] : files) out[prefix + path] = text;
  return out;
}

}  // namespace

TEST(OutputFolderAtomicity, AFailedRenameLeavesNoSummaryOfAnUnfinishedRun) {
  const auto dir = fs::temp_directory_path() / ("hpc-commit-atomicity-" + std::to_string(::getpid()));
  const Files earlier = {{"summary.json", "earlier"}, {"contact.csv", "earlier"},
                         {"rp/pressure-1.csv", "earlier"}, {"input.yaml", "earlier"}};
  const Files newer = {{"summary.json", "newer"}, {"contact.csv", "newer"},
                       {"solution.vtu", "newer"}, {"rp/pressure-1.csv", "newer"},
                       {"rp/pressure-2.csv", "newer"}};
  for (const bool failed_run : {false, true}) {  // commit, or commit_subfolder("last-good")
    const std::string sub = failed_run ? "last-good" : "";
    // the renames of one whole commit, counted
    fs::remove_all(dir);
    {
      driver::OutputFolder folder(dir.string(), driver::run_layout());
      commit(folder, earlier);
    }
    renames_seen = 0;
    {
      driver::OutputFolder folder(dir.string(), driver::run_layout());
      commit(folder, newer, sub);
    }
    const int renames = renames_seen;
    ASSERT_GE(renames, static_cast<int>(newer.size()) + 2);  // every file and the manifest twice
    // the folder after the whole commit
    Files after = newer;
    if (failed_run) {
      after = earlier;
      for (const auto& [path, text] : under("last-good/", newer)) after[path] = text;
    }
    for (int n = 0; n < renames; ++n) {
      fs::remove_all(dir);
      {
        driver::OutputFolder folder(dir.string(), driver::run_layout());
        commit(folder, earlier);
      }
      {
        driver::OutputFolder folder(dir.string(), driver::run_layout());
        renames_before_failure = n;
        EXPECT_THROW(commit(folder, newer, sub), IoError) << "rename " << n << " of " << renames;
        renames_before_failure = -1;
      }
      const Files left = files_in(dir);
      const std::string marker = failed_run ? "last-good/summary.json" : "summary.json";
      if (left.count(marker)) {
        // a marker claims a finished run (or last good state): all of its files are there
        const bool old_state = left.at(marker) == "earlier";
        EXPECT_EQ(left, old_state ? earlier : after) << "rename " << n << " failed";
      }
      if (failed_run) EXPECT_EQ(left.at("summary.json"), "earlier") << "rename " << n << " failed";
      // the next run takes the folder over, and leaves exactly its own results
      {
        driver::OutputFolder folder(dir.string(), driver::run_layout());
        commit(folder, {{"summary.json", "next"}});
      }
      EXPECT_EQ(files_in(dir), (Files{{"summary.json", "next"}})) << "rename " << n << " failed";
    }
  }
  fs::remove_all(dir);
}
