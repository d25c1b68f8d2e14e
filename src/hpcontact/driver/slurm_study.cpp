// Submitting a study as a job array, following it and collecting its rows; what was submitted is
// recorded in OUT/slurm/submission.json (slurm_record.hpp).
#include "hpcontact/driver/slurm_study.hpp"

#include <sys/stat.h>
#include <sys/vfs.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "hpcontact/core/error.hpp"
#include "hpcontact/driver/command.hpp"
#include "hpcontact/driver/contact_compare.hpp"
#include "hpcontact/driver/slurm_queue.hpp"
#include "hpcontact/driver/slurm_record.hpp"
#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/io/text_file.hpp"
#include "hpcontact/post/output_file.hpp"

namespace hpcontact::driver {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const char* const kScript = "slurm/array.sh";
/// A task's log is copied into its row's log.txt; a run at -q prints a few lines.
constexpr std::size_t kMaxLogBytes = 16u << 20;
/// How long the scheduler may fail to answer while a study is followed.
constexpr double kSchedulerSilenceSeconds = 120;

std::string absolute_folder(const OutputFolder& folder) {
  return fs::absolute(folder.target()).lexically_normal().string();
}

std::string join(const std::vector<std::string>& parts, const std::string& between) {
  std::string out;
  for (std::size_t i = 0; i < parts.size(); ++i) out += (i ? between : "") + parts[i];
  return out;
}

std::string first_line(const std::string& text) {
  std::string line = text.substr(0, text.find('\n'));
  return line.empty() ? "(nothing printed)" : line;
}

std::string now_utc() {
  const std::time_t t = std::time(nullptr);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return text;
}

/// The task's last line "hpcontact-task: exit CODE after SECONDS s", if its log has one.
struct TaskLine {
  int exit_code = 0;
  double seconds = 0;
};
std::optional<TaskLine> task_line(const std::string& log) {
  std::ifstream in(log);
  std::optional<TaskLine> found;
  const std::string prefix = std::string(kTaskLinePrefix) + " exit ";
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(prefix, 0) != 0) continue;
    std::istringstream fields(line.substr(prefix.size()));
    TaskLine t;
    std::string after;
    if (fields >> t.exit_code >> after >> t.seconds && after == "after") found = t;
  }
  return found;
}

std::string relative_run_dir(const io::StudySpec& study, int i) {
  return "runs/" + row_folder_name(i, study.runs[i].label);
}

/// Whether the run folder's summary.json was written at or after `since` (a committed run: the
/// summary is written in the staging folder and moved into place when the run has succeeded).
bool summary_written_since(const std::string& run_dir, std::time_t since) {
  struct stat st{};
  return since > 0 && ::stat((run_dir + "/summary.json").c_str(), &st) == 0 && st.st_mtime >= since;
}

