// Property tests of static condensation: condensed solve + recovery equals the full solve.
#include "hpcontact/fem/condensation.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>
#include <string>

#include "hpcontact/core/error.hpp"

using namespace hpcontact;

namespace {

/// Random symmetric positive definite matrix Q diag(lambda) Q^T with eigenvalues in [1, 10]
/// (condition number <= 10), reproducible.
Eigen::MatrixXd random_spd(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0), ev(1.0, 10.0);
  Eigen::MatrixXd M(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) M(i, j) = u(rng);
  const Eigen::MatrixXd Q = Eigen::HouseholderQR<Eigen::MatrixXd>(M).householderQ();
  Eigen::VectorXd lambda(n);
  for (int i = 0; i < n; ++i) lambda(i) = ev(rng);
  const Eigen::MatrixXd A = Q * lambda.asDiagonal() * Q.transpose();
  return 0.5 * (A + A.transpose());
}

Eigen::VectorXd random_vector(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v(i) = u(rng);
  return v;
}

}  // namespace

// Solving the condensed system and recovering the internal dofs shall give the solution of the
// full system to 1e-13 relative (condition number <= 10, so the round-off is ~10·1e-16·n), for
// several sizes, including no and all-but-one internal modes.
TEST(Condensation, CondensedSolvePlusRecoveryEqualsFullSolve) {
  unsigned seed = 1;
  for (auto [n_modes, n_internal] :
       std::vector<std::pair<int, int>>{{4, 0}, {7, 3}, {12, 5}, {20, 9}, {5, 4}}) {
    const int n = 2 * n_modes;
    const Eigen::MatrixXd K = random_spd(n, seed++);
    const Eigen::VectorXd f = random_vector(n, seed++);
    const Eigen::VectorXd u_full = K.llt().solve(f);
    const fem::CondensedElement c = fem::condense(K, f, n_modes, n_internal);
    const int ne = 2 * (n_modes - n_internal);
    ASSERT_EQ(static_cast<int>(c.external.size()), ne);
    ASSERT_EQ(static_cast<int>(c.internal.size()), 2 * n_internal);
    ASSERT_EQ(c.K.rows(), ne);
    // The condensed matrix (a Schur complement) is symmetric positive definite.
    EXPECT_LE((c.K - c.K.transpose()).norm(), 1e-14 * c.K.norm());
    EXPECT_EQ(Eigen::LLT<Eigen::MatrixXd>(c.K).info(), Eigen::Success);
    const Eigen::VectorXd u_e = c.K.llt().solve(c.f);
    const Eigen::VectorXd u = c.recover(u_e);
    EXPECT_LE((u - u_full).norm(), 1e-13 * u_full.norm())
        << n_modes << " modes, " << n_internal << " internal";
    // The external dofs are the first n_modes - n_internal of each component block.
    for (int r = 0; r < ne; ++r) {
      const int comp = r / (n_modes - n_internal), a = r % (n_modes - n_internal);
      EXPECT_EQ(c.external[r], comp * n_modes + a);
    }
  }
}

// Under the load λ f the condensed load is λ f_c and the recovery with load factor λ shall give
// the full solution of K u = λ f (to 1e-13 relative), for λ = 0, 0.37 and −2.
TEST(Condensation, RecoveryUnderALoadFactor) {
  const int n_modes = 9, n_internal = 4, n = 2 * n_modes;
  const Eigen::MatrixXd K = random_spd(n, 41);
  const Eigen::VectorXd f = random_vector(n, 42);
  const fem::CondensedElement c = fem::condense(K, f, n_modes, n_internal);
  for (double lambda : {0.0, 0.37, -2.0}) {
    const Eigen::VectorXd u_full = K.llt().solve(lambda * f);
    const Eigen::VectorXd u_e = c.K.llt().solve(lambda * c.f);
    EXPECT_LE((c.recover(u_e, lambda) - u_full).norm(), 1e-13 * std::max(1.0, u_full.norm()))
        << "lambda " << lambda;
  }
}

// With no internal modes condensation shall be the identity.
TEST(Condensation, NoInternalModesIsIdentity) {
  const Eigen::MatrixXd K = random_spd(8, 99);
  const Eigen::VectorXd f = random_vector(8, 100);
  const auto c = fem::condense(K, f, 4, 0);
  EXPECT_EQ((c.K - K).norm(), 0.0);
  EXPECT_EQ((c.f - f).norm(), 0.0);
  const Eigen::VectorXd u = random_vector(8, 101);
  EXPECT_EQ((c.recover(u) - u).norm(), 0.0);
}

// An internal block that is not positive definite shall be a NumericalError.
TEST(Condensation, IndefiniteInternalBlockIsRejected) {
  Eigen::MatrixXd K = random_spd(8, 7);
  K(3, 3) = -5;  // internal mode of component x
  EXPECT_THROW(fem::condense(K, random_vector(8, 8), 4, 1), NumericalError);
}
