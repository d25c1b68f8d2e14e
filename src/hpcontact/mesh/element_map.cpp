// Blending and isoparametric element maps.
#include "hpcontact/mesh/element_map.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "hpcontact/basis/quadrature.hpp"
#include "hpcontact/core/error.hpp"

namespace hpcontact::mesh {

ElementMap ElementMap::blending(const Mesh& mesh, int q) {
  ElementMap m;
  const auto& v = mesh.quad(q);
  for (int k = 0; k < 4; ++k) m.blend_.vertices[k] = mesh.node(v[k]);
  for (int e = 0; e < 4; ++e) {
    const Edge& edge = mesh.edge(mesh.quad_edge(q, e));
    if (!edge.curve) continue;
    m.blend_.edges[e] = mesh.quad_edge_reversed(q, e) ? edge.curve->reversed() : edge.curve;
  }
  return m;
}

ElementMap ElementMap::isoparametric(const Mesh& mesh, int q, basis::LagrangeType type) {
  ElementMap m;
  m.iso_ = true;
  m.type_ = type;
  const auto& v = mesh.quad(q);
  for (int k = 0; k < 4; ++k) m.iso_nodes_.push_back(mesh.node(v[k]));
  if (type == basis::LagrangeType::q4) return m;
  // Mid-edge nodes on the exact edge (its parameter midpoint), in the order E1, E2, E3, E4.
  for (int e = 0; e < 4; ++e) m.iso_nodes_.push_back(mesh.edge_point(mesh.quad_edge(q, e), 0.0));
  if (type == basis::LagrangeType::q9) m.iso_nodes_.push_back(blending(mesh, q).map(0.0, 0.0));
  return m;
}

double ElementMap::regularity(double xi, double eta) const {
  Mat2 J;
  map(xi, eta, &J);
  return std::abs(J.determinant()) / std::max(J.squaredNorm(), 1e-300);
}

Vec2 ElementMap::map(double xi, double eta, Mat2* J) const {
  if (!iso_) return blend_.map(xi, eta, J);
  double N[9], dx[9], de[9];
  basis::lagrange_evaluate(type_, xi, eta, N, dx, de);
  Vec2 x = Vec2::Zero();
  Mat2 Jm = Mat2::Zero();
  for (size_t i = 0; i < iso_nodes_.size(); ++i) {
    x += N[i] * iso_nodes_[i];
    Jm.col(0) += dx[i] * iso_nodes_[i];
    Jm.col(1) += de[i] * iso_nodes_[i];
  }
  if (J) *J = Jm;
  return x;
}

void check_jacobian(const ElementMap& map, const Mesh& mesh, int q, int n_points) {
  const auto& rule = basis::gauss_legendre(n_points);
  // At the Gauss points det J must be positive, beyond round-off of the map's scale |J|². At a
  // corner it may vanish: two edges of one element on the same smooth curve meet there at 180°
  // (the quarter-disc 2×2 mesh), which is harmless because no quadrature point sits at a corner;
  // only a negative value is an error.
  struct Point {
    double xi, eta, det;
    bool corner;
  };
  std::vector<Point> points;
  double scale = 0;
  auto add = [&](double xi, double eta, bool corner) {
    Mat2 J;
    map.map(xi, eta, &J);
    points.push_back({xi, eta, J.determinant(), corner});
    scale = std::max(scale, J.squaredNorm());
  };
  for (double xi : rule.points)
    for (double eta : rule.points) add(xi, eta, false);
  for (double xi : {-1.0, 1.0})
    for (double eta : {-1.0, 1.0}) add(xi, eta, true);
  for (const Point& p : points) {
    const bool ok = p.corner ? p.det >= -1e-10 * scale : p.det > 1e-12 * scale;
    HPC_REQUIRE(ok && std::isfinite(p.det), MeshError, mesh.context(), ": element ",
                mesh.quad_id(q), " has a ", p.det > 0 ? "vanishing" : "non-positive",
                " Jacobian determinant ", p.det, " at (xi, eta) = (", p.xi, ", ", p.eta,
                "): it is inverted or degenerate, or its curved edges cross");
  }
}

}  // namespace hpcontact::mesh
