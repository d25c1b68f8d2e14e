// Parsing scontrol's and sacct's one-line records; asking them, each with a time limit.
#include "hpcontact/driver/slurm_queue.hpp"

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <set>
#include <sstream>

#include "hpcontact/driver/command.hpp"

namespace hpcontact::driver {

namespace {

/// The value of `key=` in a line of space-separated key=value fields, or "".
std::string field(const std::string& line, const std::string& key) {
  const std::string token = key + "=";
  for (std::size_t at = line.find(token); at != std::string::npos; at = line.find(token, at + 1)) {
    if (at != 0 && line[at - 1] != ' ') continue;
    const std::size_t start = at + token.size();
    return line.substr(start, line.find(' ', start) - start);
  }
  return "";
}

bool all_digits(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

constexpr double kQuerySeconds = 30;

}  // namespace

bool slurm_state_final(const std::string& state) {
  static const std::set<std::string> active = {"PENDING",   "RUNNING",   "CONFIGURING",
                                               "COMPLETING", "SUSPENDED", "REQUEUED",
                                               "REQUEUE_HOLD", "REQUEUE_FED", "RESIZING",
                                               "SIGNALING", "STAGE_OUT", "RESV_DEL_HOLD"};
  return !state.empty() && !active.count(state);
}

std::string array_ranges(const std::vector<int>& indices) {
  std::ostringstream os;
  for (std::size_t i = 0; i < indices.size();) {
    std::size_t j = i;
    while (j + 1 < indices.size() && indices[j + 1] == indices[j] + 1) ++j;
    os << (i ? "," : "") << indices[i];
    if (j > i) os << "-" << indices[j];
    i = j + 1;
  }
  return os.str();
}

std::vector<int> parse_array_ranges(const std::string& spec) {
  std::vector<int> out;
  std::stringstream parts(spec.substr(0, spec.find('%')));
  for (std::string part; std::getline(parts, part, ',');) {
    const auto dash = part.find('-');
    const std::string a = part.substr(0, dash), b = dash == std::string::npos ? a : part.substr(dash + 1);
    if (!all_digits(a) || !all_digits(b) || a.size() > 9 || b.size() > 9) return {};
    for (int k = std::stoi(a); k <= std::stoi(b); ++k) out.push_back(k);
  }
  return out;
}

std::map<int, SlurmTaskState> parse_scontrol_tasks(const std::string& text) {
  std::map<int, SlurmTaskState> tasks;
  std::stringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    const std::string ids = field(line, "ArrayTaskId");
    const SlurmTaskState state{field(line, "JobState"), field(line, "ExitCode")};
    if (ids.empty() || state.state.empty()) continue;
    for (const int k : parse_array_ranges(ids)) tasks[k] = state;
  }
  return tasks;
}

std::map<int, SlurmTaskState> parse_sacct_tasks(const std::string& text, const std::string& job_id) {
  std::map<int, SlurmTaskState> tasks;
  std::stringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::stringstream fields(line);
    std::string id, state, exit_code;
    if (!std::getline(fields, id, '|') || !std::getline(fields, state, '|')) continue;
    std::getline(fields, exit_code, '|');
    if (id.rfind(job_id + "_", 0) != 0) continue;
    std::string ids = id.substr(job_id.size() + 1);
    if (ids.size() > 2 && ids.front() == '[' && ids.back() == ']') ids = ids.substr(1, ids.size() - 2);
    // "CANCELLED by 0" -> "CANCELLED"
    state = state.substr(0, state.find(' '));
    for (const int k : parse_array_ranges(ids)) tasks[k] = {state, exit_code};
  }
  return tasks;
}

SlurmArrayQuery query_slurm_array(const std::string& job_id) {
  SlurmArrayQuery query;
  try {
    const std::string scontrol = find_on_path("scontrol");
    if (scontrol.empty()) {
      query.error = "scontrol is not on PATH";
      return query;
    }
    const auto shown = run_captured({scontrol, "-o", "show", "job", job_id}, kQuerySeconds);
    if (shown.exit_code == 0 && !shown.timed_out) {
      query.known = true;
      query.tasks = parse_scontrol_tasks(shown.out);
      return query;
    }
    // The controller forgets a finished job after MinJobAge; accounting, if kept, does not.
    if (shown.timed_out || shown.err.find("Invalid job id") == std::string::npos) {
      query.error = "scontrol show job " + job_id + ": " +
                    (shown.timed_out ? "no answer within 30 s" : shown.err.substr(0, shown.err.find('\n')));
      return query;
    }
    const std::string sacct = find_on_path("sacct");
    if (sacct.empty()) return query;
    const auto accounted =
        run_captured({sacct, "-n", "-P", "-X", "-j", job_id, "-o", "JobID,State,ExitCode"}, kQuerySeconds);
    if (accounted.exit_code == 0 && !accounted.timed_out) {
      query.tasks = parse_sacct_tasks(accounted.out, job_id);
      query.known = !query.tasks.empty();
    }
  } catch (const std::exception& e) {
    query.error = e.what();
  }
  return query;
}

}  // namespace hpcontact::driver
