// Closest-point projection onto a deformed high-order boundary: each edge's distance function
// is sampled to bracket its minima, which are then refined by the Pegasus method.
#include "hpcontact/contact/deformable_boundary.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

#include "hpcontact/core/error.hpp"
#include "hpcontact/core/roots.hpp"
#include "hpcontact/fem/edge_load.hpp"

namespace hpcontact::contact {

namespace {
constexpr int kSamples = 16;  ///< sub-intervals per edge when bracketing minima of the distance
}

DeformableBoundary::DeformableBoundary(const mesh::Mesh& mesh, const fem::DofMap& dofs,
                                       const std::vector<mesh::ElementMap>& maps,
                                       const std::vector<int>& edges)
    : mesh_(mesh), dofs_(dofs), maps_(maps), u_(Eigen::VectorXd::Zero(dofs.n_dofs())) {
  for (int e : edges) {
    const auto& edge = mesh.edge(e);
    HPC_REQUIRE(edge.on_boundary(), InputError, mesh.context(), ": contact edge ",
                mesh.node_id(edge.v0), "-", mesh.node_id(edge.v1), " is not on the boundary");
    Edge be{edge.quads[0], edge.local_edge[0], {}};
    const auto& es = dofs.element(be.element);
    Eigen::VectorXd N(es.n_modes());
    const auto r = fem::edge_reference_point(be.local_edge, 0.123456789);
    es.evaluate(r[0], r[1], N.data(), nullptr, nullptr);
    for (int a = 0; a < es.n_modes(); ++a)
      if (N(a) != 0.0) be.local.push_back(a);
    edges_.push_back(std::move(be));
  }
  // Which edge ends lie on a vertex shared with another edge of the boundary: a foot there is a
  // real closest point (between two edges); at a free end of the boundary it is not.
  std::vector<std::array<int, 2>> end_vertex;
  for (const Edge& be : edges_) {
    const auto& edge = mesh.edge(mesh.quad_edge(be.element, be.local_edge));
    std::array<int, 2> v{};
    for (int end = 0; end < 2; ++end) {
      const auto r = fem::edge_reference_point(be.local_edge, end == 0 ? -1.0 : 1.0);
      const Vec2 p = maps[be.element].map(r[0], r[1]);
      v[end] = (mesh.node(edge.v0) - p).norm() < (mesh.node(edge.v1) - p).norm() ? edge.v0 : edge.v1;
    }
    end_vertex.push_back(v);
  }
  for (size_t k = 0; k < edges_.size(); ++k)
    for (int end = 0; end < 2; ++end)
      for (size_t j = 0; j < edges_.size(); ++j)
        for (int other = 0; other < 2; ++other)
          if (j != k && end_vertex[j][other] == end_vertex[k][end]) {
            edges_[k].shared_end[end] = true;
            edges_[k].neighbour[end] = {static_cast<int>(j), other};
          }
}

const DeformableBoundary::Sample* DeformableBoundary::samples_of(int k) const {
  if (!sampled_) {
    samples_.resize(edges_.size() * (kSamples + 1));
    BoundaryPoint bp;
    for (size_t e = 0; e < edges_.size(); ++e)
      for (int i = 0; i <= kSamples; ++i) {
        evaluate(static_cast<int>(e), -1 + 2.0 * i / kSamples, bp);
        samples_[e * (kSamples + 1) + i] = {bp.x, bp.dx_dt};
      }
    sampled_ = true;
  }
  return &samples_[k * (kSamples + 1)];
}

Vec2 DeformableBoundary::tangent_at(int k, double t) const {
  BoundaryPoint bp;
  evaluate(k, t, bp);
  return bp.dx_dt;
}

void DeformableBoundary::evaluate(int k, double t, BoundaryPoint& bp) const {
  const Edge& e = edges_[k];
  const auto& es = dofs_.element(e.element);
  const int n = es.n_modes();
  Eigen::VectorXd &N = N_, &dxi = dxi_, &deta = deta_;  // scratch: no allocation per call
  N.resize(n);
  dxi.resize(n);
  deta.resize(n);
  const auto r = fem::edge_reference_point(e.local_edge, t);
  es.evaluate(r[0], r[1], N.data(), dxi.data(), deta.data());
  Mat2 J;
  const Vec2 X = maps_[e.element].map(r[0], r[1], &J);
  const bool along_xi = e.local_edge % 2 == 0;
  bp.edge = k;
  bp.t = t;
  bp.x = X;
  bp.dx_dt = along_xi ? Vec2(J.col(0)) : Vec2(J.col(1));
  const int m = static_cast<int>(e.local.size());
  bp.modes.resize(m);
  bp.N.resize(m);
  bp.dN.resize(m);
  for (int i = 0; i < m; ++i) {
    const int a = e.local[i];
    const int mode = es.modes[a];
    bp.modes[i] = mode;
    bp.N(i) = N(a);
    bp.dN(i) = along_xi ? dxi(a) : deta(a);
    const Vec2 uk(u_(2 * mode), u_(2 * mode + 1));
    bp.x += bp.N(i) * uk;
    bp.dx_dt += bp.dN(i) * uk;
  }
  // E1, E2 run counter-clockwise around the element, E3, E4 clockwise (see fem::edge_geometry).
  const Vec2 T = bp.dx_dt;
  bp.normal = (e.local_edge < 2 ? Vec2(T.y(), -T.x()) : Vec2(-T.y(), T.x())).normalized();
}

Vec2 DeformableBoundary::undeformed(int k, double t) const {
  const Edge& e = edges_[k];
  return fem::edge_geometry(maps_[e.element], e.local_edge, t, nullptr, nullptr);
}

double DeformableBoundary::stretch(int k, double t) const {
  const Edge& e = edges_[k];
  double dS_dt = 0;
  fem::edge_geometry(maps_[e.element], e.local_edge, t, nullptr, &dS_dt);
  return tangent_at(k, t).norm() / dS_dt;
}

std::vector<DeformableBoundary::Vertex> DeformableBoundary::vertices() const {
  std::vector<Vertex> out;
  std::vector<int> count;
  BoundaryPoint bp;
  for (int k = 0; k < n_edges(); ++k)
    for (double t : {-1.0, 1.0}) {
      evaluate(k, t, bp);
      // an edge's tangent points along its parameter; the vertex's mean tangent follows the
      // first edge that has it
      const Vec2 tau = bp.dx_dt.normalized();
      const double tol = 1e-12 * (1 + bp.x.norm());
      size_t v = 0;
      while (v < out.size() && (out[v].x - bp.x).norm() > tol) ++v;
      if (v == out.size()) {
        out.push_back({bp.x, tau});
        count.push_back(1);
      } else {
        out[v].tangent += tau.dot(out[v].tangent) >= 0 ? tau : Vec2(-tau);
        ++count[v];
      }
    }
  for (auto& v : out) v.tangent.normalize();
  return out;
}

std::vector<double> DeformableBoundary::segments(int k, const DeformableBoundary& master) const {
  std::vector<double> ends{-1.0, 1.0};
  BoundaryPoint bp;
  const Sample* s = samples_of(k);
  const double length = (s[kSamples].x - s[0].x).norm();
  for (const Vertex& v : master.vertices()) {
    // f(t) = (x(t) − x_v)·τ_v changes sign where the edge passes the normal through the vertex
    auto f = [&](double t) {
      evaluate(k, t, bp);
      return (bp.x - v.x).dot(v.tangent);
    };
    double ta = -1, fa = (s[0].x - v.x).dot(v.tangent);
    for (int i = 1; i <= kSamples; ++i) {
      const double tb = -1 + 2.0 * i / kSamples, fb = (s[i].x - v.x).dot(v.tangent);
      if ((fa < 0) != (fb < 0)) {
        const double t = pegasus_root(f, ta, tb, fa, fb, 1e-15);
        evaluate(k, t, bp);
        // only a vertex near the edge: one across the body would project elsewhere
        if (t > -1 && t < 1 && (bp.x - v.x).norm() < 0.5 * length) ends.push_back(t);
      }
      ta = tb;
      fa = fb;
    }
  }
  std::sort(ends.begin(), ends.end());
  // segments shorter than round-off would carry no quadrature weight
  std::vector<double> out{ends.front()};
  for (size_t i = 1; i < ends.size(); ++i)
    if (ends[i] - out.back() > 1e-12) out.push_back(ends[i]);
  if (out.back() < 1.0) out.back() = 1.0;
  return out;
}

double DeformableBoundary::curvature(const BoundaryPoint& foot) const {
  // central differences of the exact tangent (step 1e-4: error ~1e-8 relative)
  const double h = 1e-4;
  const Vec2 d2x = (tangent_at(foot.edge, foot.t + h) - tangent_at(foot.edge, foot.t - h)) / (2 * h);
  return foot.normal.dot(d2x);
}

bool DeformableBoundary::project(const Vec2& x, BoundaryPoint& foot) const {
  double best = std::numeric_limits<double>::infinity();
  bool found = false;
  BoundaryPoint bp;
  // f(t) = (x − x_m(t))·dx_m/dt = −½ d|x − x_m|²/dt: a minimum of the distance where f falls
  // through zero.
  auto f = [&](int k, double t) {
    evaluate(k, t, bp);
    return (x - bp.x).dot(bp.dx_dt);
  };
  auto consider = [&](int k, double t) {
    evaluate(k, t, bp);
    const double dist = (x - bp.x).norm();
    if (dist < best) {
      best = dist;
      foot = bp;
      found = true;
    }
  };
  auto shared_vertex = [&](int k, double end) { return edges_[k].shared_end[end > 0 ? 1 : 0]; };
  // x lies beyond end `end` (0: t = −1, 1: t = +1) of edge k: the distance falls towards it.
  auto beyond = [&](int k, int end) {
    const Sample& at = samples_of(k)[end == 0 ? 0 : kSamples];
    const double f_end = (x - at.x).dot(at.dx_dt);
    return end == 0 ? f_end < 0 : f_end > 0;
  };
  // A shared vertex is a foot where x lies beyond the ends of both edges that meet there (the
  // distance has its minimum at the corner): beyond this edge's end alone, x may lie beyond the
  // other edge's far end too, past a free end of the boundary, where it has no foot at all.
  auto corner_foot = [&](int k, double end) {
    const int e = end > 0 ? 1 : 0;
    const auto [j, other] = edges_[k].neighbour[e];
    return edges_[k].shared_end[e] && j >= 0 && beyond(j, other);
  };
  // A point level with a free end of the boundary (to round-off of the edge's size) has its
  // foot there: a node of the other body over the end of a matching boundary.
  auto level_with_free_end = [&](int k, double end, double f_end, const Sample& at) {
    return !shared_vertex(k, end) && std::abs(f_end) <= 1e-10 * at.dx_dt.squaredNorm();
  };
  for (int k = 0; k < static_cast<int>(edges_.size()); ++k) {
    const Sample* s = samples_of(k);
    auto f_sample = [&](int i) { return (x - s[i].x).dot(s[i].dx_dt); };
    double ta = -1, fa = f_sample(0);
    if ((fa < 0 && corner_foot(k, -1)) || level_with_free_end(k, -1, fa, s[0])) consider(k, -1);
    for (int i = 1; i <= kSamples; ++i) {
      const double tb = -1 + 2.0 * i / kSamples, fb = f_sample(i);
      if (fa > 0 && fb <= 0) {
        const double t = pegasus_root([&](double r) { return f(k, r); }, ta, tb, fa, fb,
                                      1e-15 * (1 + s[i].dx_dt.squaredNorm()));
        if (std::abs(t) < 1 || shared_vertex(k, t)) consider(k, t);
      }
      ta = tb;
      fa = fb;
    }
    if ((fa > 0 && corner_foot(k, 1)) || level_with_free_end(k, 1, fa, s[kSamples])) consider(k, 1);
  }
  return found;
}

bool DeformableBoundary::free_end(const Vec2& x, BoundaryPoint& end) const {
  double best = std::numeric_limits<double>::infinity();
  BoundaryPoint bp;
  for (int k = 0; k < static_cast<int>(edges_.size()); ++k)
    for (int e = 0; e < 2; ++e) {
      if (edges_[k].shared_end[e]) continue;
      evaluate(k, e == 0 ? -1.0 : 1.0, bp);
      if (const double d = (x - bp.x).norm(); d < best) {
        best = d;
        end = bp;
      }
    }
  return best < std::numeric_limits<double>::infinity();
}

double DeformableBoundary::gap(const Vec2& x, Vec2* normal, Mat2* dnormal_dx) const {
  if (dnormal_dx) dnormal_dx->setZero();
  BoundaryPoint foot;
  if (!project(x, foot)) {
    if (normal) *normal = Vec2(0, 1);
    return std::numeric_limits<double>::infinity();
  }
  if (normal) *normal = foot.normal;
  return (x - foot.x).dot(foot.normal);
}

std::string DeformableBoundary::describe() const {
  std::ostringstream os;
  os << "the deformable boundary of " << edges_.size() << " edges of " << mesh_.context();
  return os.str();
}

}  // namespace hpcontact::contact
