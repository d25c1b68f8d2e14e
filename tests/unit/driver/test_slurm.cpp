// The Slurm executor's pure parts: array specifications, scontrol's and sacct's records, the
// batch script's quoting and content, the submission record, and running a short command.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "hpcontact/core/error.hpp"
#include "hpcontact/driver/command.hpp"
#include "hpcontact/driver/slurm_queue.hpp"
#include "hpcontact/driver/slurm_record.hpp"
#include "hpcontact/driver/slurm_script.hpp"
#include "hpcontact/driver/slurm_study.hpp"
#include "hpcontact/driver/study.hpp"
#include "hpcontact/post/output_file.hpp"

using namespace hpcontact;
using namespace hpcontact::driver;

// The rows of a resubmission are written as Slurm's shortest array specification, and read back.
TEST(SlurmQueue, ArrayRangesRoundTrip) {
  EXPECT_EQ(array_ranges({0, 1, 2, 5, 7, 8}), "0-2,5,7-8");
  EXPECT_EQ(array_ranges({3}), "3");
  EXPECT_EQ(parse_array_ranges("0-2,5,7-8"), (std::vector<int>{0, 1, 2, 5, 7, 8}));
  EXPECT_EQ(parse_array_ranges("3-5%2"), (std::vector<int>{3, 4, 5}));
  EXPECT_TRUE(parse_array_ranges("N/A").empty());
}

// scontrol's one-line records give each task's state, pending tasks grouped in a range.
TEST(SlurmQueue, ScontrolRecords) {
  const std::string text =
      "JobId=12 ArrayJobId=12 ArrayTaskId=2-3 JobName=x UserId=root(0) JobState=PENDING Reason=Resources ExitCode=0:0 RunTime=00:00:00\n"
      "JobId=14 ArrayJobId=12 ArrayTaskId=1 JobName=x JobState=CANCELLED Reason=None ExitCode=0:15\n"
      "JobId=13 ArrayJobId=12 ArrayTaskId=0 JobName=x JobState=COMPLETED Reason=None ExitCode=0:0\n";
  const auto tasks = parse_scontrol_tasks(text);
  ASSERT_EQ(tasks.size(), 4u);
  EXPECT_EQ(tasks.at(0).state, "COMPLETED");
  EXPECT_EQ(tasks.at(1).state, "CANCELLED");
  EXPECT_EQ(tasks.at(1).exit_code, "0:15");
  EXPECT_EQ(tasks.at(3).state, "PENDING");
  EXPECT_TRUE(slurm_state_final("CANCELLED"));
  EXPECT_TRUE(slurm_state_final("TIMEOUT"));
  EXPECT_FALSE(slurm_state_final("RUNNING"));
  EXPECT_FALSE(slurm_state_final("PENDING"));
}

// sacct's records of another job, or of the job's steps, are not the array's tasks.
TEST(SlurmQueue, SacctRecords) {
  const auto tasks = parse_sacct_tasks(
      "12_0|COMPLETED|0:0\n12_1|CANCELLED by 0|0:15\n12_[2-3]|PENDING|0:0\n120_1|FAILED|1:0\n", "12");
  ASSERT_EQ(tasks.size(), 4u);
  EXPECT_EQ(tasks.at(1).state, "CANCELLED");
  EXPECT_EQ(tasks.at(3).state, "PENDING");
}

// A value reaches the task as one word, whatever it holds.
TEST(SlurmScript, ShellQuote) {
  EXPECT_EQ(shell_quote("discretization.degree=4"), "discretization.degree=4");
  EXPECT_EQ(shell_quote("a b"), "'a b'");
  EXPECT_EQ(shell_quote("it's"), "'it'\\''s'");
  EXPECT_EQ(shell_quote("$(rm -rf x)"), "'$(rm -rf x)'");
  EXPECT_EQ(shell_quote(""), "''");
}

