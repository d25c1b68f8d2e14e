// A stop request (core/stop.hpp) ends Newton's method before its next iteration, with the
// iterate it had reached and a status of its own; without one the same system converges.
#include <gtest/gtest.h>

#include <csignal>
#include <cmath>

#include "hpcontact/core/stop.hpp"
#include "hpcontact/solve/newton.hpp"

using namespace hpcontact;

namespace {

/// R(x) = x³ − 8 (root 2); asks to stop when evaluated for the `stop_at`-th time (0: never).
class Cubic : public solve::NonlinearSystem {
public:
  explicit Cubic(int stop_at) : stop_at_(stop_at) {}
  int size() const override { return 1; }
  void evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& r, solve::SparseMatrix* K) override {
    if (++evaluations == stop_at_) request_stop(SIGTERM);
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
};

}  // namespace

TEST(NewtonStop, EndsBeforeTheNextIterationWithTheIterateReached) {
  clear_stop();
  Cubic free(0);
  Eigen::VectorXd x = Eigen::VectorXd::Constant(1, 5.0);
  const auto done = solve::newton(free, x, {});
  ASSERT_TRUE(done.ok());
  EXPECT_NEAR(x(0), 2.0, 1e-9);  // to the default tolerance on |R|
  EXPECT_GT(done.iterations, 3);

  Cubic stopped(3);  // asks during the third evaluation, i.e. in iteration 2
  x = Eigen::VectorXd::Constant(1, 5.0);
  const auto rep = solve::newton(stopped, x, {});
  EXPECT_EQ(rep.status, solve::SolveStatus::stopped);
  EXPECT_EQ(rep.iterations, 3);
  EXPECT_EQ(stopped.evaluations, 3);  // no evaluation after the request
  EXPECT_GT(std::abs(x(0) - 2.0), 1e-3);  // the iterate of the third step, not converged
  EXPECT_NE(rep.message.find("stopped by SIGTERM"), std::string::npos);
  EXPECT_TRUE(stop_requested());
  EXPECT_EQ(stop_signal(), SIGTERM);
  clear_stop();
  EXPECT_FALSE(stop_requested());
  EXPECT_EQ(stop_signal(), 0);
}
