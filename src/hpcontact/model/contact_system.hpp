// The contact problem as a nonlinear system for the solvers: R(x) = K u − λ_f f − f_c(u, λ) (and
// the finite-strain internal forces) over the unknowns of the elastic operator, followed by the
// contact multipliers of exactly enforced pairs and, under force control, the load factor.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "hpcontact/model/contact_forces.hpp"
#include "hpcontact/model/linear_solve.hpp"
#include "hpcontact/solve/arc_length.hpp"
#include "hpcontact/solve/saddle_point.hpp"

namespace hpcontact::model {

/// The nonlinear system over the unknowns x = (u, λ, α):
/// - u, the unknowns of the elastic operator: with static condensation only the free external
///   dofs, since contact acts on vertex and edge modes alone and the internal modes of the linear
///   elastic elements can be eliminated once, before Newton (not with a finite-strain body,
///   whose internal modes stay unknowns). Finite-strain bodies add their internal forces and
///   tangents at every evaluation.
/// - λ, the pressures at the multiplier nodes of the exactly enforced pairs, pair after pair.
///   Their rows are the complementarity functions W_j C_j, C_j = λ_j − max(0, λ_j − ε_j ĝ_j)
///   (active: ε_j G_j = 0, inactive: W_j λ_j = 0), whose semi-smooth Newton step changes the
///   active set from one iteration to the next.
/// - α, under force control (bordered), the factor on the prescribed displacements, its row
///   the target resultant of the first pair: s·F_c(λ) − F = 0.
/// The tangent is factorised by eliminating λ and α (solve::SaddlePointSolver).
class ContactSystem final : public solve::NonlinearSystem {
public:
  /// How the Newton tangent is formed: analytic; the seed's differences (normals of the
  /// undisturbed state frozen, symmetrised); plain central differences of the residual (the
  /// exact Jacobian to O(h²), for checking the analytic one).
  enum class Tangent { analytic, seed_difference, central_difference };

  /// `elastic`: the bodies' elastic operator of d (assemble_elastic with this `condense`) when
  /// the caller has it from another system on d (NonlinearSolution::elastic), else assembled.
  ContactSystem(const Discretization& d, const std::vector<ContactPair>& pairs, bool condense,
                Tangent tangent = Tangent::analytic,
                std::shared_ptr<const ElasticOperator> elastic = nullptr);

  /// The bodies' elastic operator, shared with whoever keeps it.
  const std::shared_ptr<const ElasticOperator>& elastic() const { return op_; }

  /// Why the last evaluation failed (an inverted element), empty if it did not.
  const std::string& failure() const { return failure_; }
  /// Contact points with a pressure at the state last evaluated (both sides of two-body pairs;
  /// the active nodes of exactly enforced pairs).
  int points_in_contact() const { return points_in_contact_; }

  /// Before the first load step from the undeformed state (x there): the multiplier nodes that
  /// touch or overlap the other side at their own point (g <= 1e-9 of the body's size), or
  /// between them and their neighbour on the edge (touching_nodes: a curve touching at a point
  /// no node lies on, as after an adaptive loop moved the node that did) — a curved body
  /// touching at one point, whose weighted gap the rising surface around the node makes
  /// positive; an overlap that contact[].interference: ramp makes a touch — start active:
  /// their multiplier the least that passes the active-set test (none where the weighted gap is
  /// already a penetration). Otherwise no node
  /// would be active in the first Newton iteration and a body that only the contact (and its
  /// friction) holds would be free.
  void activate_touching(Eigen::VectorXd& x) const;
  /// The factors on the prescribed displacements (and obstacle displacements) and on the loads.
  void set_factors(double displacements, double loads) { set_factors(Vec2(displacements, displacements), loads); }
  /// Separate factors on the x and the y components of the prescribed displacements.
  void set_factors(const Vec2& displacements, double loads);
  /// Force control as one more unknown: the factor on the prescribed displacements, found with
  /// the first pair's resultant component (0: x, 1: y) equal to `value` in magnitude. The first
  /// pair must be enforced exactly. Off (nullopt): the factor is set_factors()'s. With
  /// `scales_loads` the loads follow the same factor (the proportional path); without, they keep
  /// set_factors()'s (a stage that shears at a held normal force).
  void set_force_target(std::optional<std::pair<int, double>> target, bool scales_loads = true);
  bool force_controlled() const { return target_.has_value(); }
  /// The factors on the prescribed displacements' x and y components at x (both the unknown α
  /// under force control), and on the loads (α too under force control on the proportional path).
  Vec2 displacement_factors(const Eigen::VectorXd& x) const;
  /// The unknown α under force control, else the y displacements' factor.
  double displacement_factor(const Eigen::VectorXd& x) const { return displacement_factors(x).y(); }
  double loads_factor(const Eigen::VectorXd& x) const;

