// Running a study: every run of a study file as its own `hpcontact run` process, several at a
// time, and one table of their summaries.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hpcontact/driver/output_folder.hpp"
#include "hpcontact/driver/study_table.hpp"
#include "hpcontact/io/study_reader.hpp"

namespace hpcontact::driver {

struct StudyOptions {
  std::string program;  ///< the hpcontact executable each run is started with
  std::string out_dir;  ///< OUT: OUT/runs/NN-label/ per run, OUT/study.csv, OUT/study.json
  /// OUT opened by the caller (before reading the study file); when set, out_dir is not used.
  OutputFolder* folder = nullptr;
  int jobs = 1;         ///< runs at a time
  /// Called (from one thread at a time) when a run finishes: the row, how many are done.
  std::function<void(const StudyRowResult&, int done, int total)> finished;
};

/// The files a study writes into OUT (an OutputFolder): study.json (the marker), study.csv and
/// runs/NN-label/log.txt; each run's own files are its folder's. A study on Slurm adds
/// slurm/submission.json and slurm/array.sh; the tasks' logs in slurm/logs/ are Slurm's, named
/// by job id, and never replaced.
FolderLayout study_layout();

struct StudyOutcome {
  std::vector<StudyRowResult> rows;
  /// SIGINT, SIGTERM or SIGHUP if the study was stopped by one: it was passed on to the running
  /// runs, they were waited for, and no table was written; 0 otherwise.
  int signal = 0;
  /// Stopped: where the logs of the runs it had started are (OUT/stopped/runs), or empty.
  std::string logs;
  /// The study's `columns` that no run's summary.json has (absent_columns).
  std::vector<std::string> absent_columns;
};

/// Runs every row (`program run CASE --out OUT/runs/NN-label -q --parent-pid PID --set ...`,
/// PID this process, its output in the folder's log.txt) and writes OUT/study.csv and
/// OUT/study.json. A run that fails is a row with
/// its message, not an exception. IoError if OUT cannot be written or a process not started.
StudyOutcome run_study(const io::StudySpec& study, const StudyOptions& options);

}  // namespace hpcontact::driver
