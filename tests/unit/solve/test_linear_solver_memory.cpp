// CHOLMOD running out of memory: whichever of its allocations fails, the solver says so (the
// system's size, what the factor needs) and the process goes on.
#include <gtest/gtest.h>

#include <SuiteSparse_config.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "hpcontact/core/error.hpp"
#include "hpcontact/solve/linear_solver.hpp"

using namespace hpcontact;

namespace {

/// SuiteSparse's allocator, failing once `budget` allocations have been made (-1: never).
long budget = -1;
bool spend() { return budget < 0 || budget-- > 0; }
void* failing_malloc(size_t n) { return spend() ? std::malloc(n) : nullptr; }
void* failing_calloc(size_t n, size_t size) { return spend() ? std::calloc(n, size) : nullptr; }
void* failing_realloc(void* p, size_t n) { return spend() ? std::realloc(p, n) : nullptr; }

/// Installs the failing allocator for the life of the object.
struct FailingAllocator {
  decltype(SuiteSparse_config.malloc_func) malloc_ = SuiteSparse_config.malloc_func;
  decltype(SuiteSparse_config.calloc_func) calloc_ = SuiteSparse_config.calloc_func;
  decltype(SuiteSparse_config.realloc_func) realloc_ = SuiteSparse_config.realloc_func;
  FailingAllocator() {
    SuiteSparse_config.malloc_func = failing_malloc;
    SuiteSparse_config.calloc_func = failing_calloc;
    SuiteSparse_config.realloc_func = failing_realloc;
  }
  ~FailingAllocator() {
    SuiteSparse_config.malloc_func = malloc_;
    SuiteSparse_config.calloc_func = calloc_;
    SuiteSparse_config.realloc_func = realloc_;
    budget = -1;
  }
};

/// The 2D five-point Laplacian on an m×m grid plus 0.1·I (SPD).
solve::SparseMatrix laplacian(int m) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      const int k = i * m + j;
      t.emplace_back(k, k, 4.1);
      if (i > 0) t.emplace_back(k, k - m, -1);
      if (i + 1 < m) t.emplace_back(k, k + m, -1);
      if (j > 0) t.emplace_back(k, k - 1, -1);
      if (j + 1 < m) t.emplace_back(k, k + 1, -1);
    }
  solve::SparseMatrix A(m * m, m * m);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

}  // namespace

// Every allocation of the analysis, factorisation and solve in turn fails: each time the solver
// throws ResourceError naming the stage, "out of memory" and the size of the system, or, once
// the budget suffices, solves correctly.
TEST(LinearSolverMemory, EveryFailedAllocationIsReported) {
  const solve::SparseMatrix A = laplacian(30);
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(A.rows(), -1, 2);
  const Eigen::VectorXd b = A * x;
  int reported = 0;
  for (long n = 0;; ++n) {
    FailingAllocator failing;
    solve::LinearSolver solver(solve::LinearSolverKind::cholmod);
    budget = n;
    try {
      solver.factorize(A);
      const Eigen::VectorXd y = solver.solve(b);
      budget = -1;
      EXPECT_LE((y - x).norm(), 1e-10 * x.norm());
      break;
    } catch (const ResourceError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("out of memory"), std::string::npos) << m;
      EXPECT_NE(m.find("of the system of 900 unknowns"), std::string::npos) << m;
      ++reported;
    }
    ASSERT_LT(n, 10000) << "the solver never succeeded";
  }
  EXPECT_GT(reported, 3);
}
