// Lagrange maps of the hexahedron: tensor products of the 1D Lagrange polynomials on the nodes
// {-1, 1} (trilinear) or {-1, 0, 1} (triquadratic).
#include "hpcontact/mesh/hex_map.hpp"

#include <algorithm>
#include <cmath>

#include "hpcontact/basis/hex_modes.hpp"
#include "hpcontact/basis/quadrature.hpp"
#include "hpcontact/core/error.hpp"

namespace hpcontact::mesh {

const int kHex27Nodes[27][3] = {
    // vertices
    {-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1},
    {-1, 1, 1},
    // mid-edge: V0V1, V0V3, V0V4, V1V2, V1V5, V2V3, V2V6, V3V7, V4V5, V4V7, V5V6, V6V7
    {0, -1, -1}, {-1, 0, -1}, {-1, -1, 0}, {1, 0, -1}, {1, -1, 0}, {0, 1, -1}, {1, 1, 0},
    {-1, 1, 0}, {0, -1, 1}, {-1, 0, 1}, {1, 0, 1}, {0, 1, 1},
    // face centres: zeta = -1, eta = -1, xi = -1, xi = +1, eta = +1, zeta = +1
    {0, 0, -1}, {0, -1, 0}, {-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1},
    // centre
    {0, 0, 0}};

namespace {

/// The 1D Lagrange polynomial of node c in {-1, 0, 1} of the given degree, and its derivative:
///   degree 1: (1 + c t)/2;
///   degree 2: t (t + c)/2 at c = ±1, 1 − t² at c = 0.
void lagrange_1d(int degree, int c, double t, double& value, double& derivative) {
  if (degree == 1) {
    value = 0.5 * (1 + c * t);
    derivative = 0.5 * c;
  } else if (c == 0) {
    value = 1 - t * t;
    derivative = -2 * t;
  } else {
    value = 0.5 * t * (t + c);
    derivative = t + 0.5 * c;
  }
}

}  // namespace

HexMap HexMap::trilinear(const std::array<Vec3, 8>& vertices) {
  HexMap m;
  m.kind_ = HexMapKind::trilinear;
  m.nodes_.assign(vertices.begin(), vertices.end());
  for (const auto& x : basis::kHexVertexCoordinates) m.reference_.push_back({x[0], x[1], x[2]});
  return m;
}

HexMap HexMap::triquadratic(const std::array<Vec3, 27>& nodes) {
  HexMap m;
  m.kind_ = HexMapKind::triquadratic;
  m.nodes_.assign(nodes.begin(), nodes.end());
  for (const auto& x : kHex27Nodes) m.reference_.push_back({x[0], x[1], x[2]});
  return m;
}

HexMap HexMap::blending(const geometry::BlendingHex& geometry) {
  HexMap m;
  m.kind_ = HexMapKind::blending;
  m.nodes_.assign(geometry.vertices.begin(), geometry.vertices.end());
  for (const auto& x : basis::kHexVertexCoordinates) m.reference_.push_back({x[0], x[1], x[2]});
  m.blend_ = geometry;
  return m;
}

int HexMap::polynomial_degree() const {
  switch (kind_) {
    case HexMapKind::trilinear: return 1;
    case HexMapKind::triquadratic: return 2;
    case HexMapKind::blending: return kBlendingQuadratureDegree;
  }
  return 2;
}

Vec3 HexMap::map(double xi, double eta, double zeta, Mat3* J) const {
  if (kind_ == HexMapKind::blending) return blend_.map(xi, eta, zeta, J);
  // x = sum_n x_n L_n(xi) L_n(eta) L_n(zeta), J's columns the three partial derivatives.
  const int q = polynomial_degree();
  Vec3 x = Vec3::Zero();
  if (J) J->setZero();
  for (size_t n = 0; n < nodes_.size(); ++n) {
    const auto& c = reference_[n];
    double a, da, b, db, e, de;
    lagrange_1d(q, c[0], xi, a, da);
    lagrange_1d(q, c[1], eta, b, db);
    lagrange_1d(q, c[2], zeta, e, de);
    x += (a * b * e) * nodes_[n];
    if (J) {
      J->col(0) += (da * b * e) * nodes_[n];
      J->col(1) += (a * db * e) * nodes_[n];
      J->col(2) += (a * b * de) * nodes_[n];
    }
  }
  return x;
}

void check_hex_jacobian(const HexMap& map, std::string_view context, int element, int n_points) {
  const auto& rule = basis::gauss_legendre(n_points);
  struct Point {
    double xi, eta, zeta, det;
  };
  std::vector<Point> points;
  double scale = 0;
  auto add = [&](double xi, double eta, double zeta) {
    Mat3 J;
    map.map(xi, eta, zeta, &J);
    points.push_back({xi, eta, zeta, J.determinant()});
    // (|J|_F / √3)³ is det J for a cube (J = h/2 I): the scale det J is measured against.
    scale = std::max(scale, std::pow(J.norm() / std::sqrt(3.0), 3));
  };
  for (double xi : rule.points)
    for (double eta : rule.points)
      for (double zeta : rule.points) add(xi, eta, zeta);
  for (const auto& c : basis::kHexVertexCoordinates) add(c[0], c[1], c[2]);
  // Unlike the 2D check (element_map.cpp), a vanishing det J at a corner is refused too: a
  // polynomial map has no smooth 180° corners, only collapsed edges and faces (a blending map could
  // have one where two faces on one surface meet; such a hexahedron is refused as degenerate).
  for (const Point& p : points)
    HPC_REQUIRE(p.det > 1e-12 * scale && std::isfinite(p.det), MeshError, context, ": element ",
                element, " has a ", p.det >= 0 ? "vanishing" : "negative",
                " Jacobian determinant ", p.det, " at (xi, eta, zeta) = (", p.xi, ", ", p.eta,
                ", ", p.zeta, "): it is inverted or degenerate");
}

}  // namespace hpcontact::mesh
