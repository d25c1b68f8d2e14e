// The cylindrical arc-length method (Crisfield) for R(x, λ) = 0 along a load path: each step
// advances a fixed length ‖Δx‖ = Δl, the load factor λ an unknown, so limit points (where the
// load falls while the displacement grows) can be passed. Knows residuals and tangents, no FE.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "hpcontact/solve/newton.hpp"

namespace hpcontact::solve {

/// A system R(x, λ) whose load factor λ the solver sets.
class LoadPathSystem : public NonlinearSystem {
public:
  virtual void set_load_factor(double lambda) = 0;
  /// ∂R/∂λ at x and the current λ (minus the load vector, for loads proportional to λ).
  virtual Eigen::VectorXd load_derivative(const Eigen::VectorXd& x) = 0;
  /// The arc length measures the first path_size() unknowns (the displacements: unknowns
  /// after them, e.g. contact multipliers, have other units and follow the path).
  virtual int path_size() const { return size(); }
};

struct ArcLengthOptions {
  double target = 1;          ///< stop when λ reaches this
  double initial_length = 0;  ///< Δl of the first step; 0: that of a load-controlled step to target / steps
  int steps = 10;             ///< for the default initial length
  double min_length = 0;      ///< 0: initial / 1024
  double max_length = 0;      ///< 0: 8 × initial
  int desired_iterations = 5; ///< Δl scales by √(desired / used) after each step
  int max_iterations = 25;    ///< per step
  int max_steps = 500;
  double tolerance = 1e-10;   ///< ‖R‖ relative to max(‖R₀‖, reference_norm)
  double reference_norm = 0;
  LinearSolverKind linear_solver = LinearSolverKind::lu;
};

struct ArcLengthStep {
  double lambda = 0;  ///< load factor reached
  double length = 0;  ///< Δl used
  int iterations = 0;
};

struct ArcLengthReport {
  bool reached = false;  ///< λ = target reached
  std::string message;   ///< why not
  std::vector<ArcLengthStep> steps;
  int iterations = 0;    ///< all corrector iterations
};

/// Called after each converged step with its state x and the step (λ reached, length,
/// iterations); returning false stops the path.
using ArcLengthCallback = std::function<bool(const Eigen::VectorXd&, const ArcLengthStep&)>;

/// From the converged state (x, λ) to λ = target. A step that does not converge is retried with
/// half the length, down to min_length: below it the run stops with a message (the last
/// converged x, λ are kept). The step that would pass the target is finished under load
/// control at λ = target.
ArcLengthReport arc_length(LoadPathSystem& system, Eigen::VectorXd& x, double& lambda,
                           const ArcLengthOptions& options, const ArcLengthCallback& on_step = {});

}  // namespace hpcontact::solve
