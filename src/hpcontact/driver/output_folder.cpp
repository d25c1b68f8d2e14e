// The output folder: staging, commit by rename, the manifest and the lock, on file descriptors
// (openat and friends with O_NOFOLLOW) so that no symbolic link inside the folder is followed.
#include "hpcontact/driver/output_folder.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <utility>
#include <vector>

#include "hpcontact/core/error.hpp"
#include "hpcontact/io/text_file.hpp"
#include "hpcontact/post/output_file.hpp"

namespace hpcontact::driver {

namespace fs = std::filesystem;

namespace {

const char* const kLock = ".hpcontact-lock";
const char* const kManifest = ".hpcontact-manifest";
const char* const kManifestNew = ".hpcontact-manifest.new";
const char* const kStagingPrefix = ".hpcontact-staging-";
/// A manifest is a few hundred lines; anything much larger was not written by us.
constexpr std::size_t kManifestMaxBytes = 16 << 20;

/// A file descriptor closed when it goes out of scope.
class Fd {
public:
  explicit Fd(int fd = -1) : fd_(fd) {}
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  Fd(Fd&& o) noexcept : fd_(std::exchange(o.fd_, -1)) {}
  Fd& operator=(Fd&& o) noexcept {
    std::swap(fd_, o.fd_);
    return *this;
  }
  int get() const { return fd_; }
  int release() { return std::exchange(fd_, -1); }

private:
  int fd_;
};

std::string system_error(int e = errno) { return std::strerror(e); }

enum class Kind { missing, file, folder, link, other };

Kind kind_of(int dir, const std::string& name) {
  struct stat st;
  if (::fstatat(dir, name.c_str(), &st, AT_SYMLINK_NOFOLLOW) != 0) return Kind::missing;
  if (S_ISLNK(st.st_mode)) return Kind::link;
  if (S_ISDIR(st.st_mode)) return Kind::folder;
  if (S_ISREG(st.st_mode)) return Kind::file;
  return Kind::other;
}

/// The names in an open folder, sorted (without . and ..).
std::vector<std::string> names_in(int dir, const std::string& shown) {
  const int fd = ::openat(dir, ".", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  DIR* d = fd < 0 ? nullptr : ::fdopendir(fd);
  if (!d) {
    const int e = errno;
    if (fd >= 0) ::close(fd);
    throw IoError(shown + ": cannot list the folder: " + system_error(e));
  }
  std::vector<std::string> names;
  while (const dirent* entry = ::readdir(d)) {
    const std::string name = entry->d_name;
    if (name != "." && name != "..") names.push_back(name);
  }
  ::closedir(d);
  std::sort(names.begin(), names.end());
  return names;
}

/// (folder, name) of a relative path: ("rp", "pressure-1.csv"), ("", "summary.json").
std::pair<std::string, std::string> split(const std::string& relative) {
  const auto slash = relative.rfind('/');
  if (slash == std::string::npos) return {"", relative};
  return {relative.substr(0, slash), relative.substr(slash + 1)};
}

/// Opens the folder `relative` below `base` without following a link at any step, creating the
/// missing steps if `create`. An invalid Fd if a step is missing (and not created).
Fd open_folder(int base, const std::string& relative, bool create, const std::string& shown_base) {
  Fd fd(::openat(base, ".", O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (fd.get() < 0) throw IoError(shown_base + ": cannot open the folder: " + system_error());
  std::string walked = shown_base;
  std::stringstream steps(relative);
  for (std::string step; std::getline(steps, step, '/');) {
    if (step.empty()) continue;
    walked += "/" + step;
    if (create && ::mkdirat(fd.get(), step.c_str(), 0755) != 0 && errno != EEXIST)
      throw IoError(walked + ": cannot create the folder: " + system_error());
    Fd next(::openat(fd.get(), step.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
    if (next.get() < 0) {
      const int e = errno;
      if (e == ENOENT && !create) return Fd();
      if (e == ELOOP || e == ENOTDIR)
        throw IoError(walked + ": not a folder (a symbolic link or a file) where hpcontact writes "
                               "a folder; links in an output folder are never followed");
      throw IoError(walked + ": cannot open the folder: " + system_error(e));
    }
    fd = std::move(next);
  }
  return fd;
}

/// Removes the folder `name` in `parent` and everything in it, links themselves (never what they
/// point to). False if something could not be removed.
bool remove_tree(int parent, const std::string& name) noexcept {
  Fd fd(::openat(parent, name.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
  if (fd.get() < 0) return false;
  bool ok = true;
  try {
    for (const auto& entry : names_in(fd.get(), name)) {
      if (kind_of(fd.get(), entry) == Kind::folder)
        ok = remove_tree(fd.get(), entry) && ok;
      else
        ok = ::unlinkat(fd.get(), entry.c_str(), 0) == 0 && ok;
    }
  } catch (const std::exception&) {
    return false;
  }
  return ::unlinkat(parent, name.c_str(), AT_REMOVEDIR) == 0 && ok;
}

/// Every regular file below the open folder `dir`, as relative paths; IoError on anything else
/// (nothing but our writers put files there).
void list_files(int dir, const std::string& prefix, const std::string& shown,
                std::vector<std::string>& files) {
  for (const auto& name : names_in(dir, shown + prefix)) {
    const std::string relative = prefix + name;
    switch (kind_of(dir, name)) {
      case Kind::file: files.push_back(relative); break;
      case Kind::folder: {
        const Fd sub = open_folder(dir, name, false, shown + prefix);
        list_files(sub.get(), relative + "/", shown, files);
        break;
      }
      default:
        throw IoError(shown + relative + ": not a regular file in the staging folder");
    }
  }
}

/// A path of the manifest: relative, without empty, '.' or '..' steps.
bool plain_relative(const std::string& path) {
  if (path.empty() || path.front() == '/' || path.back() == '/') return false;
  std::stringstream steps(path);
  for (std::string step; std::getline(steps, step, '/');)
    if (step.empty() || step == "." || step == "..") return false;
  return true;
}

}  // namespace

OutputFolder::OutputFolder(std::string target, FolderLayout layout, const std::vector<Input>& inputs)
    : target_(std::move(target)), layout_(std::move(layout)) {
  std::error_code ec;
  fs::create_directories(target_, ec);
  HPC_REQUIRE(!ec, IoError, target_, ": cannot create the output folder: ", ec.message());
  dir_ = ::open(target_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  HPC_REQUIRE(dir_ >= 0, IoError, target_, ": cannot open the output folder: ", system_error());
  try {
    for (const auto& input : inputs) refuse_if_inside(input.file, input.what);
    lock();
    read_manifest();
    remove_stale_staging();
  } catch (...) {
    if (lock_ >= 0) ::close(lock_);
    ::close(dir_);
    throw;
  }
}

const std::string& OutputFolder::begin() {
  HPC_REQUIRE(staging_name_.empty() || committed_, IoError, target_,
              ": the output folder was begun twice");
  refuse_foreign_files(dir_, "");
  committed_ = false;
  std::string name = target_ + "/" + kStagingPrefix + "XXXXXX";
  HPC_REQUIRE(::mkdtemp(name.data()), IoError, target_, ": cannot create a staging folder: ",
              system_error());
  staging_name_ = fs::path(name).filename().string();
  staging_path_ = name;
  staging_ = ::openat(dir_, staging_name_.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  HPC_REQUIRE(staging_ >= 0, IoError, staging_path_, ": cannot open the staging folder: ",
              system_error());
  return staging_path_;
}

OutputFolder::~OutputFolder() {
  if (staging_ >= 0) ::close(staging_);
  if (!committed_ && !staging_name_.empty()) remove_tree(dir_, staging_name_);
  if (lock_ >= 0) ::close(lock_);  // releases the flock
  if (dir_ >= 0) ::close(dir_);
}

std::string OutputFolder::shown(const std::string& relative) const {
  return relative.empty() ? target_ : target_ + "/" + relative;
}

void OutputFolder::lock() {
  lock_ = ::openat(dir_, kLock, O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);
  HPC_REQUIRE(lock_ >= 0, IoError, shown(kLock), ": cannot open the lock file: ",
              errno == ELOOP ? "it is a symbolic link, which is not followed" : system_error());
  if (::flock(lock_, LOCK_EX | LOCK_NB) == 0) return;
  HPC_REQUIRE(errno != EWOULDBLOCK, IoError, target_,
              ": another hpcontact run is writing into this output folder (it holds ",
              shown(kLock), "); wait for it to finish or choose another output folder");
  throw IoError(shown(kLock) + ": cannot lock the output folder: " + system_error());
}

void OutputFolder::read_manifest() {
  if (kind_of(dir_, kManifest) == Kind::missing) return;
  const std::string text =
      io::read_bounded_file(shown(kManifest), "manifest", kManifestMaxBytes, false);
  std::stringstream lines(text);
  int number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    if (line.empty()) continue;
    // Only names we write are ever taken from it: an edited manifest cannot make us remove
    // anything else. A name of another kind of results is that kind's folder (a study's results
    // where a run would write, or the other way round), which this one must not take over.
    const std::string shown_line = "'" + line.substr(0, 200) + "'";
    HPC_REQUIRE(plain_relative(line), IoError, shown(kManifest), ":", number, ": ", shown_line,
                " is not a path inside the folder as hpcontact writes them (relative, without '.' "
                "or '..' steps): the manifest was edited; choose another output folder (nothing "
                "was changed)");
    HPC_REQUIRE(layout_.is_output(line, false), IoError, target_, ": holds results that are not ",
                layout_.kind, "'s: its manifest (", kManifest, ":", number, ") lists ", shown_line,
                ", which ", layout_.kind, " never writes; the folder holds another command's "
                "results (a run and a study cannot share an output folder) or its manifest was "
                "edited: choose another output folder (nothing was changed)");
    manifest_.insert(line);
  }
}

void OutputFolder::remove_stale_staging() {
  // Under the lock no other run is writing here: a staging folder is left from a run that was
  // killed, and holds nothing anyone can use.
  for (const auto& name : names_in(dir_, target_))
    if (name.rfind(kStagingPrefix, 0) == 0 && kind_of(dir_, name) == Kind::folder)
      HPC_REQUIRE(remove_tree(dir_, name), IoError, shown(name),
                  ": cannot remove the staging folder an interrupted run left: ", system_error());
}

void OutputFolder::refuse_foreign_files(int folder, const std::string& prefix) const {
  for (const auto& name : names_in(folder, shown(prefix))) {
    const std::string relative = prefix + name;
    const bool as_file = layout_.is_output(relative, false);
    const bool as_folder = layout_.is_output(relative, true);
    if (!as_file && !as_folder) continue;
    const Kind kind = kind_of(folder, name);
    HPC_REQUIRE(kind != Kind::link, IoError, shown(relative),
                ": a symbolic link where hpcontact writes its results; links in an output folder "
                "are never followed: remove it or choose another output folder");
    if (as_folder && kind == Kind::folder) {
      const Fd sub = open_folder(folder, name, false, shown(prefix));
      refuse_foreign_files(sub.get(), relative + "/");
      continue;
    }
    if (as_file && kind == Kind::file) {
      HPC_REQUIRE(manifest_.count(relative), IoError, shown(relative),
                  ": hpcontact did not write this file (the folder's ", kManifest,
                  " does not list it) and would replace it: move it away or choose another "
                  "output folder");
      continue;
    }
    throw IoError(shown(relative) + ": " + (as_folder ? "not a folder" : "not a regular file") +
                  ", where hpcontact writes " + (as_folder ? "a folder" : "a file") +
                  ": move it away or choose another output folder");
  }
}

void OutputFolder::refuse_if_inside(const std::string& file, const std::string& what) const {
  std::error_code ec;
  const fs::path real = fs::canonical(file, ec);
  if (ec) return;
  struct stat folder;
  HPC_REQUIRE(::fstat(dir_, &folder) == 0, IoError, target_, ": ", system_error());
  for (fs::path p = real.parent_path(); !p.empty(); p = p.parent_path()) {
    struct stat st;
    HPC_REQUIRE(::stat(p.c_str(), &st) != 0 || st.st_dev != folder.st_dev ||
                    st.st_ino != folder.st_ino,
                IoError, target_, ": the output folder holds ", what, " ", file,
                "; hpcontact replaces the files of its output folder, which must not hold the "
                "run's input: choose another output folder");
    if (p == p.root_path()) break;
  }
}

void OutputFolder::commit() { move_in(""); }

void OutputFolder::commit_subfolder(const std::string& sub) {
  HPC_REQUIRE(staging_ >= 0, IoError, target_, ": nothing staged to move in");
  const Fd into = open_folder(staging_, sub, true, staging_path_);
  for (const auto& name : names_in(staging_, staging_path_)) {
    if (name == sub) continue;
    HPC_REQUIRE(kind_of(into.get(), name) == Kind::missing, IoError, staging_path_, "/", sub, "/",
                name, ": staged twice");
    HPC_REQUIRE(::renameat(staging_, name.c_str(), into.get(), name.c_str()) == 0, IoError,
                staging_path_, "/", name, ": cannot move it into ", sub, "/: ", system_error());
  }
  move_in(sub + "/");
}

void OutputFolder::move_in(const std::string& prefix) {
  HPC_REQUIRE(staging_ >= 0 && !committed_, IoError, target_,
              ": nothing staged to move in (not begun, or moved in already)");
  std::vector<std::string> staged;
  list_files(staging_, "", staging_path_ + "/", staged);
  const std::set<std::string> staged_set(staged.begin(), staged.end());
  std::set<std::string> replaced, after;
  for (const auto& f : manifest_) (f.rfind(prefix, 0) == 0 ? replaced : after).insert(f);
  after.insert(staged.begin(), staged.end());

  // While files move, the manifest lists the old and the new ones: a run killed in between
  // leaves nothing the next run would take for a stranger's file.
  std::set<std::string> during = manifest_;
  during.insert(staged.begin(), staged.end());
  write_manifest(during);
  manifest_ = during;

  // The marker goes first and comes last: a folder caught half way has no summary claiming a
  // finished run.
  const std::string marker = prefix + layout_.marker;
  if (replaced.count(marker)) unlink_listed(marker);
  std::set<std::string> touched = {""};
  for (const auto& f : staged)
    if (f != marker) place(f, touched);
  std::set<std::string> emptied;
  for (const auto& f : replaced) {
    if (staged_set.count(f)) continue;
    unlink_listed(f);
    for (auto folder = split(f).first; !folder.empty(); folder = split(folder).first)
      emptied.insert(folder);
  }
  // Our folders that now hold nothing go (the deepest first); one that holds a user's file stays.
  std::vector<std::string> folders(emptied.begin(), emptied.end());
  std::sort(folders.begin(), folders.end(),
            [](const std::string& a, const std::string& b) { return a.size() > b.size(); });
  for (const auto& folder : folders) {
    const auto [parent, name] = split(folder);
    const Fd p = open_folder(dir_, parent, false, target_);
    if (p.get() >= 0) ::unlinkat(p.get(), name.c_str(), AT_REMOVEDIR);  // fails if not empty
  }
  if (staged_set.count(marker)) place(marker, touched);
  write_manifest(after);
  manifest_ = after;
  for (const auto& folder : touched) {
    const Fd fd = open_folder(dir_, folder, false, target_);
    HPC_REQUIRE(fd.get() < 0 || ::fsync(fd.get()) == 0 || errno == EINVAL, IoError, shown(folder),
                ": cannot synchronise the folder: ", system_error());
  }
  ::close(staging_);
  staging_ = -1;
  remove_tree(dir_, staging_name_);
  committed_ = true;
}

void OutputFolder::place(const std::string& relative, std::set<std::string>& touched) {
  const auto [folder, name] = split(relative);
  const Fd to = open_folder(dir_, folder, true, target_);
  const Fd from = open_folder(staging_, folder, false, staging_path_);
  HPC_REQUIRE(from.get() >= 0, IoError, staging_path_, "/", relative, ": missing");
  const Kind there = kind_of(to.get(), name);
  // The folder was checked before the run; this guards against a file put there since.
  HPC_REQUIRE(there == Kind::missing || (there != Kind::folder && manifest_.count(relative)),
              IoError, shown(relative), ": appeared in the output folder during the run and is "
              "not hpcontact's: it was not replaced, and the results were not all moved in");
  HPC_REQUIRE(::renameat(from.get(), name.c_str(), to.get(), name.c_str()) == 0, IoError,
              shown(relative), ": cannot move the result into place: ", system_error());
  touched.insert(folder);
}

void OutputFolder::unlink_listed(const std::string& relative) {
  const auto [folder, name] = split(relative);
  const Fd fd = open_folder(dir_, folder, false, target_);
  if (fd.get() < 0) return;
  HPC_REQUIRE(::unlinkat(fd.get(), name.c_str(), 0) == 0 || errno == ENOENT, IoError,
              shown(relative), ": cannot remove the earlier result: ", system_error());
}

void OutputFolder::write_manifest(const std::set<std::string>& files) {
  std::string text;
  for (const auto& f : files) text += f + "\n";
  post::write_text_file(staging_path_ + "/" + kManifestNew, text);
  HPC_REQUIRE(::renameat(staging_, kManifestNew, dir_, kManifest) == 0, IoError, shown(kManifest),
              ": cannot write the manifest: ", system_error());
}

}  // namespace hpcontact::driver