// The script has the options as #SBATCH lines, a case per row with its overrides quoted, and
// ends by printing the run's exit code; sbatch's command line carries the rows and the options.
TEST(SlurmScript, BatchScript) {
  BatchJob job;
  job.name = "t51";
  job.out_dir = "/shared/out";
  job.program = "/opt/hpcontact/bin/hpcontact";
  job.options.partition = "long";
  job.options.time = "00:10:00";
  job.options.cpus_per_task = 2;
  job.options.sbatch_options = {"--mem=2G"};
  job.rows = {{0, "runs/01-a", "/shared/a.yaml", {}},
              {1, "runs/02-b", "/shared/b.yaml", {"contact[0].penalty=1e8", "title=two words"}}};
  const std::string s = batch_script(job);
  for (const char* line : {"#SBATCH --job-name=hpcontact-t51\n", "#SBATCH --output=/shared/out/slurm/logs/%A_%a.out\n",
                           "#SBATCH --cpus-per-task=2\n", "#SBATCH --partition=long\n", "#SBATCH --time=00:10:00\n",
                           "  0) dir=runs/01-a; set -- /shared/a.yaml ;;\n",
                           "  1) dir=runs/02-b; set -- /shared/b.yaml --set 'contact[0].penalty=1e8' --set 'title=two words' ;;\n",
                           "export OMP_NUM_THREADS=\"${SLURM_CPUS_PER_TASK:-1}\"\n", "exit $code\n"})
    EXPECT_NE(s.find(line), std::string::npos) << line << " not in\n" << s;
  EXPECT_EQ(s.rfind("#!/bin/bash\n", 0), 0u);
  EXPECT_EQ(sbatch_command("/usr/bin/sbatch", job, {1, 2, 3}, "/shared/out/slurm/array.sh", true),
            (std::vector<std::string>{"/usr/bin/sbatch", "--parsable", "--array=1-3", "--test-only",
                                      "--mem=2G", "/shared/out/slurm/array.sh"}));
  EXPECT_EQ(task_log_path("/shared/out", "12", 3), "/shared/out/slurm/logs/12_3.out");
}

namespace {

/// A folder of its own for a test, empty.
std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("hpc-slurm-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// A job of one row (task 0) in `dir`, whose program is a script that writes the arguments it
/// was given into dir/argv, one a line.
BatchJob job_in(const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir / "out" / "slurm");
  std::filesystem::create_directories(dir / "out" / "runs");
  post::write_text_file((dir / "out" / "slurm" / "submission.json").string(), "{}\n");
  const auto program = dir / "fake hpcontact";
  post::write_text_file(program.string(),
                        "#!/bin/sh\nfor a in \"$@\"; do printf '%s\\n' \"$a\"; done > '" +
                            (dir / "argv").string() + "'\n");
  std::filesystem::permissions(program, std::filesystem::perms::owner_all);
  BatchJob job;
  job.name = "s";
  job.file = (dir / "s.yaml").string();
  job.out_dir = (dir / "out").string();
  job.program = program.string();
  job.rows = {{0, "runs/01-a", (dir / "a.yaml").string(), {}}};
  return job;
}

/// Runs the job's script as array task 0 with bash; its exit code.
int run_task(const std::filesystem::path& dir, const std::string& script) {
  post::write_text_file((dir / "array.sh").string(), script);
  return run_captured({find_on_path("env"), "SLURM_ARRAY_TASK_ID=0", find_on_path("bash"),
                       (dir / "array.sh").string()},
                      30)
      .exit_code;
}

}  // namespace

// What the shell would read as syntax — quotes, $(...), backticks, ';', '#', '*', spaces —
// reaches the task's run as data: the script runs the program with exactly the arguments given
// and nothing else.
TEST(SlurmScript, ShellSyntaxInTheValuesIsData) {
  const auto dir = scratch("syntax");
  BatchJob job = job_in(dir);
  const auto planted = dir / "PLANTED";
  const std::string hostile = "it's \"q\" $(touch " + planted.string() + ") `touch " +
                              planted.string() + "`; touch " + planted.string() + " # *";
  job.name = hostile;
  job.rows[0].case_file = (dir / hostile).string();
  job.rows[0].sets = {"title=" + hostile, "solver.linear=lu"};
  ASSERT_EQ(run_task(dir, batch_script(job)), 0);
  EXPECT_FALSE(std::filesystem::exists(planted));
  EXPECT_EQ(read_text(dir / "argv"),
            "run\n" + job.rows[0].case_file + "\n--set\ntitle=" + hostile +
                "\n--set\nsolver.linear=lu\n--out\n" + job.out_dir + "/runs/01-a\n-q\n");
  std::filesystem::remove_all(dir);
}

