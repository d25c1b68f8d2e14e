// Assembly of hexahedra element by element into a pattern built from the modes they couple.
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
  const int n_system_modes = options.condense_internal ? dofs.n_external_modes() : dofs.n_modes();
  const int n_dofs = 3 * n_system_modes;

  // The pattern, from the modes each element couples: the rows of dof 3 a + c are the dofs of
  // every mode that shares an element with mode a, in order. Built per mode (a ninth of the
  // entries) and the matrix's values added in place: a triplet list would take 16 bytes per
  // element matrix entry, twice the matrix at 10⁵ unknowns.
  std::vector<std::vector<int>> coupled(n_system_modes);
  for (int h = 0; h < n_elements; ++h) {
    std::vector<int> modes;
    for (int mode : dofs.element(h).modes)
      if (mode < n_system_modes) modes.push_back(mode);
    for (int a : modes) coupled[a].insert(coupled[a].end(), modes.begin(), modes.end());
  }
  Eigen::Index nnz = 0;
  for (auto& c : coupled) {
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
    nnz += 9 * static_cast<Eigen::Index>(c.size());
  }
  HexSystem system;
  system.f = Eigen::VectorXd::Zero(n_dofs);
  system.K.resize(n_dofs, n_dofs);
  system.K.reserve(nnz);
  for (int col = 0; col < n_dofs; ++col) {
    system.K.startVec(col);
    for (int mode : coupled[col / 3])
      for (int c = 0; c < 3; ++c) system.K.insertBack(3 * mode + c, col) = 0.0;
  }
  system.K.finalize();
  coupled = {};
  const int* outer = system.K.outerIndexPtr();
  const int* inner = system.K.innerIndexPtr();
  double* value = system.K.valuePtr();

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
      // Kept for the recovery of the internal modes, without its condensed matrix (assembled
      // here, and four times the rest of the element's data at p = 4).
      K.swap(c.K);
      f.swap(c.f);
      c.K.resize(0, 0);
      c.f.resize(0);
      system.condensed.push_back(std::move(c));
    } else {
      for (int local = 0; local < 3 * n; ++local)
        global.push_back(3 * space.modes[local % n] + local / n);
    }
    // The local rows in the order of their global dofs, found in each column by one sweep.
    const int ne = static_cast<int>(global.size());
    std::vector<int> by_row(ne);
    for (int r = 0; r < ne; ++r) by_row[r] = r;
    std::sort(by_row.begin(), by_row.end(), [&](int a, int b) { return global[a] < global[b]; });
    for (int s = 0; s < ne; ++s) {
      system.f(global[s]) += f(s);
      const int* position = inner + outer[global[s]];
      const int* end = inner + outer[global[s] + 1];
      for (int r : by_row) {
        while (position != end && *position < global[r]) ++position;  // a merge of two sorted lists
        HPC_ASSERT(position != end && *position == global[r], "hex assembly: dof ", global[r],
                   " missing from the pattern of column ", global[s]);
        value[position - inner] += K(r, s);
      }
    }
  }
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
