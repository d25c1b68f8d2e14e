// What Slurm says about the tasks of a job array: `scontrol show job` while the controller
// remembers the job, `sacct` after that where accounting is kept.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace hpcontact::driver {

/// One array task as the scheduler reports it.
struct SlurmTaskState {
  std::string state;  ///< PENDING, RUNNING, COMPLETED, FAILED, CANCELLED, TIMEOUT, ...
  std::string exit_code;  ///< Slurm's "code:signal" ("0:15" for a task ended by SIGTERM)
};

/// Whether a job state is final (the task runs no more): every state but PENDING, RUNNING,
/// CONFIGURING, COMPLETING, SUSPENDED, REQUEUED, RESIZING, SIGNALING, STAGE_OUT.
bool slurm_state_final(const std::string& state);

/// Row indices as a Slurm array specification: {0, 1, 2, 5} -> "0-2,5". Sorted, unique input.
std::string array_ranges(const std::vector<int>& indices);

/// The indices of an array specification ("0-2,5", "3-7%2": the throttle is ignored); empty if
/// it is not one.
std::vector<int> parse_array_ranges(const std::string& spec);

/// The tasks in the output of `scontrol -o show job ARRAY_ID` (a line per task, pending tasks
/// grouped as "ArrayTaskId=3-5"): task index -> state.
std::map<int, SlurmTaskState> parse_scontrol_tasks(const std::string& text);

/// The tasks of array `job_id` in the output of `sacct -n -P -X -o JobID,State,ExitCode`
/// ("12_3|COMPLETED|0:0", "12_[4-5]|PENDING|0:0").
std::map<int, SlurmTaskState> parse_sacct_tasks(const std::string& text, const std::string& job_id);

/// The scheduler's view of one job array.
struct SlurmArrayQuery {
  bool known = false;  ///< the controller or the accounting knows the job
  std::map<int, SlurmTaskState> tasks;
  std::string error;   ///< why the scheduler could not be asked ("" if it answered)
};

/// Asks `scontrol` (then `sacct`, if the controller forgot the job) about array `job_id`.
/// Never throws: a command that cannot be run or times out is `error`.
SlurmArrayQuery query_slurm_array(const std::string& job_id);

}  // namespace hpcontact::driver
