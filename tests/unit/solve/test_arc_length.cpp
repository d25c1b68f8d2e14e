// The cylindrical arc-length method on a two-unknown snap-through with a closed-form path.
#include "hpcontact/solve/arc_length.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace hpcontact;

namespace {

/// R(x, λ) = g(x) − λ e₁ with g₁ = f(x₁) + c (x₁ − x₂), g₂ = c (x₂ − x₁) + x₂, f(s) = s − 2s² + s³,
/// c = 0.1: a softening spring f in series with a stiff one. R = 0 gives x₂ = c x₁/(1 + c) and
/// λ(x₁) = f(x₁) + c x₁/(1 + c), whose λ' = 3x₁² − 4x₁ + 1 + 1/11 vanishes at
/// x₁ = (4 ∓ √(16 − 12·12/11))/6 = 0.3821, 0.9513: a limit point at λ = 0.1806, the load
/// falls to 0.0886 and rises again (λ = 1 at x₁ = 1.705). The tangent is symmetric.
class SnapThrough final : public solve::LoadPathSystem {
public:
  static constexpr double c = 0.1;
  static double f(double s) { return s - 2 * s * s + s * s * s; }
  static double df(double s) { return 1 - 4 * s + 3 * s * s; }
  static double lambda_on_path(double x1) { return f(x1) + c * x1 / (1 + c); }

  int size() const override { return 2; }
  void set_load_factor(double lambda) override { lambda_ = lambda; }
  void evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& r, solve::SparseMatrix* K) override {
    r.resize(2);
    r(0) = f(x(0)) + c * (x(0) - x(1)) - lambda_;
    r(1) = c * (x(1) - x(0)) + x(1);
    if (!K) return;
    std::vector<Eigen::Triplet<double>> t = {
        {0, 0, df(x(0)) + c}, {0, 1, -c}, {1, 0, -c}, {1, 1, c + 1}};
    K->resize(2, 2);
    K->setFromTriplets(t.begin(), t.end());
  }
  Eigen::VectorXd load_derivative(const Eigen::VectorXd&) override { return Eigen::Vector2d(-1, 0); }

private:
  double lambda_ = 0;
};

}  // namespace

// Every arc-length step shall advance exactly its length, ‖x_n − x_{n−1}‖ = Δl_n (to 1e-12
// relative; the corrector solves the constraint exactly), end on the equilibrium path
// (λ_n = λ(x₁), x₂ = c x₁/(1 + c) to 1e-9), and the path shall pass the limit point: x₁ rises
// in every step while λ rises to 0.1806, falls to 0.0886 and rises to the target 1 (the last
// step, under load control at λ = 1, is exempt from the length).
TEST(ArcLength, EveryStepKeepsItsLengthOnTheEquilibriumPath) {
  SnapThrough system;
  Eigen::VectorXd x = Eigen::Vector2d::Zero();
  double lambda = 0;
  solve::ArcLengthOptions o;
  o.initial_length = 0.05;
  o.max_length = 0.1;
  o.reference_norm = 1;
  Eigen::VectorXd previous = x;
  std::vector<solve::ArcLengthStep> steps;
  std::vector<Eigen::VectorXd> states;
  const auto rep = solve::arc_length(system, x, lambda, o, [&](const Eigen::VectorXd& xs,
                                                                 const solve::ArcLengthStep& st) {
    steps.push_back(st);
    states.push_back(xs);
    return true;
  });
  ASSERT_TRUE(rep.reached) << rep.message;
  ASSERT_EQ(steps.size(), rep.steps.size());
  ASSERT_GE(steps.size(), 10u);
  EXPECT_EQ(lambda, 1.0);
  double peak = 0, valley = 1;
  bool passed_peak = false;
  for (size_t n = 0; n < steps.size(); ++n) {
    const Eigen::VectorXd& xn = states[n];
    const Eigen::VectorXd& xp = n ? states[n - 1] : previous;
    const double lam_prev = n ? steps[n - 1].lambda : 0.0;
    if (n + 1 < steps.size())
      EXPECT_NEAR((xn - xp).norm(), steps[n].length, 1e-12 * steps[n].length) << "step " << n;
    EXPECT_NEAR(steps[n].lambda, SnapThrough::lambda_on_path(xn(0)), 1e-9) << "step " << n;
    EXPECT_NEAR(xn(1), SnapThrough::c * xn(0) / (1 + SnapThrough::c), 1e-9) << "step " << n;
    EXPECT_GT(xn(0), xp(0)) << "step " << n;
    if (steps[n].lambda < lam_prev) passed_peak = true;
    if (!passed_peak) peak = std::max(peak, steps[n].lambda);
    if (passed_peak) valley = std::min(valley, steps[n].lambda);
  }
  std::printf("%zu arc-length steps, peak %.5f, valley %.5f\n", steps.size(), peak, valley);
  EXPECT_TRUE(passed_peak);
  // The steps sample the path; its extremes (0.1806, 0.0886) bound what they see.
  EXPECT_LT(peak, 0.1806 + 1e-4);
  EXPECT_GT(peak, 0.15);
  EXPECT_GT(valley, 0.0886 - 1e-4);
  EXPECT_LT(valley, 0.12);
  EXPECT_NEAR(x(0), 1.705, 1e-3);
}
