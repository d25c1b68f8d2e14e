// Hexahedron values: reference gradients through the inverse Jacobian, ∇_x N = J⁻ᵀ ∇_ξ N.
#include "hpcontact/fem/hex_values.hpp"

#include "hpcontact/basis/quadrature.hpp"
#include "hpcontact/core/error.hpp"

namespace hpcontact::fem {

std::array<int, 3> hex_gauss_points(const basis::HierarchicHex& element, const mesh::HexMap& map) {
  const int q = map.polynomial_degree();
  return {element.p[0] + q, element.p[1] + q, element.p[2] + q};
}

HexValues hex_values(const basis::HierarchicHex& element, const mesh::HexMap& map,
                     const std::array<int, 3>& n_points) {
  const auto& r0 = basis::gauss_legendre(n_points[0]);
  const auto& r1 = basis::gauss_legendre(n_points[1]);
  const auto& r2 = basis::gauss_legendre(n_points[2]);
  const int n = element.n_modes(), nq = r0.size() * r1.size() * r2.size();
  HexValues v;
  v.N.resize(n, nq);
  v.dN_dx.resize(n, nq);
  v.dN_dy.resize(n, nq);
  v.dN_dz.resize(n, nq);
  v.JxW.resize(nq);
  v.x.resize(nq);
  Eigen::MatrixXd ref(n, 3);  // reference gradients at one point, a column per direction
  int q = 0;
  for (int i = 0; i < r0.size(); ++i)
    for (int j = 0; j < r1.size(); ++j)
      for (int k = 0; k < r2.size(); ++k, ++q) {
        const double xi = r0.points[i], eta = r1.points[j], zeta = r2.points[k];
        mesh::Mat3 J;
        v.x[q] = map.map(xi, eta, zeta, &J);
        const double det_J = J.determinant();
        HPC_REQUIRE(det_J > 0, MeshError, "hexahedron: non-positive Jacobian determinant ", det_J,
                    " at (xi, eta, zeta) = (", xi, ", ", eta, ", ", zeta, ")");
        v.JxW(q) = r0.weights[i] * r1.weights[j] * r2.weights[k] * det_J;
        element.evaluate(xi, eta, zeta, v.N.col(q).data(), ref.col(0).data(), ref.col(1).data(),
                         ref.col(2).data());
        // dN/dx_k = sum_d dN/dxi_d (J⁻¹)_dk: the rows of ref × J⁻¹.
        const Eigen::MatrixXd phys = ref * J.inverse();
        v.dN_dx.col(q) = phys.col(0);
        v.dN_dy.col(q) = phys.col(1);
        v.dN_dz.col(q) = phys.col(2);
      }
  return v;
}

}  // namespace hpcontact::fem
