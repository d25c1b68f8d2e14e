// One run of a problem: discretise, solve, post-process, write the results.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include <Eigen/Dense>

#include "hpcontact/driver/contact_compare.hpp"
#include "hpcontact/driver/contact_table.hpp"
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
  ContactTable contact;  ///< the rows of contact.csv; empty without contact
  /// The curves of pressure.csv, when the first contact pair has a `compare` section.
  std::optional<PressureCurve> pressure_curve;
};

/// Creates the output folder and removes the files an earlier run left there (summary.json,
/// contact.csv, ..., last-good/, rp/, hp/, steps/), so that the folder of a run that then fails holds
/// nothing that could pass for its result. Files the program does not write are kept. IoError.
void prepare_output_folder(const std::string& out_dir);

/// Runs the problem (calling prepare_output_folder first when out_dir is set). Input and mesh errors propagate as exceptions before anything is written;
/// summary.json is written last, so its presence means the run finished.
RunResult run_problem(const model::ProblemSpec& spec, const RunOptions& options);

}  // namespace hpcontact::driver
