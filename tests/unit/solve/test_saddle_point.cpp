// The saddle-point solver against a dense LU of the whole system: constraints, multipliers fixed
// by their own rows, ties between multipliers, a force-target row, a body held only by its
// constraints, and the sparsity pattern kept between tangents.
#include "hpcontact/solve/saddle_point.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <random>
#include <vector>

#include "hpcontact/core/error.hpp"

using namespace hpcontact;
using solve::LinearSolver;
using solve::LinearSolverKind;
using solve::SaddlePointSolver;
using solve::SparseMatrix;

namespace {

/// A system of a chain of n springs (stiffness 1 + i/n, the first end held when `held`) and
/// m multiplier rows, as the contact system writes them.
struct Blocks {
  int n = 0, m = 0;
  std::vector<Eigen::Triplet<double>> t;
  Eigen::VectorXd gamma;

  Blocks(int n_, int m_, bool held) : n(n_), m(m_), gamma(Eigen::VectorXd::Zero(m_)) {
    for (int i = 0; i + 1 < n; ++i) {
      const double k = 1 + double(i) / n;
      t.emplace_back(i, i, k);
      t.emplace_back(i + 1, i + 1, k);
      t.emplace_back(i, i + 1, -k);
      t.emplace_back(i + 1, i, -k);
    }
    if (held) t.emplace_back(0, 0, 1.0);
  }
  /// Row k: g·Δu = … (a constraint on the unknowns `dofs`), augmented by γ; its force column
  /// E(:, k) = −g (the multiplier pushes along the constraint's gradient).
  void constraint(int k, const std::vector<std::pair<int, double>>& g, double g_scale, double gam,
                  std::vector<std::pair<int, double>> force = {}) {
    if (force.empty()) force = g;
    for (auto [i, v] : g) t.emplace_back(n + k, i, g_scale * v);
    for (auto [i, v] : force) t.emplace_back(i, n + k, -v);
    gamma(k) = gam;
  }
  /// Row k fixes its multiplier (an inactive node): H_kk = w, its force column still stored,
  /// its gradient stored as zeros.
  void fixed(int k, const std::vector<std::pair<int, double>>& g, double w) {
    for (auto [i, v] : g) {
      t.emplace_back(n + k, i, 0.0);
      t.emplace_back(i, n + k, -v);
    }
    t.emplace_back(n + k, n + k, w);
  }
  SparseMatrix J() const {
    SparseMatrix A(n + m, n + m);
    A.setFromTriplets(t.begin(), t.end());
    return A;
  }
};

Eigen::VectorXd random_vector(int size, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> dist(-1, 1);
  Eigen::VectorXd v(size);
  for (int i = 0; i < size; ++i) v(i) = dist(gen);
  return v;
}

double relative_error_against_dense(const Blocks& b, LinearSolverKind kind, unsigned seed) {
  const SparseMatrix J = b.J();
  LinearSolver sparse(kind);
  SaddlePointSolver s;
  s.factorize(sparse, J, b.n, b.gamma);
  const Eigen::VectorXd rhs = random_vector(b.n + b.m, seed);
  const Eigen::VectorXd x = s.solve(sparse, rhs);
  const Eigen::VectorXd x_dense = Eigen::MatrixXd(J).fullPivLu().solve(rhs);
  return (x - x_dense).norm() / x_dense.norm();
}

}  // namespace

// Constraints on a held chain, with and without augmentation, shall give J⁻¹ b to round-off
// (the chain's condition number is ~1e3, the strongest augmentation's 1/γ = 1e3: 1e-10).
TEST(SaddlePoint, ConstraintsEqualDenseSolve) {
  for (double gam : {0.0, 1e-3, 1.0}) {
    Blocks b(30, 3, true);
    b.constraint(0, {{5, 1.0}, {6, -0.5}}, 2.0, gam);
    b.constraint(1, {{12, 0.7}}, 1.0, gam);
    b.constraint(2, {{20, 1.0}, {29, 1.0}}, 3.0, gam);
    EXPECT_LT(relative_error_against_dense(b, LinearSolverKind::cholmod, 1), 1e-10) << gam;
    // the LU's split solves (LinearSolver::splits_solves) form S from the halves of A⁻¹
    EXPECT_LT(relative_error_against_dense(b, LinearSolverKind::lu, 1), 1e-10) << gam;
  }
}

