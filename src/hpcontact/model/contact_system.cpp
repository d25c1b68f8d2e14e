// The contact system's residual and tangent: the elastic operator, finite-strain bodies and the
// contact forces of every pair, on the unknowns of the solve.
#include "hpcontact/model/contact_system.hpp"

#include <cmath>
#include <limits>

namespace hpcontact::model {

ContactSystem::ContactSystem(const Discretization& d, const std::vector<ContactPair>& pairs,
                             bool condense, Tangent tangent)
    : d_(d),
      pairs_(pairs),
      op_(assemble_elastic(d, condense && !d.finite_strain())),
      K_uu_(op_.unknown_block(d)),
      finite_(d),
      tangent_(tangent) {}

void ContactSystem::set_factors(double displacements, double loads) {
  lambda_ = displacements;
  lambda_f_ = loads;
  for (const auto& pair : pairs_)
    if (pair.moving) pair.moving->set_load_factor(displacements);
}

void ContactSystem::commit(const Eigen::VectorXd& x) const {
  if (!has_friction()) return;
  const Eigen::VectorXd u = full(x);
  for (const auto& pair : pairs_)
    if (pair.memory) commit_friction(pair, pair_forces(d_, pair, u, nullptr));
}

bool ContactSystem::has_friction() const {
  for (const auto& pair : pairs_)
    if (pair.memory) return true;
  return false;
}

Eigen::VectorXd ContactSystem::solution(const Eigen::VectorXd& x) const {
  Eigen::VectorXd u = full(x);
  op_.recover_internal(d_, u, lambda_f_);
  return u;
}

double ContactSystem::force_scale(const Eigen::VectorXd& x) const {
  const Eigen::VectorXd f = op_.K * (lambda_ * d_.prescribed);
  const Eigen::VectorXd u = full(x);
  Eigen::VectorXd g = op_.K * u;
  if (!finite_.empty()) finite_.add(u, g, nullptr, nullptr);
  return op_.restrict(d_, f).norm() + std::abs(lambda_f_) * op_.restrict(d_, op_.load).norm() +
         op_.restrict(d_, g).norm();
}

void ContactSystem::evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& r, solve::SparseMatrix* K) {
  if (K && tangent_ != Tangent::analytic) {
    PairStates undisturbed;
    residual(x, r, nullptr, &undisturbed, nullptr);
    *K = finite_difference_tangent(x, tangent_ == Tangent::seed_difference ? &undisturbed : nullptr);
    return;
  }
  std::vector<Eigen::Triplet<double>> t;
  residual(x, r, K ? &t : nullptr, nullptr, nullptr);
  if (!K) return;
  std::vector<Eigen::Triplet<double>> tf;
  tf.reserve(t.size());
  for (const auto& e : t) {
    const int i = op_.unknown(d_, e.row()), j = op_.unknown(d_, e.col());
    if (i >= 0 && j >= 0) tf.emplace_back(i, j, e.value());
  }
  solve::SparseMatrix Kc(size(), size());
  Kc.setFromTriplets(tf.begin(), tf.end());
  *K = K_uu_ + Kc;
}

void ContactSystem::residual(const Eigen::VectorXd& x, Eigen::VectorXd& r,
                             std::vector<Eigen::Triplet<double>>* t, PairStates* states,
                             const PairStates* frozen) const {
  const Eigen::VectorXd u = full(x);
  Eigen::VectorXd R = op_.K * u - lambda_f_ * op_.load;
  if (!finite_.empty() && !finite_.add(u, R, t, &failure_)) {
    // An inverted element has no internal force: a not-finite residual makes Newton stop and
    // the load step be cut.
    r = Eigen::VectorXd::Constant(size(), std::numeric_limits<double>::quiet_NaN());
    return;
  }
  if (states) states->resize(pairs_.size());
  points_in_contact_ = 0;
  for (size_t k = 0; k < pairs_.size(); ++k) {
    const ContactPair& pair = pairs_[k];
    PairForces f = pair_forces(d_, pair, u, t, frozen ? &(*frozen)[k] : nullptr);
    for (const auto* side : {&f.states, &f.other_states})
      for (const auto& s : *side) points_in_contact_ += s.pressure > 0;
    R.segment(d_.bodies[pair.body].dof_offset, f.body.size()) -= f.body;
    if (pair.other >= 0) R.segment(d_.bodies[pair.other].dof_offset, f.other.size()) -= f.other;
    if (states) (*states)[k] = std::move(f.states);
  }
  r = op_.restrict(d_, R);
}

solve::SparseMatrix ContactSystem::finite_difference_tangent(const Eigen::VectorXd& x,
                                                             const PairStates* undisturbed) const {
  std::vector<Eigen::Triplet<double>> t;
  Eigen::VectorXd xd = x, r_plus, r_minus;
  for (int m = 0; m < size(); ++m) {
    const double h = 1e-6 * (std::abs(x(m)) + 1e-3);
    xd(m) = x(m) + h / 2;
    residual(xd, r_plus, nullptr, nullptr, undisturbed);
    xd(m) = x(m) - h / 2;
    residual(xd, r_minus, nullptr, nullptr, undisturbed);
    xd(m) = x(m);
    for (int i = 0; i < size(); ++i)
      if (const double v = (r_plus(i) - r_minus(i)) / h; v != 0) t.emplace_back(i, m, v);
  }
  solve::SparseMatrix K(size(), size());
  K.setFromTriplets(t.begin(), t.end());
  if (!undisturbed) return K;
  // Central differences are symmetric up to round-off and up to columns straddling a contact
  // switch; the seed solves the symmetric part ("symmetric equation system"), and so do we.
  return solve::SparseMatrix(0.5 * (K + solve::SparseMatrix(K.transpose())));
}

}  // namespace hpcontact::model
