// Global numbering of the vertex, edge, face and internal modes of a hexahedral mesh.
#pragma once

#include <array>
#include <vector>

#include "hpcontact/basis/hex_modes.hpp"
#include "hpcontact/mesh/hex_topology.hpp"

namespace hpcontact::fem {

/// Which hierarchic hexahedra a body uses.
struct HexSpaceOptions {
  basis::Space space = basis::Space::tensor_product;
  /// (p_xi, p_eta, p_zeta) per element, along its local axes; one entry per element.
  std::vector<std::array<int, 3>> degrees;
};

/// The shape functions of one hexahedron and the global mode of each of its local modes.
struct HexElementSpace {
  basis::HierarchicHex hierarchic;  ///< with the mesh's edge/face degrees and orientations
  std::vector<int> modes;  ///< global mode per local mode, in the local order of hex_modes.hpp
  int n_internal = 0;      ///< the last n_internal local modes are internal (bubble) modes

  int n_modes() const { return static_cast<int>(modes.size()); }
};

/// Mode numbering of one hexahedral body: vertex modes first (by first use), then edge modes
/// (edge by edge, degree 2..edge_degree), then face modes (face by face, in the face's global
/// axes: i = 2..p_S outer, j = 2..p_T inner, trunk i + j <= max(p_S, p_T)), then internal modes
/// (element by element), so internal modes can be condensed as one block.
/// Minimum rule: an edge's degree is the smallest degree along it of the elements around it; a
/// face's degrees along its global axes (S, T) are the smaller of its two elements' degrees
/// along each.
/// Each mode carries three degrees of freedom: dof = 3 * mode + component (0 = x, 1 = y, 2 = z).
class HexDofMap {
 public:
  /// Throws InputError for a missing degree or one below 1, naming the element.
  HexDofMap(const mesh::HexTopology& topology, const HexSpaceOptions& options);

  int n_modes() const { return n_modes_; }
  int n_dofs() const { return 3 * n_modes_; }
  /// Modes below this index are vertex, edge or face modes; the rest are internal.
  int n_external_modes() const { return n_external_modes_; }

  const HexElementSpace& element(int h) const { return elements_[h]; }
  /// Global mode of a node's vertex mode; -1 for a node of no element.
  int vertex_mode(int node) const { return vertex_mode_[node]; }
  /// Polynomial degree of an edge (minimum rule); 1 means no edge modes.
  int edge_degree(int edge) const { return edge_degree_[edge]; }
  /// Global mode of the edge mode of degree k (2..edge_degree), in the edge's global direction.
  int edge_mode(int edge, int k) const { return edge_first_mode_[edge] + k - 2; }
  /// Degrees of a face along its global axes (S, T) (minimum rule).
  const std::array<int, 2>& face_degree(int face) const { return face_degree_[face]; }
  /// The face's modes are face_first_mode .. face_first_mode + n_face_modes - 1 in the order above.
  int face_first_mode(int face) const { return face_first_mode_[face]; }
  int n_face_modes(int face) const;
  /// Every mode that is non-zero on a face of `topology` (the map's own): its four vertex modes,
  /// the modes of its four edges, its face modes — what a condition on the face constrains.
  std::vector<int> modes_on_face(const mesh::HexTopology& topology, int face) const;

 private:
  basis::Space space_ = basis::Space::tensor_product;
  int n_modes_ = 0, n_external_modes_ = 0;
  std::vector<int> vertex_mode_, edge_degree_, edge_first_mode_, face_first_mode_;
  std::vector<std::array<int, 2>> face_degree_;
  std::vector<HexElementSpace> elements_;
};

}  // namespace hpcontact::fem
