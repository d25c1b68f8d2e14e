// Reactions at the supports and contact pairs, from the residual the solve leaves at the
// prescribed dofs, and each body's balance of forces.
#include "hpcontact/model/reactions.hpp"

#include <algorithm>
#include <cmath>

#include "hpcontact/fem/element_values.hpp"
#include "hpcontact/model/contact_forces.hpp"
#include "hpcontact/model/contact_multipliers.hpp"
#include "hpcontact/model/contact_results.hpp"
#include "hpcontact/model/edge_interpolant.hpp"
#include "hpcontact/model/finite_strain_body.hpp"
#include "hpcontact/model/follower_forces.hpp"
#include "hpcontact/model/linear_solve.hpp"
#include "hpcontact/model/parallel.hpp"

namespace hpcontact::model {

namespace {

/// The elements of a body with a prescribed dof: the only ones whose internal forces reach one.
std::vector<int> supported_elements(const Discretization& d, const Body& body) {
  std::vector<int> qs;
  for (int q = 0; q < body.mesh.n_quads(); ++q) {
    const int n = 2 * body.dofs.element(q).n_modes();
    for (int a = 0; a < n; ++a)
      if (d.free_index[body.global_dof(q, a)] < 0) {
        qs.push_back(q);
        break;
      }
  }
  return qs;
}

/// The internal forces of element q at u (component-blocked local order): K_e u_e for small
/// strain, t ∫ Bᵀ S dA for finite strain (empty where it inverts; a mixed body's pressure rows
/// after the displacements').
Eigen::VectorXd internal_forces(const Body& body, int q, const Eigen::VectorXd& u) {
  const Eigen::VectorXd ue = body.element_coefficients(q, u);
  if (!body.finite_strain()) return element_stiffness(body, q) * ue;
  const auto ev = fem::element_values(body.dofs.element(q), body.maps[q], body.n_gauss[q], body.mesh, q);
  return finite_strain_element(body, q, ev, u, false).f_int;
}

/// A force vector's resultant and moment with a body's resultant weights w and boundary
/// positions X computed once (force_and_moment).
ForceMoment force_and_moment(const Body& body, const Eigen::VectorXd& w, const std::vector<Vec2>& X,
                             const Eigen::VectorXd& f, const Eigen::VectorXd& u_body) {
  ForceMoment fm;
  for (int m = 0; m < body.dofs.n_modes(); ++m) fm.force += w(m) * Vec2(f(2 * m), f(2 * m + 1));
  if (body.axisymmetric()) return fm;
  fm.moment = 0;
  for (int m = 0; m < body.dofs.n_modes(); ++m) {
    Vec2 x = X[m];
    if (body.finite_strain()) x += Vec2(u_body(2 * m), u_body(2 * m + 1));
    fm.moment += x.x() * f(2 * m + 1) - x.y() * f(2 * m);
  }
  return fm;
}

/// f_int(u) − λ_f f − f_c at the prescribed dofs, f_c the pairs' contact forces (all dofs).
Eigen::VectorXd support_residual(const Discretization& d, const Eigen::VectorXd& u,
                                 double loads_factor, const Eigen::VectorXd& f_c) {
  Eigen::VectorXd R = -loads_factor * d.load - f_c;
  for (const Body& body : d.bodies) {
    const auto qs = supported_elements(d, body);
    std::vector<Eigen::VectorXd> fe(qs.size());
    parallel_for(static_cast<int>(qs.size()), [&](int i) { fe[i] = internal_forces(body, qs[i], u); });
    for (size_t i = 0; i < qs.size(); ++i)
      for (int a = 0; a < fe[i].size(); ++a) R(body.global_dof(qs[i], a)) += fe[i](a);
  }
  for (int i = 0; i < d.n_dofs; ++i)
    if (d.free_index[i] >= 0) R(i) = 0.0;
  return R;
}

}  // namespace

Eigen::VectorXd resultant_weights(const Body& body) {
  Eigen::VectorXd w = Eigen::VectorXd::Zero(body.dofs.n_modes());
  if (body.dofs.lagrange()) return Eigen::VectorXd::Ones(body.dofs.n_modes());
  for (int v = 0; v < body.mesh.n_nodes(); ++v) w(body.dofs.vertex_mode(v)) = 1.0;
  return w;
}

std::vector<Vec2> boundary_positions(const Body& body) {
  std::vector<Vec2> X(body.dofs.n_modes(), Vec2::Zero());
  for (int v = 0; v < body.mesh.n_nodes(); ++v) X[body.dofs.vertex_mode(v)] = body.mesh.node(v);
  for (int e = 0; e < body.mesh.n_edges(); ++e) {
    const auto x = edge_mode_values(body, e, [](const Vec2& p) { return p.x(); });
    const auto y = edge_mode_values(body, e, [](const Vec2& p) { return p.y(); });
    for (size_t i = 0; i < x.size(); ++i)
      X[body.dofs.edge_mode(e, static_cast<int>(i) + 2)] = Vec2(x[i], y[i]);
  }
  return X;
}

ForceMoment force_and_moment(const Body& body, const Eigen::VectorXd& f, const Eigen::VectorXd& u_body) {
  return force_and_moment(body, resultant_weights(body), boundary_positions(body), f, u_body);
}

Eigen::VectorXd pair_contact_forces(const Discretization& d, const ContactPair& pair,
                                    const Eigen::VectorXd& u, const Eigen::VectorXd& multipliers) {
  Eigen::VectorXd fc = Eigen::VectorXd::Zero(d.n_dofs);
  if (!pair.constraints) {
    const PairForces f = pair_forces(d, pair, u, nullptr);
    fc.segment(d.bodies[pair.body].dof_offset, f.body.size()) += f.body;
    if (pair.other >= 0) fc.segment(d.bodies[pair.other].dof_offset, f.other.size()) += f.other;
    return fc;
  }
  pair_constraint_state(d, pair, u, multipliers, &fc);  // subtracts the contact forces
  return -fc;
}

Eigen::VectorXd support_forces(const Discretization& d, const std::vector<ContactPair>& pairs,
                               const Eigen::VectorXd& u,
                               const std::vector<Eigen::VectorXd>& multipliers, double loads_factor) {
  Eigen::VectorXd f_c = Eigen::VectorXd::Zero(d.n_dofs);
  for (size_t k = 0; k < pairs.size(); ++k)
    f_c += pair_contact_forces(d, pairs[k], u, k < multipliers.size() ? multipliers[k] : Eigen::VectorXd());
  // the follower loads are external forces the residual subtracts, as the contact's
  f_c += follower_forces(d, pairs, u, multipliers, loads_factor);
  return support_residual(d, u, loads_factor, f_c);
}

Reactions reactions(const Discretization& d, const std::vector<ContactPair>& pairs,
                    const Eigen::VectorXd& u, const std::vector<Eigen::VectorXd>& multipliers,
                    double loads_factor) {
  static const Eigen::VectorXd none;
  auto multipliers_of = [&](size_t k) -> const Eigen::VectorXd& {
    return k < multipliers.size() ? multipliers[k] : none;
  };
  Reactions r;
  std::vector<Eigen::VectorXd> f_c(pairs.size());
  Eigen::VectorXd f_c_all = Eigen::VectorXd::Zero(d.n_dofs);
  for (size_t k = 0; k < pairs.size(); ++k) {
    f_c[k] = pair_contact_forces(d, pairs[k], u, multipliers_of(k));
    f_c_all += f_c[k];
  }
  const Eigen::VectorXd follower = follower_forces(d, pairs, u, multipliers, loads_factor);
  const Eigen::VectorXd R = support_residual(d, u, loads_factor, f_c_all + follower);
  const int nb = static_cast<int>(d.bodies.size());
  std::vector<Eigen::VectorXd> weights(nb);
  std::vector<std::vector<Vec2>> positions(nb);
  for (int b = 0; b < nb; ++b) {
    weights[b] = resultant_weights(d.bodies[b]);
    positions[b] = boundary_positions(d.bodies[b]);
  }
  r.balance.resize(nb);
  // the largest force each body's balance involves, per component
  std::vector<Vec2> scale(nb, Vec2::Zero());
  auto involve = [&](int b, const Vec2& f) { scale[b] = scale[b].cwiseMax(f.cwiseAbs()); };
  for (int b = 0; b < nb; ++b) {
    const Body& body = d.bodies[b];
    const int n = body.dofs.n_dofs();
    const Eigen::VectorXd ub = u.segment(body.dof_offset, n);
    for (size_t c = 0; c < body.constraint_dofs.size(); ++c) {
      Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
      for (int dof : body.constraint_dofs[c]) f(dof - body.dof_offset) = R(dof);
      const ForceMoment fm = force_and_moment(body, weights[b], positions[b], f, ub);
      r.supports.push_back({b, static_cast<int>(c), fm});
      r.balance[b].reactions += fm.force;
      involve(b, fm.force);
    }
    const Eigen::VectorXd load =
        loads_factor * d.load.segment(body.dof_offset, n) + follower.segment(body.dof_offset, n);
    r.balance[b].loads = force_and_moment(body, weights[b], positions[b], load, ub).force;
    involve(b, r.balance[b].loads);
  }
  for (size_t k = 0; k < pairs.size(); ++k) {
    const ContactPair& pair = pairs[k];
    const Body& body = d.bodies[pair.body];
    const int n = body.dofs.n_dofs();
    ForceMoment fm = force_and_moment(body, weights[pair.body], positions[pair.body],
                                      f_c[k].segment(body.dof_offset, n), u.segment(body.dof_offset, n));
    // the force as the contact results report it (∫ traction ds over the contact points)
    fm.force = contact_resultant(d, pair, u, pair.constraints ? &multipliers_of(k) : nullptr);
    r.pairs.push_back(fm);
    r.balance[pair.body].contact += fm.force;
    involve(pair.body, fm.force);
    if (pair.other >= 0) {
      r.balance[pair.other].contact -= fm.force;
      involve(pair.other, fm.force);
    }
  }
  for (int b = 0; b < nb; ++b) {
    BodyBalance& bb = r.balance[b];
    bb.imbalance = bb.reactions + bb.loads + bb.contact;
    // an axisymmetric body's radial totals do not balance, but their round-off is in its axial
    // ones too: they stay in the scale
    if (d.bodies[b].axisymmetric()) bb.imbalance.x() = 0;
    const double largest = scale[b].maxCoeff();
    bb.relative = largest > 0 ? bb.imbalance.cwiseAbs().maxCoeff() / largest : 0.0;
    r.equilibrium_residual = std::max(r.equilibrium_residual, bb.relative);
  }
  return r;
}

}  // namespace hpcontact::model