// A chain held by nothing but a constraint is singular in K: the augmentation shall make the
// sparse block definite and the solve exact.
TEST(SaddlePoint, AugmentationHoldsAFloatingBody) {
  Blocks b(20, 2, false);
  b.constraint(0, {{0, 1.0}}, 1e3, 1e3);
  b.constraint(1, {{19, 1.0}}, 1e3, 1e3);
  EXPECT_LT(relative_error_against_dense(b, LinearSolverKind::cholmod, 2), 1e-11);
  EXPECT_LT(relative_error_against_dense(b, LinearSolverKind::lu, 2), 1e-11);
  Blocks unaugmented = b;
  unaugmented.gamma.setZero();
  LinearSolver sparse;
  SaddlePointSolver s;
  EXPECT_THROW(s.factorize(sparse, unaugmented.J(), unaugmented.n, unaugmented.gamma), NumericalError);
}

// Inactive multipliers (fixed by their own rows), a multiplier tied to another (a slipping
// node: its row H_kk z_k + H_kl z_l = …) and a target-force row without u-part (a load factor
// as the last unknown, its column the load) shall be eliminated or kept as the algebra says.
TEST(SaddlePoint, FixedTiedAndTargetRowsEqualDenseSolve) {
  const int n = 25;
  Blocks b(n, 5, true);
  b.constraint(0, {{8, 1.0}}, 5.0, 5.0);   // active normal node
  b.fixed(1, {{10, 1.0}}, 0.3);            // inactive node
  // slipping node: tangential multiplier 2 tied to normal multiplier 0: z_2 − 0.4 z_0 = …
  for (int i : {8, 9}) b.t.emplace_back(i, n + 2, -0.5);
  b.t.emplace_back(n + 2, n + 2, 2.0);
  b.t.emplace_back(n + 2, n + 0, -0.8);
  b.constraint(3, {{15, 1.0}, {16, 1.0}}, 1.0, 1.0);
  // load factor z_4: column = a load on dof 24, row: the resultant of multipliers 0 and 3
  b.t.emplace_back(24, n + 4, -1.0);
  b.t.emplace_back(n + 4, n + 0, 1.0);
  b.t.emplace_back(n + 4, n + 3, 2.0);
  SaddlePointSolver s;
  LinearSolver sparse;
  s.factorize(sparse, b.J(), b.n, b.gamma);
  EXPECT_EQ(s.n_eliminated(), 2);
  EXPECT_EQ(s.n_schur(), 3);
  EXPECT_LT(relative_error_against_dense(b, LinearSolverKind::cholmod, 3), 1e-12);
  EXPECT_LT(relative_error_against_dense(b, LinearSolverKind::lu, 4), 1e-12);
}

// Tangents that differ only in which constraints are active (inactive gradients stored as
// zeros) shall reuse one symbolic analysis.
TEST(SaddlePoint, ActiveSetChangeKeepsThePattern) {
  LinearSolver sparse;
  SaddlePointSolver s;
  for (int active = 0; active < 3; ++active) {
    Blocks b(40, 3, true);
    for (int k = 0; k < 3; ++k) {
      const std::vector<std::pair<int, double>> g{{10 * k + 3, 1.0}, {10 * k + 4, -1.0}};
      if (k <= active) b.constraint(k, g, 1.0, 1.0);
      else b.fixed(k, g, 1.0);
    }
    s.factorize(sparse, b.J(), b.n, b.gamma);
    const Eigen::VectorXd rhs = random_vector(b.n + b.m, 7);
    const Eigen::VectorXd x = s.solve(sparse, rhs);
    EXPECT_LT((b.J() * x - rhs).norm(), 1e-11 * rhs.norm());
  }
  EXPECT_EQ(sparse.analyses(), 1);
}

