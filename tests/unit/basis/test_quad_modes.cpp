// Unit tests of the hierarchic and Lagrange shape functions on the reference square [-1, 1]^2.
#include "hpcontact/basis/quad_modes.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "hpcontact/basis/legendre.hpp"
#include "hpcontact/basis/quadrature.hpp"

namespace hb = hpcontact::basis;

namespace {

struct Values {
  std::vector<double> N, dN_dxi, dN_deta;
};

Values evaluate(const hb::HierarchicQuad& quad, double xi, double eta) {
  const int n = quad.n_modes();
  Values v{std::vector<double>(n), std::vector<double>(n), std::vector<double>(n)};
  quad.evaluate(xi, eta, v.N.data(), v.dN_dxi.data(), v.dN_deta.data());
  return v;
}

Values evaluate(hb::LagrangeType type, double xi, double eta) {
  const int n = hb::lagrange_n_nodes(type);
  Values v{std::vector<double>(n), std::vector<double>(n), std::vector<double>(n)};
  hb::lagrange_evaluate(type, xi, eta, v.N.data(), v.dN_dxi.data(), v.dN_deta.data());
  return v;
}

/// Reproducible points inside the reference square.
std::vector<std::array<double, 2>> random_points(int n) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<std::array<double, 2>> points(n);
  for (auto& p : points) p = {u(rng), u(rng)};
  return points;
}

hb::HierarchicQuad isotropic(int p, hb::Space space) {
  hb::HierarchicQuad quad;
  quad.p_xi = quad.p_eta = p;
  quad.space = space;
  quad.edge_degree = {p, p, p, p};
  return quad;
}

/// Anisotropic element with reduced edge degrees (minimum rule) and two reversed edges.
hb::HierarchicQuad anisotropic() {
  hb::HierarchicQuad quad;
  quad.p_xi = 4;
  quad.p_eta = 6;
  quad.edge_degree = {3, 6, 4, 5};
  quad.edge_reversed = {true, false, false, true};
  return quad;
}

/// Index of the first mode of edge e (vertex modes first, then edges in order).
int first_edge_mode(const hb::HierarchicQuad& quad, int e) {
  int index = 4;
  for (int f = 0; f < e; ++f) index += quad.n_edge_modes(f);
  return index;
}

/// Point on edge e at its local parameter t, running in the direction of the header's sketch.
std::array<double, 2> point_on_edge(int e, double t) {
  switch (e) {
    case 0: return {t, -1.0};
    case 1: return {1.0, t};
    case 2: return {t, 1.0};
    default: return {-1.0, t};
  }
}

/// The edges on which a mode may be non-zero: two for a vertex mode, its own for an edge mode,
/// none for an internal mode.
std::vector<std::set<int>> mode_supports(const hb::HierarchicQuad& quad) {
  std::vector<std::set<int>> support{{0, 3}, {0, 1}, {1, 2}, {2, 3}};
  for (int e = 0; e < 4; ++e)
    for (int k = 0; k < quad.n_edge_modes(e); ++k) support.push_back({e});
  support.resize(quad.n_modes());
  return support;
}

/// L2 projection of f onto the span of the modes; returns the largest pointwise error.
double projection_error(const hb::HierarchicQuad& quad,
                        const std::function<double(double, double)>& f) {
  const int n = quad.n_modes();
  const auto& rule = hb::gauss_legendre(std::max(quad.p_xi, quad.p_eta) + 4);
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < rule.size(); ++i)
    for (int j = 0; j < rule.size(); ++j) {
      const double xi = rule.points[i], eta = rule.points[j];
      const double w = rule.weights[i] * rule.weights[j];
      const auto v = evaluate(quad, xi, eta);
      const Eigen::Map<const Eigen::VectorXd> N(v.N.data(), n);
      M += w * N * N.transpose();
      b += w * f(xi, eta) * N;
    }
  const Eigen::VectorXd c = M.ldlt().solve(b);
  if (!c.allFinite()) return std::numeric_limits<double>::infinity();
  double error = 0.0;
  for (auto [xi, eta] : random_points(50)) {
    const auto v = evaluate(quad, xi, eta);
    const double u = Eigen::Map<const Eigen::VectorXd>(v.N.data(), n).dot(c);
    error = std::max(error, std::abs(u - f(xi, eta)));
  }
  return error;
}

}  // namespace

