// Global numbering of the nodal, edge and internal modes of one body, and each element's space.
#pragma once

#include <array>
#include <vector>

#include "hpcontact/basis/quad_modes.hpp"
#include "hpcontact/mesh/mesh.hpp"

namespace hpcontact::fem {

/// Which shape functions a body uses.
struct SpaceOptions {
  bool lagrange = false;  ///< true: isoparametric h-version; false: hierarchic p-version
  basis::LagrangeType lagrange_type = basis::LagrangeType::q8;
  basis::Space space = basis::Space::tensor_product;
  /// (p_xi, p_eta) per element (hierarchic only); one entry per element of the mesh.
  std::vector<std::array<int, 2>> degrees;
};

/// The shape functions of one element and the global mode of each of its local modes.
struct ElementSpace {
  bool is_lagrange = false;
  basis::HierarchicQuad hierarchic;
  basis::LagrangeType lagrange_type = basis::LagrangeType::q4;
  std::vector<int> modes;  ///< global mode per local mode, in the local order of basis/quad_modes.hpp
  int n_internal = 0;      ///< the last n_internal local modes are internal (bubble) modes

  int n_modes() const { return static_cast<int>(modes.size()); }
  /// Largest polynomial degree in either direction (2 for Q8/Q9, 1 for Q4).
  int max_degree() const;
  void evaluate(double xi, double eta, double* N, double* dN_dxi, double* dN_deta) const;
};

/// Mode numbering of one body: vertex modes first, then edge modes (edge by edge, by degree),
/// then internal modes (element by element), so internal modes can be condensed as one block.
/// Each mode carries two degrees of freedom: dof = 2 * mode + component (0 = x, 1 = y).
class DofMap {
public:
  DofMap(const mesh::Mesh& mesh, const SpaceOptions& options);

  int n_modes() const { return n_modes_; }
  int n_dofs() const { return 2 * n_modes_; }
  /// Modes below this index are vertex or edge modes; the rest are internal.
  int n_external_modes() const { return n_external_modes_; }

  const ElementSpace& element(int q) const { return elements_[q]; }
  int vertex_mode(int node) const { return vertex_mode_[node]; }
  /// Polynomial degree of an edge (minimum rule over its elements); 1 means no edge modes.
  int edge_degree(int edge) const { return edge_degree_[edge]; }
  /// Global mode of the edge mode of degree k (2..edge_degree) of an edge, in the edge's global
  /// direction (v0 -> v1).
  int edge_mode(int edge, int k) const { return edge_first_mode_[edge] + k - 2; }
  bool lagrange() const { return lagrange_; }

private:
  bool lagrange_ = false;
  int n_modes_ = 0, n_external_modes_ = 0;
  std::vector<int> vertex_mode_, edge_degree_, edge_first_mode_;
  std::vector<ElementSpace> elements_;
};

}  // namespace hpcontact::fem
