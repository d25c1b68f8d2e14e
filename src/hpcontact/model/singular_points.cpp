// Singular points of a contact zone: the ends and corners of both bodies' contact edges where the
// zone is closed, and a least-squares fit of the pressure's singularity around each.
#include "hpcontact/model/singular_points.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "hpcontact/fem/edge_load.hpp"
#include "hpcontact/model/contact_results.hpp"

namespace hpcontact::model {

namespace {

/// Where a chain of contact edges ends or turns: the vertex, and the unit tangent of one edge
/// there pointing into that edge.
struct ChainEnd {
  int node = -1;
  Vec2 X, tangent;
  bool corner = false;  ///< two contact edges meet there at an angle (else the chain ends)
  double turn_degrees = 0;
};

/// The unit tangent of mesh edge e at its vertex `node`, pointing into the edge.
Vec2 inward_tangent(const Body& body, int e, int node) {
  const auto& edge = body.mesh.edge(e);
  const int q = edge.quads[0], le = edge.local_edge[0];
  const bool first = body.mesh.quad(q)[mesh::kEdgeVertices[le][0]] == node;
  Vec2 N;
  double ds_dt = 0;
  fem::edge_geometry(body.maps[q], le, first ? -1.0 : 1.0, &N, &ds_dt);
  Vec2 t(-N.y(), N.x());
  const int other = edge.v0 == node ? edge.v1 : edge.v0;
  if (t.dot(body.mesh.nodes()[other] - body.mesh.nodes()[node]) < 0) t = -t;
  return t;
}

/// The ends of the chains of `edges` (mesh edges of `body`) and their corners, where two of
/// them meet at more than kCornerAngleDegrees (listed once per edge: each side is an end).
std::vector<ChainEnd> chain_ends(const Body& body, const std::vector<int>& edges) {
  std::vector<ChainEnd> ends;
  std::vector<std::vector<int>> at(body.mesh.n_nodes());
  for (int e : edges) {
    at[body.mesh.edge(e).v0].push_back(e);
    at[body.mesh.edge(e).v1].push_back(e);
  }
  for (int v = 0; v < body.mesh.n_nodes(); ++v) {
    if (at[v].size() == 1) {
      ends.push_back({v, body.mesh.nodes()[v], inward_tangent(body, at[v][0], v), false, 0});
    } else if (at[v].size() == 2) {
      const Vec2 a = inward_tangent(body, at[v][0], v), b = inward_tangent(body, at[v][1], v);
      const double turn = std::acos(std::clamp(-a.dot(b), -1.0, 1.0)) * 180 / std::numbers::pi;
      if (turn <= kCornerAngleDegrees) continue;
      for (const Vec2& t : {a, b}) ends.push_back({v, body.mesh.nodes()[v], t, true, turn});
    }
  }
  return ends;
}

/// Whether a chain's end lies on a mirror or the axis: its displacement along the boundary's
/// tangent there (x or y) held at zero and the other component free.
bool on_mirror(const Discretization& d, const Body& body, const ChainEnd& end) {
  int along = -1;
  if (std::abs(end.tangent.x()) > 1 - 1e-9) along = 0;
  if (std::abs(end.tangent.y()) > 1 - 1e-9) along = 1;
  if (along < 0) return false;
  const int dof = body.dof_offset + 2 * body.dofs.vertex_mode(end.node);
  const int held = dof + along, other = dof + 1 - along;
  return d.free_index[held] < 0 && d.prescribed(held) == 0 && d.free_index[other] >= 0;
}

/// How far the edges of `body` among `edges` that reach s0 along the frame extend from it on the
/// side `side` (+1: increasing s): the elements whose polynomial makes the peak.
double touching_extent(const Body& body, const std::vector<int>& edges, const ContactPair& pair,
                       double s0, int side, double tol) {
  double extent = 0;
  for (int e : edges) {
    const auto& edge = body.mesh.edge(e);
    const double a = pair.frame->coordinate(body.mesh.nodes()[edge.v0]);
    const double b = pair.frame->coordinate(body.mesh.nodes()[edge.v1]);
    if (s0 < std::min(a, b) - tol || s0 > std::max(a, b) + tol) continue;
    extent = std::max(extent, std::max((a - s0) * side, (b - s0) * side));
  }
  return extent;
}

/// The rows of the result in contact (exact: active multiplier nodes; penalty: points that
/// penetrate) with a positive pressure.
std::vector<int> rows_in_contact(const ContactPair& pair, const ContactResult& r) {
  std::vector<int> rows;
  for (size_t i = 0; i < r.states.size(); ++i) {
    const bool closed = pair.constraints ? r.nodes[i].active : r.states[i].gap < 0;
    if (closed && r.pressure[i] > 0) rows.push_back(static_cast<int>(i));
  }
  return rows;
}

/// Least squares of log p + λ₀ log d over (d, p) against 1, d, d² (λ₀ given), or with λ free
/// (λ₀ = NaN) against 1, −log d, d: the columns, d scaled by its largest for conditioning.
Eigen::VectorXd fit_log_pressure(const std::vector<std::pair<double, double>>& dp, double L, double fixed,
                                 double* rms) {
  const int n = static_cast<int>(dp.size());
  Eigen::MatrixXd A(n, 3);
  Eigen::VectorXd y(n);
  for (int i = 0; i < n; ++i) {
    const double x = dp[i].first / L;
    const double log_x = std::log(x);
    A.row(i) << 1, std::isnan(fixed) ? -log_x : x, std::isnan(fixed) ? x : x * x;
    y(i) = std::log(dp[i].second) + (std::isnan(fixed) ? 0.0 : fixed * log_x);
  }
  const Eigen::VectorXd c = A.colPivHouseholderQr().solve(y);
  *rms = std::sqrt((A * c - y).squaredNorm() / n);
  return c;
}

/// The fit of p ≈ K d^(−λ) over (d, p): λ and K free (with a correction linear in d), and K
/// with λ = 1/2; none with fewer than 6 points.
std::optional<SingularityFit> fit_singularity(const std::vector<std::pair<double, double>>& dp) {
  if (dp.size() < 6) return std::nullopt;
  SingularityFit fit;
  fit.from = std::numeric_limits<double>::infinity();
  for (const auto& [dist, p] : dp) {
    fit.from = std::min(fit.from, dist);
    fit.to = std::max(fit.to, dist);
  }
  const double L = fit.to;
  const Eigen::VectorXd c = fit_log_pressure(dp, L, std::nan(""), &fit.rms);
  fit.exponent = c(1);
  fit.strength = std::exp(c(0)) * std::pow(L, c(1));
  double rms_root = 0;
  const Eigen::VectorXd r = fit_log_pressure(dp, L, 0.5, &rms_root);
  fit.square_root_strength = std::exp(r(0)) * std::sqrt(L);
  fit.square_root_rms = rms_root;
  fit.points = static_cast<int>(dp.size());
  return fit;
}

/// The singular point at a chain end of `body` (the pair's own, or the other body's), if the
/// zone is closed there and the pressure rises towards it.
std::optional<SingularPoint> examine_end(const Discretization& d, const ContactPair& pair,
                                         const Eigen::VectorXd& u, const ContactResult& r,
                                         const Body& body, const ChainEnd& end, double tol) {
  if (!end.corner && on_mirror(d, body, end)) return std::nullopt;
  const Body& own = d.bodies[pair.body];
  const bool other = &body != &own;
  const int vertex = body.dof_offset + 2 * body.dofs.vertex_mode(end.node);
  const Vec2 x_end = end.X + Vec2(u(vertex), u(vertex + 1));  // the end deformed
  Vec2 foot_X = end.X;
  if (other) {  // the other body's corner: at the foot of its deformed position on this body
    contact::BoundaryPoint foot;
    if (!pair.boundary->project(x_end, foot)) return std::nullopt;
    foot_X = pair.boundary->undeformed(foot.edge, foot.t);
  }
  const double s0 = pair.frame->coordinate(foot_X);
  const int side = pair.frame->rate(end.X, end.tangent) >= 0 ? 1 : -1;
  const auto rows = rows_in_contact(pair, r);
  // the pair's own points on the side of the end's edge: the nearest beyond the end itself
  // (where a point exactly at the other body's corner may be either) must be in contact
  double nearest_open = std::numeric_limits<double>::infinity(), nearest_closed = nearest_open, reach = 0;
  int nearest_row = -1;
  std::vector<char> closed(r.s.size(), 0);
  for (int i : rows) closed[i] = 1;
  for (size_t i = 0; i < r.s.size(); ++i)
    if (!closed[i] && (r.s[i] - s0) * side > tol) nearest_open = std::min(nearest_open, (r.s[i] - s0) * side);
  double mean = 0;
  for (int i : rows) {
    mean += r.pressure[i] / rows.size();
    const double dist = (r.s[i] - s0) * side;
    if (dist <= -tol) continue;
    reach = std::max(reach, dist);
    if (dist < nearest_closed) {
      nearest_closed = dist;
      nearest_row = i;
    }
  }
  const double excluded = std::max(touching_extent(own, pair.edges, pair, s0, side, tol),
                                   pair.other >= 0 ? touching_extent(d.bodies[pair.other], pair.other_edges,
                                                                     pair, s0, side, tol)
                                                   : 0.0);
  // closed: in contact nearer than any open point, or within the elements touching the end
  // (whose polynomials oscillate there)
  if (nearest_row < 0 || nearest_closed > std::max(nearest_open, excluded)) return std::nullopt;
  if (other) {  // the other body's end must lie on this body's contact edges
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const double s : r.s) lo = std::min(lo, s), hi = std::max(hi, s);
    if (s0 < lo - tol || s0 > hi + tol) return std::nullopt;
  }
  SingularPoint sp;
  sp.X = end.X;
  sp.x = x_end;
  sp.s = s0;
  sp.foot = foot_X;
  sp.on_other = other;
  sp.peak = r.pressure[nearest_row];
  sp.excluded = excluded;
  sp.pressure_max_beyond = std::max(excluded, kPressureMaxDistance * reach);
  std::vector<std::pair<double, double>> dp;
  for (int i : rows) {
    const double dist = (r.s[i] - s0) * side;
    if (dist >= sp.excluded * (1 + 1e-6) + tol && dist <= 0.25 * reach) dp.push_back({dist, r.pressure[i]});
  }
  sp.fit = fit_singularity(dp);
  const bool rising = sp.fit ? sp.fit->exponent > 0.05 : sp.peak > 1.5 * mean;
  if (!rising) return std::nullopt;
  std::ostringstream where;
  where << (end.corner ? "a corner of body '" : "the end of the contact edges of body '") << body.name
        << "' (node " << body.mesh.node_id(end.node);
  if (end.corner) where << ", where they turn by " << std::lround(end.turn_degrees) << "°";
  where << ")";
  sp.where = where.str();
  return sp;
}

}  // namespace

