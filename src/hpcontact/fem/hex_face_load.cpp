// Pressure loads on hexahedron faces by Gauss quadrature over the face's reference square.
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

Eigen::VectorXd hex_face_pressure_load(const basis::HierarchicHex& element,
                                       const mesh::HexMap& map, int lf, double pressure,
                                       int n_points) {
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
      const double w = rule.weights[i] * rule.weights[j];
      for (int c = 0; c < 3; ++c) {
        const double q = -pressure * w * n_dA(c);
        for (int a = 0; a < n; ++a) f(c * n + a) += q * N[a];
      }
    }
  return f;
}

}  // namespace hpcontact::fem
