// Sum-factorised hexahedron stiffness: three 1D contractions over the Gauss grid, then the
// element's modes gathered from the matrix over all tensor products.
#include "hpcontact/fem/hex_factored_stiffness.hpp"

#include "hpcontact/basis/legendre.hpp"
#include "hpcontact/basis/quadrature.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/core/stop.hpp"

namespace hpcontact::fem {

namespace {

/// The component pairs (i, j), i <= j, whose blocks K_ij are formed; K_ji = K_ijᵀ.
constexpr int kPairs[6][2] = {{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2}, {2, 2}};

/// Values and derivatives (m × n) of the m = p + 1 1D hierarchic functions of degree p (index
/// k as in hierarchic_1d) at the n Gauss points of one direction.
struct Table1D {
  Eigen::MatrixXd value, derivative;
};

Table1D table_1d(int p, const basis::QuadratureRule1D& rule) {
  Table1D t;
  t.value.resize(p + 1, rule.size());
  t.derivative.resize(p + 1, rule.size());
  for (int q = 0; q < rule.size(); ++q)
    basis::hierarchic_1d(p, rule.points[q], t.value.col(q).data(), t.derivative.col(q).data());
  return t;
}

/// The pair tables of one direction by kind (bit 0: the left factor differentiated, bit 1: the
/// right one): row α + m β of P[kind] (m² × n) is F_α G_β at each point, F and G the values or
/// the derivatives. The left index runs fastest, so that the element's modes, which run fastest
/// along ζ, are gathered from consecutive entries.
std::array<Eigen::MatrixXd, 4> pair_tables(const Table1D& t) {
  const int m = static_cast<int>(t.value.rows()), n = static_cast<int>(t.value.cols());
  std::array<Eigen::MatrixXd, 4> P;
  for (int kind = 0; kind < 4; ++kind) {
    const Eigen::MatrixXd& F = kind & 1 ? t.derivative : t.value;
    const Eigen::MatrixXd& G = kind & 2 ? t.derivative : t.value;
    P[kind].resize(m * m, n);
    for (int q = 0; q < n; ++q)
      for (int beta = 0; beta < m; ++beta)
        for (int alpha = 0; alpha < m; ++alpha)
          P[kind](alpha + m * beta, q) = F(alpha, q) * G(beta, q);
  }
  return P;
}

/// The kind of direction d's pair table in the term ∂_r N_a ∂_s N_b.
int kind(int d, int r, int s) { return (r == d) + 2 * (s == d); }

}  // namespace

HexGridGeometry hex_grid_geometry(const mesh::HexMap& map, const std::array<int, 3>& n_points) {
  const auto& r0 = basis::gauss_legendre(n_points[0]);
  const auto& r1 = basis::gauss_legendre(n_points[1]);
  const auto& r2 = basis::gauss_legendre(n_points[2]);
  HexGridGeometry g;
  g.n_points = n_points;
  g.JxW.resize(r0.size() * r1.size() * r2.size());
  g.J_inv.resize(g.JxW.size());
  int q = 0;
  for (int i = 0; i < r0.size(); ++i)
    for (int j = 0; j < r1.size(); ++j)
      for (int k = 0; k < r2.size(); ++k, ++q) {
        const double xi = r0.points[i], eta = r1.points[j], zeta = r2.points[k];
        mesh::Mat3 J;
        map.map(xi, eta, zeta, &J);
        const double det_J = J.determinant();
        HPC_REQUIRE(det_J > 0, MeshError, "hexahedron: non-positive Jacobian determinant ", det_J,
                    " at (xi, eta, zeta) = (", xi, ", ", eta, ", ", zeta, ")");
        g.JxW(q) = r0.weights[i] * r1.weights[j] * r2.weights[k] * det_J;
        g.J_inv[q] = J.inverse();
      }
  return g;
}

Eigen::MatrixXd hex_stiffness_factored(const basis::HierarchicHex& element,
                                       const HexGridGeometry& geometry,
                                       const material::LinearElastic& material) {
  const auto [n0, n1, n2] = geometry.n_points;
  const int m0 = element.p[0] + 1, m1 = element.p[1] + 1, m2 = element.p[2] + 1;
  const int nq = geometry.size();
  const std::array<Eigen::MatrixXd, 4> P0 =
      pair_tables(table_1d(element.p[0], basis::gauss_legendre(n0)));
  const std::array<Eigen::MatrixXd, 4> P1 =
      pair_tables(table_1d(element.p[1], basis::gauss_legendre(n1)));
  const std::array<Eigen::MatrixXd, 4> P2 =
      pair_tables(table_1d(element.p[2], basis::gauss_legendre(n2)));
  stop_point("assembling");

  // A^ij_rs at every point, column 3 r + s, row ((ij n1 + q1) n0 + q0) n2 + q2 (ξ faster than η,
  // so that the sum over η below is one product per pair ij).
  const double lambda = material.lambda(), mu = material.mu();
  Eigen::MatrixXd A(6 * nq, 9);
  for (int q0 = 0, q = 0; q0 < n0; ++q0)
    for (int q1 = 0; q1 < n1; ++q1)
      for (int q2 = 0; q2 < n2; ++q2, ++q) {
        const mesh::Mat3& Ji = geometry.J_inv[q];
        const double w = geometry.JxW(q);
        const mesh::Mat3 G = Ji * Ji.transpose();
        for (int ij = 0; ij < 6; ++ij) {
          const int i = kPairs[ij][0], j = kPairs[ij][1];
          const int row = ((ij * n1 + q1) * n0 + q0) * n2 + q2;
          for (int r = 0; r < 3; ++r)
            for (int s = 0; s < 3; ++s)
              A(row, 3 * r + s) = w * (lambda * Ji(r, i) * Ji(s, j) + mu * Ji(r, j) * Ji(s, i) +
                                       (i == j ? mu * G(r, s) : 0.0));
        }
      }

  // The sums over ζ and η for each (r, s), gathered by the kind t0 of its ξ table:
  //   T2(ij C + (a1 + m1 b1) m2² + a2 + m2 b2, t0 n0 + q0)
  //     = Σ_{(r,s) of kind t0 along ξ} Σ_q1 P1(a1 b1, q1) Σ_q2 P2(a2 b2, q2) A^ij_rs(q0, q1, q2).
  const int m1s = m1 * m1, m2s = m2 * m2, C = m1s * m2s;
  Eigen::MatrixXd T2 = Eigen::MatrixXd::Zero(6 * static_cast<Eigen::Index>(C), 4 * n0);
  for (int r = 0; r < 3; ++r)
    for (int s = 0; s < 3; ++s) {
      const int t0 = kind(0, r, s);
      // Σ over ζ: column (ij n1 + q1) n0 + q0 of T1.
      const Eigen::Map<const Eigen::MatrixXd> X(A.col(3 * r + s).data(), n2, 6 * n1 * n0);
      const Eigen::MatrixXd T1 = P2[kind(2, r, s)] * X;
      const Eigen::MatrixXd P1t = P1[kind(1, r, s)].transpose();
      for (int ij = 0; ij < 6; ++ij) {
        // Σ over η: rows (a2 b2, q0), columns a1 b1.
        const Eigen::Map<const Eigen::MatrixXd> Y(
            T1.data() + static_cast<Eigen::Index>(ij) * m2s * n1 * n0, m2s * n0, n1);
        const Eigen::MatrixXd W = Y * P1t;
        for (int q0 = 0; q0 < n0; ++q0)
          for (int ab1 = 0; ab1 < m1s; ++ab1)
            T2.col(t0 * n0 + q0).segment(static_cast<Eigen::Index>(ij) * C + ab1 * m2s, m2s) +=
                W.col(ab1).segment(q0 * m2s, m2s);
      }
    }
  stop_point("assembling");

  // Σ over ξ, the four kinds at once, for one ξ factor b0 of the right mode at a time (6 C × m0
  // entries, which stay in cache while the element's modes are gathered from them):
  //   Kt(ij C + c, a0) = Σ_{t0, q0} T2(ij C + c, t0 n0 + q0) P0[t0](a0 + m0 b0, q0).
  Eigen::MatrixXd P0_stacked(4 * n0, m0 * m0);
  for (int t0 = 0; t0 < 4; ++t0) P0_stacked.middleRows(t0 * n0, n0) = P0[t0].transpose();

  // The element's modes ± a_{a0} b_{a1} c_{a2}: entry (a, b) of block ij is
  // sign_a sign_b Kt(ij C + left[a] + right[b]) (column-major Kt, b0 fixed).
  const std::vector<std::array<int, 3>> ijk = element.mode_indices();
  const std::vector<double> sign = element.mode_signs();
  const int n = static_cast<int>(ijk.size());
  const Eigen::Index ld = 6 * static_cast<Eigen::Index>(C);
  std::vector<Eigen::Index> left(n), right(n);
  std::vector<std::vector<int>> with_b0(m0);  // the modes b of each ξ factor b0
  for (int a = 0; a < n; ++a) {
    const auto [a0, a1, a2] = ijk[a];
    left[a] = static_cast<Eigen::Index>(a1) * m2s + a2 + ld * a0;
    right[a] = static_cast<Eigen::Index>(a1) * m1 * m2s + a2 * m2;
    with_b0[a0].push_back(a);
  }
  Eigen::MatrixXd K(3 * n, 3 * n);
  Eigen::MatrixXd Kt(ld, m0);
  for (int b0 = 0; b0 < m0; ++b0) {
    if (with_b0[b0].empty()) continue;
    stop_point("assembling");
    Kt.noalias() = T2 * P0_stacked.middleCols(b0 * m0, m0);
    const double* kt = Kt.data();
    for (int ij = 0; ij < 6; ++ij) {
      const int i = kPairs[ij][0], j = kPairs[ij][1];
      for (int b : with_b0[b0]) {
        const double* column = kt + static_cast<Eigen::Index>(ij) * C + right[b];
        double* out = &K(i * n, j * n + b);
        for (int a = 0; a < n; ++a) out[a] = sign[a] * sign[b] * column[left[a]];
      }
    }
  }
  for (int ij = 0; ij < 6; ++ij) {
    const int i = kPairs[ij][0], j = kPairs[ij][1];
    if (i == j)  // symmetric to round-off: made exactly so
      K.block(i * n, i * n, n, n) =
          0.5 * (K.block(i * n, i * n, n, n) + K.block(i * n, i * n, n, n).transpose()).eval();
    else
      K.block(j * n, i * n, n, n) = K.block(i * n, j * n, n, n).transpose();
  }
  return K;
}

Eigen::VectorXd hex_body_force_factored(const basis::HierarchicHex& element,
                                        const HexGridGeometry& geometry, const mesh::Vec3& b) {
  const auto [n0, n1, n2] = geometry.n_points;
  const int m1 = element.p[1] + 1, m2 = element.p[2] + 1;
  const Table1D V0 = table_1d(element.p[0], basis::gauss_legendre(n0));
  const Table1D V1 = table_1d(element.p[1], basis::gauss_legendre(n1));
  const Table1D V2 = table_1d(element.p[2], basis::gauss_legendre(n2));
  // F(a2 + m2 a1, a0) = Σ_q w det J a_{a0}(ξ) b_{a1}(η) c_{a2}(ζ), one direction at a time.
  const Eigen::Map<const Eigen::MatrixXd> w(geometry.JxW.data(), n2, n0 * n1);
  const Eigen::MatrixXd U1 = V2.value * w;  // m2 × (q0 n1 + q1)
  Eigen::MatrixXd U2(m2 * m1, n0);
  for (int q0 = 0; q0 < n0; ++q0)
    Eigen::Map<Eigen::MatrixXd>(U2.col(q0).data(), m2, m1) =
        U1.middleCols(q0 * n1, n1) * V1.value.transpose();
  const Eigen::MatrixXd F = U2 * V0.value.transpose();
  const std::vector<std::array<int, 3>> ijk = element.mode_indices();
  const std::vector<double> sign = element.mode_signs();
  const int n = static_cast<int>(ijk.size());
  Eigen::VectorXd f(3 * n);
  for (int a = 0; a < n; ++a) {
    const double integral = sign[a] * F(ijk[a][2] + m2 * ijk[a][1], ijk[a][0]);
    for (int i = 0; i < 3; ++i) f(i * n + a) = b(i) * integral;
  }
  return f;
}

}  // namespace hpcontact::fem
