// The batch script of a study's job array: a task per row, each `hpcontact run` of its row.
#pragma once

#include <string>
#include <vector>

namespace hpcontact::driver {

/// The scheduler's options of `hpcontact study --executor slurm`.
struct SlurmOptions {
  std::string partition;                   ///< --partition; "" the cluster's default
  std::string time;                        ///< --time per task; "" the partition's default
  int cpus_per_task = 1;                   ///< --cpus-per-task (and the run's OMP_NUM_THREADS)
  std::vector<std::string> sbatch_options;  ///< passed to sbatch as they are
};

/// One row of the array: task `index` runs `program run case_file --set ... --out OUT/run_dir`.
struct BatchRow {
  int index = 0;
  std::string run_dir;    ///< relative to OUT: runs/NN-label
  std::string case_file;  ///< absolute
  std::vector<std::string> sets;
};

struct BatchJob {
  std::string file;     ///< the study file, for messages
  std::string name;     ///< the study's name (the job's name is hpcontact-<name>)
  std::string out_dir;  ///< OUT, absolute
  std::string program;  ///< the hpcontact executable, absolute
  std::vector<BatchRow> rows;  ///< every row of the study (a task runs only its own)
  SlurmOptions options;
};

/// The last line a task writes into its log: "hpcontact-task: exit CODE after SECONDS s".
inline const char* const kTaskLinePrefix = "hpcontact-task:";
/// A task's exit code when it does not see the study's output folder (not shared).
constexpr int kTaskFolderMissing = 97;

/// InputError naming `file` (if not empty) and `what` (the value shown with its control
/// characters escaped)
/// if `value` cannot be written into the job's script as it is: it holds a control character
/// (a newline would end its line, and the rest would be a command of every task), or, on an
/// #SBATCH line (`sbatch_line`), white space, a quote, '\' or '#', which sbatch reads there as
/// syntax.
void require_script_value(const std::string& file, const std::string& value,
                          const std::string& what, bool sbatch_line);

/// `text` as one word for the shell, in single quotes where needed.
std::string shell_quote(const std::string& text);

/// The log of array task `index` of job `job_id`: OUT/slurm/logs/JOB_INDEX.out.
std::string task_log_path(const std::string& out_dir, const std::string& job_id, int index);

/// The bash script (docs/study.md shows one): #SBATCH lines for the job's name, its logs
/// (OUT/slurm/logs/%A_%a.out), the folder, one task of cpus_per_task CPUs, the partition and
/// the time; then a check that OUT is the study's folder, a case per row and the run. Every
/// value is checked by require_script_value (those of #SBATCH lines as such) and the shell's
/// are quoted: InputError if one cannot be written.
std::string batch_script(const BatchJob& job);

/// sbatch's command line for the rows `indices` (sorted): sbatch --parsable --array=...
/// [sbatch_options] SCRIPT; with `test_only`, --test-only (nothing submitted).
std::vector<std::string> sbatch_command(const std::string& sbatch, const BatchJob& job,
                                        const std::vector<int>& indices, const std::string& script,
                                        bool test_only);

}  // namespace hpcontact::driver
