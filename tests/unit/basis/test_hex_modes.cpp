// Unit tests of the hierarchic shape functions on the reference hexahedron [-1, 1]^3.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "hpcontact/basis/hex_modes.hpp"
#include "hpcontact/basis/legendre.hpp"
#include "hpcontact/basis/quadrature.hpp"

namespace hb = hpcontact::basis;

namespace {

using Point = std::array<double, 3>;

struct Values {
  std::vector<double> N, d_xi, d_eta, d_zeta;
};

Values evaluate(const hb::HierarchicHex& hex, const Point& x) {
  const int n = hex.n_modes();
  Values v{std::vector<double>(n), std::vector<double>(n), std::vector<double>(n),
           std::vector<double>(n)};
  hex.evaluate(x[0], x[1], x[2], v.N.data(), v.d_xi.data(), v.d_eta.data(), v.d_zeta.data());
  return v;
}

/// Reproducible points inside the reference cube.
std::vector<Point> random_points(int n, unsigned seed = 42) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Point> points(n);
  for (auto& x : points) x = {u(rng), u(rng), u(rng)};
  return points;
}

hb::HierarchicHex isotropic(int p, hb::Space space) { return hb::hierarchic_hex({p, p, p}, space); }

/// Anisotropic element as the minimum rule leaves it: reduced edge and face degrees, reversed
/// edges and a face in each of several orientations.
hb::HierarchicHex anisotropic(hb::Space space = hb::Space::tensor_product) {
  auto hex = hb::hierarchic_hex({4, 6, 5}, space);
  hex.edge_degree = {3, 6, 4, 2, 4, 5, 1, 6, 5, 3, 5, 4};
  hex.edge_reversed = {true, false, false, true,  false, true,
                       true, false, false, false, true,  true};
  // Local face axes: F0, F1 (eta, zeta) <= (6, 5); F2, F3 (xi, zeta) <= (4, 5); F4, F5 (xi, eta).
  hex.face_degree = {{{6, 4}, {3, 5}, {4, 5}, {2, 3}, {4, 6}, {3, 6}}};
  hex.face_orientation = {{{false, false, false},
                           {true, false, true},
                           {false, true, true},
                           {true, true, false},
                           {true, true, true},
                           {false, false, true}}};
  return hex;
}

/// Index of the first mode of face f (vertex modes, then edges, then faces in order).
int first_face_mode(const hb::HierarchicHex& hex, int f) {
  int index = 8;
  for (int e = 0; e < 12; ++e) index += hex.n_edge_modes(e);
  for (int g = 0; g < f; ++g) index += hex.n_face_modes(g);
  return index;
}

/// Index of the first mode of edge e.
int first_edge_mode(const hb::HierarchicHex& hex, int e) {
  int index = 8;
  for (int g = 0; g < e; ++g) index += hex.n_edge_modes(g);
  return index;
}

/// Reference point of face f at local face coordinates (s, t).
Point point_on_face(int f, double s, double t) {
  Point x{};
  x[hb::kHexFaceNormalAxis[f]] = f % 2 == 0 ? -1.0 : 1.0;
  x[hb::kHexFaceAxes[f][0]] = s;
  x[hb::kHexFaceAxes[f][1]] = t;
  return x;
}

/// Per mode, the set of local faces on which it may be non-zero, from the mode order alone:
/// a vertex mode on the three faces through its vertex, an edge mode on the two faces containing
/// its edge, a face mode on its face, an internal mode on none.
std::vector<std::set<int>> face_supports(const hb::HierarchicHex& hex) {
  auto faces_with = [](std::vector<int> vertices) {
    std::set<int> faces;
    for (int f = 0; f < 6; ++f) {
      const auto* fv = hb::kHexFaceVertices[f];
      if (std::all_of(vertices.begin(), vertices.end(),
                      [&](int v) { return std::find(fv, fv + 4, v) != fv + 4; }))
        faces.insert(f);
    }
    return faces;
  };
  std::vector<std::set<int>> support;
  for (int v = 0; v < 8; ++v) support.push_back(faces_with({v}));
  for (int e = 0; e < 12; ++e)
    for (int k = 0; k < hex.n_edge_modes(e); ++k)
      support.push_back(faces_with({hb::kHexEdgeVertices[e][0], hb::kHexEdgeVertices[e][1]}));
  for (int f = 0; f < 6; ++f)
    for (int k = 0; k < hex.n_face_modes(f); ++k) support.push_back({f});
  support.resize(hex.n_modes());
  return support;
}

