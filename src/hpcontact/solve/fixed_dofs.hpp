// Linear systems with some unknowns prescribed: those eliminated, the rest solved by the shared
// sparse solver (CHOLMOD, as the 2D code).
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "hpcontact/solve/linear_solver.hpp"

namespace hpcontact::solve {

/// Solves K u = f with the unknowns `fixed` (no repeats) prescribed: for each column c of
/// `values` (n_fixed × n_cases), the free unknowns from K_ff u_f = f_f − K_fc values.col(c), one
/// factorisation of K_ff by `solver` (whose factors and figures stay for the caller: memory(),
/// a second solve with the same K_ff). K is symmetric, stored whole (UMFPACK's LU reads both
/// triangles; for CHOLMOD and LDLᵀ only the lower one of K_ff is copied). Returns every unknown,
/// n × n_cases. Throws InputError for a fixed index out of range or repeated, NumericalError when
/// K_ff is singular or (for CHOLMOD and LDLᵀ) not positive definite, ResourceError when its
/// factor will not fit in memory (LinearSolver::factorize).
Eigen::MatrixXd solve_with_fixed_dofs(const SparseMatrix& K, const Eigen::VectorXd& f,
                                      const std::vector<int>& fixed, const Eigen::MatrixXd& values,
                                      LinearSolver& solver);

/// The pivot ratio below which solve_with_fixed_dofs's own solver takes K_ff for singular
/// (LinearSolver::singular_pivot_ratio): lower than the solver's default for slender solids.
inline constexpr double kSlenderSingularPivotRatio = 1e-13;

/// The same with a CHOLMOD solver of its own, which refuses K_ff as singular below
/// kSlenderSingularPivotRatio.
Eigen::MatrixXd solve_with_fixed_dofs(const SparseMatrix& K, const Eigen::VectorXd& f,
                                      const std::vector<int>& fixed, const Eigen::MatrixXd& values);

}  // namespace hpcontact::solve
