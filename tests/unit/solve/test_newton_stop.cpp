// A stop request (core/stop.hpp) ends Newton's method before its next iteration, or inside one
// at a stop point of its assembly or factorisation (the iteration given up), with the iterate
// it had reached and a status of its own; without one the same system converges. A stop point
// acts only inside stoppable work, and leaves a factorisation it interrupts fit to be used.
#include <gtest/gtest.h>

#include <csignal>
#include <cmath>
#include <string>

#include "hpcontact/core/stop.hpp"
#include "hpcontact/solve/linear_solver.hpp"
#include "hpcontact/solve/newton.hpp"

using namespace hpcontact;

namespace {

/// R(x) = x³ − 8 (root 2); asks to stop when evaluated for the `stop_at`-th time (0: never),
/// and, if `assembly_point`, passes a stop point half way through each evaluation (as an
/// assembly loop between its elements).
class Cubic : public solve::NonlinearSystem {
public:
  explicit Cubic(int stop_at, bool assembly_point = false)
      : stop_at_(stop_at), assembly_point_(assembly_point) {}
  int size() const override { return 1; }
  void evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& r, solve::SparseMatrix* K) override {
    if (++evaluations == stop_at_) request_stop(SIGTERM);
    if (assembly_point_) stop_point("assembling");
    r.resize(1);
    r(0) = x(0) * x(0) * x(0) - 8;
    if (K) {
      K->resize(1, 1);
      K->setZero();
      K->insert(0, 0) = 3 * x(0) * x(0);
      K->makeCompressed();
    }
  }
  int evaluations = 0;

private:
  int stop_at_;
  bool assembly_point_;
};

/// The iterate after `steps` Newton steps from x0.
double newton_steps(double x0, int steps) {
  for (int k = 0; k < steps; ++k) x0 -= (x0 * x0 * x0 - 8) / (3 * x0 * x0);
  return x0;
}

}  // namespace

TEST(NewtonStop, EndsBeforeTheNextIterationWithTheIterateReached) {
  clear_stop();
  Cubic free(0);
  Eigen::VectorXd x = Eigen::VectorXd::Constant(1, 5.0);
  const auto done = solve::newton(free, x, {});
  ASSERT_TRUE(done.ok());
  EXPECT_NEAR(x(0), 2.0, 1e-9);  // to the default tolerance on |R|
  EXPECT_GT(done.iterations, 3);

  Cubic stopped(0);
  x = Eigen::VectorXd::Constant(1, 5.0);
  const auto rep = solve::newton(stopped, x, {}, [](int it, double, double, double) {
    if (it == 2) request_stop(SIGTERM);  // after the second iteration
  });
  EXPECT_EQ(rep.status, solve::SolveStatus::stopped);
  EXPECT_EQ(rep.iterations, 2);
  EXPECT_EQ(stopped.evaluations, 2);  // no evaluation after the request
  EXPECT_DOUBLE_EQ(x(0), newton_steps(5.0, 2));
  EXPECT_EQ(rep.message, "stopped by SIGTERM before Newton iteration 2");
  EXPECT_TRUE(stop_requested());
  EXPECT_EQ(stop_signal(), SIGTERM);
  clear_stop();
  EXPECT_FALSE(stop_requested());
  EXPECT_EQ(stop_signal(), 0);
}

// Asked during an iteration's work, Newton gives the iteration up at its next stop point — in the
// assembly, or before the factorisation — and ends at the iterate the iteration began from.
TEST(NewtonStop, AStopInsideAnIterationGivesItUp) {
  for (const bool assembly_point : {false, true}) {
    clear_stop();
    Cubic stopped(3, assembly_point);  // asks during the third evaluation: iteration 2's
    Eigen::VectorXd x = Eigen::VectorXd::Constant(1, 5.0);
    const auto rep = solve::newton(stopped, x, {});
    EXPECT_EQ(rep.status, solve::SolveStatus::stopped);
    EXPECT_EQ(rep.iterations, 2);
    EXPECT_EQ(rep.factorizations, 2);  // iteration 2's tangent never factorised
    EXPECT_EQ(stopped.evaluations, 3);
    EXPECT_DOUBLE_EQ(x(0), newton_steps(5.0, 2));
    EXPECT_EQ(rep.message, std::string("stopped by SIGTERM in Newton iteration 2 (while ") +
                               (assembly_point ? "assembling" : "factorising") + ")");
    clear_stop();
  }
}

// A stop point throws only while stoppable work lives: work that keeps a stopped run's results
// (writing last-good/) passes its stop points.
TEST(NewtonStop, StopPointsActOnlyInsideStoppableWork) {
  clear_stop();
  request_stop(SIGINT);
  EXPECT_NO_THROW(stop_point("assembling"));
  {
    const StoppableWork outer;
    {
      const StoppableWork inner;
    }
    try {
      stop_point("assembling");
      ADD_FAILURE() << "a stop point inside stoppable work passed a stop request";
    } catch (const Stopped& e) {
      EXPECT_EQ(std::string(e.what()), "stopped by SIGINT while assembling");
      EXPECT_EQ(e.doing(), "assembling");
    }
  }
  EXPECT_NO_THROW(stop_point("assembling"));
  clear_stop();
  const StoppableWork armed;
  EXPECT_NO_THROW(stop_point("assembling"));  // no request
}

// A factorisation given up at a stop point leaves the solver fit for the next: the same matrix
// factorised again (its pattern now analysed or not) solves the system exactly.
TEST(NewtonStop, AnInterruptedFactorisationLeavesTheSolverFit) {
  // the 1D Laplacian with a spring at one end, n = 50 (SPD)
  const int n = 50;
  solve::SparseMatrix A(n, n);
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, i == 0 ? 3.0 : 2.0);
    if (i > 0) t.emplace_back(i, i - 1, -1.0), t.emplace_back(i - 1, i, -1.0);
  }
  A.setFromTriplets(t.begin(), t.end());
  const Eigen::VectorXd x_exact = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  const Eigen::VectorXd b = A * x_exact;
  for (const auto kind : {solve::LinearSolverKind::cholmod, solve::LinearSolverKind::ldlt,
                          solve::LinearSolverKind::lu}) {
    solve::LinearSolver solver(kind);
    clear_stop();
    {
      const StoppableWork armed;
      request_stop(SIGTERM);
      EXPECT_THROW(solver.factorize(A), Stopped);
      clear_stop();
      solver.factorize(A);
    }
    EXPECT_LT((solver.solve(b) - x_exact).norm(), 1e-10 * x_exact.norm());
  }
}
