// Elimination of prescribed unknowns: the free block copied column by column (no triplets: at
// 10⁵ unknowns of a 3D problem a triplet list is a gigabyte), the prescribed values moved to the
// right-hand side.
#include "hpcontact/solve/fixed_dofs.hpp"

#include <limits>

#include "hpcontact/core/error.hpp"

namespace hpcontact::solve {

Eigen::MatrixXd solve_with_fixed_dofs(const SparseMatrix& K, const Eigen::VectorXd& f,
                                      const std::vector<int>& fixed, const Eigen::MatrixXd& values,
                                      LinearSolver& solver) {
  const int n = static_cast<int>(K.rows()), n_cases = static_cast<int>(values.cols());
  HPC_REQUIRE(static_cast<int>(values.rows()) == static_cast<int>(fixed.size()), InputError,
              "solve_with_fixed_dofs: ", fixed.size(), " fixed dofs but ", values.rows(),
              " rows of values");
  // Each dof's index in the free list, or -1 - its index in `fixed`.
  constexpr int kUnset = std::numeric_limits<int>::max();
  std::vector<int> position(n, kUnset);
  for (size_t c = 0; c < fixed.size(); ++c) {
    HPC_REQUIRE(fixed[c] >= 0 && fixed[c] < n && position[fixed[c]] == kUnset, InputError,
                "solve_with_fixed_dofs: fixed dof ", fixed[c], " out of range or repeated");
    position[fixed[c]] = -1 - static_cast<int>(c);
  }
  int n_free = 0;
  for (int d = 0; d < n; ++d)
    if (position[d] == kUnset) position[d] = n_free++;

  // K_ff in column order (the free numbering keeps the order of rows within a column), only its
  // lower triangle where the solver reads no more (half the memory), and f_f − K_fc values.
  Eigen::MatrixXd rhs(n_free, n_cases);
  for (int d = 0; d < n; ++d)
    if (position[d] >= 0) rhs.row(position[d]).setConstant(f(d));
  SparseMatrix K_ff(n_free, n_free);
  const bool lower = solver.reads_lower_triangle();
  auto kept = [&](int row, int col) {
    return position[row] >= 0 && (!lower || position[row] >= position[col]);
  };
  Eigen::Index nnz = 0;
  for (int col = 0; col < n; ++col)
    if (position[col] >= 0)
      for (SparseMatrix::InnerIterator it(K, col); it; ++it) nnz += kept(it.row(), col);
  K_ff.reserve(nnz);
  for (int col = 0; col < n; ++col) {
    if (position[col] >= 0) K_ff.startVec(position[col]);
    for (SparseMatrix::InnerIterator it(K, col); it; ++it) {
      const int row = static_cast<int>(it.row());
      if (position[row] < 0) continue;
      if (position[col] >= 0) {
        if (kept(row, col)) K_ff.insertBack(position[row], position[col]) = it.value();
      } else
        rhs.row(position[row]) -= it.value() * values.row(-1 - position[col]);
    }
  }
  K_ff.finalize();

  Eigen::MatrixXd u(n, n_cases);
  Eigen::MatrixXd u_free(n_free, n_cases);
  if (n_free > 0) {
    solver.factorize(std::move(K_ff));
    u_free = solver.solve_columns(rhs);
  }
  for (int d = 0; d < n; ++d) {
    if (position[d] >= 0)
      u.row(d) = u_free.row(position[d]);
    else
      u.row(d) = values.row(-1 - position[d]);
  }
  return u;
}

Eigen::MatrixXd solve_with_fixed_dofs(const SparseMatrix& K, const Eigen::VectorXd& f,
                                      const std::vector<int>& fixed, const Eigen::MatrixXd& values) {
  LinearSolver solver(LinearSolverKind::cholmod);
  // A singular block (a rigid motion left free) factorises with pivots that are round-off,
  // refused by the solver below a ratio to their diagonal entries; 1e-13 here, not its 1e-11,
  // since a slender solid's bending is a legitimately small pivot: a cantilever of one
  // hexahedron through its section, clamped, has the smallest ratio 6.2e-8 at L = 100 h and
  // 6.2e-12 at 1000 h (4 elements; 1.6e-11 to 2.0e-11 with 8 or 10; it falls like (h/L)⁴,
  // tests/verification/test_hex_cantilever.cpp), while a free box, beam or octant (p = 1..8)
  // gives negative pivots or positive ones <= 7.3e-16.
  solver.set_singular_pivot_ratio(kSlenderSingularPivotRatio);
  return solve_with_fixed_dofs(K, f, fixed, values, solver);
}

}  // namespace hpcontact::solve
