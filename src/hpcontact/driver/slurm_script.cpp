// The job array's batch script, written so that a task needs only the shared folder and the
// executable: absolute paths, the overrides quoted, no environment from the submitting shell.
#include "hpcontact/driver/slurm_script.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "hpcontact/core/error.hpp"
#include "hpcontact/driver/slurm_queue.hpp"

namespace hpcontact::driver {

namespace {

bool is_control(char c) {
  const auto u = static_cast<unsigned char>(c);
  return u < 0x20 || u == 0x7f;
}

/// `text` for a message on one line: control characters as \xNN.
std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (!is_control(c)) {
      out += c;
      continue;
    }
    char hex[5];
    std::snprintf(hex, sizeof hex, "\\x%02x", static_cast<unsigned char>(c));
    out += hex;
  }
  return out;
}

/// The value of an #SBATCH line (a command-line option's), checked (require_script_value).
std::string sbatch_value(const std::string& value, const std::string& option) {
  require_script_value("", value, option, true);
  return value;
}

}  // namespace

void require_script_value(const std::string& file, const std::string& value,
                          const std::string& what, bool sbatch_line) {
  const bool control = std::any_of(value.begin(), value.end(), is_control);
  const bool syntax = sbatch_line && value.find_first_of(" \t\\'\"#") != std::string::npos;
  HPC_REQUIRE(!control && !syntax, InputError, file.empty() ? "" : file + ": ", what, " '",
              escaped(value), "': ",
              control ? "a control character would end its line of the job array's script "
                        "(OUT/slurm/array.sh), and the rest would be a command of every task"
                      : "white space, a quote, '\\' or '#' cannot be written on an #SBATCH line "
                        "of the job array's script (sbatch reads them there as syntax)",
              ": write it without; nothing was submitted");
}

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
  // Every value is checked before it is written: a newline in any of them would start a command.
  require_script_value(job.file, job.name, "the study's name", false);
  require_script_value(job.file, job.program, "the hpcontact executable", false);
  for (const auto& row : job.rows) {
    const std::string which = "row " + std::to_string(row.index + 1) + " (" + row.run_dir + "): ";
    require_script_value(job.file, row.run_dir, which + "its folder", false);
    require_script_value(job.file, row.case_file, which + "its problem file", false);
    for (const auto& set : row.sets) require_script_value(job.file, set, which + "--set", false);
  }
  const std::string out_dir = sbatch_value(job.out_dir, "--out");
  std::ostringstream s;
  const std::string out = shell_quote(out_dir);
  s << "#!/bin/bash\n"
       "# The job array of hpcontact study '" << job.name << "' (written by hpcontact study\n"
       "# --executor slurm; docs/study.md): array task N runs row N into OUT/runs/NN-label/ and\n"
       "# logs to OUT/slurm/logs/JOB_N.out, ending with \"" << kTaskLinePrefix << " exit CODE after SECONDS s\".\n";
  s << "#SBATCH --job-name=" << shell_quote("hpcontact-" + job.name) << "\n"
    << "#SBATCH --output=" << out_dir << "/slurm/logs/%A_%a.out\n"
    << "#SBATCH --chdir=" << out_dir << "\n"
    << "#SBATCH --ntasks=1\n"
    << "#SBATCH --cpus-per-task=" << job.options.cpus_per_task << "\n";
  if (!job.options.partition.empty())
    s << "#SBATCH --partition=" << sbatch_value(job.options.partition, "--partition") << "\n";
  if (!job.options.time.empty())
    s << "#SBATCH --time=" << sbatch_value(job.options.time, "--time") << "\n";
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
