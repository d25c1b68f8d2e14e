// The linear elastic operator of a discretisation, and the direct solution of K u = f with it.
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "hpcontact/fem/condensation.hpp"
#include "hpcontact/model/discretization.hpp"
#include "hpcontact/solve/linear_solver.hpp"

namespace hpcontact::model {

/// Element stiffness of element q of a body (component-blocked local order).
Eigen::MatrixXd element_stiffness(const Body& body, int q);

/// The linear elastic part K u - f of a problem, assembled once over all dofs (the bodies of
/// linear elasticity; finite-strain bodies contribute nothing to K, only their loads). With static
/// condensation every element's internal modes are eliminated first (they are never prescribed
/// and belong to one element), so K and load act on the external dofs only and the unknowns
/// are the free external dofs; the internal ones are recovered afterwards.
struct ElasticOperator {
  struct CondensedElement {
    int body = -1, q = -1;
    fem::CondensedElement element;
  };

  solve::SparseMatrix K;  ///< n_dofs × n_dofs (condensed when condensing)
  Eigen::VectorXd load;   ///< external load per dof (condensed when condensing)
  int n_unknowns = 0;     ///< n_free, or n_free_external when condensing
  std::vector<CondensedElement> condensed;

  /// Index of a dof among the unknowns, or -1 (prescribed, or internal when condensing).
  int unknown(const Discretization& d, int dof) const {
    const int f = d.free_index[dof];
    return f >= 0 && f < n_unknowns ? f : -1;
  }
  /// All dofs: `lambda` × prescribed values, x on the unknowns, zero on condensed modes.
  Eigen::VectorXd expand(const Discretization& d, const Eigen::VectorXd& x, double lambda) const;
  /// The entries of a vector over all dofs that belong to unknowns.
  Eigen::VectorXd restrict(const Discretization& d, const Eigen::VectorXd& v) const;
  /// K restricted to the unknowns.
  solve::SparseMatrix unknown_block(const Discretization& d) const;
  /// Fills the condensed internal modes of u, the load scaled by lambda (no-op if not condensing).
  void recover_internal(const Discretization& d, Eigen::VectorXd& u, double lambda) const;
};

/// The small-strain bodies' stiffness and loads. Stopped (core/stop.hpp) if a stop is requested
/// meanwhile: the elements are given up.
ElasticOperator assemble_elastic(const Discretization& d, bool condense);

struct LinearSolveOptions {
  bool condense = false;  ///< statically condense internal modes before the global solve
  solve::LinearSolverKind solver = solve::LinearSolverKind::cholmod;
};

struct LinearSolution {
  Eigen::VectorXd u;  ///< every dof of every body, prescribed values included
  int n_system = 0;   ///< size of the system actually factorised (n_free or n_free_external)
  double assembly_seconds = 0, solve_seconds = 0;
};

/// K u = f on the elastic operator. Stopped (core/stop.hpp) if a stop is requested while it
/// assembles or factorises.
LinearSolution solve_linear(const Discretization& d, const LinearSolveOptions& options);

}  // namespace hpcontact::model
