// The contact problem solved along its load path: load steps with cut-back, Newton's method,
// force control (a target resultant), the arc-length method; and the tangents for checking.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "hpcontact/core/progress.hpp"
#include "hpcontact/model/contact_pairs.hpp"
#include "hpcontact/model/contact_results.hpp"
#include "hpcontact/model/discretization.hpp"
#include "hpcontact/solve/newton.hpp"

namespace hpcontact::model {

struct ElasticOperator;

struct NonlinearSolution {
  /// All dofs; when not converged, those of the last converged load step (at load_factor, 0
  /// if none converged) — a state to inspect, not a solution of the problem as posed.
  Eigen::VectorXd u;
  bool converged = false;
  std::string message;  ///< why it stopped, when not converged
  int newton_iterations = 0, load_steps = 0;
  /// Numeric factorisations of Newton's tangents (fewer than its iterations where the tangent's
  /// displacement block does not change: bodies held by their constraints at small strain).
  int factorizations = 0;
  double load_factor = 1;   ///< factor on the prescribed displacements reached (y's, see below)
  /// The factors on the prescribed displacements' x and y components reached (equal unless
  /// the stages give them per direction).
  Vec2 displacement_factors = Vec2(1, 1);
  double loads_factor = 1;  ///< factor on the loads reached (= load_factor without stages)
  std::vector<ContactPair> pairs;     ///< the contact pairs solved, for post-processing
  /// The bodies' elastic operator the solve assembled (for another system on the same
  /// discretisation: multiplier_adjoint).
  std::shared_ptr<const ElasticOperator> elastic;
  /// The load path, a point per converged step: load factors, the monitored node's
  /// displacement (if solver.monitor), the first pair's contact resultant, iterations.
  struct PathPoint {
    double displacements = 0, loads = 0;  ///< the displacement factor: y's, as load_factor
    Vec2 displacement_factors = Vec2::Zero();  ///< x's and y's
    Vec2 monitor = Vec2::Zero();
    Vec2 resultant = Vec2::Zero();
    int iterations = 0;
    double arc_length = 0;  ///< Δl of an arc-length step, 0 under load control
  };
  std::vector<PathPoint> path;
  std::vector<ContactResult> contact;  ///< per pair
  /// Per converged load step: for each exactly enforced Coulomb pair its stick–slip points then
  /// and where it stuck and slipped (empty for other pairs) — model/memory_points.hpp.
  struct StepStickSlip {
    std::vector<ZoneEnds> own, other;  ///< per pair: ContactResult::stick_slip, other_stick_slip
    /// Per pair: the coordinates (ContactPair::coordinate) of its sticking and slipping points.
    std::vector<std::vector<double>> stuck, slipped;
  };
  std::vector<StepStickSlip> stick_slip_history;
  /// With friction, per converged load step: where on the path it ended and its state — what a
  /// solve of the same problem on another discretisation starts that step from (StartState::path).
  struct StepState {
    int segment = 0;     ///< which part of the path (a stage, force control's steps): 0, 1, ...
    double s = 0;        ///< the path parameter the step ended at within its segment
    double factor = 0;   ///< the factor on the prescribed displacements reached (y's)
    Eigen::VectorXd u;   ///< all dofs
    std::vector<Eigen::VectorXd> multipliers;  ///< per pair, as `multipliers` below
  };
  std::vector<StepState> step_states;
  /// Per follower load (Discretization::follower_loads): the part of its edges it acts on at
  /// the state u (with penetration: up to its pair's contact there).
  std::vector<WetRange> wet_ranges;
  /// Per pair: the pressures at its multiplier nodes (exact enforcement), empty for the penalty.
  std::vector<Eigen::VectorXd> multipliers;
  /// The pair's multipliers, or null (for evaluate_contact and BoundaryPressureProbe).
  const Eigen::VectorXd* multipliers_of(size_t pair) const {
    return pair < multipliers.size() && multipliers[pair].size() ? &multipliers[pair] : nullptr;
  }
};

/// Progress events (core/progress.hpp): a line per load step and Newton iteration, with figures.
using ProgressFn = hpcontact::ProgressFn;
/// Called after every converged load step with all dofs u, the path point just recorded, the
/// contact pairs and their multipliers (for evaluate_contact).
using StepFn = std::function<void(const Eigen::VectorXd& u, const NonlinearSolution::PathPoint&,
                                  const std::vector<ContactPair>& pairs,
                                  const std::vector<Eigen::VectorXd>& multipliers)>;


/// Where a solve starts: from nothing (the default), or from a state close to the answer (the
/// previous mesh's solution in an adaptive loop, carried onto this discretisation).
struct StartState {
  /// > 0: force control starts at this factor instead of 1.
  double factor = 0;
  /// All dofs of this discretisation, and per pair its multipliers (as NonlinearSolution
  /// holds them); empty: zero.
  Eigen::VectorXd u;
  std::vector<Eigen::VectorXd> multipliers;
  /// With friction, where the path is part of the problem and no state skips it: the states
  /// of another discretisation's load steps carried onto this one, each the first guess of
  /// Newton at the step that ends where it ended (same segment and path parameter); a step
  /// with none (a cut, a continuation's part) starts from the last converged state as usual.
  std::vector<NonlinearSolution::StepState> path;
};

/// Solves the (nonlinear) contact problem with load steps and Newton's method; with
/// solver.target_resultant, finds the load factor: as one more unknown of Newton's system when
/// the first pair is enforced exactly, else by the secant method over load-controlled solves.
NonlinearSolution solve_contact(const ProblemSpec& spec, const Discretization& d,
                                const ProgressFn& progress = {}, const StartState& start = {},
                                const StepFn& on_step = {});

/// The pairs of a solution with, for friction, the histories its last load step started from:
/// what its Newton iterations converged with (the committed slips would put slipping points on
/// the cone). Its forces at the solution are those the solve balanced.
std::vector<ContactPair> pairs_of_last_step(const NonlinearSolution& sol);

/// The Newton tangent of the contact problem at a solution, on the unknowns of its solve:
/// analytic, or the seed's central finite differences (eq. 3.36). The residual there into
/// `residual` if not null. For tests and benchmarks of the two tangents.
solve::SparseMatrix contact_tangent(const ProblemSpec& spec, const Discretization& d,
                                    const NonlinearSolution& sol, bool finite_difference,
                                    Eigen::VectorXd* residual = nullptr);

/// The adjoint of a converged solve for a linear functional of its contact multipliers,
/// J = Σ_k gradient[k] · λ_k (per pair its multipliers, normal then tangential; an empty entry:
/// none of that pair): z with Aᵀ z = ∂J/∂x, A the Newton tangent at the solution on its
/// unknowns, force control bordered as the solve had it (the total force held). Returns z's
/// displacement part over all dofs (homogeneous: zero where displacements are prescribed).
/// It weighs where an error of the displacements changes J (goal-oriented error indicators).
Eigen::VectorXd multiplier_adjoint(const ProblemSpec& spec, const Discretization& d,
                                   const NonlinearSolution& sol,
                                   const std::vector<Eigen::VectorXd>& gradient);

/// The Jacobian of the residual at a solution by plain central differences, every normal and
/// every finite-strain term re-evaluated (not the seed's frozen-normal variant, not
/// symmetrised): what the analytic tangent must equal, to O(h²). For tests.
solve::SparseMatrix residual_jacobian_by_differences(const ProblemSpec& spec, const Discretization& d,
                                                     const NonlinearSolution& sol);

}  // namespace hpcontact::model
