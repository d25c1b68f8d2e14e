// Assembly and direct solution of the linear elastic problem K u = f with prescribed values.
#pragma once

#include <Eigen/Dense>

#include "hpcontact/model/discretization.hpp"
#include "hpcontact/solve/linear_solver.hpp"

namespace hpcontact::model {

struct LinearSolveOptions {
  bool condense = false;  ///< statically condense internal modes before the global solve
  solve::LinearSolverKind solver = solve::LinearSolverKind::cholmod;
};

struct LinearSolution {
  Eigen::VectorXd u;  ///< every dof of every body, prescribed values included
  int n_system = 0;   ///< size of the system actually factorised (n_free or n_free_external)
  double assembly_seconds = 0, solve_seconds = 0;
};

/// Element stiffness of element q of a body (component-blocked local order).
Eigen::MatrixXd element_stiffness(const Body& body, int q);

/// Assembles K_ff (free × free, both triangles) and f_f - K_fc u_c over the free dofs.
void assemble_linear(const Discretization& d, solve::SparseMatrix& K, Eigen::VectorXd& f);

LinearSolution solve_linear(const Discretization& d, const LinearSolveOptions& options);

}  // namespace hpcontact::model
