// The penalty forces of contact pairs and the internal forces of finite-strain bodies at a
// state: the terms of the contact system's residual and tangent.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "hpcontact/fem/element_values.hpp"
#include "hpcontact/fem/finite_strain.hpp"
#include "hpcontact/model/contact_pairs.hpp"

namespace hpcontact::model {

/// The contact forces of a pair at the state u (all dofs): on its body, and against another
/// body on that one too, with the states of both sides' points and, if t is not null, the
/// triplets of their tangent (all dofs). Against another body both sides are evaluated, each
/// with half weight: no master/slave preference (seed §3.6). With `frozen`, gaps against a rigid
/// obstacle use the normals of those states (see penalty_contact).
struct PairForces {
  Eigen::VectorXd body, other;
  std::vector<contact::PointState> states, other_states;
  /// ∫ traction ds on the pair's body: its points' tractions, and against another body half of
  /// them plus the reactions of half of the other's points.
  Vec2 resultant(const ContactPair& pair) const {
    Vec2 r = Vec2::Zero();
    const double own = pair.other < 0 ? 1.0 : 0.5;
    for (size_t i = 0; i < pair.points.size(); ++i) r += own * pair.points[i].weight * states[i].traction;
    for (size_t i = 0; i < pair.other_points.size(); ++i)
      r -= 0.5 * pair.other_points[i].weight * other_states[i].traction;
    return r;
  }
};

PairForces pair_forces(const Discretization& d, const ContactPair& pair, const Eigen::VectorXd& u,
                       std::vector<Eigen::Triplet<double>>* t,
                       const std::vector<contact::PointState>* frozen = nullptr);

/// The internal forces of the finite-strain bodies at the state u (all dofs), their tangent's
/// triplets into t if not null. The element values are computed once and kept.
class FiniteStrainForces {
public:
  explicit FiniteStrainForces(const Discretization& d);
  bool empty() const { return elements_.empty(); }

  /// Adds the internal forces into R (all dofs). Returns false, and says where in `inverted`,
  /// when an element inverts (det F ≤ 0 at a quadrature point).
  bool add(const Eigen::VectorXd& u, Eigen::VectorXd& R, std::vector<Eigen::Triplet<double>>* t,
           std::string* inverted) const;
  /// The same, the tangent formed on unknowns: K (n × n) becomes the sum of the element
  /// blocks, each dof's row and column at unknown[dof] (−1: a dof that is no unknown, left out).
  /// The pattern and where each element's entries go in it are found at the first call and
  /// kept (`unknown` and n must be the same at every call): the blocks are added in place, in
  /// the elements' order (the sums of the triplets' assembly, to the bit), with nothing sorted.
  bool add(const Eigen::VectorXd& u, Eigen::VectorXd& R, const std::vector<int>& unknown, int n,
           Eigen::SparseMatrix<double>& K, std::string* inverted) const;

private:
  struct Ref {
    int body, q;
  };
  const Discretization& d_;
  std::vector<Ref> elements_;
  std::vector<fem::ElementValues> values_;
  /// The elements at u (the tangents if asked for), their forces added into R; false (and
  /// `inverted` says where) if one inverts.
  bool elements(const Eigen::VectorXd& u, Eigen::VectorXd& R, bool tangent, std::string* inverted,
                std::vector<fem::FiniteStrainElement>& el) const;
  /// The global dofs of element i's local ones.
  std::vector<int> element_dofs(int i) const;
  /// The tangent's pattern on the unknowns (values zero), and per element the position in its
  /// values of each entry of the element's matrix (column-major; −1: not an unknown's).
  mutable Eigen::SparseMatrix<double> pattern_;
  mutable std::vector<std::vector<int>> positions_;
  void find_pattern(const std::vector<int>& unknown, int n) const;
};

/// Anchors and slips of a pair's points after a converged load step (see FrictionHistory).
void commit_friction(const ContactPair& pair, const PairForces& f);

}  // namespace hpcontact::model
