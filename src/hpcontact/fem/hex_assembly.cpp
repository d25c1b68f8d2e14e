// Assembly of hexahedra element by element into triplets; Dirichlet dofs by elimination.
#include "hpcontact/fem/hex_assembly.hpp"

#include <algorithm>
#include <limits>

#include "hpcontact/core/error.hpp"
#include "hpcontact/fem/hex_elasticity.hpp"
#include "hpcontact/fem/hex_values.hpp"

namespace hpcontact::fem {

HexSystem assemble_hex_elasticity(const HexBody& body, const HexAssemblyOptions& options) {
  HPC_REQUIRE(body.dofs != nullptr, InputError, body.context, ": no dof map");
  const HexDofMap& dofs = *body.dofs;
  const int n_elements = static_cast<int>(body.maps.size());
  const int n_dofs = options.condense_internal ? 3 * dofs.n_external_modes() : dofs.n_dofs();
  HexSystem system;
  system.f = Eigen::VectorXd::Zero(n_dofs);
  std::vector<Eigen::Triplet<double>> triplets;
  for (int h = 0; h < n_elements; ++h) {
    const HexElementSpace& space = dofs.element(h);
    const std::array<int, 3> n_points = hex_gauss_points(space.hierarchic, body.maps[h]);
    mesh::check_hex_jacobian(body.maps[h], body.context, h,
                             std::max({n_points[0], n_points[1], n_points[2]}));
    const HexValues values = hex_values(space.hierarchic, body.maps[h], n_points);
    Eigen::MatrixXd K = hex_stiffness(values, body.material);
    Eigen::VectorXd f = hex_body_force(values, body.body_force);
    const int n = space.n_modes();
    // Global dof of each local dof (component-blocked) of the matrix assembled.
    std::vector<int> global;
    if (options.condense_internal) {
      CondensedElement c = condense(K, f, n, space.n_internal, 3);
      for (int local : c.external) global.push_back(3 * space.modes[local % n] + local / n);
      K = c.K;
      f = c.f;
      system.condensed.push_back(std::move(c));
    } else {
      for (int local = 0; local < 3 * n; ++local)
        global.push_back(3 * space.modes[local % n] + local / n);
    }
    for (size_t r = 0; r < global.size(); ++r) {
      system.f(global[r]) += f(r);
      for (size_t s = 0; s < global.size(); ++s) triplets.emplace_back(global[r], global[s], K(r, s));
    }
  }
  system.K.resize(n_dofs, n_dofs);
  system.K.setFromTriplets(triplets.begin(), triplets.end());
  return system;
}

Eigen::VectorXd HexSystem::recover(const HexDofMap& dofs, const Eigen::VectorXd& u) const {
  if (condensed.empty()) return u;
  Eigen::VectorXd all = Eigen::VectorXd::Zero(dofs.n_dofs());
  all.head(u.size()) = u;
  for (size_t h = 0; h < condensed.size(); ++h) {
    const CondensedElement& c = condensed[h];
    const HexElementSpace& space = dofs.element(static_cast<int>(h));
    const int n = space.n_modes();
    Eigen::VectorXd external(c.external.size());
    for (size_t r = 0; r < c.external.size(); ++r)
      external(r) = u(3 * space.modes[c.external[r] % n] + c.external[r] / n);
    const Eigen::VectorXd local = c.recover(external);
    for (int local_dof : c.internal)
      all(3 * space.modes[local_dof % n] + local_dof / n) = local(local_dof);
  }
  return all;
}

Eigen::MatrixXd solve_with_fixed_dofs(const Eigen::SparseMatrix<double>& K,
                                      const Eigen::VectorXd& f, const std::vector<int>& fixed,
                                      const Eigen::MatrixXd& values) {
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
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::MatrixXd rhs(n_free, n_cases);
  for (int d = 0; d < n; ++d)
    if (position[d] >= 0) rhs.row(position[d]).setConstant(f(d));
  for (int col = 0; col < n; ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, col); it; ++it) {
      const int row = static_cast<int>(it.row());
      if (position[row] < 0) continue;
      if (position[col] >= 0)
        triplets.emplace_back(position[row], position[col], it.value());
      else
        rhs.row(position[row]) -= it.value() * values.row(-1 - position[col]);
    }
  Eigen::SparseMatrix<double> K_ff(n_free, n_free);
  K_ff.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(K_ff);
  HPC_REQUIRE(ldlt.info() == Eigen::Success, NumericalError,
              "solve_with_fixed_dofs: the free block of the stiffness cannot be factorised");
  // A singular block (a rigid motion left free) factorises with pivots that are round-off:
  // refused below kSingularPivotRatio of their diagonal entries of P K Pᵀ, as solve/linear_solver
  // does with 1e-11. Lower here, since a slender solid's bending is a legitimately small pivot:
  // a cantilever of one hexahedron through its section, clamped, has the smallest ratio
  // 6.2e-8 at L = 100 h and 6.2e-12 at 1000 h (4 elements; 1.6e-11 to 2.0e-11 with 8 or 10;
  // it falls like (h/L)⁴, tests/verification/test_hex_cantilever.cpp), while a free box, beam or
  // octant (p = 1..8) gives negative pivots or positive ones <= 7.3e-16.
  constexpr double kSingularPivotRatio = 1e-13;
  const Eigen::VectorXd diagonal = ldlt.permutationP() * Eigen::VectorXd(K_ff.diagonal());
  for (int i = 0; i < n_free; ++i)
    HPC_REQUIRE(ldlt.vectorD()(i) > kSingularPivotRatio * diagonal(i), NumericalError,
                "solve_with_fixed_dofs: the free block of the stiffness is singular (pivot ",
                ldlt.vectorD()(i), " against the diagonal ", diagonal(i), ")");
  const Eigen::MatrixXd u_free = ldlt.solve(rhs);
  Eigen::MatrixXd u(n, n_cases);
  for (int d = 0; d < n; ++d)
    u.row(d) = position[d] >= 0 ? u_free.row(position[d]) : values.row(-1 - position[d]);
  return u;
}

}  // namespace hpcontact::fem
