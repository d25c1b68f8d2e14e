// The contact problem as a nonlinear system for the solvers: R(x) = K u − λ_f f − f_c(u) (and
// the finite-strain internal forces) over the unknowns of the elastic operator, its tangent.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "hpcontact/model/contact_forces.hpp"
#include "hpcontact/model/linear_solve.hpp"
#include "hpcontact/solve/arc_length.hpp"

namespace hpcontact::model {

/// The nonlinear system over the unknowns of the elastic operator: with static condensation only
/// the free external dofs, since contact acts on vertex and edge modes alone and the internal
/// modes of the linear elastic elements can be eliminated once, before Newton (not with a
/// finite-strain body, whose internal modes stay unknowns). Finite-strain bodies add their
/// internal forces and tangents at every evaluation.
class ContactSystem final : public solve::NonlinearSystem {
public:
  /// How the Newton tangent is formed: analytic; the seed's differences (normals of the
  /// undisturbed state frozen, symmetrised); plain central differences of the residual (the
  /// exact Jacobian to O(h²), for checking the analytic one).
  enum class Tangent { analytic, seed_difference, central_difference };

  ContactSystem(const Discretization& d, const std::vector<ContactPair>& pairs, bool condense,
                Tangent tangent = Tangent::analytic);

  /// Why the last evaluation failed (an inverted element), empty if it did not.
  const std::string& failure() const { return failure_; }
  /// Contact points with a pressure at the state last evaluated (both sides of two-body pairs).
  int points_in_contact() const { return points_in_contact_; }

  /// The factors on the prescribed displacements (and obstacle displacements) and on the loads.
  void set_factors(double displacements, double loads);

  /// After a converged load step at x: the friction histories take its anchors and slips.
  void commit(const Eigen::VectorXd& x) const;
  /// The load vector on the unknowns (what a unit load factor applies).
  Eigen::VectorXd load_vector() const { return op_.restrict(d_, op_.load); }
  double displacement_factor() const { return lambda_; }
  bool has_friction() const;
  /// The unknowns' values in a vector of all dofs.
  Eigen::VectorXd unknowns(const Eigen::VectorXd& u) const { return op_.restrict(d_, u); }
  int size() const override { return op_.n_unknowns; }

  /// All dofs from the unknowns (condensed internal modes zero; see solution()).
  Eigen::VectorXd full(const Eigen::VectorXd& x) const { return op_.expand(d_, x, lambda_); }
  /// All dofs, the condensed internal modes recovered.
  Eigen::VectorXd solution(const Eigen::VectorXd& x) const;

  /// Scale of the residual: the norm of the forces the current load produces, and of the
  /// internal forces at the state x (a load step that starts from a loaded state, e.g. a
  /// displaced obstacle with no other load, must converge relative to those, not to its own
  /// small increment).
  double force_scale(const Eigen::VectorXd& x) const;

  void evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& r, solve::SparseMatrix* K) override;

private:
  using PairStates = std::vector<std::vector<contact::PointState>>;

  /// R(x) on the unknowns; the contact tangent's triplets (all dofs) into t, the points' states
  /// into states; with `frozen`, gaps use the normals of those states (see penalty_contact).
  void residual(const Eigen::VectorXd& x, Eigen::VectorXd& r, std::vector<Eigen::Triplet<double>>* t,
                PairStates* states, const PairStates* frozen) const;

  /// The seed's tangent (eq. 3.35–3.36): column m by central differences of the whole residual
  /// with the step h_m = ν (|x_m| + 1e-3), ν = 1e-6 (< √η; below the seed's 1e-5 because a
  /// column straddling a contact switch is wrong and a small step makes that rare), the normals
  /// of the undisturbed state kept. Without `undisturbed`: plain central differences, not
  /// symmetrised.
  solve::SparseMatrix finite_difference_tangent(const Eigen::VectorXd& x,
                                                const PairStates* undisturbed) const;

  const Discretization& d_;
  const std::vector<ContactPair>& pairs_;
  mutable int points_in_contact_ = 0;
  ElasticOperator op_;
  solve::SparseMatrix K_uu_;  ///< the linear bodies' tangent on the unknowns, constant
  FiniteStrainForces finite_;
  mutable std::string failure_;
  Tangent tangent_ = Tangent::analytic;
  double lambda_ = 1.0;    ///< factor on the prescribed displacements
  double lambda_f_ = 1.0;  ///< factor on the loads
};

/// The system on the path of the loads' factor (arc-length), the prescribed displacements held.
class LoadsOnPath final : public solve::LoadPathSystem {
public:
  explicit LoadsOnPath(ContactSystem& s) : s_(s) {}
  int size() const override { return s_.size(); }
  void evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& r, solve::SparseMatrix* K) override {
    s_.evaluate(x, r, K);
  }
  void set_load_factor(double lambda) override { s_.set_factors(s_.displacement_factor(), lambda); }
  Eigen::VectorXd load_derivative(const Eigen::VectorXd&) override { return -s_.load_vector(); }

private:
  ContactSystem& s_;
};

}  // namespace hpcontact::model
