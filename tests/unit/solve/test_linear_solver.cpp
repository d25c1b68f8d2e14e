// Property tests of the sparse direct solvers: accuracy on SPD systems, rejection of singular
// and indefinite matrices, solver names.
#include "hpcontact/solve/linear_solver.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <cmath>
#include <string>
#include <vector>

#include "hpcontact/core/error.hpp"

using namespace hpcontact;
using solve::LinearSolver;
using solve::LinearSolverKind;
using solve::SparseMatrix;

namespace {

const std::vector<LinearSolverKind> kinds = {LinearSolverKind::cholmod, LinearSolverKind::ldlt};

std::string kind_name(LinearSolverKind k) { return k == LinearSolverKind::cholmod ? "cholmod" : "ldlt"; }

SparseMatrix from_triplets(int n, const std::vector<Eigen::Triplet<double>>& t) {
  SparseMatrix A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

/// The 2D five-point Laplacian on an m×m grid plus 0.1·I: SPD, condition number ~ 1e2·m²/π².
SparseMatrix laplacian_2d(int m) {
  std::vector<Eigen::Triplet<double>> t;
  auto id = [m](int i, int j) { return i * m + j; };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      t.emplace_back(id(i, j), id(i, j), 4.1);
      if (i > 0) t.emplace_back(id(i, j), id(i - 1, j), -1);
      if (i + 1 < m) t.emplace_back(id(i, j), id(i + 1, j), -1);
      if (j > 0) t.emplace_back(id(i, j), id(i, j - 1), -1);
      if (j + 1 < m) t.emplace_back(id(i, j), id(i, j + 1), -1);
    }
  return from_triplets(m * m, t);
}

}  // namespace

// Both solvers shall solve a small SPD system to 1e-12 relative error (condition number ~40,
// so the backward-stable factorisations give ~1e-14).
TEST(LinearSolver, SolvesSmallSpdSystem) {
  // A 3×3 SPD matrix with a known solution.
  const SparseMatrix A3 = from_triplets(
      3, {{0, 0, 4}, {0, 1, 1}, {1, 0, 1}, {1, 1, 3}, {1, 2, -1}, {2, 1, -1}, {2, 2, 2}});
  const Eigen::Vector3d x3(1, -2, 0.5);
  const SparseMatrix A = laplacian_2d(12);
  Eigen::VectorXd x(A.rows());
  for (int i = 0; i < x.size(); ++i) x(i) = std::sin(0.37 * i) + 0.1 * i;
  for (auto kind : kinds) {
    LinearSolver s(kind);
    s.factorize(A3);
    EXPECT_LE((s.solve(A3 * x3) - x3).norm(), 1e-12 * x3.norm()) << kind_name(kind);
    LinearSolver big(kind);
    big.factorize(A);
    const Eigen::VectorXd b = A * x;
    EXPECT_LE((big.solve(b) - x).norm(), 1e-12 * x.norm()) << kind_name(kind);
    // Factorise once, solve many right-hand sides.
    EXPECT_LE((big.solve(2 * b) - 2 * x).norm(), 1e-12 * 2 * x.norm()) << kind_name(kind);
  }
}

// Both solvers shall use only the lower triangle, as documented: a matrix whose upper triangle
// is garbage (or empty) gives the solution of the symmetric matrix.
TEST(LinearSolver, UsesTheLowerTriangle) {
  const Eigen::Vector3d x(1, -2, 0.5);
  const SparseMatrix full = from_triplets(
      3, {{0, 0, 4}, {0, 1, 1}, {1, 0, 1}, {1, 1, 3}, {1, 2, -1}, {2, 1, -1}, {2, 2, 2}});
  const SparseMatrix lower = from_triplets(3, {{0, 0, 4}, {1, 0, 1}, {1, 1, 3}, {2, 1, -1}, {2, 2, 2}});
  for (auto kind : kinds) {
    LinearSolver s(kind);
    s.factorize(lower);
    EXPECT_LE((s.solve(full * x) - x).norm(), 1e-12 * x.norm()) << kind_name(kind);
  }
}

// A singular matrix [[1,1],[1,1]] shall be a NumericalError for both kinds.
TEST(LinearSolver, SingularMatrixIsANumericalError) {
  const SparseMatrix A = from_triplets(2, {{0, 0, 1}, {0, 1, 1}, {1, 0, 1}, {1, 1, 1}});
  for (auto kind : kinds) {
    LinearSolver s(kind);
    EXPECT_THROW(s.factorize(A), NumericalError) << kind_name(kind);
  }
}

