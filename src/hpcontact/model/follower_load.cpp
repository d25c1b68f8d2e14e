// The wetted part of a follower load's edges and its forces on the deformed boundary.
#include "hpcontact/model/follower_load.hpp"

#include <algorithm>
#include <cmath>

#include "hpcontact/basis/quadrature.hpp"
#include "hpcontact/fem/edge_load.hpp"
#include "hpcontact/model/discretization.hpp"

namespace hpcontact::model {

namespace {

/// Chain position of local parameter t on chain edge k: s = k + the fraction of the edge passed
/// in the chain's direction.
double chain_position(const FollowerEdge& e, int k, double t) {
  return k + (e.against ? 0.5 * (1 - t) : 0.5 * (1 + t));
}

/// Local parameter of chain position s on chain edge k (s clamped to the edge).
double edge_parameter(const FollowerEdge& e, int k, double s) {
  const double fraction = std::clamp(s - k, 0.0, 1.0);
  return e.against ? 1 - 2 * fraction : 2 * fraction - 1;
}

/// The pieces of chain edge k inside the range, as local parameter intervals between its breaks.
std::vector<std::pair<double, double>> wet_pieces(const FollowerEdge& e, int k, const WetRange& range) {
  double lo = edge_parameter(e, k, range.from), hi = edge_parameter(e, k, range.to);
  if (lo > hi) std::swap(lo, hi);
  std::vector<std::pair<double, double>> pieces;
  for (size_t i = 0; i + 1 < e.breaks.size(); ++i) {
    const double t0 = std::max(e.breaks[i], lo), t1 = std::min(e.breaks[i + 1], hi);
    if (t1 - t0 > 1e-14) pieces.emplace_back(t0, t1);
  }
  return pieces;
}

}  // namespace

WetRange wetted_range(const FollowerLoad& L, const std::vector<ContactMark>& marks, double loads_factor) {
  const double n = static_cast<double>(L.edges.size());
  WetRange range{0, n, false};
  if (!L.penetration) return range;
  // the first point in contact from the pressurised end: the least chain position from the
  // start, the largest from the end
  bool found = false;
  double stop = L.penetration->from_end ? 0.0 : n;
  for (const auto& mark : marks) {
    if (mark.body != L.body || !(mark.pressure > 0) ||
        mark.pressure <= loads_factor * std::abs(L.pressure(mark.X)))
      continue;
    for (size_t k = 0; k < L.edges.size(); ++k) {
      if (L.edges[k].mesh_edge != mark.mesh_edge) continue;
      const double s = chain_position(L.edges[k], static_cast<int>(k), mark.t);
      stop = L.penetration->from_end ? std::max(stop, s) : std::min(stop, s);
      found = true;
    }
  }
  range.leaks = !found;
  if (L.penetration->from_end) range.from = stop;
  else range.to = stop;
  return range;
}

void add_follower_force(const Discretization& d, const FollowerLoad& L, const Eigen::VectorXd& u,
                        const WetRange& range, double factor, Eigen::VectorXd& f,
                        std::vector<Eigen::Triplet<double>>* t) {
  const Body& body = d.bodies[L.body];
  for (size_t k = 0; k < L.edges.size(); ++k) {
    const FollowerEdge& e = L.edges[k];
    const Eigen::VectorXd ue = L.dead ? Eigen::VectorXd::Zero(2 * body.dofs.element(e.q).n_modes())
                                      : body.element_coefficients(e.q, u);
    const int n2 = 2 * body.dofs.element(e.q).n_modes();
    for (const auto& [t0, t1] : wet_pieces(e, static_cast<int>(k), range)) {
      const fem::FollowerForce F =
          fem::follower_pressure(body.dofs.element(e.q), body.maps[e.q], e.le, t0, t1,
                                 body.n_gauss[e.q] + 8, body.out_of_plane(), ue, L.pressure, t != nullptr && !L.dead);
      for (int a = 0; a < n2; ++a) f(body.global_dof(e.q, a)) += factor * F.f(a);
      if (!t || L.dead) continue;
      for (int a = 0; a < n2; ++a)
        for (int b = 0; b < n2; ++b)
          if (F.K(a, b) != 0.0)
            t->emplace_back(body.global_dof(e.q, a), body.global_dof(e.q, b), factor * F.K(a, b));
    }
  }
}

WetExtent wetted_extent(const Discretization& d, const FollowerLoad& L, const WetRange& range) {
  const Body& body = d.bodies[L.body];
  WetExtent out;
  const double stop = L.penetration && L.penetration->from_end ? range.from : range.to;
  const int k_stop = std::clamp(static_cast<int>(std::floor(stop)), 0, static_cast<int>(L.edges.size()) - 1);
  if (!L.edges.empty()) {
    const FollowerEdge& e = L.edges[k_stop];
    out.stop = fem::edge_geometry(body.maps[e.q], e.le, edge_parameter(e, k_stop, stop), nullptr, nullptr);
  }
  for (size_t k = 0; k < L.edges.size(); ++k) {
    const FollowerEdge& e = L.edges[k];
    double lo = edge_parameter(e, static_cast<int>(k), range.from), hi = edge_parameter(e, static_cast<int>(k), range.to);
    if (lo > hi) std::swap(lo, hi);
    if (hi - lo <= 0) continue;
    const auto& rule = basis::gauss_legendre(body.n_gauss[e.q] + 8);
    for (int i = 0; i < rule.size(); ++i) {
      double ds;
      fem::edge_geometry(body.maps[e.q], e.le, 0.5 * (lo + hi) + 0.5 * (hi - lo) * rule.points[i], nullptr, &ds);
      out.length += 0.5 * (hi - lo) * rule.weights[i] * ds;
    }
  }
  return out;
}

}  // namespace hpcontact::model