  /// After a converged load step at x: the friction histories take its anchors and slips (and
  /// exact friction measures its slips from x), and the step's slips are measured.
  void commit(const Eigen::VectorXd& x);
  /// Per pair with exact friction, per multiplier node, the weighted slip of the last committed
  /// step: ĝ_T,j = G_T,j / W_j (zero at a passive node), from the state before it to the one
  /// committed; empty for the other pairs. What locates the stick–slip points
  /// (ContactResult::stick_slip).
  const std::vector<Eigen::VectorXd>& step_slips() const { return step_slips_; }
  /// The same, the slips of every committed step added up, signed along the node's tangent (the
  /// path's slip: contact.csv `slip`).
  const std::vector<Eigen::VectorXd>& total_slips() const { return total_slips_; }
  /// The load vector on the unknowns (what a unit load factor applies), the follower loads
  /// left out.
  Eigen::VectorXd load_vector() const;
  /// The same at the state x with the follower loads on the deformed boundary, over the parts
  /// of their edges the last evaluation wetted: ∂(λ f)/∂λ at x.
  Eigen::VectorXd load_vector(const Eigen::VectorXd& x) const;
  const Vec2& displacement_factors() const { return factors_; }
  bool has_friction() const;
  /// Whether the displacement block of a tangent may be unsymmetric: friction, or a pair
  /// pressing along the mean normal (its force direction is not the gap's gradient).
  bool has_unsymmetric_tangent() const;
  /// The unknowns x of all dofs u and the multipliers of each pair (empty for penalty pairs; an
  /// empty list: zero multipliers), α = the current factor under force control.
  Eigen::VectorXd unknowns(const Eigen::VectorXd& u,
                           const std::vector<Eigen::VectorXd>& multipliers = {}) const;
  /// The multipliers of each pair at x (empty for penalty pairs).
  std::vector<Eigen::VectorXd> multipliers(const Eigen::VectorXd& x) const;
  int size() const override { return n_u_ + n_z_; }
  /// The number of displacement unknowns (the multipliers follow them).
  int n_displacements() const { return n_u_; }
  /// The multipliers of pair k: its nodes' normal pressures, then with friction their
  /// tangential tractions (0 for a penalty pair).
  int n_multipliers(size_t k) const {
    const auto& c = pairs_[k].constraints;
    return c ? c->size() * (c->has_friction() ? 2 : 1) : 0;
  }

  /// All dofs from the unknowns (condensed internal modes zero; see solution()).
  Eigen::VectorXd full(const Eigen::VectorXd& x) const;
  /// All dofs, the condensed internal modes recovered.
  Eigen::VectorXd solution(const Eigen::VectorXd& x) const;
  /// The displacement part of x as a field over all dofs with no load and nothing prescribed
  /// (zero on prescribed dofs, condensed internal modes from x alone): what a correction or an
  /// adjoint solution is.
  Eigen::VectorXd homogeneous_field(const Eigen::VectorXd& x) const;

  /// Scale of the residual: the norm of the forces the current load produces, and of the
  /// internal forces at the state x (a load step that starts from a loaded state, e.g. a
  /// displaced obstacle with no other load, must converge relative to those, not to its own
  /// small increment).
  double force_scale(const Eigen::VectorXd& x) const;

