// CHOLMOD running out of memory: whichever of its allocations fails, the solver says so (the
// system's size, what the factor needs) and the process goes on; a factor that will not fit is
// refused before it is allocated, with its estimate.
#include <gtest/gtest.h>

#include <SuiteSparse_config.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
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

/// The 3D seven-point Laplacian on an m×m×m grid plus 0.1·I (SPD): its factor grows like m⁴,
/// a 3D mesh's does.
solve::SparseMatrix laplacian_3d(int m) {
  std::vector<Eigen::Triplet<double>> t;
  auto node = [m](int i, int j, int k) { return (i * m + j) * m + k; };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      for (int k = 0; k < m; ++k) {
        const int r = node(i, j, k);
        t.emplace_back(r, r, 6.1);
        for (int d = -1; d <= 1; d += 2) {
          if (i + d >= 0 && i + d < m) t.emplace_back(r, node(i + d, j, k), -1);
          if (j + d >= 0 && j + d < m) t.emplace_back(r, node(i, j + d, k), -1);
          if (k + d >= 0 && k + d < m) t.emplace_back(r, node(i, j, k + d), -1);
        }
      }
  solve::SparseMatrix A(m * m * m, m * m * m);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

/// An FEM-like pattern: every node of an m×m×m grid coupled with its 26 neighbours, 3 unknowns
/// a node (a trilinear elasticity mesh's), diagonally dominant: more matrix entries per factor
/// entry than the Laplacian, so that the copies of A count.
solve::SparseMatrix trilinear_pattern(int m) {
  std::vector<Eigen::Triplet<double>> t;
  auto node = [m](int i, int j, int k) { return (i * m + j) * m + k; };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      for (int k = 0; k < m; ++k)
        for (int a = std::max(i - 1, 0); a <= std::min(i + 1, m - 1); ++a)
          for (int b = std::max(j - 1, 0); b <= std::min(j + 1, m - 1); ++b)
            for (int c = std::max(k - 1, 0); c <= std::min(k + 1, m - 1); ++c)
              for (int x = 0; x < 3; ++x)
                for (int y = 0; y < 3; ++y) {
                  const int r = 3 * node(i, j, k) + x, s = 3 * node(a, b, c) + y;
                  t.emplace_back(r, s, r == s ? 90.0 : -0.3);
                }
  solve::SparseMatrix A(3 * m * m * m, 3 * m * m * m);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

}  // namespace

// The analysis's estimate shall be what the factorisation takes: within 2 % of CHOLMOD's peak
// memory on the 3D Laplacian of 20³ and 30³ unknowns and on the trilinear pattern of 15³ nodes
// (10125 unknowns; measured: 0.1 % above the peak each; the Laplacians of 40³ and 50³, 185 and
// 503 MB: 0.0 %).
TEST(LinearSolverMemory, EstimateIsWhatTheFactorisationTakes) {
  for (const solve::SparseMatrix& A : {laplacian_3d(20), laplacian_3d(30), trilinear_pattern(15)}) {
    solve::LinearSolver solver(solve::LinearSolverKind::cholmod);
    solver.factorize(A);
    const solve::FactorMemory memory = solver.memory();
    EXPECT_GT(memory.factor_entries, 0.0);
    EXPECT_GT(memory.flops, memory.factor_entries);
    EXPECT_NEAR(memory.estimate_bytes / memory.peak_bytes, 1.0, 0.02) << A.rows();
  }
}

// Under an address-space limit (setrlimit RLIMIT_AS, in a child process) of what is in use plus
// 32 MB, the 3D Laplacian of 30³ unknowns, whose factor takes 60 MB, shall be refused after its
// analysis with a ResourceError that gives the estimate in GB, the memory available, its limit
// and what to do: not a failed allocation ("would run out", not "out of memory" from CHOLMOD's
// status), not a signal.
TEST(LinearSolverMemoryDeathTest, FactorBeyondTheLimitIsRefusedWithItsEstimate) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const solve::SparseMatrix A = laplacian_3d(30);
  auto refuse = [&A] {
    long pages = 0;
    std::ifstream("/proc/self/statm") >> pages;
    const rlim_t limit = static_cast<rlim_t>(pages) * sysconf(_SC_PAGESIZE) + (rlim_t{32} << 20);
    const rlimit r{limit, limit};
    if (setrlimit(RLIMIT_AS, &r) != 0) std::_Exit(3);
    solve::LinearSolver solver(solve::LinearSolverKind::cholmod);
    try {
      solver.factorize(A);
    } catch (const ResourceError& e) {
      std::fprintf(stderr, "%s\n", e.what());
      std::_Exit(0);
    }
    std::_Exit(1);
  };
  EXPECT_EXIT(refuse(), ::testing::ExitedWithCode(0),
              "the sparse Cholesky factorisation \\(CHOLMOD\\) of the system of 27000 unknowns "
              "\\([0-9]+ stored matrix entries\\) would run out of memory: its factor has "
              "4\\.1[0-9]e\\+06 entries and needs about 0\\.0[56][0-9]* GB with its workspace "
              "\\([0-9.]+ GFLOP to compute\\), but 0\\.0[0-3][0-9]* GB are available \\(the "
              "address-space limit \\(ulimit -v\\) of [0-9.]+ GB, [0-9.]+ GB of it in use\\)\\. "
              "Use fewer elements or a lower degree \\(or static condensation\\), or run where "
              "more memory is available");
}

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