// The tensor-product space of degrees (p_xi, p_eta) shall have (p_xi + 1)(p_eta + 1) modes.
TEST(HierarchicQuad, TensorProductModeCount) {
  for (int p = 1; p <= 10; ++p)
    EXPECT_EQ(isotropic(p, hb::Space::tensor_product).n_modes(), (p + 1) * (p + 1)) << "p = " << p;
  for (int p_xi = 1; p_xi <= 6; ++p_xi)
    for (int p_eta = 1; p_eta <= 6; ++p_eta) {
      hb::HierarchicQuad quad;
      quad.p_xi = p_xi;
      quad.p_eta = p_eta;
      quad.edge_degree = {p_xi, p_eta, p_xi, p_eta};
      EXPECT_EQ(quad.n_modes(), (p_xi + 1) * (p_eta + 1)) << p_xi << ", " << p_eta;
    }
}

// The trunk space of degree p >= 2 shall have 4p + (p-2)(p-3)/2 modes (17 for p = 4), the first
// internal mode appearing at p = 4.
TEST(HierarchicQuad, TrunkModeCount) {
  EXPECT_EQ(isotropic(1, hb::Space::trunk).n_modes(), 4);
  EXPECT_EQ(isotropic(4, hb::Space::trunk).n_modes(), 4 + 4 * 3 + 1);
  EXPECT_EQ(isotropic(3, hb::Space::trunk).n_internal_modes(), 0);
  for (int p = 2; p <= 12; ++p)
    EXPECT_EQ(isotropic(p, hb::Space::trunk).n_modes(), 4 * p + (p - 2) * (p - 3) / 2)
        << "p = " << p;
}

// With the minimum rule, each edge shall contribute edge_degree - 1 modes.
TEST(HierarchicQuad, ReducedEdgeDegreesModeCount) {
  const auto quad = anisotropic();
  EXPECT_EQ(quad.n_modes(), 4 + (2 + 5 + 3 + 4) + 3 * 5);
}

// Reference gradients shall agree with central finite differences of the values.
TEST(HierarchicQuad, GradientsMatchFiniteDifferences) {
  constexpr double h = 1e-6;
  // Modes up to degree 6 have third derivatives below ~1e3: truncation h^2/6 * 1e3 and
  // round-off eps/h are both below 1e-9.
  for (const auto& quad :
       {isotropic(5, hb::Space::tensor_product), isotropic(6, hb::Space::trunk), anisotropic()}) {
    for (auto [xi, eta] : random_points(20)) {
      const auto v = evaluate(quad, xi, eta);
      const auto xp = evaluate(quad, xi + h, eta), xm = evaluate(quad, xi - h, eta);
      const auto ep = evaluate(quad, xi, eta + h), em = evaluate(quad, xi, eta - h);
      for (int m = 0; m < quad.n_modes(); ++m) {
        EXPECT_NEAR(v.dN_dxi[m], (xp.N[m] - xm.N[m]) / (2 * h), 1e-8) << "mode " << m;
        EXPECT_NEAR(v.dN_deta[m], (ep.N[m] - em.N[m]) / (2 * h), 1e-8) << "mode " << m;
      }
    }
  }
}

// Null gradient arrays shall be accepted and leave the values unchanged.
TEST(HierarchicQuad, ValuesWithoutGradients) {
  const auto quad = anisotropic();
  const auto v = evaluate(quad, 0.3, -0.7);
  std::vector<double> N(quad.n_modes());
  quad.evaluate(0.3, -0.7, N.data(), nullptr, nullptr);
  EXPECT_EQ(N, v.N);
}

