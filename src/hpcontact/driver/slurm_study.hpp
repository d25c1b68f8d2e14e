// A study as a Slurm job array: submitted (only the rows without a successful run), followed,
// and collected into the same study.csv and study.json as the local executor's.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "hpcontact/driver/output_folder.hpp"
#include "hpcontact/driver/slurm_script.hpp"
#include "hpcontact/driver/study.hpp"
#include "hpcontact/io/study_reader.hpp"

namespace hpcontact::driver {

struct SlurmStudyOptions {
  std::string program;           ///< the hpcontact executable the tasks run (absolute)
  OutputFolder* folder = nullptr;  ///< OUT, opened (and locked) by the caller
  SlurmOptions slurm;
  double poll_seconds = 2;       ///< between two questions to the scheduler while following
  /// Called when a followed task ends (as StudyOptions::finished): the row, done, total.
  std::function<void(const StudyRowResult&, int done, int total)> finished;
  /// Lines for the user (the job submitted, a warning); may be empty.
  std::function<void(const std::string&)> note;
};

/// sbatch's path; IoError naming --executor slurm and $PATH if it is not on PATH. Called before
/// anything is written. Also refuses an OUT whose path cannot be written on an #SBATCH line.
std::string require_slurm_client(const std::string& out_dir);

struct SlurmSubmission {
  std::string job_id;      ///< "" if nothing was submitted (every row had a successful run)
  std::vector<int> rows;   ///< the rows submitted (0-based), one array task each
  int complete = 0;        ///< rows left out: their run folder has a summary of this input
};

/// Resolves every row's input (reading the problem with its overrides, as the task will; an
/// invalid row is an InputError naming it, and nothing is submitted), checks the partition
/// (sinfo) and the options (sbatch --test-only), writes OUT/slurm/array.sh and
/// OUT/slurm/submission.json and submits the rows that have no successful summary of the same
/// input. IoError if a job of an earlier submission is still pending or running.
SlurmSubmission submit_slurm_study(const io::StudySpec& study, const SlurmStudyOptions& options);

/// Follows the tasks of OUT's submissions that have not ended (scontrol, sacct, the tasks' logs)
/// until all have, calling `finished` for each. IoError if the scheduler stops answering.
void follow_slurm_study(const SlurmStudyOptions& options);

/// Builds OUT/study.csv, OUT/study.json and OUT/runs/NN-label/log.txt (the task's log) from the
/// runs as they are: a row whose task failed, was cancelled, left no log or has not ended is a
/// failed row with the reason. IoError if OUT holds no submission.
StudyOutcome collect_slurm_study(const SlurmStudyOptions& options);

}  // namespace hpcontact::driver