/// Values of all modes at the points of a (n × n × n) Gauss grid: one row per point.
Eigen::MatrixXd collocation(const hb::HierarchicHex& hex, int n, std::vector<Point>* points) {
  const auto& rule = hb::gauss_legendre(n);
  Eigen::MatrixXd A(n * n * n, hex.n_modes());
  int row = 0;
  for (double x : rule.points)
    for (double y : rule.points)
      for (double z : rule.points) {
        const auto v = evaluate(hex, {x, y, z});
        A.row(row++) = Eigen::Map<const Eigen::RowVectorXd>(v.N.data(), hex.n_modes());
        if (points) points->push_back({x, y, z});
      }
  return A;
}

/// Largest residual of the least-squares fit of each monomial xi^a eta^b zeta^c in `monomials` by
/// the modes, sampled on a Gauss grid of max degree + 2 points per direction (enough to see any
/// polynomial of degree max + 1 in each variable that the space lacks).
std::vector<double> fit_residuals(const hb::HierarchicHex& hex,
                                  const std::vector<std::array<int, 3>>& monomials) {
  int degree = std::max({hex.p[0], hex.p[1], hex.p[2]});
  for (const auto& m : monomials) degree = std::max({degree, m[0], m[1], m[2]});
  std::vector<Point> points;
  const Eigen::MatrixXd A = collocation(hex, degree + 2, &points);
  Eigen::MatrixXd F(A.rows(), static_cast<int>(monomials.size()));
  for (int r = 0; r < A.rows(); ++r)
    for (int c = 0; c < F.cols(); ++c)
      F(r, c) = std::pow(points[r][0], monomials[c][0]) * std::pow(points[r][1], monomials[c][1]) *
                std::pow(points[r][2], monomials[c][2]);
  const Eigen::MatrixXd C = A.colPivHouseholderQr().solve(F);
  const Eigen::MatrixXd R = A * C - F;
  std::vector<double> residual(monomials.size());
  for (int c = 0; c < F.cols(); ++c) residual[c] = R.col(c).cwiseAbs().maxCoeff();
  return residual;
}

/// Superlinear degree of xi^a eta^b zeta^c: the sum of its exponents that are at least 2.
int superlinear_degree(const std::array<int, 3>& m) {
  int d = 0;
  for (int e : m) d += e >= 2 ? e : 0;
  return d;
}

/// The trunk (serendipity) space's dimension by the closed form of the header.
int trunk_dimension(int p) {
  int n = 8 + 12 * (p - 1);
  if (p >= 4) n += 3 * (p - 2) * (p - 3);
  if (p >= 6) n += (p - 3) * (p - 4) * (p - 5) / 6;
  return n;
}

}  // namespace

