// The job array's batch script, written so that a task needs only the shared folder and the
// executable: absolute paths, the overrides quoted, no environment from the submitting shell.
#include "hpcontact/driver/slurm_script.hpp"

#include <sstream>

#include "hpcontact/driver/slurm_queue.hpp"

namespace hpcontact::driver {

std::string shell_quote(const std::string& text) {
  const bool plain = !text.empty() && text.find_first_not_of(
      "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-+=./,:@%") == std::string::npos;
  if (plain) return text;
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string task_log_path(const std::string& out_dir, const std::string& job_id, int index) {
  return out_dir + "/slurm/logs/" + job_id + "_" + std::to_string(index) + ".out";
}

std::string batch_script(const BatchJob& job) {
  std::ostringstream s;
  const std::string out = shell_quote(job.out_dir);
  s << "#!/bin/bash\n"
       "# The job array of hpcontact study '" << job.name << "' (written by hpcontact study\n"
       "# --executor slurm; docs/study.md): array task N runs row N into OUT/runs/NN-label/ and\n"
       "# logs to OUT/slurm/logs/JOB_N.out, ending with \"" << kTaskLinePrefix << " exit CODE after SECONDS s\".\n";
  s << "#SBATCH --job-name=" << shell_quote("hpcontact-" + job.name) << "\n"
    << "#SBATCH --output=" << job.out_dir << "/slurm/logs/%A_%a.out\n"
    << "#SBATCH --chdir=" << job.out_dir << "\n"
    << "#SBATCH --ntasks=1\n"
    << "#SBATCH --cpus-per-task=" << job.options.cpus_per_task << "\n";
  if (!job.options.partition.empty()) s << "#SBATCH --partition=" << job.options.partition << "\n";
  if (!job.options.time.empty()) s << "#SBATCH --time=" << job.options.time << "\n";
  s << "out=" << out << "\n"
    << "program=" << shell_quote(job.program) << "\n"
    << "if [ ! -f \"$out/slurm/submission.json\" ] || [ ! -w \"$out/runs\" ]; then\n"
       "  echo \"" << kTaskLinePrefix << " $out is not this study's output folder on $(hostname), or the task\"\\\n"
       "       \" cannot write into it: it must be on a file system the nodes share\" >&2\n"
       "  exit " << kTaskFolderMissing << "\n"
       "fi\n"
       "case \"${SLURM_ARRAY_TASK_ID:-}\" in\n";
  for (const auto& row : job.rows) {
    s << "  " << row.index << ") dir=" << shell_quote(row.run_dir) << "; set -- " << shell_quote(row.case_file);
    for (const auto& set : row.sets) s << " --set " << shell_quote(set);
    s << " ;;\n";
  }
  s << "  *) echo \"" << kTaskLinePrefix << " array task '${SLURM_ARRAY_TASK_ID:-}' is not a row of this study\" >&2\n"
       "     exit 98 ;;\n"
       "esac\n"
       "export OMP_NUM_THREADS=\"${SLURM_CPUS_PER_TASK:-1}\"\n"
       "start=$(date +%s.%N)\n"
       "\"$program\" run \"$@\" --out \"$out/$dir\" -q\n"
       "code=$?\n"
       "echo \"" << kTaskLinePrefix << " exit $code after $(awk -v a=\"$start\" -v b=\"$(date +%s.%N)\" 'BEGIN { printf \"%.3f\", b - a }') s\"\n"
       "exit $code\n";
  return s.str();
}

std::vector<std::string> sbatch_command(const std::string& sbatch, const BatchJob& job,
                                        const std::vector<int>& indices, const std::string& script,
                                        bool test_only) {
  std::vector<std::string> argv = {sbatch, "--parsable", "--array=" + array_ranges(indices)};
  if (test_only) argv.push_back("--test-only");
  for (const auto& option : job.options.sbatch_options) argv.push_back(option);
  argv.push_back(script);
  return argv;
}

}  // namespace hpcontact::driver
