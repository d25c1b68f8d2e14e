// One run of a problem: discretise, solve, post-process, write the results.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include <Eigen/Dense>

#include "hpcontact/driver/contact_compare.hpp"
#include "hpcontact/driver/contact_history.hpp"
#include "hpcontact/driver/contact_table.hpp"
#include "hpcontact/driver/output_folder.hpp"
#include "hpcontact/model/contact_solve.hpp"
#include "hpcontact/model/discretization.hpp"
#include "hpcontact/model/problem_spec.hpp"
#include "hpcontact/model/reactions.hpp"
#include "hpcontact/post/summary.hpp"

namespace hpcontact::driver {

struct RunOptions {
  std::string out_dir;           ///< the output folder (see OutputFolder); empty: write nothing
  /// The output folder opened by the caller (the command line opens it before it reads the
  /// problem file, to refuse a folder that holds it); when set, out_dir is not used.
  OutputFolder* folder = nullptr;
  std::string effective_input;   ///< YAML text written as input.yaml (if not empty)
  /// Progress events (core/progress.hpp): load steps, Newton iterations, adaptive steps, files
  /// written, messages; may be empty.
  model::ProgressFn progress;
  /// Each warning as it arises (it names the file, the place and the cause; summary.json's
  /// `warnings` lists them too); may be empty.
  std::function<void(const std::string&)> warning;
};

struct RunResult {
  post::Summary summary;
  model::Discretization discretization;
  Eigen::VectorXd u;  ///< all dofs
  ContactTable contact;  ///< the rows of contact.csv; empty without contact
  /// The curves of pressure.csv, when the first contact pair has a `compare` section.
  std::optional<PressureCurve> pressure_curve;
  /// The reactions at the supports and pairs and the bodies' balance at every converged load
  /// step (a linear solve: its one), the last the result's (summary.json `reactions`).
  std::vector<model::Reactions> reaction_history;
  /// The load path (path.csv's rows: a point per converged step; rp and hp: the final mesh's).
  std::vector<model::NonlinearSolution::PathPoint> path;
  /// contact_history.csv's rows: per converged step, per pair (none for rp and hp).
  std::vector<ContactHistoryRow> contact_history;
};

/// The files a run writes into its output folder: summary.json (the marker), report.html, input.yaml,
/// contact.csv, pressure.csv, path.csv, mesh.yaml, solution.vtu/.pvd, contact.vtu/.pvd, rp/ and hp/
/// (pressure-N.csv), steps/ (step-NNNN.vtu, contact-NNNN.vtu), and all of these in last-good/.
FolderLayout run_layout();

/// Runs the problem. With an output folder, the results are written into its staging folder and
/// moved in only when the run has succeeded; a run that fails after a converged state moves
/// that state into last-good/ (with converged: false) and leaves the earlier results; any other
/// failure leaves the folder as it was. The folder is refused, before anything is solved, if it
/// holds the problem file or the reference of a compare section. Errors propagate as exceptions.
RunResult run_problem(const model::ProblemSpec& spec, const RunOptions& options);

}  // namespace hpcontact::driver