// A value that would end its line of the script — a newline (or any control character) in the
// study's name, a path, an override, the partition or the time — is refused, naming it, instead
// of becoming a command that every task runs. On #SBATCH lines white space, quotes, '\' and '#'
// are refused too: sbatch reads them there as syntax.
TEST(SlurmScript, ValuesThatWouldEndTheirLineAreRefused) {
  const auto dir = scratch("newline");
  const auto planted = dir / "PLANTED";
  const std::string line = "x\ntouch " + planted.string() + " #";
  struct Case {
    const char* what;  ///< named in the message
    std::function<void(BatchJob&)> plant;
  };
  const std::vector<Case> cases = {
      {"the study's name", [&](BatchJob& j) { j.name = line; }},
      {"--partition", [&](BatchJob& j) { j.options.partition = line; }},
      {"--time", [&](BatchJob& j) { j.options.time = line; }},
      {"--time", [&](BatchJob& j) { j.options.time = "5 #"; }},
      {"--partition", [&](BatchJob& j) { j.options.partition = "de'bug"; }},
      {"--out", [&](BatchJob& j) { j.out_dir += "\ntouch " + planted.string(); }},
      {"--out", [&](BatchJob& j) { j.out_dir += "#x"; }},
      {"the hpcontact executable", [&](BatchJob& j) { j.program += "\r\n"; }},
      {"its problem file", [&](BatchJob& j) { j.rows[0].case_file += line; }},
      {"--set", [&](BatchJob& j) { j.rows[0].sets = {"title=" + line}; }},
      {"its folder", [&](BatchJob& j) { j.rows[0].run_dir += '\x1b'; }},
  };
  for (const auto& c : cases) {
    BatchJob job = job_in(dir);
    c.plant(job);
    try {
      const std::string script = batch_script(job);
      run_task(dir, script);
      ADD_FAILURE() << c.what << ": accepted; the script:\n" << script;
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(c.what), std::string::npos) << m;
      EXPECT_EQ(m.find('\n'), std::string::npos) << "the value is shown escaped: " << m;
    }
    EXPECT_FALSE(std::filesystem::exists(planted)) << c.what;
    std::filesystem::remove(planted);
  }
  std::filesystem::remove_all(dir);
}

// A command's output, exit code and time limit; a command that is not there is found missing.
TEST(Command, RunsAndCaptures) {
  const std::string sh = find_on_path("sh");
  ASSERT_FALSE(sh.empty());
  const auto r = run_captured({sh, "-c", "echo out; echo err >&2; exit 3"}, 10);
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_EQ(r.out, "out\n");
  EXPECT_EQ(r.err, "err\n");
  EXPECT_FALSE(r.timed_out);
  const auto slow = run_captured({sh, "-c", "sleep 10"}, 0.2);
  EXPECT_TRUE(slow.timed_out);
  EXPECT_EQ(find_on_path("no-such-command-hpcontact"), "");
  EXPECT_THROW(run_captured({"/no/such/program"}, 1), IoError);
}

// The record keeps the study's rows as they were, and says which task ran a row last.
TEST(SlurmRecord, RowsAndTasks) {
  io::StudySpec study;
  study.file = "s.yaml";
  study.name = "s";
  study.columns = {"contact.half_width"};
  study.runs = {{"a", "a.yaml", {"x=1"}, {{"dofs", 710}}}, {"b", "b.yaml", {}, {}}};
  const auto back = study_from_json(study_to_json(study));
  ASSERT_EQ(back.runs.size(), 2u);
  EXPECT_EQ(back.runs[0].sets, study.runs[0].sets);
  EXPECT_EQ(back.runs[0].seed, study.runs[0].seed);
  EXPECT_EQ(back.columns, study.columns);
  const nlohmann::json record = {
      {"study", study_to_json(study)},
      {"submissions", {{{"job_id", "7"}, {"rows", {0, 1}}, {"complete", nlohmann::json::array()}},
                       {{"job_id", "9"}, {"rows", {1}}, {"complete", {0}}},
                       {{"job_id", ""}, {"rows", {0}}, {"complete", nlohmann::json::array()}}}}};
  EXPECT_EQ(submitted(record).size(), 2u);  // the last never reached sbatch
  EXPECT_EQ(latest_task(record, 0)->job_id, "7");
  EXPECT_EQ(latest_task(record, 1)->job_id, "9");
  EXPECT_FALSE(latest_task(record, 2));
  EXPECT_TRUE(listed_complete(record, 0));
  EXPECT_FALSE(listed_complete(record, 1));
}

