// Assembly of hexahedra element by element into triplets.
#include "hpcontact/fem/hex_assembly.hpp"

#include <algorithm>

#include "hpcontact/core/error.hpp"
#include "hpcontact/fem/hex_element.hpp"
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
    auto [K, f] = hex_element_matrices(space.hierarchic, body.maps[h], body.material,
                                       body.body_force, options.kernel);
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

}  // namespace hpcontact::fem
