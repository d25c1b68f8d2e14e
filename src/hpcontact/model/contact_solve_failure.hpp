// Why a contact solve fails, said for the user: a Newton solve's failure with its cause, a load
// step that cannot be cut further, force control with no force to scale.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "hpcontact/model/contact_pairs.hpp"
#include "hpcontact/model/discretization.hpp"
#include "hpcontact/model/problem_spec.hpp"
#include "hpcontact/solve/newton.hpp"

namespace hpcontact::model {

class ContactSystem;

/// Why a Newton solve of `system` failed: the report's message, with the inverted element (not
/// finite) or the body and unknown whose pivot vanished (singular; bodies in a pair with friction
/// named as such).
std::string newton_failure_reason(const solve::SolveReport& report, const Discretization& d,
                                  const std::vector<ContactPair>& pairs,
                                  const ContactSystem& system);

/// Whether two failed attempts' residual histories are the same (to round-off), and not empty.
bool same_residuals(const std::vector<double>& a, const std::vector<double>& b);

/// A load step that failed for good (no cut left, or none that could help).
struct StepFailure {
  int step = 0;            ///< its number, from 1
  std::string factors;     ///< its load factors, described
  int cuts = 0;            ///< the halvings the step had
  int max_cuts = 0;        ///< solver.max_cuts
  std::string reason;      ///< why its last Newton solve failed (newton_failure_reason)
  bool repeated = false;   ///< its last halving repeated the residuals of the longer step
  /// The step was the shortest allowed, after converged steps of this path: the load cannot be
  /// carried beyond `last_converged`.
  bool at_capacity = false;
  std::string last_converged;  ///< the factors of the last converged step, described
  std::string capacity_used;   ///< ContactSystem::capacity_used(), with at_capacity
  std::vector<double> residuals;  ///< its last Newton solve's residual history
  /// Its last Newton solve ran out of iterations (solver.max_iterations) while still converging
  /// (still_converging): more iterations, not a shorter step, is what it lacks.
  bool slow = false;
  int max_iterations = 0;  ///< solver.max_iterations, with slow
};

/// Whether the residual history of a Newton solve that ran out of iterations shows it still
/// converging: over the second half of its iterations the residual fell by a factor 10 or more
/// from its largest there and ends at its smallest (not a load beyond what can be carried, an
/// active set that cycles, a stagnating or diverging solve).
bool still_converging(const std::vector<double>& residuals);

/// The message of a failed load step: what failed, why, what more cuts could do, the residuals.
std::string failed_step_message(const StepFailure& failure);

/// Why force control has nothing to scale: the first pair's resultant R at the state u of the
/// displacement factor `factor` has no component `component`. Says which of the usual causes it
/// is: nothing prescribed to scale, the force in the other component, or no contact (and how far
/// the body is from it).
std::string no_force_to_scale(const SolverSpec& ss, const Discretization& d,
                              const ContactPair& pair, const Eigen::VectorXd& u,
                              const Eigen::VectorXd* multipliers, double factor, const Vec2& R);

}  // namespace hpcontact::model