// A zero matrix, and a stiffness with an unconstrained rigid mode (1D chain, free ends), shall be
// NumericalErrors for both kinds.
TEST(LinearSolver, RankDeficientMatricesAreNumericalErrors) {
  const SparseMatrix zero = from_triplets(3, {{0, 0, 0}, {1, 1, 0}, {2, 2, 0}});
  std::vector<Eigen::Triplet<double>> t;
  const int n = 6;
  for (int i = 0; i + 1 < n; ++i) {  // springs between consecutive nodes, no support
    t.emplace_back(i, i, 1);
    t.emplace_back(i + 1, i + 1, 1);
    t.emplace_back(i, i + 1, -1);
    t.emplace_back(i + 1, i, -1);
  }
  const SparseMatrix chain = from_triplets(n, t);
  for (auto kind : kinds) {
    LinearSolver s(kind);
    EXPECT_THROW(s.factorize(zero), NumericalError) << kind_name(kind);
    LinearSolver c(kind);
    EXPECT_THROW(c.factorize(chain), NumericalError) << kind_name(kind);
  }
}

// An indefinite matrix [[1,2],[2,1]] shall be a NumericalError for both kinds (it is not a
// stiffness: LDLT would factorise it, but a negative pivot is refused).
TEST(LinearSolver, IndefiniteMatrixIsANumericalError) {
  const SparseMatrix A = from_triplets(2, {{0, 0, 1}, {0, 1, 2}, {1, 0, 2}, {1, 1, 1}});
  for (auto kind : kinds) {
    LinearSolver s(kind);
    EXPECT_THROW(s.factorize(A), NumericalError) << kind_name(kind);
  }
}

// cholmod_else_lu shall solve an indefinite but nonsingular matrix by LU (and stay with LU),
// solve a positive definite one by CHOLMOD, and still refuse a singular one.
TEST(LinearSolver, CholmodGivesWayToLuOnAnIndefiniteMatrix) {
  const SparseMatrix indefinite = from_triplets(2, {{0, 0, 1}, {0, 1, 2}, {1, 0, 2}, {1, 1, 1}});
  const SparseMatrix definite = from_triplets(2, {{0, 0, 2}, {0, 1, 1}, {1, 0, 1}, {1, 1, 2}});
  LinearSolver s(LinearSolverKind::cholmod_else_lu);
  s.factorize(definite);
  EXPECT_EQ(s.kind(), LinearSolverKind::cholmod);
  s.factorize(indefinite);
  EXPECT_EQ(s.kind(), LinearSolverKind::lu);
  const Eigen::Vector2d b(1, 5);  // [[1,2],[2,1]] x = b: x = (3, -1)
  const Eigen::VectorXd x = s.solve(b);
  EXPECT_NEAR(x(0), 3, 1e-14);
  EXPECT_NEAR(x(1), -1, 1e-14);
  const Eigen::MatrixXd X = s.solve_columns(Eigen::Matrix2d::Identity() * 3);
  EXPECT_LT((Eigen::MatrixXd(indefinite) * X - Eigen::Matrix2d::Identity() * 3).norm(), 1e-14);
  s.factorize(definite);  // LU from now on, still right
  EXPECT_EQ(s.kind(), LinearSolverKind::lu);
  EXPECT_LT((Eigen::MatrixXd(definite) * s.solve(b) - b).norm(), 1e-14);

  const SparseMatrix singular = from_triplets(2, {{0, 0, 1}, {0, 1, 1}, {1, 0, 1}, {1, 1, 1}});
  LinearSolver t(LinearSolverKind::cholmod_else_lu);
  EXPECT_THROW(t.factorize(singular), NumericalError);
}

// cholmod_else_lu shall factorise a matrix symmetric to round-off (asymmetry 1e-14 of the
// diagonal) by CHOLMOD, and give way to LU at one that is not (asymmetry 1e-6): the solution is
// then that of the matrix itself, not of its lower triangle, and LU stays.
TEST(LinearSolver, CholmodGivesWayToLuOnAnUnsymmetricMatrix) {
  auto matrix = [](double asymmetry) {
    return from_triplets(3, {{0, 0, 4}, {0, 1, 1 + asymmetry}, {1, 0, 1}, {1, 1, 3}, {1, 2, -1},
                             {2, 1, -1}, {2, 2, 2}});
  };
  const Eigen::Vector3d x(1, -2, 0.5);
  LinearSolver s(LinearSolverKind::cholmod_else_lu);
  s.factorize(matrix(1e-14));
  EXPECT_EQ(s.kind(), LinearSolverKind::cholmod);
  const SparseMatrix A = matrix(1e-6);
  s.factorize(A);
  EXPECT_EQ(s.kind(), LinearSolverKind::lu);
  EXPECT_EQ(s.factorizations(), 2);
  EXPECT_LE((s.solve(A * x) - x).norm(), 1e-14 * x.norm());
  s.factorize(matrix(0));
  EXPECT_EQ(s.kind(), LinearSolverKind::lu);
}

