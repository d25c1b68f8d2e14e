// Topology of a hexahedral mesh: unique edges and faces with global orientations, per element.
//
// Global orientation rules (what lets neighbouring elements agree on edge and face modes,
// basis/hex_modes.hpp):
//   edge: runs from its smaller global node index v0 to the larger v1;
//   face: its global axes (S, T) start at its smallest global vertex; S runs towards the smaller
//         of that vertex's two neighbours on the face, T towards the other one.
// For each element, a local edge is reversed when its local direction (hex_modes.hpp) runs from
// the larger node to the smaller; a local face carries the HexFaceOrientation that maps its local
// axes (s, t) onto the face's global axes (S, T).
#pragma once

#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "hpcontact/basis/hex_modes.hpp"

namespace hpcontact::mesh {

/// An edge of a hexahedral mesh, oriented from v0 to v1 with v0 < v1 (node indices).
struct HexEdge {
  int v0 = -1, v1 = -1;
};

/// A face of a hexahedral mesh.
struct HexFace {
  /// Node indices in the face's global axes: the origin (smallest index), the end of S, the
  /// corner opposite the origin, the end of T; (S, T) = (-1,-1), (1,-1), (1,1), (-1,1).
  std::array<int, 4> vertices{-1, -1, -1, -1};
  std::array<int, 2> hexes{-1, -1};       ///< adjacent elements (second is -1 on the boundary)
  std::array<int, 2> local_face{-1, -1};  ///< local face number (0..5) in each adjacent element
  bool on_boundary() const { return hexes[1] < 0; }
};

/// Edges and faces of a conforming mesh of hexahedra given by node indices.
class HexTopology {
 public:
  /// Elements by their 8 node indices (0-based, in the vertex order of basis/hex_modes.hpp:
  /// VTK/Gmsh); nodes index [0, n_nodes). `context` prefixes messages. Throws MeshError for a node
  /// index out of range, an element with a repeated node, an element given twice, a face shared
  /// by more than two elements or by two whose corners go round it in different orders.
  HexTopology(std::vector<std::array<int, 8>> hexes, int n_nodes,
              std::string context = "hexahedral mesh");
  HexTopology() = default;  ///< no elements

  int n_nodes() const { return n_nodes_; }
  int n_hexes() const { return static_cast<int>(hexes_.size()); }
  int n_edges() const { return static_cast<int>(edges_.size()); }
  int n_faces() const { return static_cast<int>(faces_.size()); }

  const std::array<int, 8>& hex(int h) const { return hexes_[h]; }
  const HexEdge& edge(int e) const { return edges_[e]; }
  const HexFace& face(int f) const { return faces_[f]; }

  /// Global edge of local edge le (0..11) of element h, and whether its global direction is
  /// opposite to the local one.
  int hex_edge(int h, int le) const { return hex_edges_[h][le]; }
  bool hex_edge_reversed(int h, int le) const { return hex_edge_reversed_[h][le]; }
  /// Global face of local face lf (0..5) of element h, and the map of its local axes onto the
  /// face's global ones.
  int hex_face(int h, int lf) const { return hex_faces_[h][lf]; }
  basis::HexFaceOrientation hex_face_orientation(int h, int lf) const {
    return hex_face_orientation_[h][lf];
  }

  /// Faces with one element, in increasing order.
  std::vector<int> boundary_faces() const;
  /// Edge between nodes a and b (either order), or -1.
  int find_edge(int a, int b) const;
  /// Face with these four corners (any order), or -1.
  int find_face(std::array<int, 4> corners) const;

 private:
  int n_nodes_ = 0;
  std::vector<std::array<int, 8>> hexes_;
  std::vector<HexEdge> edges_;
  std::vector<HexFace> faces_;
  std::vector<std::array<int, 12>> hex_edges_;
  std::vector<std::array<bool, 12>> hex_edge_reversed_;
  std::vector<std::array<int, 6>> hex_faces_;
  std::vector<std::array<basis::HexFaceOrientation, 6>> hex_face_orientation_;
  std::map<std::pair<int, int>, int> edge_of_pair_;
  std::map<std::array<int, 4>, int> face_of_corners_;  ///< sorted corners -> face
  std::string context_;
};

}  // namespace hpcontact::mesh
