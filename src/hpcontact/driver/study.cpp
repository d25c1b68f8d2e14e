// Study runs as child processes (a crash or a hang of one run cannot take the others with it),
// `jobs` at a time, and the table of their summaries.
#include "hpcontact/driver/study.hpp"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <thread>

#include "hpcontact/core/error.hpp"
#include "hpcontact/driver/study_table.hpp"

extern char** environ;

namespace hpcontact::driver {

namespace fs = std::filesystem;

namespace {

/// While it lives, SIGINT, SIGTERM and SIGHUP are blocked in the calling thread and the threads
/// it starts, and a watcher thread takes them: it records the signal and passes it on to every
/// run started through spawn(), and spawn() starts no run after it.
class SignalForwarder {
public:
  SignalForwarder() {
    sigemptyset(&signals_);
    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&signals_, signal);
    pthread_sigmask(SIG_BLOCK, &signals_, &previous_);
    watcher_ = std::thread([this] { watch(); });
  }
  ~SignalForwarder() {
    stop_ = true;
    watcher_.join();
    pthread_sigmask(SIG_SETMASK, &previous_, nullptr);
  }
  SignalForwarder(const SignalForwarder&) = delete;
  SignalForwarder& operator=(const SignalForwarder&) = delete;

  /// Calls start() (which returns a child's pid, or 0 if none started) unless a signal came;
  /// -1 if it did.
  template <class Start>
  pid_t spawn(Start start) {
    std::lock_guard lock(mutex_);
    if (signal_) return -1;
    const pid_t pid = start();
    if (pid > 0) running_.insert(pid);
    return pid;
  }
  void ended(pid_t pid) {
    std::lock_guard lock(mutex_);
    running_.erase(pid);
  }
  /// The signal that stopped the study, or 0.
  int signal() const { return signal_; }
  /// The set of signals forwarded (for a child's default dispositions).
  const sigset_t& signals() const { return signals_; }

private:
  void watch() {
    const timespec tick{0, 50'000'000};
    while (!stop_) {
      const int sig = sigtimedwait(&signals_, nullptr, &tick);
      if (sig <= 0) continue;
      std::lock_guard lock(mutex_);
      if (!signal_) signal_ = sig;
      for (const pid_t pid : running_) kill(pid, sig);
    }
  }

  sigset_t signals_, previous_;
  std::mutex mutex_;
  std::set<pid_t> running_;
  std::atomic<int> signal_{0};
  std::atomic<bool> stop_{false};
  std::thread watcher_;
};

/// Starts `argv` with stdout and stderr into `log` (with the default dispositions of the
/// forwarded signals, unblocked); waits for it. Returns the exit code, minus the signal that
/// ended it, or nullopt if the study was stopped before the run could start. The calling thread
/// is the child's parent: a parent-death signal the child asks for (run --parent-pid) comes when
/// this thread ends, which it does not before the child has, unless the whole study is killed.
std::optional<int> run_process(const std::vector<std::string>& argv, const fs::path& log,
                               SignalForwarder& forwarder) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, STDIN_FILENO);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setsigdefault(&attributes, &forwarder.signals());
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  int rc = 0;
  const pid_t pid = forwarder.spawn([&] {
    pid_t child = 0;
    rc = posix_spawn(&child, args[0], &actions, &attributes, args.data(), environ);
    return rc == 0 ? child : 0;
  });
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (pid < 0) return std::nullopt;
  if (rc != 0) throw IoError(argv[0] + ": cannot start a run: " + std::strerror(rc));
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno == EINTR) continue;
    forwarder.ended(pid);
    throw IoError(argv[0] + ": lost a run: " + std::strerror(errno));
  }
  forwarder.ended(pid);
  if (WIFSIGNALED(status)) return -WTERMSIG(status);
  return WEXITSTATUS(status);
}

}  // namespace