// symmetric_to_round_off shall measure the asymmetry against the diagonal entries of its row
// and column: 1e-9 √(a_ii a_jj) is over the tolerance, 1e-11 of it is not, whatever the scale.
TEST(LinearSolver, SymmetryIsRelativeToTheDiagonal) {
  for (const double scale : {1e-8, 1.0, 1e8}) {
    auto matrix = [scale](double asymmetry) {  // √(a_00 a_11) = 10 scale
      return from_triplets(2, {{0, 0, 4 * scale}, {0, 1, scale * (1 + 10 * asymmetry)}, {1, 0, scale},
                               {1, 1, 25 * scale}});
    };
    EXPECT_TRUE(solve::symmetric_to_round_off(matrix(0)));
    EXPECT_TRUE(solve::symmetric_to_round_off(matrix(1e-11)));
    EXPECT_FALSE(solve::symmetric_to_round_off(matrix(1e-9)));
  }
  EXPECT_FALSE(solve::symmetric_to_round_off(from_triplets(2, {{0, 1, 1e-300}})));  // no diagonal
}

// Solver names shall parse ("cholmod", "ldlt"); anything else is an InputError naming the key.
TEST(LinearSolver, KindFromName) {
  EXPECT_EQ(solve::linear_solver_kind("cholmod", "k"), LinearSolverKind::cholmod);
  EXPECT_EQ(solve::linear_solver_kind("ldlt", "k"), LinearSolverKind::ldlt);
  try {
    solve::linear_solver_kind("umfpack", "solver.linear");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("solver.linear"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("umfpack"), std::string::npos) << e.what();
  }
}

namespace {

/// Stiffness of a free chain of springs k_i between nodes i and i+1: singular (the translation
/// is a null vector) but, with stiffnesses not exactly representable, its last pivot is round-off
/// of either sign rather than an exact zero.
SparseMatrix free_chain(const std::vector<double>& k) {
  const int n = static_cast<int>(k.size()) + 1;
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i + 1 < n; ++i) {
    t.emplace_back(i, i, k[i]);
    t.emplace_back(i + 1, i + 1, k[i]);
    t.emplace_back(i, i + 1, -k[i]);
    t.emplace_back(i + 1, i, -k[i]);
  }
  return from_triplets(n, t);
}

}  // namespace

// A matrix singular in exact arithmetic whose zero pivot comes out as a tiny positive round-off
// value passes a test of the pivots' signs alone (23 of 50 random rank-one-deficient 8×8 SPD
// matrices passed CHOLMOD's); factorize() also refuses pivots below 1e-11 of their diagonal entry.
TEST(LinearSolver, RoundOffSingularMatrixIsANumericalError) {
  const std::vector<std::vector<double>> chains = {{0.1, 0.2, 0.3},
                                                   {1.1, 2.3, 0.7, 0.9, 1.3, 2.9, 0.1}};
  for (const auto& k : chains)
    for (auto kind : kinds) {
      LinearSolver s(kind);
      EXPECT_THROW(s.factorize(free_chain(k)), NumericalError)
          << kind_name(kind) << ", chain of " << k.size() << " springs";
    }
}

// The refused pivot names a row of the singular part: a free chain of springs (singular) beside an
// SPD block; the row reported is one of the chain's.
TEST(LinearSolver, SingularPivotNamesARowOfTheFreePart) {
  const std::vector<double> k = {1.1, 2.3, 0.7, 0.9};
  const SparseMatrix chain = free_chain(k), spd = laplacian_2d(4);
  const int nc = static_cast<int>(chain.rows()), ns = static_cast<int>(spd.rows());
  std::vector<Eigen::Triplet<double>> t;
  for (int c = 0; c < ns; ++c)
    for (SparseMatrix::InnerIterator it(spd, c); it; ++it) t.emplace_back(it.row(), it.col(), it.value());
  for (int c = 0; c < nc; ++c)
    for (SparseMatrix::InnerIterator it(chain, c); it; ++it)
      t.emplace_back(ns + it.row(), ns + it.col(), it.value());
  const SparseMatrix A = from_triplets(ns + nc, t);
  for (auto kind : kinds) {
    LinearSolver s(kind);
    EXPECT_THROW(s.factorize(A), NumericalError) << kind_name(kind);
    EXPECT_GE(s.last_singular_row(), ns) << kind_name(kind);
    EXPECT_LT(s.last_singular_row(), ns + nc) << kind_name(kind);
    s.factorize(spd);  // a good matrix afterwards clears it
    EXPECT_EQ(s.last_singular_row(), -1) << kind_name(kind);
  }
}

