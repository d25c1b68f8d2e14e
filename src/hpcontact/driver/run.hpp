// One run of a problem: discretise, solve, post-process, write the results.
#pragma once

#include <functional>
#include <string>

#include <Eigen/Dense>

#include "hpcontact/model/discretization.hpp"
#include "hpcontact/model/problem_spec.hpp"
#include "hpcontact/post/summary.hpp"

namespace hpcontact::driver {

struct RunOptions {
  std::string out_dir;           ///< where results go; empty: write nothing
  std::string effective_input;   ///< YAML text written as input.yaml (if not empty)
  std::function<void(const std::string&)> progress;  ///< one line per stage; may be empty
};

struct RunResult {
  post::Summary summary;
  model::Discretization discretization;
  Eigen::VectorXd u;  ///< all dofs
};

/// Runs the problem. Input and mesh errors propagate as exceptions before anything is written;
/// summary.json is written last, so its presence means the run finished.
RunResult run_problem(const model::ProblemSpec& spec, const RunOptions& options);

}  // namespace hpcontact::driver
