// The output folder of a run or a study: written through a staging folder, replaced by rename,
// guarded by a manifest of what we wrote and by a lock.
#pragma once

#include <set>
#include <string>
#include <vector>

namespace hpcontact::driver {

/// What a kind of run writes into its output folder.
struct FolderLayout {
  /// The file whose presence says the results are complete (summary.json); moved in last.
  std::string marker;
  /// Whether `relative` (a '/'-separated path inside the folder) names a file (`folder` false)
  /// or a folder (`folder` true) that this kind of run writes.
  bool (*is_output)(const std::string& relative, bool folder) = nullptr;
  /// Whose results they are, for messages: "a run", "a study".
  std::string kind;
};

/// An output folder held for one run or study; docs/input.md ("The output folder") says the same
/// for users.
/// - The target is created if missing and locked (flock on .hpcontact-lock) while the object
///   lives: a second run into the same folder fails at once.
/// - Files are written into staging(), a fresh folder inside the target; only commit() or
///   commit_subfolder() move them into the target, each by rename(2). Without a commit the
///   staging folder is removed on destruction and the target is as it was. Staging folders left
///   by an interrupted run are removed by the next one.
/// - .hpcontact-manifest lists the files the last run moved in (one relative path a line); only
///   those are ever replaced or removed. A file with an output name that the manifest does not
///   list (a user's own pressure.csv) refuses the folder, before anything is solved.
/// - Symbolic links inside the target are never followed (a link where an output goes refuses
///   the folder); the target itself may be a link.
/// Every failure is an IoError naming the file and the system's error text.
class OutputFolder {
public:
  /// A file the run reads, which the folder must not hold (see refuse_if_inside).
  struct Input {
    std::string file;
    std::string what;  ///< for the message: "the problem file"
  };
  /// Creates and opens the folder, refusing it if it holds one of `inputs` or another run holds
  /// its lock; removes the staging folders of interrupted runs.
  OutputFolder(std::string target, FolderLayout layout, const std::vector<Input>& inputs = {});
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  /// IoError if `file` lies in the target or in a folder below it (folders compared by device
  /// and inode, so links and other spellings of a path count); `what` names it in the message
  /// ("the problem file"). Nothing if `file` does not exist.
  void refuse_if_inside(const std::string& file, const std::string& what) const;

  const std::string& target() const { return target_; }
  /// Refuses the folder if a file or link is where an output goes and is not ours, then creates
  /// the staging folder and returns its path: the folder to write into, whose files become the
  /// target's at commit. Called when the inputs are known and checked; again only after a
  /// commit (a study on Slurm commits its submission, then its tables).
  const std::string& begin();

  /// The run succeeded: the manifest's files are replaced by the staged ones (the files it lists
  /// that this run did not write are removed; the marker is moved in last) and the manifest is
  /// rewritten.
  void commit();
  /// The run failed, keeping its last good state in `sub` (last-good): every other staged entry
  /// is moved under sub/, and only the target's sub/ is replaced; the earlier results stay.
  void commit_subfolder(const std::string& sub);

private:
  void lock();
  void read_manifest();
  void remove_stale_staging();
  void refuse_foreign_files(int folder, const std::string& prefix) const;
  void move_in(const std::string& prefix);
  void place(const std::string& relative, std::set<std::string>& touched);
  void unlink_listed(const std::string& relative);
  void write_manifest(const std::set<std::string>& files);
  std::string shown(const std::string& relative) const;

  std::string target_;
  FolderLayout layout_;
  int dir_ = -1;      ///< the target, opened once; every path below is resolved from it
  int lock_ = -1;     ///< .hpcontact-lock, flock'ed
  int staging_ = -1;  ///< the staging folder
  std::string staging_name_, staging_path_;
  std::set<std::string> manifest_;
  bool committed_ = false;
};

}  // namespace hpcontact::driver
