// Patch tests and polynomial reproduction of the p- and h-versions.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <sstream>

#include "hpcontact/model/discretization.hpp"
#include "hpcontact/model/linear_solve.hpp"
#include "hpcontact/post/fields.hpp"
#include "problems.hpp"

using namespace hpcontact;

namespace {

model::LinearSolution solve_problem(const model::ProblemSpec& spec, model::Discretization& d,
                            bool condense = false) {
  d = model::discretize(spec);
  model::LinearSolveOptions o;
  o.condense = condense;
  return model::solve_linear(d, o);
}

/// Sample points inside every element.
std::vector<std::array<double, 2>> sample_points() {
  return {{-0.9, -0.7}, {0.0, 0.0}, {0.3, -0.5}, {0.77, 0.61}, {-0.4, 0.95}, {1.0, 1.0}};
}

}  // namespace

// A linear displacement prescribed on the boundary of a distorted patch yields constant stress
// everywhere, for every degree p = 1..8 (tensor product and trunk space).
TEST(PatchTest, DirichletConstantStressOnDistortedMesh) {
  for (auto space : {model::ShapeSpace::tensor_product, model::ShapeSpace::trunk}) {
    for (int p = 1; p <= 8; ++p) {
      auto spec = test_problems::distorted_patch(p);
      spec.discretization.space = space;
      model::ConstraintSpec c;
      c.edge_sets = {"boundary"};
      c.ux = "0.001 + 0.002*x - 0.0005*y";
      c.uy = "-0.001 + 0.0015*x + 0.003*y";
      spec.bodies[0].constraints = {c};
      model::Discretization d;
      const auto sol = solve_problem(spec, d);
      const auto& body = d.bodies[0];
      const Eigen::Vector3d eps(0.002, 0.003, -0.0005 + 0.0015);
      const Eigen::Vector3d sigma = body.material.D() * eps;
      for (int q = 0; q < body.mesh.n_quads(); ++q)
        for (auto [xi, eta] : sample_points()) {
          const auto r = post::evaluate(body, q, xi, eta, sol.u);
          EXPECT_LT((r.stress - sigma).norm(), 1e-10 * sigma.norm())
              << "p = " << p << " element " << q << " at " << xi << ", " << eta;
        }
    }
  }
}

// A constant traction on one side with minimal supports gives the uniform stress state of a
// bar in tension on a distorted mesh (Neumann patch test), for p = 1..8.
TEST(PatchTest, NeumannUniformTensionOnDistortedMesh) {
  for (int p = 1; p <= 8; ++p) {
    auto spec = test_problems::distorted_patch(p);
    test_problems::hold_as_bar(spec.bodies[0], 150.0, 0.0);
    model::Discretization d;
    const auto sol = solve_problem(spec, d);
    for (int q = 0; q < d.bodies[0].mesh.n_quads(); ++q)
      for (auto [xi, eta] : sample_points()) {
        const auto r = post::evaluate(d.bodies[0], q, xi, eta, sol.u);
        EXPECT_LT((r.stress - Eigen::Vector3d(150, 0, 0)).norm(), 1e-10 * 150) << "p = " << p;
      }
  }
}

namespace {

/// Real and imaginary parts of n z^(n-1), z = x + iy, as muparser formulas (binomial expansion).
std::pair<std::string, std::string> power_terms(int n) {
  std::ostringstream re, im;
  re.precision(17);
  im.precision(17);
  re << "0";
  im << "0";
  const int m = n - 1;
  double binom = 1;
  for (int k = 0; k <= m; ++k) {
    // term: n * C(m,k) x^(m-k) (iy)^k ; i^k cycles 1, i, -1, -i
    const double c = n * binom;
    std::ostringstream mono;
    mono.precision(17);
    mono << c << "*x^" << (m - k) << "*y^" << k;
    switch (k % 4) {
      case 0: re << "+" << mono.str(); break;
      case 1: im << "+" << mono.str(); break;
      case 2: re << "-" << mono.str(); break;
      case 3: im << "-" << mono.str(); break;
    }
    binom = binom * (m - k) / (k + 1);
  }
  return {re.str(), im.str()};
}

}  // namespace

