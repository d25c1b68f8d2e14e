// Starting a short external command (sbatch, scontrol, sinfo) and capturing what it prints.
#pragma once

#include <string>
#include <vector>

namespace hpcontact::driver {

struct CommandOutput {
  int exit_code = -1;  ///< < 0: ended by a signal (its number, negated)
  bool timed_out = false;  ///< killed after the time limit
  std::string out, err;    ///< its standard output and standard error
};

/// The absolute path of `name` in the folders of $PATH (the first executable file), or "" if
/// there is none. A name with a '/' is returned as it is if it is executable.
std::string find_on_path(const std::string& name);

/// Runs argv[0] (an absolute path; see find_on_path) with no standard input, waits at most
/// `timeout_seconds` (then kills it) and returns its exit status and output. IoError if it
/// cannot be started.
CommandOutput run_captured(const std::vector<std::string>& argv, double timeout_seconds);

}  // namespace hpcontact::driver