// The tables shall agree with the header's drawing: each edge joins two vertices differing only
// along its axis, from -1 to +1; each face's four vertices lie on it, the second one step along s
// from the origin, the fourth one step along t, the third opposite; s x t is outward on F1, F2,
// F5 only.
TEST(HierarchicHex, ReferenceTablesAreConsistent) {
  const auto& X = hb::kHexVertexCoordinates;
  for (int e = 0; e < 12; ++e) {
    const int a = hb::kHexEdgeVertices[e][0], b = hb::kHexEdgeVertices[e][1];
    for (int d = 0; d < 3; ++d) {
      if (d == hb::kHexEdgeAxis[e]) {
        EXPECT_EQ(X[a][d], -1) << "edge " << e;
        EXPECT_EQ(X[b][d], 1) << "edge " << e;
      } else {
        EXPECT_EQ(X[a][d], X[b][d]) << "edge " << e;
      }
    }
  }
  for (int f = 0; f < 6; ++f) {
    const auto* v = hb::kHexFaceVertices[f];
    const int n = hb::kHexFaceNormalAxis[f], s = hb::kHexFaceAxes[f][0], t = hb::kHexFaceAxes[f][1];
    EXPECT_LT(s, t);
    EXPECT_TRUE(n != s && n != t);
    const std::array<std::array<int, 2>, 4> st{{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}};
    // s x t along the normal axis: + where the header says outward (F1, F2, F5).
    const int cross = (n == 1 ? -1 : 1);  // e_xi x e_zeta = -e_eta, the others +
    const int outward = f % 2 == 0 ? -1 : 1;
    EXPECT_EQ(cross * outward > 0, f == 1 || f == 2 || f == 5) << "face " << f;
    for (int k = 0; k < 4; ++k) {
      EXPECT_EQ(X[v[k]][n], f % 2 == 0 ? -1 : 1) << "face " << f;
      EXPECT_EQ(X[v[k]][s], st[k][0]) << "face " << f << " vertex " << k;
      EXPECT_EQ(X[v[k]][t], st[k][1]) << "face " << f << " vertex " << k;
    }
  }
}

// The tensor-product space of degrees (p_xi, p_eta, p_zeta) shall have
// (p_xi + 1)(p_eta + 1)(p_zeta + 1) modes: (p + 1)^3 when isotropic.
TEST(HierarchicHex, TensorProductModeCount) {
  for (int p = 1; p <= 10; ++p)
    EXPECT_EQ(isotropic(p, hb::Space::tensor_product).n_modes(), (p + 1) * (p + 1) * (p + 1));
  for (int a = 1; a <= 5; ++a)
    for (int b = 1; b <= 5; ++b)
      for (int c = 1; c <= 5; ++c)
        EXPECT_EQ(hb::hierarchic_hex({a, b, c}, hb::Space::tensor_product).n_modes(),
                  (a + 1) * (b + 1) * (c + 1))
            << a << ", " << b << ", " << c;
}

// The trunk space of degree p shall have 8 + 12(p−1) + 3(p−2)(p−3) + (p−3)(p−4)(p−5)/6 modes
// (face modes from p = 4, internal from p = 6), which is the number of monomials of superlinear
// degree <= p (counted here independently), p = 1..12.
TEST(HierarchicHex, TrunkModeCount) {
  const std::vector<int> known{8, 20, 32, 50, 74, 105, 144};  // serendipity S_p(I^3), p = 1..7
  for (int p = 1; p <= 12; ++p) {
    const auto hex = isotropic(p, hb::Space::trunk);
    int monomials = 0;
    for (int a = 0; a <= p; ++a)
      for (int b = 0; b <= p; ++b)
        for (int c = 0; c <= p; ++c) monomials += superlinear_degree({a, b, c}) <= p;
    EXPECT_EQ(hex.n_modes(), trunk_dimension(p)) << "p = " << p;
    EXPECT_EQ(hex.n_modes(), monomials) << "p = " << p;
    if (p <= 7) EXPECT_EQ(hex.n_modes(), known[p - 1]) << "p = " << p;
    EXPECT_EQ(hex.n_internal_modes(), p < 6 ? 0 : (p - 3) * (p - 4) * (p - 5) / 6);
    EXPECT_EQ(hex.n_face_modes(0), p < 4 ? 0 : (p - 2) * (p - 3) / 2);
  }
}

