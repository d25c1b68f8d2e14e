// Penalty forces of the contact pairs (one side against a rigid obstacle, both sides between two
// bodies) and the finite-strain internal forces, each with its tangent's triplets.
#include "hpcontact/model/contact_forces.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "hpcontact/contact/two_body.hpp"
#include "hpcontact/model/finite_strain_body.hpp"
#include "hpcontact/model/parallel.hpp"

namespace hpcontact::model {

PairForces pair_forces(const Discretization& d, const ContactPair& pair, const Eigen::VectorXd& u,
                       std::vector<Eigen::Triplet<double>>* t,
                       const std::vector<contact::PointState>* frozen) {
  const Body& body = d.bodies[pair.body];
  const int n = body.dofs.n_dofs();
  const Eigen::VectorXd ua = u.segment(body.dof_offset, n);
  PairForces f;
  f.body = Eigen::VectorXd::Zero(n);
  contact::FrictionInput fr, fr_other;
  if (pair.memory) {
    fr = {&pair.friction, &pair.memory->points};
    fr_other = {&pair.friction, &pair.memory->other_points};
  }
  if (pair.other < 0) {
    contact::penalty_contact(pair.points, *pair.obstacle, pair.penalty, ua, f.body, t,
                             body.dof_offset, &f.states, frozen, fr);
    return f;
  }
  const Body& other = d.bodies[pair.other];
  const int m = other.dofs.n_dofs();
  const Eigen::VectorXd ub = u.segment(other.dof_offset, m);
  f.other = Eigen::VectorXd::Zero(m);
  pair.boundary->set_displacement(ua);
  pair.other_boundary->set_displacement(ub);
  contact::two_body_contact(pair.points, ua, *pair.other_boundary, pair.penalty, 0.5, f.body, f.other,
                            t, body.dof_offset, other.dof_offset, &f.states, fr);
  contact::two_body_contact(pair.other_points, ub, *pair.boundary, pair.penalty, 0.5, f.other, f.body,
                            t, other.dof_offset, body.dof_offset, &f.other_states, fr_other);
  return f;
}

FiniteStrainForces::FiniteStrainForces(const Discretization& d) : d_(d) {
  for (int b = 0; b < static_cast<int>(d.bodies.size()); ++b) {
    const Body& body = d.bodies[b];
    if (!body.finite_strain()) continue;
    for (int q = 0; q < body.mesh.n_quads(); ++q) {
      elements_.push_back({b, q});
      values_.push_back(fem::element_values(body.dofs.element(q), body.maps[q], body.n_gauss[q],
                                            body.mesh, q));
    }
  }
}

std::vector<int> FiniteStrainForces::element_dofs(int i) const {
  const Body& body = d_.bodies[elements_[i].body];
  const int q = elements_[i].q;
  std::vector<int> dofs(2 * body.dofs.element(q).n_modes() + body.n_pressure_modes(q));
  for (int a = 0; a < static_cast<int>(dofs.size()); ++a) dofs[a] = body.global_dof(q, a);
  return dofs;
}

bool FiniteStrainForces::elements(const Eigen::VectorXd& u, Eigen::VectorXd& R, bool tangent,
                                  std::string* inverted, std::vector<fem::FiniteStrainElement>& el) const {
  const int ne = static_cast<int>(elements_.size());
  el.assign(ne, {});
  parallel_for(ne, [&](int i) {
    const Body& body = d_.bodies[elements_[i].body];
    const int q = elements_[i].q;
    el[i] = finite_strain_element(body, q, values_[i], u, tangent);
  });
  for (int i = 0; i < ne; ++i) {
    const Body& body = d_.bodies[elements_[i].body];
    const int q = elements_[i].q;
    if (el[i].inverted()) {
      if (inverted) {
        const Vec2& X = values_[i].x[el[i].min_J_point];
        std::ostringstream os;
        os << "element " << body.mesh.quad_id(q) << " of body '" << body.name
           << "' inverts: det F = " << el[i].min_J << " at (" << X.x() << ", " << X.y() << ")";
        *inverted = os.str();
      }
      return false;
    }
    const int n = static_cast<int>(el[i].f_int.size());
    for (int a = 0; a < n; ++a) R(body.global_dof(q, a)) += el[i].f_int(a);
  }
  return true;
}

bool FiniteStrainForces::add(const Eigen::VectorXd& u, Eigen::VectorXd& R,
                             std::vector<Eigen::Triplet<double>>* t, std::string* inverted) const {
  std::vector<fem::FiniteStrainElement> el;
  if (!elements(u, R, t != nullptr, inverted, el)) return false;
  if (!t) return true;
  std::size_t entries = t->size();
  for (const auto& e : el) entries += static_cast<std::size_t>(e.K.size());
  t->reserve(entries);
  for (int i = 0; i < static_cast<int>(el.size()); ++i) {
    const std::vector<int> dofs = element_dofs(i);
    const int n = static_cast<int>(el[i].K.rows());
    for (int b = 0; b < n; ++b)  // K is column-major
      for (int a = 0; a < n; ++a) t->emplace_back(dofs[a], dofs[b], el[i].K(a, b));
  }
  return true;
}

void FiniteStrainForces::find_pattern(const std::vector<int>& unknown, int n) const {
  std::vector<Eigen::Triplet<double>> t;
  std::vector<std::vector<int>> rows(elements_.size());  // the unknown of each local dof
  for (size_t i = 0; i < elements_.size(); ++i) {
    for (const int dof : element_dofs(static_cast<int>(i))) rows[i].push_back(unknown[dof]);
    for (const int b : rows[i])
      for (const int a : rows[i])
        if (a >= 0 && b >= 0) t.emplace_back(a, b, 0.0);
  }
  pattern_.resize(n, n);
  pattern_.setFromTriplets(t.begin(), t.end());
  pattern_.makeCompressed();
  positions_.assign(elements_.size(), {});
  const int* outer = pattern_.outerIndexPtr();
  const int* inner = pattern_.innerIndexPtr();
  for (size_t i = 0; i < elements_.size(); ++i)
    for (const int b : rows[i])
      for (const int a : rows[i]) {
        int position = -1;
        if (a >= 0 && b >= 0) position = static_cast<int>(std::lower_bound(inner + outer[b], inner + outer[b + 1], a) - inner);
        positions_[i].push_back(position);
      }
}

bool FiniteStrainForces::add(const Eigen::VectorXd& u, Eigen::VectorXd& R, const std::vector<int>& unknown,
                             int n, Eigen::SparseMatrix<double>& K, std::string* inverted) const {
  std::vector<fem::FiniteStrainElement> el;
  if (!elements(u, R, true, inverted, el)) return false;
  if (positions_.size() != elements_.size() || pattern_.rows() != n) find_pattern(unknown, n);
  K = pattern_;
  double* values = K.valuePtr();
  for (size_t i = 0; i < el.size(); ++i) {
    const double* k = el[i].K.data();
    const std::vector<int>& at = positions_[i];
    for (size_t e = 0; e < at.size(); ++e)
      if (at[e] >= 0) values[at[e]] += k[e];
  }
  return true;
}

/// Anchors and slips of a pair's points after a converged load step (see FrictionHistory).
void commit_friction(const ContactPair& pair, const PairForces& f) {
  if (!pair.memory) return;
  auto update = [&](std::vector<contact::FrictionHistory>& hs,
                    const std::vector<contact::PointState>& states) {
    for (size_t i = 0; i < hs.size(); ++i) {
      auto& h = hs[i];
      const auto& s = states[i];
      if (s.gap > 0 || !std::isfinite(s.gap)) {
        h = contact::FrictionHistory{};
        continue;
      }
      if (h.anchored) {
        h.slip = s.slip;
        continue;
      }
      h.anchored = true;
      h.edge = s.foot_edge;
      h.t = s.foot_t;
      h.anchor = s.foot - pair.obstacle->offset();
      h.tau = s.tau;
      h.slip = 0;
    }
  };
  pair.memory->points_before = pair.memory->points;
  pair.memory->other_points_before = pair.memory->other_points;
  update(pair.memory->points, f.states);
  if (pair.other >= 0) update(pair.memory->other_points, f.other_states);
}

}  // namespace hpcontact::model
