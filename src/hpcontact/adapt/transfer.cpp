// Warm starts of adaptive solves: the previous solution interpolated at the new mesh's vertices
// and multiplier nodes.
#include "hpcontact/adapt/transfer.hpp"

#include <algorithm>
#include <limits>
#include <memory>

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

/// Whether `to` has the meshes of `from` and element spaces that contain its spaces (the hierarchic
/// modes of each element of `from` among those of `to`: the estimate's solve one degree higher).
bool nested(const model::Discretization& from, const model::Discretization& to) {
  if (from.bodies.size() != to.bodies.size()) return false;
  for (size_t k = 0; k < from.bodies.size(); ++k) {
    const auto &a = from.bodies[k], &b = to.bodies[k];
    if (a.mesh.n_nodes() != b.mesh.n_nodes() || a.mesh.n_quads() != b.mesh.n_quads()) return false;
    for (int v = 0; v < a.mesh.n_nodes(); ++v)
      if (a.mesh.node(v) != b.mesh.node(v)) return false;
    for (int q = 0; q < a.mesh.n_quads(); ++q) {
      const auto &sa = a.dofs.element(q), &sb = b.dofs.element(q);
      if (a.mesh.quad(q) != b.mesh.quad(q) || sa.is_lagrange || sb.is_lagrange ||
          sa.hierarchic.space != sb.hierarchic.space)
        return false;
      const auto in_b = sb.hierarchic.mode_indices();
      for (const auto& ij : sa.hierarchic.mode_indices())
        if (std::find(in_b.begin(), in_b.end(), ij) == in_b.end()) return false;
    }
  }
  return true;
}

/// u of `from` as the same field over the dofs of `to` (nested(from, to)): each mode's
/// coefficients where `to` has the same mode, the modes `to` adds zero.
Eigen::VectorXd embed(const model::Discretization& from, const Eigen::VectorXd& u,
                      const model::Discretization& to) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(to.n_dofs);
  for (size_t k = 0; k < from.bodies.size(); ++k) {
    const auto &a = from.bodies[k], &b = to.bodies[k];
    for (int q = 0; q < a.mesh.n_quads(); ++q) {
      const auto ia = a.dofs.element(q).hierarchic.mode_indices();
      const auto ib = b.dofs.element(q).hierarchic.mode_indices();
      const int na = static_cast<int>(ia.size()), nb = static_cast<int>(ib.size());
      for (int m = 0; m < na; ++m) {
        const int n = static_cast<int>(std::find(ib.begin(), ib.end(), ia[m]) - ib.begin());
        for (int c = 0; c < 2; ++c) out(b.global_dof(q, n + c * nb)) = u(a.global_dof(q, m + c * na));
      }
    }
  }
  return out;
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