// With reduced edge and face degrees each edge shall contribute edge_degree − 1 modes, each face
// its tensor (or trunk) count of its pair of degrees, whatever its orientation, and the interior
// (p_xi − 1)(p_eta − 1)(p_zeta − 1) (tensor) or the i + j + k <= p_max count (trunk).
TEST(HierarchicHex, AnisotropicModeCount) {
  const auto hex = anisotropic();
  const int edges = 2 + 5 + 3 + 1 + 3 + 4 + 0 + 5 + 4 + 2 + 4 + 3;
  const int faces = 5 * 3 + 2 * 4 + 3 * 4 + 1 * 2 + 3 * 5 + 2 * 5;
  EXPECT_EQ(hex.n_modes(), 8 + edges + faces + 3 * 5 * 4);
  // Trunk, by hand: faces (i, j) with i + j <= max of the pair: (6,4): 2..6 x 2..4, i + j <= 6:
  // 3 + 2 + 1 = 6; (3,5): i <= 3, j <= 5, i + j <= 5: 2 + 1 = 3; (4,5): 2 + 1 = 3;
  // (2,3): 0; (4,6): 3 + 2 + 1 = 6; (3,6): 3 + 2 = 5. Internal, i <= 4, j <= 6, k <= 5,
  // i + j + k <= 6: (2,2,2) only.
  const auto trunk = anisotropic(hb::Space::trunk);
  EXPECT_EQ(trunk.n_modes(), 8 + edges + (6 + 3 + 3 + 0 + 6 + 5) + 1);
}

// Vertex mode v shall be 1 at vertex v and 0 at the others, every other mode 0 at every vertex,
// and the eight vertex modes shall sum to 1 everywhere (their gradients to 0).
TEST(HierarchicHex, VertexModesAreNodalAndSumToOne) {
  for (const auto& hex : {isotropic(5, hb::Space::tensor_product), isotropic(6, hb::Space::trunk),
                          anisotropic(), anisotropic(hb::Space::trunk)}) {
    for (int v = 0; v < 8; ++v) {
      const auto* x = hb::kHexVertexCoordinates[v];
      const auto values = evaluate(hex, {double(x[0]), double(x[1]), double(x[2])});
      for (int m = 0; m < hex.n_modes(); ++m)
        EXPECT_NEAR(values.N[m], m == v ? 1.0 : 0.0, 1e-15) << "vertex " << v << ", mode " << m;
    }
    for (const auto& x : random_points(50)) {
      const auto values = evaluate(hex, x);
      double sum = 0.0;
      std::array<double, 3> grad{};
      for (int v = 0; v < 8; ++v) {
        sum += values.N[v];
        grad[0] += values.d_xi[v];
        grad[1] += values.d_eta[v];
        grad[2] += values.d_zeta[v];
      }
      EXPECT_NEAR(sum, 1.0, 1e-15);
      for (double g : grad) EXPECT_NEAR(g, 0.0, 1e-15);
    }
  }
}

// Reference gradients shall agree with central differences of the values to 1e-7 at random
// points, for every mode of isotropic, trunk and anisotropic oriented elements.
TEST(HierarchicHex, GradientsMatchCentralDifferences) {
  constexpr double h = 1e-6;
  // Modes up to degree 6 have third derivatives below ~1e3: truncation h^2/6 * 1e3 and
  // round-off 1e-16/h are both near 1e-10.
  for (const auto& hex : {isotropic(6, hb::Space::tensor_product), isotropic(6, hb::Space::trunk),
                          anisotropic(), anisotropic(hb::Space::trunk)}) {
    for (const auto& x : random_points(12)) {
      const auto v = evaluate(hex, x);
      const std::array<const std::vector<double>*, 3> grad{&v.d_xi, &v.d_eta, &v.d_zeta};
      for (int d = 0; d < 3; ++d) {
        Point xp = x, xm = x;
        xp[d] += h;
        xm[d] -= h;
        const auto vp = evaluate(hex, xp), vm = evaluate(hex, xm);
        for (int m = 0; m < hex.n_modes(); ++m)
          ASSERT_NEAR((*grad[d])[m], (vp.N[m] - vm.N[m]) / (2 * h), 1e-7)
              << "mode " << m << ", direction " << d;
      }
    }
  }
}