/// A row as its task left it; `queries` caches the scheduler's answers per job.
StudyRowResult row_result(const io::StudySpec& study, const json& record, const std::string& out,
                          int i, std::map<std::string, SlurmArrayQuery>& queries) {
  StudyRowResult row;
  row.run = study.runs[i];
  row.run_dir = out + "/" + relative_run_dir(study, i);
  const auto task = latest_task(record, i);
  if (!task) {
    const bool complete = listed_complete(record, i);
    row.summary = read_summary(row.run_dir);
    row.exit_code = complete && row.summary.is_object() ? 0 : -1;
    if (row.exit_code != 0) {
      row.summary = nullptr;
      row.message = complete ? "found complete when submitted, but its run's summary.json has gone "
                               "since (" + row.run_dir + "): submit the study again to run it"
                             : "never submitted (no array task ran this row)";
    }
    return row;
  }
  const std::string name = task->job_id + "_" + std::to_string(task->index);
  const std::string log = task_log_path(out, task->job_id, task->index);
  if (const auto line = task_line(log)) {
    row.exit_code = line->exit_code;
    row.seconds = line->seconds;
    if (row.exit_code == 0) row.summary = read_summary(row.run_dir);
    if (row.converged()) return row;
    if (row.exit_code == 0) {
      row.message = "array task " + name + " ended with exit 0, but its run's summary.json has "
                    "gone since (" + row.run_dir + "): submit the study again to run it";
      return row;
    }
    row.message = row.exit_code == kTaskFolderMissing
                      ? log_error_line(log)
                      : log_error_line(log, kTaskLinePrefix);
    if (row.message.empty()) row.message = "exit code " + std::to_string(row.exit_code);
    row.message = "array task " + name + ": " + row.message + " (log " + log + ")";
    return row;
  }
  // The task's script ended without its exit line (scancel, a time limit) while the run it had
  // started went on to commit — a process the scheduler had lost track of. Its results are
  // complete, as a resubmission counts them: the row is that run.
  if (summary_written_since(row.run_dir, task->submitted))
    if (json summary = read_summary(row.run_dir); summary.is_object()) {
      row.exit_code = 0;
      row.summary = std::move(summary);
      return row;
    }
  auto known = queries.find(task->job_id);
  if (known == queries.end()) known = queries.emplace(task->job_id, query_slurm_array(task->job_id)).first;
  const SlurmArrayQuery& q = known->second;
  const auto state = q.tasks.find(task->index);
  std::error_code ec;
  const bool has_log = fs::exists(log, ec);
  std::ostringstream m;
  m << "array task " << name;
  if (state != q.tasks.end() && !slurm_state_final(state->second.state)) {
    m << " is still " << state->second.state << ": collect again when it has ended";
  } else {
    if (state != q.tasks.end())
      m << " ended " << state->second.state << " (exit code " << state->second.exit_code << ")";
    else
      m << " ended" << (q.error.empty() ? "" : " (Slurm cannot say how: " + q.error + ")");
    if (has_log) {
      const std::string last = log_error_line(log);
      m << " without an exit status: it was killed or cancelled before hpcontact ended (log " << log
        << (last.empty() ? "" : ": " + last) << ")";
    } else if (state != q.tasks.end() && state->second.state == "CANCELLED") {
      m << " before it started (no log at " << log << ")";
    } else {
      m << " and left no log at " << log << ": the node could not write the study's output folder; "
           "it must be on a file system the nodes share, writable by the job's user";
    }
  }
  row.message = m.str();
  return row;
}

/// Whether the run folder holds a summary of a run of exactly `effective_input`.
bool has_successful_run(const std::string& run_dir, const std::string& effective_input) {
  if (!read_summary(run_dir).is_object()) return false;
  std::ifstream in(fs::path(run_dir) / "input.yaml");
  std::stringstream text;
  text << in.rdbuf();
  return in && text.str() == effective_input;
}

void require_partition(const std::string& partition) {
  const std::string sinfo = find_on_path("sinfo");
  if (sinfo.empty()) return;  // sbatch --test-only will say it
  const auto listed = run_captured({sinfo, "-h", "-o", "%R"}, 30);
  if (listed.exit_code != 0 || listed.timed_out) return;
  std::vector<std::string> names;
  std::stringstream lines(listed.out);
  for (std::string line; std::getline(lines, line);)
    if (!line.empty() && std::find(names.begin(), names.end(), line) == names.end()) names.push_back(line);
  std::stringstream asked(partition);
  for (std::string p; std::getline(asked, p, ',');)
    HPC_REQUIRE(std::find(names.begin(), names.end(), p) != names.end(), InputError,
                "--partition ", p, ": the cluster has no such partition (sinfo lists: ",
                names.empty() ? std::string("none") : join(names, ", "), "); nothing was submitted");
}