// Vertex mode i shall be 1 at vertex i and 0 at the others; all other modes shall vanish at
// the vertices; the vertex modes shall sum to 1 everywhere.
TEST(HierarchicQuad, VertexModesAreNodal) {
  const std::array<std::array<double, 2>, 4> vertices{{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}};
  for (const auto& quad : {isotropic(5, hb::Space::tensor_product), anisotropic()}) {
    for (int v = 0; v < 4; ++v) {
      const auto values = evaluate(quad, vertices[v][0], vertices[v][1]);
      for (int m = 0; m < quad.n_modes(); ++m)
        EXPECT_NEAR(values.N[m], m == v ? 1.0 : 0.0, 1e-15) << "vertex " << v << ", mode " << m;
    }
    for (auto [xi, eta] : random_points(10)) {
      const auto values = evaluate(quad, xi, eta);
      EXPECT_NEAR(values.N[0] + values.N[1] + values.N[2] + values.N[3], 1.0, 1e-15);
    }
  }
}

// Every mode shall vanish on each edge outside its support: vertex modes off their two edges,
// edge modes off their own edge, internal modes on the whole boundary.
TEST(HierarchicQuad, ModesVanishOutsideTheirEdges) {
  for (const auto& quad :
       {isotropic(6, hb::Space::tensor_product), isotropic(6, hb::Space::trunk), anisotropic()}) {
    const auto support = mode_supports(quad);
    for (int e = 0; e < 4; ++e)
      for (double t : {-1.0, -0.6, -0.1, 0.35, 0.9, 1.0}) {
        const auto [xi, eta] = point_on_edge(e, t);
        const auto values = evaluate(quad, xi, eta);
        for (int m = 0; m < quad.n_modes(); ++m)
          if (!support[m].contains(e)) {
            EXPECT_NEAR(values.N[m], 0.0, 1e-15) << "edge " << e << ", t = " << t << ", mode " << m;
          }
      }
  }
}

// Reversing an edge shall flip the sign of its odd-degree modes only, so that a reversed mode
// at edge parameter t equals the unreversed one at -t: neighbours share identical traces.
TEST(HierarchicQuad, ReversedEdgeFlipsOddModes) {
  for (int e = 0; e < 4; ++e) {
    auto forward = isotropic(7, hb::Space::tensor_product);
    auto reversed = forward;
    reversed.edge_reversed[e] = true;
    const int first = first_edge_mode(forward, e);
    for (auto [xi, eta] : random_points(10)) {
      const auto a = evaluate(forward, xi, eta), b = evaluate(reversed, xi, eta);
      for (int m = 0; m < forward.n_modes(); ++m) {
        const int k = m - first + 2;  // degree, if m is a mode of edge e
        const bool flips = m >= first && m < first + forward.n_edge_modes(e) && k % 2 == 1;
        EXPECT_EQ(b.N[m], flips ? -a.N[m] : a.N[m]) << "edge " << e << ", mode " << m;
        EXPECT_EQ(b.dN_dxi[m], flips ? -a.dN_dxi[m] : a.dN_dxi[m]);
        EXPECT_EQ(b.dN_deta[m], flips ? -a.dN_deta[m] : a.dN_deta[m]);
      }
    }
    for (double t : {-0.8, -0.25, 0.4, 0.95}) {
      const auto [xi_f, eta_f] = point_on_edge(e, t);
      const auto [xi_r, eta_r] = point_on_edge(e, -t);
      const auto a = evaluate(forward, xi_f, eta_f), b = evaluate(reversed, xi_r, eta_r);
      for (int k = 0; k < forward.n_edge_modes(e); ++k)
        EXPECT_NEAR(b.N[first + k], a.N[first + k], 1e-15) << "edge " << e << ", degree " << k + 2;
    }
  }
}