// Null gradient arrays shall be accepted and leave the values unchanged.
TEST(HierarchicHex, ValuesWithoutGradients) {
  const auto hex = anisotropic();
  const auto v = evaluate(hex, {0.3, -0.7, 0.1});
  std::vector<double> N(hex.n_modes());
  hex.evaluate(0.3, -0.7, 0.1, N.data(), nullptr, nullptr, nullptr);
  EXPECT_EQ(N, v.N);
}

// Every mode shall vanish on each face outside its support (known from the mode order alone):
// vertex modes off the three faces at their vertex, edge modes off the two faces at their edge,
// face modes off their face, internal modes on the whole boundary.
TEST(HierarchicHex, ModesVanishOutsideTheirFaces) {
  for (const auto& hex : {isotropic(5, hb::Space::tensor_product), isotropic(6, hb::Space::trunk),
                          anisotropic(), anisotropic(hb::Space::trunk)}) {
    const auto support = face_supports(hex);
    int zero_checks = 0;
    for (int f = 0; f < 6; ++f)
      for (const auto& r : random_points(8, 7)) {
        const auto values = evaluate(hex, point_on_face(f, r[0], r[1]));
        for (int m = 0; m < hex.n_modes(); ++m)
          if (!support[m].contains(f)) {
            EXPECT_EQ(values.N[m], 0.0) << "face " << f << ", mode " << m;
            ++zero_checks;
          }
      }
    EXPECT_GT(zero_checks, 6 * 8 * hex.n_internal_modes());
  }
}

// The modes shall follow the documented order and factors: for p = 2 (one mode per edge, face and
// interior) the (i, j, k) of every mode written out by hand from the header's drawing; at any
// point each mode is sign · a_i b_j c_k of mode_indices() and mode_signs(), the sign + without
// reversals, names distinct; and a degree above the evaluator's stack buffer (33) gives the same
// products.
TEST(HierarchicHex, ModeOrderAndFactors) {
  using I = std::array<int, 3>;
  const std::vector<I> p2{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1},
                          {1, 1, 1}, {0, 1, 1},  // V
                          {2, 0, 0}, {1, 2, 0}, {2, 1, 0}, {0, 2, 0}, {2, 0, 1}, {1, 2, 1},
                          {2, 1, 1}, {0, 2, 1},                        // E0-7
                          {0, 0, 2}, {1, 0, 2}, {0, 1, 2}, {1, 1, 2},  // E8-11
                          {0, 2, 2}, {1, 2, 2}, {2, 0, 2}, {2, 1, 2}, {2, 2, 0}, {2, 2, 1},  // F0-5
                          {2, 2, 2}};
  EXPECT_EQ(isotropic(2, hb::Space::tensor_product).mode_indices(), p2);

  for (const auto& hex :
       {isotropic(4, hb::Space::tensor_product), isotropic(6, hb::Space::trunk), anisotropic(),
        anisotropic(hb::Space::trunk), isotropic(33, hb::Space::tensor_product)}) {
    const auto ijk = hex.mode_indices();
    const auto signs = hex.mode_signs();
    ASSERT_EQ(static_cast<int>(ijk.size()), hex.n_modes());
    ASSERT_EQ(static_cast<int>(signs.size()), hex.n_modes());
    EXPECT_EQ(std::set<I>(ijk.begin(), ijk.end()).size(), ijk.size());
    const int p_max = std::max({hex.p[0], hex.p[1], hex.p[2]});
    std::vector<double> a(p_max + 1), b(p_max + 1), c(p_max + 1);
    const bool oriented = hex.p[0] != hex.p[1];  // the anisotropic elements carry reversals
    for (const auto& x : random_points(5)) {
      hb::hierarchic_1d(hex.p[0], x[0], a.data(), nullptr);
      hb::hierarchic_1d(hex.p[1], x[1], b.data(), nullptr);
      hb::hierarchic_1d(hex.p[2], x[2], c.data(), nullptr);
      const auto v = evaluate(hex, x);
      for (int m = 0; m < hex.n_modes(); ++m) {
        const double product = a[ijk[m][0]] * b[ijk[m][1]] * c[ijk[m][2]];
        ASSERT_EQ(v.N[m], signs[m] * product) << m;
        if (!oriented) ASSERT_EQ(signs[m], 1.0) << m;
      }
    }
  }
}