  void evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& r, solve::SparseMatrix* K) override;
  void factorize(solve::LinearSolver& sparse, const solve::SparseMatrix& K) override;
  /// Under force control the factor changes by at most a factor 2 per Newton step: the active
  /// set follows the load instead of jumping between far too small and far too large zones.
  double admissible_step(const Eigen::VectorXd& x, const Eigen::VectorXd& dx) const override;
  /// The multiplier nodes' states (inactive, active; open, stick, slip) at the last two
  /// tangents were the same.
  bool settled() const override { return tangent_states_ == previous_tangent_states_; }
  /// The multiplier rows (of all exact pairs: active or not, open/stick/slip) whose state at the
  /// last tangent differs from the tangent's before (all of them at the first tangent); −1 if no
  /// pair is enforced exactly.
  int states_changed() const;
  /// Per exact pair at the last evaluation: its active nodes, how many changed since the
  /// tangent before, and the largest penetration with where it is.
  std::string describe() const override;
  /// "; there contact[k] carries 98.4 % of the tangential force its friction can ..." for each
  /// exact Coulomb pair whose tangential resultant at the last committed step is at least 90 %
  /// of μ times its normal one, else empty: why a load may not be carried further.
  std::string capacity_used() const;
  Eigen::VectorXd solve(const solve::LinearSolver& sparse, const Eigen::VectorXd& b) const override;
  /// Per follower load of the discretisation (Discretization::follower_loads), the part of its
  /// edges it acted on at the last evaluation: with penetration, up to the contact of its pair
  /// then (the active multiplier nodes; a penalty pair's points with a pressure).
  const std::vector<WetRange>& wet_ranges() const { return wet_ranges_; }
  /// Whether a follower load penetrates up to a pair's contact (its range moves with the state).
  bool has_penetration() const;
  /// Holds the follower loads' ranges at `ranges` in every evaluation until thaw_wet_ranges():
  /// Newton's iterations then solve for one front of each penetrating pressure.
  void freeze_wet_ranges(std::vector<WetRange> ranges) const { frozen_wet_ranges_ = std::move(ranges); }
  void thaw_wet_ranges() const { frozen_wet_ranges_.reset(); }
  /// Holds them at what the next evaluation computes (the state Newton starts from).
  void freeze_wet_ranges_at_next_evaluation() const {
    frozen_wet_ranges_.reset();
    freeze_next_ = true;
  }

private:
  /// Adds the follower loads' forces at u, times −the loads' factor, into R and their tangent
  /// into t; their unscaled sum into f (for ∂r/∂α) if not null. `marks` per pair: where its
  /// points or nodes are in contact.
  void add_follower_loads(const Eigen::VectorXd& u, double loads_factor,
                          const std::vector<std::vector<ContactMark>>& marks, Eigen::VectorXd& R,
                          std::vector<Eigen::Triplet<double>>* t, Eigen::VectorXd* f) const;
  mutable std::vector<WetRange> wet_ranges_;
  mutable std::optional<std::vector<WetRange>> frozen_wet_ranges_;
  mutable bool freeze_next_ = false;

  using PairStates = std::vector<std::vector<contact::PointState>>;
  /// A tangential multiplier row's state (states_): held is a sticking node whose slip no
  /// unknown moves (tangential_rows).
  enum class TangentialState : char { open, stick, slip, held };
  using Triplets = std::vector<Eigen::Triplet<double>>;

  /// R(x); the tangent's triplets on the unknowns into T (null: none); the penalty points'
  /// states into states; with `frozen`, penalty gaps use the normals of those states. With
  /// K_finite (and T, and no force target) the finite-strain bodies' tangent goes there, on the
  /// displacement unknowns (FiniteStrainForces' kept pattern), instead of into T.
  void residual(const Eigen::VectorXd& x, Eigen::VectorXd& r, Triplets* T, PairStates* states,
                const PairStates* frozen, solve::SparseMatrix* K_finite = nullptr) const;
  /// Per dof its index among the unknowns, −1 if none (ElasticOperator::unknown).
  std::vector<int> unknown_of_dof_;

  /// The seed's tangent (eq. 3.35–3.36): column m by central differences of the whole residual
  /// with the step h_m = ν (|x_m| + 1e-3), ν = 1e-6 (< √η; below the seed's 1e-5 because a
  /// column straddling a contact switch is wrong and a small step makes that rare), the normals
  /// of the undisturbed state kept, the displacement block symmetrised. Without `undisturbed`:
  /// plain central differences, not symmetrised.
  solve::SparseMatrix finite_difference_tangent(const Eigen::VectorXd& x,
                                                const PairStates* undisturbed) const;

  /// The rows of an exact pair's tangential multipliers (offset o of its normal ones): open
  /// nodes W λ_T = 0, sticking ones c_T G_T = 0, slipping ones W (λ_T − μ s λ_N) = 0; their
  /// u-parts of sticking rows on prescribed dofs into z_rows (for ∂/∂α) if not null.
  void tangential_rows(const PairConstraints& c, const ConstraintState& s,
                       const Eigen::VectorXd& lambda, const Eigen::VectorXd& lambda_t, int o,
                       Eigen::VectorXd& r, Triplets* T, Triplets* z_rows) const;