/// A warning if OUT is on a file system of this machine only while the partition has other nodes.
void warn_if_local(const std::string& out, const SlurmOptions& slurm,
                   const std::function<void(const std::string&)>& note) {
  struct statfs fs_info;
  if (!note || ::statfs(out.c_str(), &fs_info) != 0) return;
  const std::map<long, const char*> local = {{0xEF53, "ext4"}, {0x58465342, "xfs"},
                                             {0x9123683E, "btrfs"}, {0x01021994, "tmpfs"},
                                             {0x794c7630, "overlayfs"}};
  const auto kind = local.find(static_cast<long>(fs_info.f_type));
  const std::string sinfo = find_on_path("sinfo");
  if (kind == local.end() || sinfo.empty()) return;
  std::vector<std::string> argv = {sinfo, "-h", "-o", "%n %o"};
  if (!slurm.partition.empty()) argv.insert(argv.end(), {"-p", slurm.partition});
  const auto nodes = run_captured(argv, 30);
  char host[256] = {};
  ::gethostname(host, sizeof host - 1);
  const std::string self = std::string(host).substr(0, std::string(host).find('.'));
  std::stringstream lines(nodes.out);
  std::vector<std::string> others;
  // A node is this machine by its name or its address (a one-node cluster on localhost).
  for (std::string name, address; lines >> name >> address;)
    if (name != self && address != self && address != "localhost" && address.rfind("127.", 0) != 0)
      others.push_back(name);
  if (!others.empty())
    note("warning: " + out + " is on a local file system (" + kind->second + ") of " + self +
         ", and the partition has other nodes (" + join(others, ", ") +
         "): tasks there cannot write into it unless it is shared with them");
}

void refuse_active_jobs(const json& record, const std::string& out) {
  if (!record.is_object()) return;
  for (const auto& s : submitted(record)) {
    const std::string id = s.at("job_id").get<std::string>();
    const auto q = query_slurm_array(id);
    HPC_REQUIRE(q.error.empty(), IoError, out, ": cannot ask Slurm whether job ", id,
                " of the earlier submission has ended: ", q.error);
    std::vector<int> active;
    for (const auto& [k, t] : q.tasks)
      if (!slurm_state_final(t.state)) active.push_back(k);
    HPC_REQUIRE(active.empty(), IoError, out, ": job ", id, " of the earlier submission still has ",
                "tasks pending or running (", array_ranges(active), "): wait for it (hpcontact study "
                "--collect ", out, " --wait) or cancel it (scancel ", id, ") before submitting again");
  }
}

void write_record(const std::string& stage, const std::string& script, const json& record) {
  post::write_text_file(stage + "/array.sh", script);
  fs::permissions(stage + "/array.sh", fs::perms::owner_exec | fs::perms::group_exec,
                  fs::perm_options::add);
  // a path of bytes that are not UTF-8 has them as U+FFFD (the paths are shown, never opened)
  post::write_text_file(stage + "/submission.json",
                        record.dump(2, ' ', false, json::error_handler_t::replace) + "\n");
}

}  // namespace

std::string require_slurm_client(const std::string& out_dir) {
  const std::string sbatch = find_on_path("sbatch");
  const char* path = std::getenv("PATH");
  HPC_REQUIRE(!sbatch.empty(), IoError, "--executor slurm: sbatch is not on PATH (",
              path ? path : "unset", "): run the study on a machine with Slurm's client commands "
              "(a login node of the cluster), or without --executor slurm on this machine");
  const std::string out = fs::absolute(out_dir).lexically_normal().string();
  HPC_REQUIRE(out.find('%') == std::string::npos, InputError, "--out ", out,
              ": with --executor slurm the output folder's path may not hold '%' (it is written on "
              "the #SBATCH --output line, where Slurm reads it as a pattern)");
  require_script_value("", out, "--out", true);
  return sbatch;
}