std::vector<SingularPoint> singular_points(const Discretization& d, const ContactPair& pair,
                                           const Eigen::VectorXd& u, const ContactResult& result) {
  std::vector<SingularPoint> points;
  if (result.s.empty()) return points;
  const Body& body = d.bodies[pair.body];
  if (pair.other >= 0) {  // the other body's corners are projected onto this body deformed
    const Body& other = d.bodies[pair.other];
    pair.boundary->set_displacement(u.segment(body.dof_offset, body.dofs.n_dofs()));
    pair.other_boundary->set_displacement(u.segment(other.dof_offset, other.dofs.n_dofs()));
  }
  const double tol = 1e-9 * body.mesh.size();
  auto examine = [&](const Body& b, const std::vector<int>& edges) {
    for (const ChainEnd& end : chain_ends(b, edges)) {
      auto sp = examine_end(d, pair, u, result, b, end, tol);
      if (!sp) continue;
      // one point seen from both bodies (a corner on the other body's end): reported once
      const bool seen = std::any_of(points.begin(), points.end(), [&](const SingularPoint& p) {
        return std::abs(p.s - sp->s) <= std::max({1e3 * tol, p.excluded, sp->excluded});
      });
      if (!seen) points.push_back(std::move(*sp));
    }
  };
  examine(body, pair.edges);
  if (pair.other >= 0) examine(d.bodies[pair.other], pair.other_edges);
  std::sort(points.begin(), points.end(), [](const auto& a, const auto& b) { return a.s < b.s; });
  return points;
}

double pressure_max_away(const ContactResult& result, const std::vector<SingularPoint>& points) {
  double largest = 0;
  for (size_t i = 0; i < result.pressure.size(); ++i) {
    const bool near = std::any_of(points.begin(), points.end(), [&](const SingularPoint& p) {
      return std::abs(result.s[i] - p.s) < p.pressure_max_beyond * (1 + 1e-6);
    });
    if (!near) largest = std::max(largest, result.pressure[i]);
  }
  return largest;
}

}  // namespace hpcontact::model
