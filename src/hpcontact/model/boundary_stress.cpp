// What a body's stresses say at a point of its contact boundary: −n·σ·n and the tractions along
// the obstacle's normal and tangent, per unit length along a surface frame.
#include "hpcontact/model/boundary_stress.hpp"

#include <algorithm>
#include <cmath>

#include "hpcontact/contact/friction.hpp"
#include "hpcontact/fem/edge_load.hpp"
#include "hpcontact/fem/element_values.hpp"
#include "hpcontact/fem/finite_strain.hpp"
#include "hpcontact/model/body_stress.hpp"
#include "hpcontact/model/finite_strain_body.hpp"
#include "hpcontact/model/boundary_point.hpp"

namespace hpcontact::model {

namespace {

/// The direction n_o the contact force acts along at the deformed point x of a boundary point
/// with undeformed outward normal N (shape values pv, element coefficients ue): the obstacle's
/// normal there, −N where the point has no foot.
Vec2 contact_force_normal(const ContactPair& pair, const contact::Obstacle& obstacle, const Vec2& x,
                          const Vec2& N, const fem::PointValues& pv, const Eigen::VectorXd& ue) {
  Vec2 n_o = -N;
  Vec2 normal = Vec2::Zero();
  if (std::isfinite(obstacle.gap(x, &normal, nullptr)) && normal.norm() > 0) {
    n_o = normal;
    if (pair.constraints && pair.constraints->mean_normal) {
      // the direction the pair's pressure acts along: the mean of the other boundary's normal
      // and this one's deformed normal F⁻ᵀN (F = I + ∇u, in the linear theory too)
      const Mat2 F = fem::deformation_gradient(pv, ue);
      const Vec2 mean = n_o - Vec2(F.inverse().transpose() * N).normalized();
      if (mean.norm() > 1e-8) n_o = mean.normalized();
    }
  }
  return n_o;
}

}  // namespace

SideValues side_values(const Body& body, const ContactPair& pair, const contact::Obstacle& obstacle,
                       const contact::SurfaceFrame& frame, int q, int le, double t,
                       const Eigen::VectorXd& u) {
  Vec2 N;
  double dS_dt = 0;
  const Vec2 X = fem::edge_geometry(body.maps[q], le, t, &N, &dS_dt);
  const auto r = fem::edge_reference_point(le, t);
  const auto pv = fem::point_values(body.dofs.element(q), body.maps[q], r[0], r[1]);
  const Eigen::VectorXd ue = body.element_coefficients(q, u);
  const auto ps = point_stress(body, q, pv, ue, body.mixed ? mixed_pressure(body, q, r[0], r[1], u) : 0.0);
  Mat2 sigma;
  sigma << ps.stress(0), ps.stress(2), ps.stress(2), ps.stress(1);
  SideValues v;
  v.X = X;
  v.s = frame.coordinate(X);
  const Vec2 n = body.finite_strain() ? Vec2(ps.F.inverse().transpose() * N).normalized() : N;
  v.minus_sigma_nn = -n.dot(sigma * n);
  const Vec2 PN = body.finite_strain()
                      ? Vec2(ps.F.determinant() * (sigma * (ps.F.inverse().transpose() * N)))
                      : Vec2(sigma * N);
  const Vec2 x = displaced(body, q, pv.N, X, u);  // from the shape functions at hand
  const Vec2 n_o = contact_force_normal(pair, obstacle, x, N, pv, ue);
  v.length_ratio = length_ratio(frame, X, N);
  v.pressure_from_stress = n_o.dot(PN) * v.length_ratio;
  v.shear_from_stress = -contact::friction_tangent(n_o).dot(PN) * v.length_ratio;
  return v;
}

double length_ratio(const contact::SurfaceFrame& frame, const Vec2& X, const Vec2& N) {
  const double ds_dS = std::abs(frame.rate(X, Vec2(N.y(), -N.x())));
  return 1 / std::max(ds_dS, 1e-12);
}

std::optional<std::tuple<int, int, double>> node_stress_point(const Body& body, const ContactPair& pair, int j) {
  const PairConstraints& c = *pair.constraints;
  struct Candidate {
    int q, le;
    double t, regularity;
  };
  std::optional<Candidate> best;
  for (size_t k = 0; k < c.nodes.edge_nodes.size(); ++k)
    for (size_t i = 0; i < c.nodes.edge_nodes[k].size(); ++i) {
      if (c.nodes.edge_nodes[k][i] != j) continue;
      const auto& edge = body.mesh.edge(pair.edges[k]);
      const int q = edge.quads[0], le = edge.local_edge[0];
      const double t = c.nodes.edge_points[k][i];
      const auto r = fem::edge_reference_point(le, t);
      const double regularity = body.maps[q].regularity(r[0], r[1]);
      if (!best || regularity > best->regularity) best = Candidate{q, le, t, regularity};
    }
  if (!best) return std::nullopt;
  double t = best->t;
  if (best->regularity < 1e-6) t = std::clamp(t, -1 + 1e-3, 1 - 1e-3);
  return std::tuple{best->q, best->le, t};
}

}  // namespace hpcontact::model