SlurmSubmission submit_slurm_study(const io::StudySpec& study, const SlurmStudyOptions& options) {
  HPC_REQUIRE(options.folder, IoError, "submit_slurm_study: no output folder");
  OutputFolder& folder = *options.folder;
  const std::string out = absolute_folder(folder);
  const std::string sbatch = require_slurm_client(out);
  const int n = static_cast<int>(study.runs.size());

  // Every row's input as its task will read it: an invalid row is known now, not in the queue.
  BatchJob job{study.file, study.name, out, options.program, {}, options.slurm};
  std::vector<std::string> effective(n), problems;
  for (int i = 0; i < n; ++i) {
    const auto& run = study.runs[i];
    BatchRow row{i, relative_run_dir(study, i), fs::absolute(run.case_file).lexically_normal().string(),
                 run.sets};
    try {
      const auto read = io::read_problem_full(row.case_file, row.sets);
      require_references(read.spec);
      effective[i] = read.effective_yaml;
    } catch (const Error& e) {
      problems.push_back("row " + std::to_string(i + 1) + " '" + run.label + "': " + e.what());
    }
    job.rows.push_back(std::move(row));
  }
  HPC_REQUIRE(problems.empty(), InputError, study.file, ": ", problems.size(), " of the ", n,
              " rows cannot be run; nothing was submitted:\n  ", join(problems, "\n  "));
  // Before anything else is asked or written: a value the script cannot carry is refused.
  const std::string script = batch_script(job);
  if (!options.slurm.partition.empty()) require_partition(options.slurm.partition);

  json record = read_record(out);
  refuse_active_jobs(record, out);
  SlurmSubmission result;
  std::vector<int> complete;
  for (int i = 0; i < n; ++i)
    (has_successful_run(out + "/" + job.rows[i].run_dir, effective[i]) ? complete : result.rows).push_back(i);
  result.complete = static_cast<int>(complete.size());
  if (result.rows.empty()) {
    if (options.note) options.note("every row has a successful run of its input in " + out + "/runs/; nothing submitted");
    return result;
  }
  warn_if_local(out, options.slurm, options.note);

  if (!record.is_object()) record = {{"submissions", json::array()}};
  record["study"] = study_to_json(study);
  record["program"] = options.program;
  record["out"] = out;
  json submission = {{"job_id", ""}, {"rows", result.rows}, {"complete", complete},
                     {"options", options.slurm.sbatch_options}, {"submitted", now_utc()}};
  record["submissions"].push_back(submission);

  // The scheduler checks the options before anything is committed or submitted.
  const std::string stage = folder.begin();
  write_record(stage, script, record);
  const auto test = run_captured(sbatch_command(sbatch, job, result.rows, stage + "/array.sh", true), 60);
  HPC_REQUIRE(test.exit_code == 0 && !test.timed_out, IoError, "sbatch --test-only refused the job "
              "array of ", study.file, " (options: ", job.options.partition.empty() ? "" : "--partition " + job.options.partition + " ",
              job.options.time.empty() ? "" : "--time " + job.options.time + " ", "--cpus-per-task ",
              job.options.cpus_per_task, options.slurm.sbatch_options.empty() ? "" : " --sbatch-option ",
              join(options.slurm.sbatch_options, " --sbatch-option "), "): ",
              test.timed_out ? "no answer within 60 s" : first_line(test.err), "; nothing was submitted");
  folder.commit_subfolder("slurm");
  std::error_code ec;
  fs::create_directories(out + "/slurm/logs", ec);
  HPC_REQUIRE(!ec, IoError, out, "/slurm/logs: cannot create the folder of the tasks' logs: ", ec.message());
  fs::create_directories(out + "/runs", ec);
  HPC_REQUIRE(!ec, IoError, out, "/runs: cannot create the folder of the runs: ", ec.message());

  const auto sent = run_captured(sbatch_command(sbatch, job, result.rows, out + "/" + kScript, false), 120);
  HPC_REQUIRE(sent.exit_code == 0 && !sent.timed_out, IoError, "sbatch did not submit the job array of ",
              study.file, ": ", sent.timed_out ? "no answer within 120 s" : first_line(sent.err));
  std::string id = sent.out.substr(0, sent.out.find_first_of(";\n"));
  HPC_REQUIRE(!id.empty() && id.find_first_not_of("0123456789") == std::string::npos, IoError,
              "sbatch answered '", first_line(sent.out), "' where it prints the job id; the job may have "
              "been submitted: see squeue");
  result.job_id = id;
  record["submissions"].back()["job_id"] = id;
  write_record(folder.begin(), script, record);
  folder.commit_subfolder("slurm");
  if (options.note)
    options.note("submitted job array " + id + ": " + std::to_string(result.rows.size()) +
                 " tasks (rows " + array_ranges(result.rows) + ", numbered from 0)" +
                 (complete.empty() ? "" : "; " + std::to_string(complete.size()) +
                                              " rows already have a successful run"));
  return result;
}