namespace {

bool study_output(const std::string& relative, bool folder) {
  // A stopped study's logs: stopped/runs/NN-label/log.txt (no table there).
  if (relative == "stopped") return folder;
  if (relative.rfind("stopped/", 0) == 0) {
    const std::string rest = relative.substr(8);
    return rest.rfind("runs", 0) == 0 && study_output(rest, folder);
  }
  if (relative == "study.csv" || relative == "study.json" || relative == "report.html") return !folder;
  if (relative == "slurm/submission.json" || relative == "slurm/array.sh") return !folder;
  if (relative == "runs" || relative == "slurm") return folder;
  if (relative.rfind("runs/", 0) != 0) return false;
  const std::string rest = relative.substr(5);
  const auto slash = rest.find('/');
  if (slash == std::string::npos) return folder && !rest.empty();
  return !folder && slash > 0 && rest.substr(slash + 1) == "log.txt";
}

}  // namespace

FolderLayout study_layout() { return {"study.json", &study_output, "a study"}; }

StudyOutcome run_study(const io::StudySpec& study, const StudyOptions& options) {
  std::optional<OutputFolder> own_folder;
  OutputFolder* folder = options.folder;
  if (!folder) {
    own_folder.emplace(options.out_dir, study_layout(),
                       std::vector<OutputFolder::Input>{{study.file, "the study file"}});
    folder = &*own_folder;
  }
  const fs::path stage = folder->begin(), target = folder->target();

  const int total = static_cast<int>(study.runs.size());
  StudyOutcome outcome;
  std::vector<StudyRowResult>& rows = outcome.rows;
  rows.resize(total);
  std::vector<fs::path> logs(total);
  for (int i = 0; i < total; ++i) {
    const std::string name = row_folder_name(i, study.runs[i].label);
    rows[i].run = study.runs[i];
    rows[i].run_dir = (target / "runs" / name).string();
    logs[i] = stage / "runs" / name / "log.txt";
  }
  std::atomic<int> next{0};
  std::mutex report;
  int done = 0;
  std::string failure;  // an IoError of a worker, rethrown after all have stopped
  SignalForwarder forwarder;
  auto worker = [&] {
    for (int i = next++; i < total && !forwarder.signal(); i = next++) {
      StudyRowResult& row = rows[i];
      try {
        fs::create_directories(logs[i].parent_path());
        // --parent-pid: a run whose study is killed outright (SIGKILL) stops as on SIGTERM.
        std::vector<std::string> argv = {options.program, "run", row.run.case_file, "--out",
                                         row.run_dir, "-q", "--parent-pid",
                                         std::to_string(::getpid())};
        for (const auto& s : row.run.sets) {
          argv.push_back("--set");
          argv.push_back(s);
        }
        const auto t0 = std::chrono::steady_clock::now();
        const auto code = run_process(argv, logs[i], forwarder);
        if (!code) break;
        row.exit_code = *code;
        row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (row.exit_code == 0) row.summary = read_summary(row.run_dir);
        if (!row.converged()) {
          row.message = log_error_line(logs[i].string());
          if (row.exit_code < 0) row.message = "killed by signal " + std::to_string(-row.exit_code) +
                                               (row.message.empty() ? "" : " after: " + row.message);
          if (row.message.empty()) row.message = "exit code " + std::to_string(row.exit_code);
        }
      } catch (const std::exception& e) {
        std::lock_guard lock(report);
        if (failure.empty()) failure = e.what();
        row.message = e.what();
      }
      std::lock_guard lock(report);
      ++done;
      if (options.finished && !forwarder.signal()) options.finished(row, done, total);
    }
  };
  {
    const int jobs = std::clamp(options.jobs, 1, std::max(1, total));
    std::vector<std::thread> threads;
    for (int j = 0; j < jobs; ++j) threads.emplace_back(worker);
    for (auto& t : threads) t.join();
  }
  // A stopped study writes no table: its rows would pass for runs that failed. The logs of the
  // runs it started go to stopped/, apart from a finished study's (each stopped run's converged
  // state is in its own folder's last-good/).
  outcome.signal = forwarder.signal();
  if (outcome.signal) {
    if (fs::exists(stage / "runs")) {
      folder->commit_subfolder("stopped");
      outcome.logs = (target / "stopped" / "runs").string();
    }
    return outcome;
  }
  write_study_tables(study, rows, stage.string());
  outcome.absent_columns = absent_columns(study, rows);
  folder->commit();
  HPC_REQUIRE(failure.empty(), IoError, study.file, ": ", failure);
  return outcome;
}

}  // namespace hpcontact::driver
