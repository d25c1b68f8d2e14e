// Parallel element loops: an exception leaves the OpenMP region as the error it is.
#include <gtest/gtest.h>

#include <atomic>
#include <string>
#include <vector>

#include "hpcontact/core/error.hpp"
#include "hpcontact/model/expression.hpp"
#include "hpcontact/model/parallel.hpp"

using namespace hpcontact;

TEST(ParallelFor, EveryIndexRunsOnce) {
  std::vector<std::atomic<int>> calls(1000);
  model::parallel_for(1000, [&](int i) { ++calls[i]; });
  for (const auto& c : calls) EXPECT_EQ(c.load(), 1);
}

// Several calls throw: the one of the smallest index reaches the caller, with its type and
// message, whatever the threads' timing (run repeatedly).
TEST(ParallelFor, SmallestFailingIndexIsRethrownAsItsType) {
  for (int repeat = 0; repeat < 20; ++repeat) {
    try {
      model::parallel_for(500, [](int i) {
        if (i % 97 == 41) throw NumericalError("element " + std::to_string(i));
        if (i == 300) throw std::bad_alloc();
      });
      FAIL() << "no exception";
    } catch (const NumericalError& e) {
      EXPECT_EQ(std::string(e.what()), "element 41");
    }
  }
}

// A user formula evaluated from the parallel element loop (a parametric curve's x(s) inside the
// assembly): every thread gets its own argument's value. The parser holds the variables, so
// unguarded evaluations overwrote each other's s (seen as a random "non-positive Jacobian" of
// curved elements in about one run in six).
TEST(ParallelFor, OneFormulaEvaluatedFromEveryThread) {
  const model::Expression f("2 + 0.3*s*(1 - s)", {"s"}, "curves[0].parametric.x");
  constexpr int n = 20000;
  std::vector<double> value(n);
  for (int repeat = 0; repeat < 5; ++repeat) {
    model::parallel_for(n, [&](int i) { value[i] = f(i / double(n)); });
    int wrong = 0;
    for (int i = 0; i < n; ++i) {
      const double s = i / double(n);
      wrong += value[i] != 2 + 0.3 * s * (1 - s);
    }
    EXPECT_EQ(wrong, 0);
  }
}
