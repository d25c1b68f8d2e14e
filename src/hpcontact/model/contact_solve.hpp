// The contact problem: linear elastic bodies, penalty contact, load steps, Newton, force control.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "hpcontact/contact/obstacle.hpp"
#include "hpcontact/contact/deformable_boundary.hpp"
#include "hpcontact/contact/penalty.hpp"
#include "hpcontact/model/discretization.hpp"
#include "hpcontact/solve/newton.hpp"

namespace hpcontact::model {

/// A resolved contact pair: the body, its contact points, the obstacle and the penalty. Against
/// another deformable body (`other` >= 0) the obstacle is that body's deformed boundary, and
/// the other body's points are evaluated against this body's boundary too (seed §3.6).
struct ContactPair {
  int body = -1;
  std::vector<contact::ContactPoint> points;
  std::vector<int> edges;  ///< mesh edges of the contact boundary, in order
  contact::ObstaclePtr obstacle;
  /// The same obstacle when it moves (a rigid obstacle with a displacement), else null.
  std::shared_ptr<contact::DisplacedObstacle> moving;
  int other = -1;  ///< the other body of a bilateral pair, -1 against a rigid obstacle
  std::vector<contact::ContactPoint> other_points;
  std::vector<int> other_edges;  ///< the other body's contact edges (mesh edges)
  std::shared_ptr<const contact::DeformableBoundary> boundary, other_boundary;
  double penalty = 0;
  contact::FrictionLaw friction;
  /// The friction histories of the pair's points (and of the other body's points), carried from
  /// load step to load step; shared by copies of the pair.
  struct FrictionMemory {
    std::vector<contact::FrictionHistory> points, other_points;
    /// The histories the last committed step started from (what its Newton iterations saw),
    /// for its tangent (contact_tangent): evaluated with the committed slips, slipping points
    /// lie on the cone, where a difference quotient straddles stick and slip.
    std::vector<contact::FrictionHistory> points_before, other_points_before;
  };
  std::shared_ptr<FrictionMemory> memory;
  Vec2 reference_point = Vec2::Zero();  ///< obstacle point used for the half width
  Vec2 tangent = Vec2(1, 0);            ///< obstacle tangent used for the half width
  /// Coordinate of a point along the obstacle: (X − reference point)·tangent.
  double coordinate(const Vec2& X) const { return (X - reference_point).dot(tangent); }
};

/// Contact pairs of a problem; InputError naming the key when a pair is wrong.
std::vector<ContactPair> make_contact_pairs(const ProblemSpec& spec, const Discretization& d);

/// Ends of the contact zone along one body's contact boundary (Pegasus on the gap between the
/// contact points where it changes sign, seed §4.7).
struct ZoneEnds {
  std::vector<Vec2> X;     ///< undeformed
  std::vector<Vec2> x;     ///< deformed
  std::vector<int> outer;  ///< indices of the outer ends of the active region (see ContactResult)
};

/// State of the contact after a solve: per pair, its points' states and derived figures.
struct ContactResult {
  std::vector<contact::PointState> states;  ///< per contact point of the pair
  /// Normal pressure -n·σ·n from the stresses of the body at each contact point (the seed's
  /// plotted pressure), n the undeformed outward normal.
  std::vector<double> stress_pressure;
  Vec2 resultant = Vec2::Zero();            ///< ∫ traction ds on the body
  double p_max = 0, max_penetration = 0;
  /// Ends of the contact zone (Pegasus on the gap, seed §4.7) on the undeformed boundary: the
  /// points a node is moved to (rp) and where the closed forms of the linear theory put them.
  std::vector<Vec2> gamma_star;
  std::vector<Vec2> gamma_star_deformed;  ///< the same points after deformation
  /// Indices into gamma_star of the outer ends of the active region along the contact boundary
  /// (its first and last sign change, where the boundary's own ends are open): the ends rp moves
  /// nodes to. Sign changes between them are islands of opening inside the contact zone, which
  /// the penalty traction's oscillation produces on coarse discretisations.
  std::vector<int> outer_ends;
  double half_width = 0;  ///< largest |(Γ* - reference point)·tangent|, Γ* undeformed
  /// Against another body: the states of its points and the zone ends on its boundary.
  std::vector<contact::PointState> other_states;
  ZoneEnds other_zone_ends;
};

struct NonlinearSolution {
  /// All dofs; when not converged, those of the last converged load step (at load_factor, 0
  /// if none converged) — a state to inspect, not a solution of the problem as posed.
  Eigen::VectorXd u;
  bool converged = false;
  std::string message;  ///< why it stopped, when not converged
  int newton_iterations = 0, load_steps = 0;
  double load_factor = 1;   ///< factor on the prescribed displacements reached
  double loads_factor = 1;  ///< factor on the loads reached (= load_factor without stages)
  std::vector<ContactPair> pairs;     ///< the contact pairs solved, for post-processing
  /// The load path, a point per converged step: load factors, the monitored node's
  /// displacement (if solver.monitor), the first pair's contact resultant, iterations.
  struct PathPoint {
    double displacements = 0, loads = 0;
    Vec2 monitor = Vec2::Zero();
    Vec2 resultant = Vec2::Zero();
    int iterations = 0;
    double arc_length = 0;  ///< Δl of an arc-length step, 0 under load control
  };
  std::vector<PathPoint> path;
  std::vector<ContactResult> contact;  ///< per pair
};

/// Pressures at one point of a contact boundary.
struct BoundaryPressure {
  Vec2 X;                  ///< undeformed position
  Vec2 x;                  ///< deformed position
  double from_stress = 0;  ///< -n·σ·n, n the undeformed outward normal
  double penalty = 0;      ///< eps_N <-g_N>
};

/// Pressures along the contact boundary of a pair, located by the coordinate
/// s = (X - reference point)·tangent of the undeformed point X along the obstacle (the linear
/// theory's coordinate: Hertz and Shtayerman place the pressure on the undeformed surface). The boundary is sampled once when
/// constructed; each query then refines one bracket.
class BoundaryPressureProbe {
public:
  BoundaryPressureProbe(const Discretization& d, const ContactPair& pair, const Eigen::VectorXd& u);
  /// Pressures at the boundary point with coordinate s; nullopt if no contact edge reaches s.
  std::optional<BoundaryPressure> operator()(double s) const;

private:
  static constexpr int kSamples = 32;  ///< sub-intervals per edge
  const Discretization& d_;
  const ContactPair& pair_;
  const Eigen::VectorXd& u_;
  std::vector<std::array<double, kSamples + 1>> coord_;  ///< per edge, at t = -1 + 2i/kSamples
  double coordinate(int edge_index, double t) const;
};

using ProgressFn = std::function<void(const std::string&)>;
/// Called after every converged load step with all dofs u, the path point just recorded and the
/// contact pairs (for evaluate_contact).
using StepFn = std::function<void(const Eigen::VectorXd& u, const NonlinearSolution::PathPoint&,
                                  const std::vector<ContactPair>& pairs)>;

/// The contact state of a pair at the dofs u: its points' states, pressures from the stresses,
/// resultant, Γ*, half width.
ContactResult evaluate_contact(const Discretization& d, const ContactPair& pair,
                               const Eigen::VectorXd& u);

/// Solves the (nonlinear) contact problem with load steps and Newton's method; with
/// solver.target_resultant, finds the load factor by the secant method.
/// `initial_factor` > 0 starts the force control there instead of at 1 (a guess close to the
/// answer, e.g. the previous mesh's factor in an adaptive loop, saves secant iterations).
NonlinearSolution solve_contact(const ProblemSpec& spec, const Discretization& d,
                                const ProgressFn& progress = {}, double initial_factor = 0,
                                const StepFn& on_step = {});

/// The Newton tangent of the contact problem at a solution, on the unknowns of its solve:
/// analytic, or the seed's central finite differences (eq. 3.36). The residual there into
/// `residual` if not null. For tests and benchmarks of the two tangents.
solve::SparseMatrix contact_tangent(const ProblemSpec& spec, const Discretization& d,
                                    const NonlinearSolution& sol, bool finite_difference,
                                    Eigen::VectorXd* residual = nullptr);

/// The Jacobian of the residual at a solution by plain central differences, every normal and
/// every finite-strain term re-evaluated (not the seed's frozen-normal variant, not
/// symmetrised): what the analytic tangent must equal, to O(h²). For tests.
solve::SparseMatrix residual_jacobian_by_differences(const ProblemSpec& spec, const Discretization& d,
                                                     const NonlinearSolution& sol);

}  // namespace hpcontact::model
