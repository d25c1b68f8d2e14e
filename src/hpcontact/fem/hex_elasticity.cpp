// Hexahedron stiffness by derivative-pair blocks: six dense products G_k G_lᵀ, G_k = ∇_k N
// sqrt(w det J), replace the per-point Bᵀ D B (whose B is 6 × 3n and D a 6 × 6 matrix mostly of
// zeros). Both are O(p⁹) for a full element matrix; the blocks run at the speed of a GEMM.
// Sum factorisation (hex_factored_stiffness.hpp) brings the matrix to O(p⁷); this kernel is its
// reference, and the faster one at low degree and in the trunk space (hex_element.hpp).
#include "hpcontact/fem/hex_elasticity.hpp"

#include "hpcontact/fem/point_blocks.hpp"

namespace hpcontact::fem {

Eigen::MatrixXd hex_stiffness(const HexValues& values, const material::LinearElastic& material) {
  const int n = values.n_modes(), nq = values.n_points();
  const Eigen::VectorXd s = values.JxW.cwiseSqrt();
  std::array<Eigen::MatrixXd, 3> G;
  for (int k = 0; k < 3; ++k) G[k] = values.dN(k) * s.asDiagonal();
  // M[k][l] for k <= l; M_lk = M_klᵀ.
  std::array<std::array<Eigen::MatrixXd, 3>, 3> M;
  for (int k = 0; k < 3; ++k)
    for (int l = k; l < 3; ++l) M[k][l] = Eigen::MatrixXd::Zero(n, n);
  for_point_blocks(nq, 12.0 * n * n, [&](int first, int count) {
    for (int k = 0; k < 3; ++k)
      for (int l = k; l < 3; ++l)
        M[k][l].noalias() += G[k].middleCols(first, count) * G[l].middleCols(first, count).transpose();
  });
  // A GEMM's G Gᵀ is symmetric only to round-off (blocked sums in different orders): make the
  // diagonal blocks exactly symmetric, so that K is.
  for (int k = 0; k < 3; ++k) M[k][k] = 0.5 * (M[k][k] + M[k][k].transpose()).eval();
  const double lambda = material.lambda(), mu = material.mu();
  const Eigen::MatrixXd trace = M[0][0] + M[1][1] + M[2][2];
  Eigen::MatrixXd K(3 * n, 3 * n);
  for (int i = 0; i < 3; ++i) {
    K.block(i * n, i * n, n, n) = (lambda + mu) * M[i][i] + mu * trace;
    for (int j = i + 1; j < 3; ++j) {
      // M_ij with i < j is stored; M_ji = M_ijᵀ.
      K.block(i * n, j * n, n, n) = lambda * M[i][j] + mu * M[i][j].transpose();
      K.block(j * n, i * n, n, n) = K.block(i * n, j * n, n, n).transpose();
    }
  }
  return K;
}

Eigen::VectorXd hex_body_force(const HexValues& values, const mesh::Vec3& b) {
  const int n = values.n_modes();
  const Eigen::VectorXd w = values.N * values.JxW;
  Eigen::VectorXd f(3 * n);
  for (int i = 0; i < 3; ++i) f.segment(i * n, n) = b(i) * w;
  return f;
}

Eigen::Matrix<double, 6, Eigen::Dynamic> hex_strains(const HexValues& values,
                                                     const Eigen::VectorXd& u_e) {
  const int n = values.n_modes();
  const auto ux = u_e.segment(0, n), uy = u_e.segment(n, n), uz = u_e.segment(2 * n, n);
  Eigen::Matrix<double, 6, Eigen::Dynamic> eps(6, values.n_points());
  eps.row(0) = ux.transpose() * values.dN_dx;
  eps.row(1) = uy.transpose() * values.dN_dy;
  eps.row(2) = uz.transpose() * values.dN_dz;
  eps.row(3) = uy.transpose() * values.dN_dz + uz.transpose() * values.dN_dy;
  eps.row(4) = ux.transpose() * values.dN_dz + uz.transpose() * values.dN_dx;
  eps.row(5) = ux.transpose() * values.dN_dy + uy.transpose() * values.dN_dx;
  return eps;
}

}  // namespace hpcontact::fem