// Reversing edge e shall flip the sign of its odd-degree modes and of nothing else, so that the
// reversed mode at edge coordinate −t equals the forward one at t.
TEST(HierarchicHex, ReversedEdgeFlipsOddModes) {
  for (int e = 0; e < 12; ++e) {
    const auto forward = isotropic(6, hb::Space::tensor_product);
    auto reversed = forward;
    reversed.edge_reversed[e] = true;
    const int first = first_edge_mode(forward, e);
    for (const auto& x : random_points(6)) {
      const auto a = evaluate(forward, x), b = evaluate(reversed, x);
      for (int m = 0; m < forward.n_modes(); ++m) {
        const int k = m - first + 2;
        const bool flips = m >= first && m < first + forward.n_edge_modes(e) && k % 2 == 1;
        EXPECT_EQ(b.N[m], flips ? -a.N[m] : a.N[m]) << "edge " << e << ", mode " << m;
        EXPECT_EQ(b.d_zeta[m], flips ? -a.d_zeta[m] : a.d_zeta[m]);
      }
    }
    for (double t : {-0.8, -0.25, 0.4, 0.95}) {
      Point x{}, y{};
      for (int d = 0; d < 3; ++d)
        x[d] = y[d] = hb::kHexVertexCoordinates[hb::kHexEdgeVertices[e][0]][d];
      x[hb::kHexEdgeAxis[e]] = t;
      y[hb::kHexEdgeAxis[e]] = -t;
      const auto a = evaluate(forward, x), b = evaluate(reversed, y);
      for (int k = 0; k < forward.n_edge_modes(e); ++k)
        EXPECT_NEAR(b.N[first + k], a.N[first + k], 1e-15) << "edge " << e << ", degree " << k + 2;
    }
  }
}

// In each of the 8 orientations, a face's modes at local face coordinates (s, t) shall equal the
// modes of an identically oriented face whose local axes are the global ones (degrees given in
// global order), at the global coordinates (S, T) of the same point; at any depth into the
// element. A face with unequal degrees (3 along s, 5 along t) tells a swap from none.
TEST(HierarchicHex, FaceOrientationMapsLocalToGlobalAxes) {
  std::set<std::array<bool, 3>> seen;
  for (int f = 0; f < 6; ++f)
    for (int code = 0; code < 8; ++code) {
      const hb::HexFaceOrientation o{(code & 1) != 0, (code & 2) != 0, (code & 4) != 0};
      seen.insert({o.swap, o.flip1, o.flip2});
      for (auto space : {hb::Space::tensor_product, hb::Space::trunk}) {
        auto oriented = isotropic(6, space);
        oriented.face_degree[f] = {3, 6};
        oriented.face_orientation[f] = o;
        auto global = oriented;
        global.face_orientation[f] = {};
        global.face_degree[f] = o.swap ? std::array<int, 2>{6, 3} : std::array<int, 2>{3, 6};
        const int first = first_face_mode(oriented, f), n = oriented.n_face_modes(f);
        ASSERT_EQ(n, global.n_face_modes(f));
        ASSERT_GT(n, 1);
        for (const auto& r : random_points(6, 11 + f)) {
          const double s = r[0], t = r[1], depth = r[2];
          const double S = (o.flip1 ? -1 : 1) * (o.swap ? t : s);
          const double T = (o.flip2 ? -1 : 1) * (o.swap ? s : t);
          auto x = point_on_face(f, s, t), y = point_on_face(f, S, T);
          x[hb::kHexFaceNormalAxis[f]] *= std::abs(depth);
          y[hb::kHexFaceNormalAxis[f]] *= std::abs(depth);
          const auto a = evaluate(oriented, x), b = evaluate(global, y);
          for (int k = 0; k < n; ++k)
            EXPECT_NEAR(a.N[first + k], b.N[first + k], 1e-15)
                << "face " << f << ", orientation " << code << ", face mode " << k;
        }
      }
    }
  EXPECT_EQ(seen.size(), 8u);
}