// An edited or forged submission record is refused by the key that is wrong — never an error of
// the JSON library, nor a row beyond the study or a job id that would name a log elsewhere.
TEST(SlurmRecord, ForgedRecordsAreRefusedByTheirKey) {
  const auto out = scratch("record");
  std::filesystem::create_directories(out / "slurm");
  io::StudySpec study;
  study.file = "s.yaml";
  study.name = "s";
  study.runs = {{"a", "a.yaml", {"x=1"}, {{"dofs", 710}}}, {"b", "b.yaml", {}, {}}};
  const nlohmann::json good = {
      {"study", study_to_json(study)},
      {"submissions", {{{"job_id", "7"}, {"rows", {0, 1}}, {"complete", nlohmann::json::array()}}}}};
  const auto record_file = (out / "slurm" / "submission.json").string();
  post::write_text_file(record_file, good.dump());
  EXPECT_EQ(read_record(out.string()), good);
  using Edit = std::function<void(nlohmann::json&)>;
  const std::vector<std::pair<std::string, Edit>> forged = {
      {"the file must be an object", [](nlohmann::json& j) { j = nlohmann::json::array(); }},
      {"submissions must be there", [](nlohmann::json& j) { j.erase("submissions"); }},
      {"study must be an object", [](nlohmann::json& j) { j["study"] = 1; }},
      {"study.columns must be a list of strings", [](nlohmann::json& j) { j["study"]["columns"] = {3}; }},
      {"study.runs[1].label must be a string", [](nlohmann::json& j) { j["study"]["runs"][1]["label"] = 5; }},
      {"study.runs[0].seed must be a list of [name, number]",
       [](nlohmann::json& j) { j["study"]["runs"][0]["seed"] = {{"dofs"}}; }},
      {"submissions[0].rows must be a list of row numbers from 0 to 1",
       [](nlohmann::json& j) { j["submissions"][0]["rows"] = {"x"}; }},
      {"submissions[0].rows must be a list of row numbers", [](nlohmann::json& j) { j["submissions"][0]["rows"] = {2}; }},
      {"submissions[0].complete must be a list of row numbers",
       [](nlohmann::json& j) { j["submissions"][0]["complete"] = {-1}; }},
      {"submissions[0].job_id must be Slurm's job id",
       [](nlohmann::json& j) { j["submissions"][0]["job_id"] = "../../../etc/x"; }},
      {"submissions[0].submitted must be a string",
       [](nlohmann::json& j) { j["submissions"][0]["submitted"] = 12; }},
  };
  for (const auto& [said, edit] : forged) {
    nlohmann::json j = good;
    edit(j);
    post::write_text_file(record_file, j.dump());
    try {
      read_record(out.string());
      ADD_FAILURE() << "accepted a record where " << said;
    } catch (const IoError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(record_file + ": not a submission record"), std::string::npos) << m;
      EXPECT_NE(m.find(said), std::string::npos) << m;
    }
  }
  post::write_text_file(record_file, "{\"study\": ");
  EXPECT_THROW(read_record(out.string()), IoError);
  std::filesystem::remove_all(out);
}

// A row counts as done only while its run's summary.json is there: a row a submission found
// complete, and one whose task ended with exit 0, whose summary.json has since gone, are failed
// rows that say so (a resubmission runs them again: its rows are those without a summary).
TEST(SlurmCollect, ARowWhoseSummaryHasGoneIsNotASuccess) {
  const auto out = scratch("collect");
  for (const char* sub : {"slurm/logs", "runs/01-a", "runs/02-b"})
    std::filesystem::create_directories(out / sub);
  io::StudySpec study;
  study.file = "s.yaml";
  study.name = "s";
  study.runs = {{"a", "a.yaml", {}, {}}, {"b", "b.yaml", {}, {}}};
  const nlohmann::json record = {
      {"study", study_to_json(study)},
      {"submissions", {{{"job_id", "5"}, {"rows", {1}}, {"complete", {0}}}}}};
  post::write_text_file((out / "slurm" / "submission.json").string(), record.dump());
  post::write_text_file((out / ".hpcontact-manifest").string(), "slurm/submission.json\n");
  post::write_text_file((out / "slurm" / "logs" / "5_1.out").string(),
                        "hpcontact-task: exit 0 after 1.5 s\n");
  auto collect = [&] {
    OutputFolder folder(out.string(), study_layout());
    SlurmStudyOptions options;
    options.folder = &folder;
    return collect_slurm_study(options).rows;
  };
  auto rows = collect();
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_FALSE(rows[0].converged());
  EXPECT_NE(rows[0].message.find("found complete when submitted, but its run's summary.json has "
                                 "gone since"), std::string::npos) << rows[0].message;
  EXPECT_FALSE(rows[1].converged());
  EXPECT_NE(rows[1].message.find("array task 5_1 ended with exit 0, but its run's summary.json "
                                 "has gone since"), std::string::npos) << rows[1].message;
  for (const char* run : {"runs/01-a", "runs/02-b"})
    post::write_text_file((out / run / "summary.json").string(), "{\"converged\": true}\n");
  rows = collect();
  EXPECT_TRUE(rows[0].converged()) << rows[0].message;
  EXPECT_TRUE(rows[1].converged()) << rows[1].message;
  std::filesystem::remove_all(out);
}
