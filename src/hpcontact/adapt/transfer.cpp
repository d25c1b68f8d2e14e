// Warm starts of adaptive solves: the previous solution interpolated at the new mesh's vertices
// and multiplier nodes.
#include "hpcontact/adapt/transfer.hpp"

#include <algorithm>
#include <limits>

#include "hpcontact/post/point_location.hpp"

namespace hpcontact::adapt {

namespace {

/// Whether two discretisations number their dofs alike: the same bodies, nodes, elements, modes.
bool same_numbering(const model::Discretization& a, const model::Discretization& b) {
  if (a.n_dofs != b.n_dofs || a.bodies.size() != b.bodies.size()) return false;
  for (size_t k = 0; k < a.bodies.size(); ++k) {
    const auto &ma = a.bodies[k].mesh, &mb = b.bodies[k].mesh;
    if (ma.n_nodes() != mb.n_nodes() || ma.n_quads() != mb.n_quads() ||
        a.bodies[k].dofs.n_modes() != b.bodies[k].dofs.n_modes())
      return false;
    for (int q = 0; q < ma.n_quads(); ++q)
      if (ma.quad(q) != mb.quad(q)) return false;
  }
  return true;
}

/// The displacement of a solution at an undeformed point of body `body`, zero outside it.
Vec2 displacement_at(const model::Discretization& d, const post::PointLocator& locate,
                     const Eigen::VectorXd& u, int body, const Vec2& X) {
  const auto at = locate.locate(X, body);
  if (!at) return Vec2::Zero();
  const model::Body& b = d.bodies[at->body];
  const auto& es = b.dofs.element(at->element);
  Eigen::VectorXd N(es.n_modes());
  es.evaluate(at->xi, at->eta, N.data(), nullptr, nullptr);
  Vec2 v = Vec2::Zero();
  for (int a = 0; a < es.n_modes(); ++a) {
    const int dof = b.dof_offset + 2 * es.modes[a];
    v += N(a) * Vec2(u(dof), u(dof + 1));
  }
  return v;
}

/// The pressure of the old pair at X, interpolated linearly between its two nodes nearest to X
/// along the boundary (the nearest node and the nearer of its neighbours).
double pressure_at(const model::ContactResult& old, const Vec2& X) {
  const auto& nodes = old.nodes;
  if (nodes.empty()) return 0;
  size_t best = 0;
  for (size_t j = 1; j < nodes.size(); ++j)
    if ((nodes[j].X - X).norm() < (nodes[best].X - X).norm()) best = j;
  size_t other = best;
  double d_other = std::numeric_limits<double>::infinity();
  for (size_t j : {best - 1, best + 1})
    if (j < nodes.size() && (nodes[j].X - X).norm() < d_other) {
      other = j;
      d_other = (nodes[j].X - X).norm();
    }
  if (other == best) return nodes[best].pressure;
  const Vec2 a = nodes[best].X, b = nodes[other].X;
  const double s = std::clamp((X - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
  return (1 - s) * nodes[best].pressure + s * nodes[other].pressure;
}

}  // namespace

model::StartState carry_over(const model::Discretization& from_d,
                             const model::NonlinearSolution& from, const model::Discretization& to,
                             const std::vector<model::ContactPair>& to_pairs) {
  model::StartState start;
  start.factor = from.load_factor;
  if (same_numbering(from_d, to)) {
    start.u = from.u;
    start.multipliers = from.multipliers;
    return start;
  }
  const post::PointLocator locate(from_d);
  start.u = Eigen::VectorXd::Zero(to.n_dofs);
  for (size_t k = 0; k < to.bodies.size() && k < from_d.bodies.size(); ++k) {
    const model::Body& b = to.bodies[k];
    for (int v = 0; v < b.mesh.n_nodes(); ++v) {
      const int mode = b.dofs.vertex_mode(v);
      if (mode < 0) continue;
      const Vec2 uv = displacement_at(from_d, locate, from.u, static_cast<int>(k), b.mesh.node(v));
      start.u(b.dof_offset + 2 * mode) = uv.x();
      start.u(b.dof_offset + 2 * mode + 1) = uv.y();
    }
  }
  start.multipliers.resize(to_pairs.size());
  for (size_t k = 0; k < to_pairs.size() && k < from.contact.size(); ++k) {
    const auto& c = to_pairs[k].constraints;
    if (!c || c->has_friction()) continue;
    Eigen::VectorXd lambda(c->size());
    for (int j = 0; j < c->size(); ++j) lambda(j) = pressure_at(from.contact[k], c->nodes.nodes[j].X);
    start.multipliers[k] = lambda;
  }
  return start;
}

}  // namespace hpcontact::adapt
