// Reactions: which modes carry a force vector's resultant (the vertex modes alone, on the code's
// own basis), and the moment of a load on a curved edge from its nodal forces.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "hpcontact/basis/legendre.hpp"
#include "hpcontact/basis/quadrature.hpp"
#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/model/discretization.hpp"
#include "hpcontact/model/reactions.hpp"

using namespace hpcontact;

namespace {

/// A quarter annulus a = 10, b = 20 of two elements (exact arcs), a uniform traction (tx, ty)
/// on its inner arc, degree p; `method` p or h.
model::Discretization loaded_annulus(int p, const std::string& method, double tx, double ty) {
  const std::string yaml = R"(
case: arc-load
bodies:
  - name: ring
    material: {E: 200000, nu: 0.3, plane: strain}
    nodes: {1: [10, 0], 2: [20, 0], 3: [7.0710678118654755, 7.0710678118654755],
            4: [14.142135623730951, 14.142135623730951], 5: [0, 10], 6: [0, 20]}
    elements: {1: [1, 2, 4, 3], 2: [3, 4, 6, 5]}
    curves:
      - {nodes: [1, 3], arc: {center: [0, 0], radius: 10}}
      - {nodes: [3, 5], arc: {center: [0, 0], radius: 10}}
      - {nodes: [2, 4], arc: {center: [0, 0], radius: 20}}
      - {nodes: [4, 6], arc: {center: [0, 0], radius: 20}}
    edge_sets: {inner: [[1, 3], [3, 5]], bottom: [[1, 2]], left: [[5, 6]]}
    constraints:
      - {edges: [bottom], uy: 0}
      - {edges: [left], ux: 0}
    loads:
      - {edges: [inner], traction: [)" + std::to_string(tx) + ", " + std::to_string(ty) + R"(]}
discretization: {method: )" + method + ", degree: " + std::to_string(p) + R"(}
)";
  return model::discretize(io::parse_problem(yaml, "arc-load.yaml"));
}

}  // namespace

// The rule the resultants use: on the code's basis the two vertex modes of an edge sum to one
// and every higher mode vanishes at both ends, so the constant field 1 is the vertex modes alone
// and a force vector's resultant is the sum of its vertex entries. Its edge entries are not
// zero (∫ φ_2 ≠ 0 along the edge: "higher modes integrate to zero" is false for k = 2), so a sum
// over all modes is wrong.
TEST(Reactions, VertexModesAloneAreTheConstantField) {
  for (int p = 2; p <= 12; ++p) {
    std::vector<double> N(p + 1);
    for (int i = 0; i <= 40; ++i) {
      basis::hierarchic_1d(p, -1 + i / 20.0, N.data(), nullptr);
      EXPECT_NEAR(N[0] + N[1], 1.0, 1e-15) << "p = " << p;
    }
    for (double end : {-1.0, 1.0}) {
      basis::hierarchic_1d(p, end, N.data(), nullptr);
      for (int k = 2; k <= p; ++k) EXPECT_NEAR(N[k], 0.0, 1e-15) << "p = " << p << ", k = " << k;
    }
    double integral = 0;
    const auto& rule = basis::gauss_legendre(p + 2);
    for (int i = 0; i < rule.size(); ++i) {
      basis::hierarchic_1d(p, rule.points[i], N.data(), nullptr);
      integral += rule.weights[i] * N[2];
    }
    EXPECT_GT(std::abs(integral), 0.5) << "∫ φ_2 along the edge, p = " << p;
  }
}

// A uniform traction t on the quarter arc r = 10: its load vector's resultant weights give
// ∫ t ds = t R π/2 to quadrature accuracy (hierarchic: vertex entries; Lagrange Q8: every
// node's), while the sum of all its entries misses by the edge modes' share; its moment about the
// origin, from the nodal forces and the arc's coordinates projected onto the edge modes, is
// R² [t_y (sin θ1 − sin θ0) + t_x (cos θ1 − cos θ0)] = R² (t_y − t_x) to the projection's error,
// exponentially small in p.
TEST(Reactions, ResultantAndMomentOfALoadOnACurvedEdge) {
  const double R = 10, tx = 3, ty = -2, L = R * M_PI / 2;
  const double moment = R * R * (ty - tx);
  double previous = 1;
  for (int p : {4, 6, 8}) {
    const auto d = loaded_annulus(p, "p", tx, ty);
    const auto& body = d.bodies[0];
    const Eigen::VectorXd u = Eigen::VectorXd::Zero(d.n_dofs);
    const auto fm = model::force_and_moment(body, d.load, u);
    EXPECT_NEAR(fm.force.x(), tx * L, 1e-11 * L) << "p = " << p;
    EXPECT_NEAR(fm.force.y(), ty * L, 1e-11 * L) << "p = " << p;
    Vec2 all = Vec2::Zero();
    for (int m = 0; m < body.dofs.n_modes(); ++m) all += Vec2(d.load(2 * m), d.load(2 * m + 1));
    EXPECT_GT((all - Vec2(tx, ty) * L).norm(), 1e-3 * L) << "all modes, p = " << p;
    const double error = std::abs(fm.moment - moment) / std::abs(moment);
    EXPECT_LT(error, previous) << "p = " << p;
    previous = error;
  }
  EXPECT_LT(previous, 1e-12);  // measured at p = 4, 6, 8: 2.4e-8, 1.0e-11, 3.2e-15
  const auto q8 = loaded_annulus(2, "h", tx, ty);
  const auto fm = model::force_and_moment(q8.bodies[0], q8.load, Eigen::VectorXd::Zero(q8.n_dofs));
  // Q8's isoparametric arc is not the circle: its length to ~1e-3
  EXPECT_NEAR(fm.force.x(), tx * L, 1e-2 * L);
  EXPECT_NEAR(fm.force.y(), ty * L, 1e-2 * L);
}
