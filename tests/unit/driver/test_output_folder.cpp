// The output folder: staged files move in only at commit, the manifest bounds what is replaced,
// the lock keeps a second writer out.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "hpcontact/core/error.hpp"
#include "hpcontact/driver/output_folder.hpp"
#include "hpcontact/driver/run.hpp"
#include "hpcontact/post/output_file.hpp"

using namespace hpcontact;
namespace fs = std::filesystem;

namespace {

fs::path temp_folder(const std::string& name) {
  const auto dir = fs::temp_directory_path() /
                   ("hpc-output-folder-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read(const fs::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The names in a folder without our bookkeeping (lock, manifest).
std::set<std::string> listing(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const auto rel = fs::relative(e.path(), dir).string();
    if (rel.rfind(".hpcontact-", 0) != 0) names.insert(rel);
  }
  return names;
}

}  // namespace

TEST(OutputFolder, NothingMovesInWithoutCommit) {
  const auto dir = temp_folder("no-commit");
  {
    driver::OutputFolder folder(dir.string(), driver::run_layout());
    post::write_text_file(folder.begin() + "/summary.json", "{}");
  }
  EXPECT_TRUE(listing(dir).empty());
  fs::remove_all(dir);
}

TEST(OutputFolder, CommitReplacesOnlyTheListedFiles) {
  const auto dir = temp_folder("commit");
  {
    driver::OutputFolder folder(dir.string(), driver::run_layout());
    const std::string stage = folder.begin();
    fs::create_directories(stage + "/rp");
    post::write_text_file(stage + "/summary.json", "one");
    post::write_text_file(stage + "/rp/pressure-1.csv", "x");
    folder.commit();
  }
  post::write_text_file((dir / "notes.txt").string(), "mine");
  post::write_text_file((dir / "rp" / "notes.txt").string(), "mine too");
  {
    driver::OutputFolder folder(dir.string(), driver::run_layout());
    post::write_text_file(folder.begin() + "/summary.json", "two");
    folder.commit();
  }
  EXPECT_EQ(listing(dir), (std::set<std::string>{"notes.txt", "rp", "rp/notes.txt", "summary.json"}));
  EXPECT_EQ(read(dir / "summary.json"), "two");
  EXPECT_EQ(read(dir / ".hpcontact-manifest"), "summary.json\n");
  fs::remove_all(dir);
}

TEST(OutputFolder, FailedRunReplacesOnlyLastGood) {
  const auto dir = temp_folder("last-good");
  {
    driver::OutputFolder folder(dir.string(), driver::run_layout());
    post::write_text_file(folder.begin() + "/summary.json", "good");
    folder.commit();
  }
  {
    driver::OutputFolder folder(dir.string(), driver::run_layout());
    const std::string stage = folder.begin();
    fs::create_directories(stage + "/rp");
    fs::create_directories(stage + "/last-good");
    post::write_text_file(stage + "/rp/pressure-1.csv", "iteration 1");
    post::write_text_file(stage + "/last-good/summary.json", "kept");
    folder.commit_subfolder("last-good");
  }
  EXPECT_EQ(listing(dir), (std::set<std::string>{"summary.json", "last-good", "last-good/rp",
                                                 "last-good/rp/pressure-1.csv",
                                                 "last-good/summary.json"}));
  EXPECT_EQ(read(dir / "summary.json"), "good");
  fs::remove_all(dir);
}

// An edited manifest cannot make a run remove a file it does not write, nor one outside; the
// message names the cause — a path outside, or results a run does not write — and advises no
// removal.
TEST(OutputFolder, ManifestWithForeignNamesIsRefused) {
  const auto dir = temp_folder("manifest");
  for (const char* line : {"../victim.txt", "notes.txt", "/etc/passwd", "rp/../summary.json"}) {
    post::write_text_file((dir / ".hpcontact-manifest").string(), std::string(line) + "\n");
    try {
      driver::OutputFolder folder(dir.string(), driver::run_layout());
      FAIL() << "accepted the manifest line " << line;
    } catch (const IoError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(std::string(line) == "notes.txt"
                           ? "which a run never writes"
                           : "is not a path inside the folder as hpcontact writes them"),
                std::string::npos)
          << m;
      EXPECT_NE(m.find("choose another output folder (nothing was changed)"), std::string::npos) << m;
      EXPECT_EQ(m.find("remove"), std::string::npos) << m;
    }
  }
  fs::remove_all(dir);
}

TEST(OutputFolder, SecondWriterIsRefusedWhileTheFirstHoldsTheLock) {
  const auto dir = temp_folder("lock");
  {
    driver::OutputFolder first(dir.string(), driver::run_layout());
    try {
      driver::OutputFolder second(dir.string(), driver::run_layout());
      FAIL() << "a second writer got the lock";
    } catch (const IoError& e) {
      EXPECT_NE(std::string(e.what()).find("another hpcontact run is writing"), std::string::npos)
          << e.what();
    }
  }
  EXPECT_NO_THROW(driver::OutputFolder(dir.string(), driver::run_layout()));
  fs::remove_all(dir);
}

// A manifest, lock file or staging folder that is a symbolic link is not followed: the folder
// is refused, and the link's target is neither read nor written.
TEST(OutputFolder, BookkeepingLinksAreNotFollowed) {
  const auto dir = temp_folder("links");
  const auto victim = temp_folder("links-victim") / "victim.txt";
  post::write_text_file(victim.string(), "summary.json\n");
  for (const char* name : {".hpcontact-manifest", ".hpcontact-lock"}) {
    fs::create_symlink(victim, dir / name);
    try {
      driver::OutputFolder folder(dir.string(), driver::run_layout());
      FAIL() << "followed " << name;
    } catch (const IoError& e) {
      EXPECT_NE(std::string(e.what()).find("symbolic link"), std::string::npos) << e.what();
    }
    fs::remove(dir / ".hpcontact-manifest");
    fs::remove(dir / ".hpcontact-lock");
  }
  // A link named like a staging folder is not ours to clean up: it and its target stay.
  fs::create_symlink(victim.parent_path(), dir / ".hpcontact-staging-planted");
  { driver::OutputFolder folder(dir.string(), driver::run_layout()); }
  EXPECT_TRUE(fs::is_symlink(dir / ".hpcontact-staging-planted"));
  EXPECT_EQ(read(victim), "summary.json\n");
  fs::remove_all(dir);
  fs::remove_all(victim.parent_path());
}