/// A nodal field at X given its values at the points `at` (in order along a boundary),
/// interpolated linearly between the two points nearest to X along it (the nearest and the
/// nearer of its neighbours).
double value_along(const std::vector<Vec2>& at, const Eigen::Ref<const Eigen::VectorXd>& values, const Vec2& X) {
  if (at.empty()) return 0;
  size_t best = 0;
  for (size_t j = 1; j < at.size(); ++j)
    if ((at[j] - X).norm() < (at[best] - X).norm()) best = j;
  size_t other = best;
  double d_other = std::numeric_limits<double>::infinity();
  for (size_t j : {best - 1, best + 1})
    if (j < at.size() && (at[j] - X).norm() < d_other) {
      other = j;
      d_other = (at[j] - X).norm();
    }
  if (other == best) return values(best);
  const Vec2 a = at[best], b = at[other];
  const double s = std::clamp((X - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
  return (1 - s) * values(best) + s * values(other);
}

template <class Node>
std::vector<Vec2> positions(const std::vector<Node>& nodes) {
  std::vector<Vec2> X;
  for (const auto& n : nodes) X.push_back(n.X);
  return X;
}

/// Each exact pair's multipliers of `from` (normal, then with friction tangential, per node) at
/// the nodes of `to_pairs`: on the same edges' polynomials when the meshes are the same
/// (`nested`), else interpolated along the old nodes. A pair whose layout differs is left empty.
std::vector<Eigen::VectorXd> carried_multipliers(const std::vector<model::ContactPair>& from_pairs,
                                                 const std::vector<Eigen::VectorXd>& from,
                                                 const std::vector<model::ContactPair>& to_pairs,
                                                 bool nested_meshes) {
  std::vector<Eigen::VectorXd> out(to_pairs.size());
  for (size_t k = 0; k < to_pairs.size() && k < from_pairs.size() && k < from.size(); ++k) {
    const auto& c = to_pairs[k].constraints;
    const auto& old = from_pairs[k].constraints;
    if (!c || !old || c->has_friction() != old->has_friction()) continue;
    const int blocks = c->has_friction() ? 2 : 1, n_old = old->size(), n = c->size();
    if (from[k].size() != blocks * n_old) continue;
    const std::vector<Vec2> old_X = positions(old->nodes.nodes);
    Eigen::VectorXd l(blocks * n);
    for (int b = 0; b < blocks; ++b) {
      const auto values = from[k].segment(b * n_old, n_old);
      for (int j = 0; j < n; ++j)
        l(b * n + j) = nested_meshes ? old->nodes.interpolate(c->nodes.nodes[j].edge, c->nodes.nodes[j].t, values)
                                     : value_along(old_X, values, c->nodes.nodes[j].X);
    }
    out[k] = l;
  }
  return out;
}

/// u of `from_d` on the vertices of `to` (vertex modes; edge and internal modes zero).
Eigen::VectorXd vertex_displacements(const model::Discretization& from_d, const post::PointLocator& locate,
                                     const Eigen::VectorXd& u, const model::Discretization& to) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(to.n_dofs);
  for (size_t k = 0; k < to.bodies.size() && k < from_d.bodies.size(); ++k) {
    const model::Body& b = to.bodies[k];
    for (int v = 0; v < b.mesh.n_nodes(); ++v) {
      const int mode = b.dofs.vertex_mode(v);
      if (mode < 0) continue;
      const Vec2 uv = displacement_at(from_d, locate, u, static_cast<int>(k), b.mesh.node(v));
      out(b.dof_offset + 2 * mode) = uv.x();
      out(b.dof_offset + 2 * mode + 1) = uv.y();
    }
  }
  return out;
}

/// The load steps' states of a frictional solve carried onto `to` (StartState::path).
std::vector<model::NonlinearSolution::StepState> carried_path(const model::Discretization& from_d,
                                                              const model::NonlinearSolution& from,
                                                              const model::Discretization& to,
                                                              const std::vector<model::ContactPair>& to_pairs) {
  std::vector<model::NonlinearSolution::StepState> path;
  if (from.step_states.empty()) return path;
  const bool same = same_numbering(from_d, to), in = !same && nested(from_d, to);
  std::unique_ptr<post::PointLocator> locate;
  if (!same && !in) locate = std::make_unique<post::PointLocator>(from_d);
  for (const auto& st : from.step_states) {
    model::NonlinearSolution::StepState carried{st.segment, st.s, st.factor, {}, {}};
    if (same) {
      carried.u = st.u;
      carried.multipliers = st.multipliers;
    } else {
      carried.u = in ? embed(from_d, st.u, to) : vertex_displacements(from_d, *locate, st.u, to);
      carried.multipliers = carried_multipliers(from.pairs, st.multipliers, to_pairs, in);
    }
    path.push_back(std::move(carried));
  }
  return path;
}

}  // namespace

model::StartState carry_over(const model::Discretization& from_d,
                             const model::NonlinearSolution& from, const model::Discretization& to,
                             const std::vector<model::ContactPair>& to_pairs) {
  model::StartState start;
  start.factor = from.load_factor;
  start.path = carried_path(from_d, from, to, to_pairs);
  if (same_numbering(from_d, to)) {
    start.u = from.u;
    start.multipliers = from.multipliers;
    return start;
  }
  // The final state without friction (a frictional solve follows its path: StartState::path).
  if (nested(from_d, to)) {
    // The same meshes with higher degrees: the same field, and each exact pair's multiplier
    // (a polynomial on each contact edge) at the new nodes of the same edges.
    start.u = embed(from_d, from.u, to);
    start.multipliers = carried_multipliers(from.pairs, from.multipliers, to_pairs, true);
  } else {
    const post::PointLocator locate(from_d);
    start.u = vertex_displacements(from_d, locate, from.u, to);
    start.multipliers.resize(to_pairs.size());
    for (size_t k = 0; k < to_pairs.size() && k < from.contact.size(); ++k) {
      const auto& c = to_pairs[k].constraints;
      if (!c) continue;
      const auto& nodes = from.contact[k].nodes;
      const std::vector<Vec2> old_X = positions(nodes);
      Eigen::VectorXd pressures(nodes.size());
      for (size_t j = 0; j < nodes.size(); ++j) pressures(j) = nodes[j].pressure;
      Eigen::VectorXd lambda(c->size());
      for (int j = 0; j < c->size(); ++j) lambda(j) = value_along(old_X, pressures, c->nodes.nodes[j].X);
      start.multipliers[k] = lambda;
    }
  }
  for (size_t k = 0; k < to_pairs.size() && k < start.multipliers.size(); ++k)
    if (to_pairs[k].constraints && to_pairs[k].constraints->has_friction()) start.multipliers[k] = {};
  return start;
}

}  // namespace hpcontact::adapt