// Modes shall follow the documented order: each is the product of the 1D hierarchic functions
// named in the header, including degrees above the evaluator's stack buffer.
TEST(HierarchicQuad, ModeOrderMatchesOneDimensionalProducts) {
  for (int p : {3, 35}) {
    const auto quad = isotropic(p, hb::Space::tensor_product);
    const double xi = 0.37, eta = -0.61;
    std::vector<double> a(p + 1), b(p + 1);
    hb::hierarchic_1d(p, xi, a.data(), nullptr);
    hb::hierarchic_1d(p, eta, b.data(), nullptr);
    std::vector<double> expected{a[0] * b[0], a[1] * b[0], a[1] * b[1], a[0] * b[1]};
    for (int k = 2; k <= p; ++k) expected.push_back(a[k] * b[0]);  // E1
    for (int k = 2; k <= p; ++k) expected.push_back(a[1] * b[k]);  // E2
    for (int k = 2; k <= p; ++k) expected.push_back(a[k] * b[1]);  // E3
    for (int k = 2; k <= p; ++k) expected.push_back(a[0] * b[k]);  // E4
    for (int i = 2; i <= p; ++i)
      for (int j = 2; j <= p; ++j) expected.push_back(a[i] * b[j]);
    EXPECT_EQ(evaluate(quad, xi, eta).N, expected) << "p = " << p;
  }
}

// The tensor-product space Q_{p_xi, p_eta} shall reproduce xi^{p_xi} eta^{p_eta} exactly.
TEST(HierarchicQuad, TensorProductReproducesItsPolynomials) {
  auto f = [](double x, double y) { return x * x * x * y * y + x * y * y * y - 2.0; };
  EXPECT_LT(projection_error(isotropic(3, hb::Space::tensor_product), f), 1e-12);
  hb::HierarchicQuad quad;
  quad.p_xi = 2;
  quad.p_eta = 4;
  quad.edge_degree = {2, 4, 2, 4};
  auto g = [](double x, double y) { return x * x * std::pow(y, 4) + y; };
  EXPECT_LT(projection_error(quad, g), 1e-12);
}

// The trunk space of degree 4 shall reproduce all polynomials of total degree 4 plus xi^4 eta and
// xi eta^4, and nothing of degree (3, 2).
TEST(HierarchicQuad, TrunkSpaceContent) {
  const auto quad = isotropic(4, hb::Space::trunk);
  EXPECT_LT(projection_error(quad,
                             [](double x, double y) {
                               return 1.0 + x - y + x * x * y * y + x * y * y * y + std::pow(x, 4) +
                                      std::pow(x, 4) * y - 3.0 * x * std::pow(y, 4);
                             }),
            1e-12);
  EXPECT_GT(projection_error(quad, [](double x, double y) { return x * x * x * y * y; }), 1e-3);
}

