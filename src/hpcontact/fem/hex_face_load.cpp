// Pressure and traction loads on hexahedron faces by Gauss quadrature over the face's reference
// square.
#include "hpcontact/fem/hex_face_load.hpp"

#include <algorithm>
#include <vector>

#include "hpcontact/basis/quadrature.hpp"
#include "hpcontact/core/error.hpp"

namespace hpcontact::fem {

mesh::Vec3 hex_face_reference_point(int lf, double s, double t) {
  HPC_REQUIRE(lf >= 0 && lf < 6, InputError, "hexahedron face: local face must be 0..5 (got ", lf,
              ")");
  mesh::Vec3 r;
  r(basis::kHexFaceNormalAxis[lf]) = lf % 2 ? 1 : -1;
  r(basis::kHexFaceAxes[lf][0]) = s;
  r(basis::kHexFaceAxes[lf][1]) = t;
  return r;
}

mesh::Vec3 hex_face_area_normal(const mesh::HexMap& map, int lf, double s, double t) {
  const mesh::Vec3 r = hex_face_reference_point(lf, s, t);
  mesh::Mat3 J;
  map.map(r(0), r(1), r(2), &J);
  const mesh::Vec3 n = J.col(basis::kHexFaceAxes[lf][0]).cross(J.col(basis::kHexFaceAxes[lf][1]));
  // s × t is outward where the normal coordinate and the cyclic order (s, t, n) agree: F1, F2, F5.
  const bool outward = lf == 1 || lf == 2 || lf == 5;
  return outward ? n : mesh::Vec3(-n);
}

int hex_face_gauss_points(const basis::HierarchicHex& element, const mesh::HexMap& map, int lf) {
  return std::max(element.face_degree[lf][0], element.face_degree[lf][1]) +
         map.polynomial_degree() + 1;
}

namespace {

/// f_e = ∫ N t dA over local face lf, the traction t given per unit reference area,
/// t ds dt = force(n dA / (ds dt)).
template <class Force>
Eigen::VectorXd face_load(const basis::HierarchicHex& element, const mesh::HexMap& map, int lf,
                          int n_points, const Force& force) {
  const auto& rule = basis::gauss_legendre(n_points);
  const int n = element.n_modes();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * n);
  std::vector<double> N(n);
  for (int i = 0; i < n_points; ++i)
    for (int j = 0; j < n_points; ++j) {
      const double s = rule.points[i], t = rule.points[j];
      const mesh::Vec3 r = hex_face_reference_point(lf, s, t);
      const mesh::Vec3 n_dA = hex_face_area_normal(map, lf, s, t);
      element.evaluate(r(0), r(1), r(2), N.data(), nullptr, nullptr, nullptr);
      const mesh::Vec3 t_dA = rule.weights[i] * rule.weights[j] * force(n_dA);
      for (int c = 0; c < 3; ++c)
        for (int a = 0; a < n; ++a) f(c * n + a) += t_dA(c) * N[a];
    }
  return f;
}

}  // namespace

Eigen::VectorXd hex_face_pressure_load(const basis::HierarchicHex& element,
                                       const mesh::HexMap& map, int lf, double pressure,
                                       int n_points) {
  return face_load(element, map, lf, n_points,
                   [pressure](const mesh::Vec3& n_dA) -> mesh::Vec3 { return -pressure * n_dA; });
}

Eigen::VectorXd hex_face_traction_load(const basis::HierarchicHex& element,
                                       const mesh::HexMap& map, int lf,
                                       const mesh::Vec3& traction, int n_points) {
  return face_load(element, map, lf, n_points, [&traction](const mesh::Vec3& n_dA) -> mesh::Vec3 {
    return n_dA.norm() * traction;
  });
}

}  // namespace hpcontact::fem