// The modes shall be linearly independent: the mass matrix (Gauss rule of p + 1 points per
// direction, exact for the degree 2p integrands) is positive definite, p = 1..6, tensor and trunk,
// and for the anisotropic oriented element; its smallest eigenvalue relative to its largest stays
// far above round-off.
TEST(HierarchicHex, MassMatrixIsPositiveDefinite) {
  auto check = [](const hb::HierarchicHex& hex, const std::string& what) {
    const int n_points = std::max({hex.p[0], hex.p[1], hex.p[2]}) + 1;
    const auto& rule = hb::gauss_legendre(n_points);
    const int n = hex.n_modes();
    Eigen::MatrixXd A(n_points * n_points * n_points, n);
    int row = 0;
    for (int i = 0; i < n_points; ++i)
      for (int j = 0; j < n_points; ++j)
        for (int k = 0; k < n_points; ++k) {
          const double w = std::sqrt(rule.weights[i] * rule.weights[j] * rule.weights[k]);
          const auto v = evaluate(hex, {rule.points[i], rule.points[j], rule.points[k]});
          A.row(row++) = w * Eigen::Map<const Eigen::RowVectorXd>(v.N.data(), n);
        }
    const Eigen::MatrixXd M = A.transpose() * A;
    EXPECT_EQ(Eigen::LLT<Eigen::MatrixXd>(M).info(), Eigen::Success) << what;
    const Eigen::VectorXd lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(M).eigenvalues();
    EXPECT_GT(lambda(0), 1e-10 * lambda(n - 1))
        << what << ": eigenvalues " << lambda(0) << " .. " << lambda(n - 1);
  };
  for (int p = 1; p <= 6; ++p) {
    check(isotropic(p, hb::Space::tensor_product), "tensor p = " + std::to_string(p));
    check(isotropic(p, hb::Space::trunk), "trunk p = " + std::to_string(p));
  }
  check(anisotropic(), "anisotropic tensor");
  check(anisotropic(hb::Space::trunk), "anisotropic trunk");
}

// The tensor-product space Q_p shall contain every monomial xi^a eta^b zeta^c with a, b, c <= p
// (least-squares residual < 1e-12) and not xi^(p+1), p = 1..6; anisotropic Q_(2,4,3) every one
// with a <= 2, b <= 4, c <= 3 and not xi^3.
TEST(HierarchicHex, TensorProductReproducesItsMonomials) {
  auto check = [](std::array<int, 3> p) {
    const auto hex = hb::hierarchic_hex(p, hb::Space::tensor_product);
    std::vector<std::array<int, 3>> inside;
    for (int a = 0; a <= p[0]; ++a)
      for (int b = 0; b <= p[1]; ++b)
        for (int c = 0; c <= p[2]; ++c) inside.push_back({a, b, c});
    const auto residual = fit_residuals(hex, inside);
    for (std::size_t m = 0; m < inside.size(); ++m)
      EXPECT_LT(residual[m], 1e-12) << "p = " << p[0] << p[1] << p[2] << ", monomial "
                                    << inside[m][0] << inside[m][1] << inside[m][2];
    const auto outside = fit_residuals(hex, {{p[0] + 1, 0, 0}, {0, p[1] + 1, 0}, {0, 0, p[2] + 1}});
    for (double r : outside) EXPECT_GT(r, 1e-3) << "p = " << p[0] << p[1] << p[2];
  };
  for (int p = 1; p <= 6; ++p) check({p, p, p});
  check({2, 4, 3});
}