  const Discretization& d_;
  const std::vector<ContactPair>& pairs_;
  mutable int points_in_contact_ = 0;
  std::shared_ptr<const ElasticOperator> op_;
  solve::SparseMatrix K_uu_;  ///< the linear bodies' tangent on the unknowns, constant
  solve::SparseMatrix K_uu_wide_;  ///< K_uu_ on all size() unknowns (evaluate())
  FiniteStrainForces finite_;
  mutable std::string failure_;
  Tangent tangent_ = Tangent::analytic;
  Vec2 factors_ = Vec2(1, 1);  ///< factors on the prescribed displacements' x and y components
  double lambda_f_ = 1.0;  ///< factor on the loads
  int n_u_ = 0;            ///< displacement unknowns
  int n_z_ = 0;            ///< multipliers and the bordered factor
  std::vector<int> z_offset_;  ///< per pair: its first multiplier's index in z, -1 for penalty
  std::optional<std::pair<int, double>> target_;  ///< force control: component, value
  bool target_scales_loads_ = true;               ///< force control: the loads' factor is α too
  Eigen::VectorXd gamma_;      ///< augmentation of each row of z (ε_j W_j; 0 for α)
  solve::SaddlePointSolver saddle_;
  /// The state of each multiplier row at the last evaluation, and at the last two with a
  /// tangent (settled()).
  mutable std::vector<char> states_;
  /// Per pair at the last evaluation (exact pairs): the deepest point and its gap.
  struct Deepest {
    double gap = 0;
    Vec2 x = Vec2::Zero();
  };
  mutable std::vector<Deepest> deepest_;
  /// Per exact pair with a ramped interference, its multiplier nodes' initial_overlaps (empty
  /// otherwise).
  std::vector<Eigen::VectorXd> initial_overlap_;
  /// What pair k's gaps still take of its initial overlap at the displacement factor f.
  InterferenceRelief relief(size_t k, double f) const;
  std::vector<char> tangent_states_, previous_tangent_states_;
  /// Per pair with exact friction: (Σ W_j λ_j, Σ W_j λ_T,j) at x, the normal and tangential
  /// resultants of its multipliers (zero for the other pairs).
  std::vector<Vec2> friction_resultants(const Eigen::VectorXd& x) const;
  std::vector<Vec2> committed_friction_;  ///< friction_resultants at the last committed step
  Eigen::VectorXd K_prescribed_;   ///< K times the prescribed displacements (for ∂/∂α)
  /// The prescribed displacements, their x and y components scaled by `factors`.
  Eigen::VectorXd prescribed(const Vec2& factors) const;
  /// What an exact friction pair's evaluation needs: its tangential multipliers, and the dofs and
  /// factors its slips are measured from (the obstacle's move since then at `factors`).
  FrictionInputs friction_inputs(const ContactPair& pair, const Eigen::VectorXd& lambda_t,
                                 const Eigen::VectorXd& u_from, const Vec2& factors_from,
                                 const Vec2& factors) const;
  /// The slips of the step committed last at x, measured from the state before it.
  std::vector<Eigen::VectorXd> measure_step_slips(const Eigen::VectorXd& x) const;
  std::vector<Eigen::VectorXd> step_slips_, total_slips_;  ///< step_slips(), total_slips()
  Eigen::VectorXd u_committed_;    ///< all dofs at the last converged step (exact friction)
  Vec2 factors_committed_ = Vec2::Zero();  ///< the displacement factors there
  /// The same at the converged step before it: where the last step started (step_slips()).
  Eigen::VectorXd u_step_start_;
  Vec2 factors_step_start_ = Vec2::Zero();
};

/// The system on the path of the loads' factor (arc-length), the prescribed displacements held.
class LoadsOnPath final : public solve::LoadPathSystem {
public:
  explicit LoadsOnPath(ContactSystem& s) : s_(s) {}
  int size() const override { return s_.size(); }
  void evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& r, solve::SparseMatrix* K) override {
    s_.evaluate(x, r, K);
  }
  void factorize(solve::LinearSolver& sparse, const solve::SparseMatrix& K) override {
    s_.factorize(sparse, K);
  }
  Eigen::VectorXd solve(const solve::LinearSolver& sparse, const Eigen::VectorXd& b) const override {
    return s_.solve(sparse, b);
  }
  void set_load_factor(double lambda) override { s_.set_factors(s_.displacement_factors(), lambda); }
  Eigen::VectorXd load_derivative(const Eigen::VectorXd& x) override {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(s_.size());
    f.head(s_.n_displacements()) = -s_.load_vector(x);
    return f;
  }
  int path_size() const override { return s_.n_displacements(); }

private:
  ContactSystem& s_;
};

}  // namespace hpcontact::model