// A matrix with the pattern of the last one shall be factorised without a new symbolic
// analysis, and solved as accurately; a new pattern shall be analysed again.
TEST(LinearSolver, SamePatternKeepsTheSymbolicAnalysis) {
  for (auto kind : {LinearSolverKind::cholmod, LinearSolverKind::ldlt, LinearSolverKind::lu}) {
    LinearSolver s(kind);
    SparseMatrix A = laplacian_2d(8);
    const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(A.rows(), -1, 2);
    for (int k = 0; k < 3; ++k) {
      s.factorize(A);
      EXPECT_LE((s.solve(A * x) - x).norm(), 1e-12 * x.norm());
      A.coeffRef(5, 5) += 1.0;  // same pattern, new values
    }
    EXPECT_EQ(s.analyses(), 1);
    s.factorize(laplacian_2d(9));
    EXPECT_EQ(s.analyses(), 2);
  }
}

// A matrix equal to the one factorised last (pattern and values) shall keep its factors; one
// that differs in a single value, in place, shall be factorised anew and solved as accurately.
TEST(LinearSolver, EqualMatrixKeepsItsFactors) {
  for (auto kind : {LinearSolverKind::cholmod, LinearSolverKind::ldlt, LinearSolverKind::lu}) {
    LinearSolver s(kind);
    SparseMatrix A = laplacian_2d(8);
    const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(A.rows(), -1, 2);
    s.factorize(A);
    EXPECT_FALSE(s.kept_factors());
    s.factorize(SparseMatrix(A));  // an equal copy
    EXPECT_TRUE(s.kept_factors());
    EXPECT_EQ(s.factorizations(), 1);
    EXPECT_LE((s.solve(A * x) - x).norm(), 1e-12 * x.norm());
    A.coeffRef(7, 7) *= 1 + 1e-9;  // one value, barely
    s.factorize(A);
    EXPECT_FALSE(s.kept_factors());
    EXPECT_EQ(s.factorizations(), 2);
    EXPECT_LE((s.solve(A * x) - x).norm(), 1e-12 * x.norm());
  }
}

// A matrix refused is not kept: the same matrix again is factorised (and refused) again.
TEST(LinearSolver, RefusedMatrixIsNotKept) {
  LinearSolver s;
  const SparseMatrix A = from_triplets(2, {{0, 0, 1.0}, {1, 1, -1.0}});
  EXPECT_THROW(s.factorize(A), NumericalError);
  EXPECT_THROW(s.factorize(A), NumericalError);
  EXPECT_FALSE(s.kept_factors());
}

// The LU's halves (A⁻¹ = B F, P R A Q = L U) shall compose to A⁻¹ and give G A⁻¹ E as
// (Bᵀ Gᵀ)ᵀ (F E), against a dense LU, on an unsymmetric matrix whose rows are scaled over six
// orders (so the row scaling R and the pivoting both matter; its condition number ~1e6 after the
// scaling leaves ~1e-16 · 1e3: 1e-11).
TEST(LinearSolver, SplitSolvesComposeToTheInverse) {
  const int n = 60;
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    const double row_scale = std::pow(10.0, 3.0 * std::sin(0.7 * i));
    t.emplace_back(i, i, row_scale * (3 + 0.1 * i));
    if (i + 1 < n) t.emplace_back(i, i + 1, row_scale * -1.3);
    if (i > 0) t.emplace_back(i, i - 1, row_scale * -0.6);
    if (i + 7 < n) t.emplace_back(i, i + 7, row_scale * 0.4 * std::cos(double(i)));
  }
  const SparseMatrix A = from_triplets(n, t);
  LinearSolver lu(LinearSolverKind::lu);
  lu.factorize(A);
  ASSERT_TRUE(lu.splits_solves());
  EXPECT_FALSE(LinearSolver(LinearSolverKind::cholmod).splits_solves());
  const Eigen::MatrixXd A_dense(A);
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(n, 3), G = Eigen::MatrixXd::Zero(3, n);
  for (int k = 0; k < 3; ++k) {
    E(10 + 20 * k, k) = 1.0;
    E(11 + 20 * k, k) = -0.5;
    G(k, 15 + 20 * k) = 2.0;
    G(k, 3 + 20 * k) = 1.0;
  }
  const Eigen::MatrixXd exact = G * A_dense.fullPivLu().solve(E);
  const Eigen::MatrixXd split =
      lu.solve_back_transposed_columns(G.transpose()).transpose() * lu.solve_front_columns(E);
  EXPECT_LE((split - exact).norm(), 1e-11 * exact.norm());
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) b(i) = std::cos(0.3 * i);
  const Eigen::VectorXd x = A_dense.fullPivLu().solve(b);
  EXPECT_LE((lu.solve_back(lu.solve_front_columns(b)) - x).norm(), 1e-11 * x.norm());
}