void follow_slurm_study(const SlurmStudyOptions& options) {
  const std::string out = absolute_folder(*options.folder);
  const json record = read_record(out);
  HPC_REQUIRE(record.is_object(), IoError, out, ": no Slurm submission to follow (no ", kSubmissionRecord, ")");
  const io::StudySpec study = study_from_json(record.at("study"));
  const auto jobs = submitted(record);
  if (jobs.empty()) return;
  const std::string job_id = jobs.back().at("job_id").get<std::string>();
  std::vector<int> waiting;
  for (const auto& r : jobs.back().at("rows")) waiting.push_back(r.get<int>());
  const int total = static_cast<int>(waiting.size());
  int done = 0;
  auto silent_since = std::chrono::steady_clock::now();
  while (!waiting.empty()) {
    std::map<std::string, SlurmArrayQuery> queries;
    queries.emplace(job_id, query_slurm_array(job_id));
    const SlurmArrayQuery& q = queries.at(job_id);
    if (q.error.empty()) silent_since = std::chrono::steady_clock::now();
    HPC_REQUIRE(std::chrono::duration<double>(std::chrono::steady_clock::now() - silent_since).count() <
                    kSchedulerSilenceSeconds,
                IoError, "job ", job_id, ": Slurm has not answered for ", kSchedulerSilenceSeconds,
                " s (", q.error, "); the job goes on: hpcontact study --collect ", out, " later");
    std::vector<int> still;
    for (const int i : waiting) {
      const auto state = q.tasks.find(i);
      const bool ended = task_line(task_log_path(out, job_id, i)).has_value() ||
                         (q.known && (state == q.tasks.end() || slurm_state_final(state->second.state))) ||
                         (!q.known && q.error.empty());
      if (!ended) {
        still.push_back(i);
        continue;
      }
      if (options.finished) options.finished(row_result(study, record, out, i, queries), ++done, total);
    }
    waiting = still;
    if (!waiting.empty()) std::this_thread::sleep_for(std::chrono::duration<double>(options.poll_seconds));
  }
}

StudyOutcome collect_slurm_study(const SlurmStudyOptions& options) {
  const std::string out = absolute_folder(*options.folder);
  const json record = read_record(out);
  HPC_REQUIRE(record.is_object(), IoError, out, ": no Slurm submission here (no ", kSubmissionRecord,
              "): submit one with hpcontact study FILE --executor slurm --out ", out);
  const io::StudySpec study = study_from_json(record.at("study"));
  const std::string stage = options.folder->begin();
  StudyOutcome outcome;
  std::map<std::string, SlurmArrayQuery> queries;
  for (int i = 0; i < static_cast<int>(study.runs.size()); ++i) {
    outcome.rows.push_back(row_result(study, record, out, i, queries));
    if (const auto task = latest_task(record, i)) {
      const std::string log = task_log_path(out, task->job_id, task->index);
      std::error_code ec;
      if (fs::is_regular_file(log, ec)) {
        fs::create_directories(stage + "/" + relative_run_dir(study, i));
        post::write_text_file(stage + "/" + relative_run_dir(study, i) + "/log.txt",
                              io::read_bounded_file(log, "task log", kMaxLogBytes, false));
      }
    }
  }
  // The submission stays: the folder's files are replaced by what is staged.
  fs::create_directories(stage + "/slurm");
  for (const char* file : {kSubmissionRecord, kScript}) {
    std::error_code ec;
    if (fs::exists(out + "/" + file, ec))
      post::write_text_file(stage + "/" + file,
                            io::read_bounded_file(out + "/" + file, "submission file", kMaxLogBytes, false));
  }
  write_study_tables(study, outcome.rows, stage);
  outcome.absent_columns = absent_columns(study, outcome.rows);
  options.folder->commit();
  return outcome;
}

}  // namespace hpcontact::driver
