// Study runs as child processes (a crash or a hang of one run cannot take the others with it),
// `jobs` at a time, and the table of their summaries.
#include "hpcontact/driver/study.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>

#include "hpcontact/core/error.hpp"
#include "hpcontact/post/summary.hpp"

extern char** environ;

namespace hpcontact::driver {

namespace fs = std::filesystem;

namespace {

/// A folder name from a label: letters, digits, '-', '.', '=' kept, the rest '_'.
std::string folder_name(int index, const std::string& label) {
  std::ostringstream os;
  os << std::setw(2) << std::setfill('0') << index + 1 << '-';
  for (char c : label) os << (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.' || c == '=' ? c : '_');
  return os.str();
}

/// The run's error line (the last "hpcontact: error: ..." line, without that prefix), else the
/// last non-empty line of its log ("" if none).
std::string error_line(const fs::path& file) {
  const std::string prefix = "hpcontact: error: ";
  std::ifstream in(file);
  std::string line, last, error;
  while (std::getline(in, line)) {
    if (!line.empty()) last = line;
    if (line.rfind(prefix, 0) == 0) error = line.substr(prefix.size());
  }
  return error.empty() ? last : error;
}

/// Starts `argv` with stdout and stderr into `log`; waits for it. Returns the exit code, or
/// minus the signal that ended it.
int run_process(const std::vector<std::string>& argv, const fs::path& log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, STDIN_FILENO);
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw IoError(argv[0] + ": cannot start a run: " + std::strerror(rc));
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw IoError(argv[0] + ": lost a run: " + std::strerror(errno));
  if (WIFSIGNALED(status)) return -WTERMSIG(status);
  return WEXITSTATUS(status);
}

/// The value at a dotted path of a JSON object ("contact.half_width"), or null.
const nlohmann::json* at_path(const nlohmann::json& j, const std::string& path) {
  const nlohmann::json* node = &j;
  std::size_t start = 0;
  while (start <= path.size()) {
    const std::size_t dot = path.find('.', start);
    const std::string key = path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (!node->is_object() || !node->contains(key)) return nullptr;
    node = &(*node)[key];
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return node;
}

std::string csv_field(std::string s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return q + "\"";
}

std::string json_cell(const nlohmann::json* v) {
  if (!v || v->is_null()) return "";
  if (v->is_number_float()) {
    std::ostringstream os;
    os << std::setprecision(12) << v->get<double>();
    return os.str();
  }
  if (v->is_string()) return v->get<std::string>();
  return v->dump();
}

// Summary keys shown when any row has them, in this order.
const char* const kMeasures[] = {
    "contact.resultant",           "contact.half_width",
    "contact.p_max",               "contact.max_penetration",
    "contact.e_seed_hertz_percent", "contact.e_seed_shtayerman_percent",
    "contact.e_L2_hertz_percent",  "contact.e_L2_shtayerman_percent",
    "contact.e_L2_reference_percent", "error.energy_rel_percent",
    "error.energy_norm_rel_percent"};

void write_tables(const io::StudySpec& study, const std::vector<StudyRowResult>& rows,
                  const std::string& out_dir) {
  const auto columns = study_columns(study, rows);
  std::ostringstream csv;
  for (std::size_t c = 0; c < columns.size(); ++c) csv << (c ? "," : "") << columns[c];
  csv << '\n';
  nlohmann::json all = nlohmann::json::array();
  for (const auto& row : rows) {
    nlohmann::json j = {{"label", row.run.label}, {"case", row.run.case_file},
                        {"set", row.run.sets}, {"run_dir", row.run_dir},
                        {"exit_code", row.exit_code}, {"converged", row.converged()},
                        {"seconds", row.seconds}};
    if (!row.converged()) j["message"] = row.message;
    if (row.summary.is_object()) j["summary"] = row.summary;
    for (const auto& [k, v] : row.run.seed) j["seed"][k] = v;
    all.push_back(j);
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const std::string& col = columns[c];
      std::string cell;
      if (col == "label") cell = row.run.label;
      else if (col == "case") cell = row.run.case_file;
      else if (col == "converged") cell = row.converged() ? "true" : "false";
      else if (col == "message") cell = row.converged() ? "" : row.message;
      else if (col == "run_dir") cell = row.run_dir;
      else if (col.rfind("seed_", 0) == 0) {
        for (const auto& [k, v] : row.run.seed)
          if ("seed_" + k == col) {
            std::ostringstream os;
            os << std::setprecision(12) << v;
            cell = os.str();
          }
      } else if (row.summary.is_object()) {
        cell = json_cell(at_path(row.summary, col));
      }
      csv << (c ? "," : "") << csv_field(cell);
    }
    csv << '\n';
  }
  post::write_text_file((fs::path(out_dir) / "study.csv").string(), csv.str());
  nlohmann::json doc = {{"study", study.name}, {"file", study.file}, {"runs", all}};
  if (!study.title.empty()) doc["title"] = study.title;
  post::write_text_file((fs::path(out_dir) / "study.json").string(), doc.dump(2) + "\n");
}

}  // namespace

std::vector<std::string> study_columns(const io::StudySpec& study,
                                       const std::vector<StudyRowResult>& rows) {
  std::vector<std::string> cols = {"label", "case", "converged", "dofs", "wall_time_s",
                                   "strain_energy", "load_steps", "newton_iterations"};
  auto any_has = [&](const std::string& key) {
    return std::any_of(rows.begin(), rows.end(), [&](const StudyRowResult& r) {
      return r.summary.is_object() && at_path(r.summary, key) != nullptr;
    });
  };
  for (const char* m : kMeasures)
    if (any_has(m)) cols.push_back(m);
  for (const auto& c : study.columns)
    if (std::find(cols.begin(), cols.end(), c) == cols.end()) cols.push_back(c);
  std::set<std::string> seen;
  for (const auto& r : study.runs)
    for (const auto& [k, v] : r.seed)
      if (seen.insert(k).second) cols.push_back("seed_" + k);
  cols.push_back("message");
  cols.push_back("run_dir");
  return cols;
}

std::vector<StudyRowResult> run_study(const io::StudySpec& study, const StudyOptions& options) {
  std::error_code ec;
  fs::create_directories(fs::path(options.out_dir) / "runs", ec);
  HPC_REQUIRE(!ec, IoError, options.out_dir, ": cannot create the study folder: ", ec.message());
  for (const char* name : {"study.csv", "study.json"}) fs::remove(fs::path(options.out_dir) / name, ec);

  const int total = static_cast<int>(study.runs.size());
  std::vector<StudyRowResult> rows(total);
  for (int i = 0; i < total; ++i) {
    rows[i].run = study.runs[i];
    rows[i].run_dir = (fs::path(options.out_dir) / "runs" / folder_name(i, study.runs[i].label)).string();
  }
  std::atomic<int> next{0};
  std::mutex report;
  int done = 0;
  std::string failure;  // an IoError of a worker, rethrown after all have stopped
  auto worker = [&] {
    for (int i = next++; i < total; i = next++) {
      StudyRowResult& row = rows[i];
      try {
        fs::create_directories(row.run_dir);
        std::vector<std::string> argv = {options.program, "run", row.run.case_file, "--out",
                                         row.run_dir, "-q"};
        for (const auto& s : row.run.sets) {
          argv.push_back("--set");
          argv.push_back(s);
        }
        const fs::path log = fs::path(row.run_dir) / "log.txt";
        const auto t0 = std::chrono::steady_clock::now();
        row.exit_code = run_process(argv, log);
        row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const fs::path summary = fs::path(row.run_dir) / "summary.json";
        if (row.exit_code == 0 && fs::exists(summary)) {
          std::ifstream in(summary);
          row.summary = nlohmann::json::parse(in, nullptr, false);
          if (row.summary.is_discarded()) row.summary = nullptr;
        }
        if (!row.converged()) {
          row.message = error_line(log);
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
      if (options.finished) options.finished(row, done, total);
    }
  };
  const int jobs = std::clamp(options.jobs, 1, std::max(1, total));
  std::vector<std::thread> threads;
  for (int j = 0; j < jobs; ++j) threads.emplace_back(worker);
  for (auto& t : threads) t.join();
  write_tables(study, rows, options.out_dir);
  HPC_REQUIRE(failure.empty(), IoError, study.file, ": ", failure);
  return rows;
}

}  // namespace hpcontact::driver