// An edge degree above the element's degree along that edge, or below 1, and an element degree
// below 1 shall be a std::logic_error naming the bad value, in every build (release included).
TEST(HierarchicQuad, RejectsEdgeDegreeOutsideElementDegree) {
  auto throws = [](hb::HierarchicQuad quad, const std::string& what) {
    std::vector<double> N(std::max(1, quad.n_modes()) + 64);
    try {
      quad.evaluate(0.0, 0.0, N.data(), nullptr, nullptr);
      ADD_FAILURE() << "no error for " << what;
    } catch (const std::logic_error& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  auto quad = isotropic(3, hb::Space::tensor_product);
  quad.edge_degree[1] = 4;
  throws(quad, "edge_degree[1] = 4 must lie in [1, 3]");
  quad = isotropic(3, hb::Space::tensor_product);
  quad.p_xi = 2;  // E1 and E3 still at 3
  throws(quad, "edge_degree[0] = 3 must lie in [1, 2]");
  quad = isotropic(3, hb::Space::tensor_product);
  quad.edge_degree[3] = 0;
  throws(quad, "edge_degree[3] = 0 must lie in [1, 3]");
  quad = isotropic(1, hb::Space::tensor_product);
  quad.p_eta = 0;
  throws(quad, "got p_xi = 1, p_eta = 0");
  // The bounds themselves are accepted.
  quad = isotropic(3, hb::Space::tensor_product);
  quad.edge_degree = {3, 1, 2, 3};
  std::vector<double> N(quad.n_modes());
  EXPECT_NO_THROW(quad.evaluate(0.3, -0.2, N.data(), nullptr, nullptr));
}

// Lagrange nodes shall follow the documented order: vertices, mid-edges of E1..E4, centre.
TEST(Lagrange, NodeCountAndOrder) {
  EXPECT_EQ(hb::lagrange_n_nodes(hb::LagrangeType::q4), 4);
  EXPECT_EQ(hb::lagrange_n_nodes(hb::LagrangeType::q8), 8);
  EXPECT_EQ(hb::lagrange_n_nodes(hb::LagrangeType::q9), 9);
  const std::vector<std::array<double, 2>> q9{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, -1},
                                              {1, 0},   {0, 1},  {-1, 0}, {0, 0}};
  EXPECT_EQ(hb::lagrange_nodes(hb::LagrangeType::q9), q9);
  using Nodes = std::vector<std::array<double, 2>>;
  EXPECT_EQ(hb::lagrange_nodes(hb::LagrangeType::q8), Nodes(q9.begin(), q9.begin() + 8));
  EXPECT_EQ(hb::lagrange_nodes(hb::LagrangeType::q4), Nodes(q9.begin(), q9.begin() + 4));
}

constexpr std::array<hb::LagrangeType, 3> lagrange_types{hb::LagrangeType::q4, hb::LagrangeType::q8,
                                                         hb::LagrangeType::q9};

// Lagrange shape function i shall be 1 at node i and 0 at every other node.
TEST(Lagrange, KroneckerDeltaAtNodes) {
  for (auto type : lagrange_types) {
    const auto nodes = hb::lagrange_nodes(type);
    for (std::size_t j = 0; j < nodes.size(); ++j) {
      const auto v = evaluate(type, nodes[j][0], nodes[j][1]);
      for (std::size_t i = 0; i < nodes.size(); ++i)
        EXPECT_EQ(v.N[i], i == j ? 1.0 : 0.0) << "node " << j << ", function " << i;
    }
  }
}

// The shape functions shall sum to 1 and their gradients to 0 everywhere.
TEST(Lagrange, PartitionOfUnity) {
  for (auto type : lagrange_types)
    for (auto [xi, eta] : random_points(20)) {
      const auto v = evaluate(type, xi, eta);
      double sum = 0.0, sum_xi = 0.0, sum_eta = 0.0;
      for (std::size_t i = 0; i < v.N.size(); ++i) {
        sum += v.N[i];
        sum_xi += v.dN_dxi[i];
        sum_eta += v.dN_deta[i];
      }
      EXPECT_NEAR(sum, 1.0, 1e-15);
      EXPECT_NEAR(sum_xi, 0.0, 1e-14);
      EXPECT_NEAR(sum_eta, 0.0, 1e-14);
    }
}

// Reference gradients shall agree with central finite differences (exact for quadratics).
TEST(Lagrange, GradientsMatchFiniteDifferences) {
  constexpr double h = 1e-6;
  for (auto type : lagrange_types)
    for (auto [xi, eta] : random_points(20)) {
      const auto v = evaluate(type, xi, eta);
      const auto xp = evaluate(type, xi + h, eta), xm = evaluate(type, xi - h, eta);
      const auto ep = evaluate(type, xi, eta + h), em = evaluate(type, xi, eta - h);
      for (std::size_t i = 0; i < v.N.size(); ++i) {
        EXPECT_NEAR(v.dN_dxi[i], (xp.N[i] - xm.N[i]) / (2 * h), 1e-9);
        EXPECT_NEAR(v.dN_deta[i], (ep.N[i] - em.N[i]) / (2 * h), 1e-9);
      }
    }
}

// Interpolation at the nodes shall reproduce exactly, with gradients: bilinears for Q4, the
// serendipity space (quadratics plus x^2 y, x y^2) for Q8, biquadratics for Q9; Q8 shall not
// reproduce x^2 y^2.
TEST(Lagrange, ReproducesItsPolynomialSpace) {
  struct Case {
    hb::LagrangeType type;
    double c_x2y2;  // coefficient of x^2 y^2, zero unless the space contains it
    bool quadratic;
  };
  for (const auto& c :
       {Case{hb::LagrangeType::q4, 0.0, false}, Case{hb::LagrangeType::q8, 0.0, true},
        Case{hb::LagrangeType::q9, 0.7, true}}) {
    const double q = c.quadratic ? 1.0 : 0.0;
    // f = 1 + 2x - 3y + 0.5xy + q (x^2 - 4y^2 + 1.5x^2 y - 2x y^2) + c x^2 y^2.
    auto f = [&](double x, double y) {
      return 1 + 2 * x - 3 * y + 0.5 * x * y +
             q * (x * x - 4 * y * y + 1.5 * x * x * y - 2 * x * y * y) + c.c_x2y2 * x * x * y * y;
    };
    auto f_x = [&](double x, double y) {
      return 2 + 0.5 * y + q * (2 * x + 3 * x * y - 2 * y * y) + 2 * c.c_x2y2 * x * y * y;
    };
    auto f_y = [&](double x, double y) {
      return -3 + 0.5 * x + q * (-8 * y + 1.5 * x * x - 4 * x * y) + 2 * c.c_x2y2 * x * x * y;
    };
    const auto nodes = hb::lagrange_nodes(c.type);
    for (auto [xi, eta] : random_points(20)) {
      const auto v = evaluate(c.type, xi, eta);
      double u = 0.0, u_x = 0.0, u_y = 0.0;
      for (std::size_t i = 0; i < nodes.size(); ++i) {
        const double f_i = f(nodes[i][0], nodes[i][1]);
        u += f_i * v.N[i];
        u_x += f_i * v.dN_dxi[i];
        u_y += f_i * v.dN_deta[i];
      }
      EXPECT_NEAR(u, f(xi, eta), 1e-14);
      EXPECT_NEAR(u_x, f_x(xi, eta), 1e-13);
      EXPECT_NEAR(u_y, f_y(xi, eta), 1e-13);
    }
  }
  // Q8 interpolates x^2 y^2 by the sum of its corner functions, which differs at (0.5, 0.5).
  const auto nodes = hb::lagrange_nodes(hb::LagrangeType::q8);
  const auto v = evaluate(hb::LagrangeType::q8, 0.5, 0.5);
  double u = 0.0;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    u += std::pow(nodes[i][0] * nodes[i][1], 2) * v.N[i];
  EXPECT_GT(std::abs(u - 0.0625), 1e-3);
}

// mode_indices() names each mode by its 1D factors: at any point the mode is ± a_i(xi) b_j(eta)
// (the sign of a reversed edge's odd mode), for tensor and trunk spaces, reduced edge degrees
// and reversed edges alike; no two modes share a name.
TEST(HierarchicQuad, ModeIndicesNameTheFactorsOfEachMode) {
  hb::HierarchicQuad trunk = anisotropic();
  trunk.space = hb::Space::trunk;
  for (const auto& quad : {isotropic(6, hb::Space::tensor_product), isotropic(6, hb::Space::trunk),
                           anisotropic(), trunk}) {
    const auto ij = quad.mode_indices();
    ASSERT_EQ(static_cast<int>(ij.size()), quad.n_modes());
    const std::set<std::array<int, 2>> distinct(ij.begin(), ij.end());
    EXPECT_EQ(distinct.size(), ij.size());
    std::vector<double> a(quad.p_xi + 1), b(quad.p_eta + 1);
    for (const auto& [xi, eta] : random_points(20)) {
      hb::hierarchic_1d(quad.p_xi, xi, a.data(), nullptr);
      hb::hierarchic_1d(quad.p_eta, eta, b.data(), nullptr);
      const Values v = evaluate(quad, xi, eta);
      for (int m = 0; m < quad.n_modes(); ++m)
        EXPECT_NEAR(std::abs(v.N[m]), std::abs(a[ij[m][0]] * b[ij[m][1]]), 1e-14) << m;
    }
  }
}