// The trunk space of degree p shall contain exactly the monomials of superlinear degree <= p
// (all of total degree <= p among them, and e.g. xi^p eta zeta): each fits to 1e-12, and every
// monomial with exponents <= p but superlinear degree p + 1 (xi^2 eta^(p−1), ...) does not,
// p = 1..6. With the counts of TrunkModeCount this is the whole space.
TEST(HierarchicHex, TrunkSpaceIsTheSerendipitySpace) {
  for (int p = 1; p <= 6; ++p) {
    const auto hex = isotropic(p, hb::Space::trunk);
    std::vector<std::array<int, 3>> inside, outside;
    for (int a = 0; a <= p; ++a)
      for (int b = 0; b <= p; ++b)
        for (int c = 0; c <= p; ++c) {
          const int d = superlinear_degree({a, b, c});
          if (d <= p) inside.push_back({a, b, c});
          if (d == p + 1) outside.push_back({a, b, c});
        }
    const auto r_in = fit_residuals(hex, inside);
    for (std::size_t m = 0; m < inside.size(); ++m)
      EXPECT_LT(r_in[m], 1e-12) << "p = " << p << ", monomial " << inside[m][0] << inside[m][1]
                                << inside[m][2];
    if (p >= 3) ASSERT_FALSE(outside.empty());
    const auto r_out = fit_residuals(hex, outside);
    for (std::size_t m = 0; m < outside.size(); ++m)
      EXPECT_GT(r_out[m], 1e-3) << "p = " << p << ", monomial " << outside[m][0] << outside[m][1]
                                << outside[m][2];
  }
}

// An edge or face degree above the element's degree along it, or below 1, and an element degree
// below 1 shall be a std::logic_error naming the bad value, in every build.
TEST(HierarchicHex, RejectsDegreesOutOfRange) {
  auto throws = [](const hb::HierarchicHex& hex, const std::string& what) {
    std::vector<double> N(4096);
    try {
      hex.evaluate(0.0, 0.0, 0.0, N.data(), nullptr, nullptr, nullptr);
      ADD_FAILURE() << "no error for " << what;
    } catch (const std::logic_error& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  auto hex = hb::hierarchic_hex({3, 4, 2}, hb::Space::tensor_product);
  hex.edge_degree[9] = 3;  // along zeta, p_zeta = 2
  throws(hex, "edge_degree[9] = 3 must lie in [1, 2]");
  hex = hb::hierarchic_hex({3, 4, 2}, hb::Space::tensor_product);
  hex.edge_degree[1] = 0;
  throws(hex, "edge_degree[1] = 0 must lie in [1, 4]");
  hex = hb::hierarchic_hex({3, 4, 2}, hb::Space::tensor_product);
  hex.face_degree[4] = {4, 3};  // F4 (xi, eta): at most (3, 4)
  throws(hex, "face_degree[4][0] = 4 must lie in [1, 3]");
  hex = hb::hierarchic_hex({3, 4, 2}, hb::Space::tensor_product);
  hex.face_degree[0] = {4, 3};  // F0 (eta, zeta): at most (4, 2)
  throws(hex, "face_degree[0][1] = 3 must lie in [1, 2]");
  hex = hb::hierarchic_hex({1, 1, 1}, hb::Space::tensor_product);
  hex.p[2] = 0;
  throws(hex, "got p = 1, 1, 0");
  // The bounds themselves are accepted.
  hex = hb::hierarchic_hex({3, 4, 2}, hb::Space::tensor_product);
  hex.face_degree[1] = {1, 2};
  hex.edge_degree[0] = 1;
  std::vector<double> N(hex.n_modes());
  EXPECT_NO_THROW(hex.evaluate(0.3, -0.2, 0.9, N.data(), nullptr, nullptr, nullptr));
}