// A polynomial displacement of degree p that solves Navier's equations without body force,
// u = grad Re(z^(p+1)), is reproduced exactly (to round-off) by degree-p elements on a mesh of
// parallelograms, for p = 1..10; also with element 4 given from its upper right node, so that
// its edges to elements 2 and 3 run against theirs (odd edge modes with the orientation sign).
TEST(PolynomialReproduction, HarmonicGradientFieldOfDegreeP) {
  for (bool reversed : {false, true})
  for (int p = 1; p <= 10; ++p) {
    model::ProblemSpec spec;
    spec.file = "parallelograms";
    auto b = test_problems::body("plate", 1000.0, 0.3);
    // 2×2 parallelograms of the sheared square x + 0.3 y, y in [0, 1].
    int id = 1;
    for (int j = 0; j <= 2; ++j)
      for (int i = 0; i <= 2; ++i) test_problems::add_node(b, id++, 0.5 * i + 0.15 * j, 0.5 * j);
    test_problems::add_element(b, 1, 1, 2, 5, 4);
    test_problems::add_element(b, 2, 2, 3, 6, 5);
    test_problems::add_element(b, 3, 4, 5, 8, 7);
    test_problems::add_element(b, 4, 5, 6, 9, 8);
    if (reversed) test_problems::start_element_at(b, 4, 9);
    test_problems::add_edge_set(b, "boundary",
                          {{1, 2}, {2, 3}, {3, 6}, {6, 9}, {9, 8}, {8, 7}, {7, 4}, {4, 1}});
    const auto [re, im] = power_terms(p + 1);
    // u = grad Re(z^n) = (Re(n z^(n-1)), -Im(n z^(n-1)))
    model::ConstraintSpec c;
    c.edge_sets = {"boundary"};
    c.ux = re;
    c.uy = "-(" + im + ")";
    b.constraints = {c};
    spec.bodies.push_back(b);
    spec.discretization.degree = {p, p};
    model::Discretization d;
    const auto sol = solve_problem(spec, d);
    double max_err = 0, max_u = 0;
    for (int q = 0; q < 4; ++q)
      for (auto [xi, eta] : sample_points()) {
        const auto r = post::evaluate(d.bodies[0], q, xi, eta, sol.u);
        const std::complex<double> z(r.x.x(), r.x.y());
        const std::complex<double> w = double(p + 1) * std::pow(z, p);
        const Vec2 exact(w.real(), -w.imag());
        max_err = std::max(max_err, (r.u - exact).norm());
        max_u = std::max(max_u, exact.norm());
      }
    EXPECT_LT(max_err, 1e-10 * max_u) << "p = " << p << (reversed ? ", reversed edges" : "");
    if (reversed) {
      int opposite = 0;  // shared edges whose two elements run along it in opposite directions
      const auto& m = d.bodies[0].mesh;
      for (int e = 0; e < m.n_edges(); ++e)
        if (!m.edge(e).on_boundary())
          opposite += m.quad_edge_reversed(m.edge(e).quads[0], m.edge(e).local_edge[0]) !=
                      m.quad_edge_reversed(m.edge(e).quads[1], m.edge(e).local_edge[1]);
      EXPECT_EQ(opposite, 2);
    }
  }
}

// Lagrange Q4, Q8 and Q9 (isoparametric h-version) pass the Dirichlet patch test on the same
// distorted mesh.
TEST(PatchTest, IsoparametricElements) {
  for (auto el : {model::LagrangeElement::q4, model::LagrangeElement::q8, model::LagrangeElement::q9}) {
    auto spec = test_problems::distorted_patch(1);
    spec.discretization.method = model::Method::h;
    spec.discretization.element = el;
    model::ConstraintSpec c;
    c.edge_sets = {"boundary"};
    c.ux = "0.002*x";
    c.uy = "0.001*x - 0.001*y";
    spec.bodies[0].constraints = {c};
    model::Discretization d;
    const auto sol = solve_problem(spec, d);
    const Eigen::Vector3d sigma = d.bodies[0].material.D() * Eigen::Vector3d(0.002, -0.001, 0.001);
    for (int q = 0; q < 4; ++q)
      for (auto [xi, eta] : sample_points()) {
        const auto r = post::evaluate(d.bodies[0], q, xi, eta, sol.u);
        EXPECT_LT((r.stress - sigma).norm(), 1e-10 * sigma.norm());
      }
  }
}