// Newton's tangents of a held body at small strain share K and the gradients of constraints
// linear in u: a second tangent shall solve only the columns of Ê that changed (here the one of
// a constraint whose gradient moved, and of one that became active), keep the others, and still
// give J⁻¹ b to round-off.
TEST(SaddlePoint, UnchangedColumnsAreKeptFromTheLastTangent) {
  LinearSolver sparse;
  SaddlePointSolver s;
  auto tangent = [](double moved, bool third_active) {
    Blocks b(40, 4, true);
    b.constraint(0, {{3, 1.0}, {4, -1.0}}, 1.0, 0.0);
    b.constraint(1, {{13, 1.0}, {14, moved}}, 1.0, 0.0);
    b.constraint(2, {{23, 1.0}}, 2.0, 0.0);
    if (third_active) b.constraint(3, {{33, 1.0}, {34, 1.0}}, 1.0, 0.0);
    else b.fixed(3, {{33, 1.0}, {34, 1.0}}, 1.0);
    return b;
  };
  const Eigen::VectorXd rhs = random_vector(44, 9);
  auto check = [&](const Blocks& b) {
    s.factorize(sparse, b.J(), b.n, b.gamma);
    const Eigen::VectorXd x = s.solve(sparse, rhs);
    const Eigen::VectorXd x_dense = Eigen::MatrixXd(b.J()).fullPivLu().solve(rhs);
    EXPECT_LT((x - x_dense).norm(), 1e-12 * x_dense.norm());
  };
  check(tangent(-1.0, false));
  EXPECT_EQ(s.columns_solved(), 3);
  check(tangent(-1.0, false));  // the same tangent
  EXPECT_TRUE(sparse.kept_factors());
  EXPECT_EQ(s.columns_solved(), 0);
  check(tangent(-0.5, true));  // multiplier 1's gradient moved, multiplier 3 active
  EXPECT_EQ(s.columns_solved(), 2);
  EXPECT_EQ(sparse.factorizations(), 1);
  // Another solver's factors: nothing is kept from a tangent solved with the first.
  LinearSolver other;
  s.factorize(other, tangent(-0.5, true).J(), 40, Eigen::VectorXd::Zero(4));
  EXPECT_EQ(s.columns_solved(), 4);
}

// Newton makes a new solver for each load step, on the stack, where the last one was: a solver
// in the same place that has factorised as often as the last one is not the same factors. The
// stiffness changed (a body's tangent at a new state), the constraints not: every column of Ê
// shall be solved again and the solve still give J⁻¹ b (reusing the last step's columns, as the
// solver's address and count allowed, it is off by the change).
TEST(SaddlePoint, ANewSolverInTheOldOnesPlaceKeepsNoColumns) {
  SaddlePointSolver s;
  std::optional<LinearSolver> sparse;
  const Eigen::VectorXd rhs = random_vector(42, 11);
  for (const double extra : {0.0, 3.0}) {
    Blocks b(40, 2, true);
    b.constraint(0, {{3, 1.0}, {4, -1.0}}, 1.0, 0.0);
    b.constraint(1, {{13, 1.0}, {14, -1.0}}, 1.0, 0.0);
    b.t.emplace_back(5, 5, extra);  // the stiffness of the second step
    sparse.reset();
    sparse.emplace();
    s.factorize(*sparse, b.J(), b.n, b.gamma);
    EXPECT_EQ(s.columns_solved(), 2) << extra;
    const Eigen::VectorXd x = s.solve(*sparse, rhs);
    const Eigen::VectorXd x_dense = Eigen::MatrixXd(b.J()).fullPivLu().solve(rhs);
    EXPECT_LT((x - x_dense).norm(), 1e-12 * x_dense.norm()) << extra;
  }
}
