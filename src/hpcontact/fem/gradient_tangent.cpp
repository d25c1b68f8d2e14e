// The first elasticity tensor on a body's slots, and the element tangent as one product per block
// of components: with M = D_i 𝔸_ik (each point's columns mixed by its small 𝔸), K_ik = M D_kᵀ
// costs 2 n² s_k n_q operations, against (2n)² (3 n_q) for Bᵀ ℂ B and 3 n² n_q more for the
// geometric part in the plane (4 and 4 in axisymmetry): about a quarter, and half of that
// again on the diagonal blocks, of which only the lower triangle is formed.
#include "hpcontact/fem/gradient_tangent.hpp"

#include "hpcontact/fem/point_blocks.hpp"

namespace hpcontact::fem {

namespace {

/// The Voigt index of E_IJ: 11, 22, 12 (and 21), θθ; -1 for the components between the plane
/// and the third direction, which no slot moves.
int voigt(int I, int J) {
  if (I == J) return I < 2 ? I : 3;
  return I < 2 && J < 2 ? 2 : -1;
}

/// ℂ_IJKL from its Voigt matrix (engineering shear: the 12 column multiplies 2 E12 = E12 + E21).
double elasticity(const Eigen::Ref<const Eigen::MatrixXd>& C, int I, int J, int K, int L) {
  const int v = voigt(I, J), u = voigt(K, L);
  return v >= 0 && u >= 0 && v < C.rows() && u < C.cols() ? C(v, u) : 0.0;
}

}  // namespace

template <std::size_t Slots>
Eigen::Matrix<double, Slots, Slots> first_elasticity(const std::array<Slot, Slots>& slots,
                                                     const Eigen::Matrix3d& F, const Eigen::Matrix3d& S,
                                                     const Eigen::Ref<const Eigen::MatrixXd>& C, double w) {
  Eigen::Matrix<double, Slots, Slots> A;
  for (std::size_t s = 0; s < Slots; ++s) {
    const auto [a, Am] = slots[s];
    for (std::size_t t = 0; t <= s; ++t) {
      const auto [b, Bm] = slots[t];
      double v = a == b ? S(Am, Bm) : 0.0;
      for (int I = 0; I < 3; ++I) {
        if (F(a, I) == 0.0) continue;
        for (int K = 0; K < 3; ++K)
          if (F(b, K) != 0.0) v += F(a, I) * F(b, K) * elasticity(C, I, Am, K, Bm);
      }
      A(s, t) = A(t, s) = w * v;
    }
  }
  return A;
}

template <std::size_t Slots>
Eigen::Matrix<double, Slots, 1> first_piola(const std::array<Slot, Slots>& slots, const Eigen::Matrix3d& F,
                                            const Eigen::Matrix3d& S, double w) {
  Eigen::Matrix<double, Slots, 1> P;
  for (std::size_t s = 0; s < Slots; ++s) P(s) = w * F.row(slots[s].first).dot(S.col(slots[s].second));
  return P;
}

template Eigen::Matrix<double, 4, 4> first_elasticity<4>(const std::array<Slot, 4>&, const Eigen::Matrix3d&,
                                                      const Eigen::Matrix3d&, const Eigen::Ref<const Eigen::MatrixXd>&, double);
template Eigen::Matrix<double, 5, 5> first_elasticity<5>(const std::array<Slot, 5>&, const Eigen::Matrix3d&,
                                                      const Eigen::Matrix3d&, const Eigen::Ref<const Eigen::MatrixXd>&, double);
template Eigen::Matrix<double, 4, 1> first_piola<4>(const std::array<Slot, 4>&, const Eigen::Matrix3d&,
                                                const Eigen::Matrix3d&, double);
template Eigen::Matrix<double, 5, 1> first_piola<5>(const std::array<Slot, 5>&, const Eigen::Matrix3d&,
                                                const Eigen::Matrix3d&, double);

Eigen::MatrixXd gradient_tangent(const Eigen::MatrixXd& D0, const Eigen::MatrixXd& D1, int s0, int s1,
                                 const Eigen::MatrixXd& A) {
  const int n = static_cast<int>(D0.rows()), s = s0 + s1;
  const int nq = static_cast<int>(D0.cols()) / s0;
  const Eigen::MatrixXd* D[2] = {&D0, &D1};
  const int slots[2] = {s0, s1}, first_slot[2] = {0, s0};
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  for_point_blocks(nq, 2.0 * n * n * s, [&](int first, int count) {
    for (const auto [i, k] : {std::pair{0, 0}, std::pair{1, 0}, std::pair{1, 1}}) {
      const int si = slots[i], sk = slots[k];
      const auto Di = D[i]->middleCols(si * first, si * count);
      const auto Dk = D[k]->middleCols(sk * first, sk * count);
      Eigen::MatrixXd M(n, sk * count);  // D_i 𝔸_ik, point by point
      for (int q = 0; q < count; ++q)
        M.middleCols(sk * q, sk).noalias() =
            Di.middleCols(si * q, si) *
            A.block(first_slot[i], s * (first + q) + first_slot[k], si, sk);
      auto block = K.block(i * n, k * n, n, n);
      if (i == k) block.triangularView<Eigen::Lower>() += M * Dk.transpose();
      else block.noalias() += M * Dk.transpose();
    }
  });
  K.topRightCorner(n, n) = K.bottomLeftCorner(n, n).transpose();
  for (int col = 0; col < 2 * n; ++col)  // the diagonal blocks' upper triangles
    for (int row = col - col % n; row < col; ++row) K(row, col) = K(col, row);
  return K;
}

}  // namespace hpcontact::fem
