// Unique edges and faces of a hexahedral mesh and their orientation in each element.
#include "hpcontact/mesh/hex_topology.hpp"

#include <algorithm>

#include "hpcontact/core/error.hpp"

namespace hpcontact::mesh {

namespace {

/// A face's corners in its global axes and the orientation of the element's local face axes.
struct OrientedFace {
  std::array<int, 4> vertices;
  basis::HexFaceOrientation orientation;
};

/// Global axes of a face whose corners g are given in local face order, (s, t) = (-1,-1), (1,-1),
/// (1,1), (-1,1) (basis/hex_modes.hpp): the origin is the smallest node index m, S runs towards
/// its smaller neighbour n1, T towards the other n2. S runs along the local t exactly when m and
/// n1 share their s; an axis is flipped when the origin lies at +1 of the local coordinate
/// that the axis runs along.
OrientedFace orient_face(const std::array<int, 4>& g) {
  constexpr int kS[4] = {-1, 1, 1, -1}, kT[4] = {-1, -1, 1, 1};
  const int m = static_cast<int>(std::min_element(g.begin(), g.end()) - g.begin());
  const int next = (m + 1) % 4, prev = (m + 3) % 4;
  const int n1 = g[next] < g[prev] ? next : prev;
  const int n2 = n1 == next ? prev : next;
  OrientedFace face;
  face.vertices = {g[m], g[n1], g[(m + 2) % 4], g[n2]};
  face.orientation.swap = kS[m] == kS[n1];
  face.orientation.flip1 = face.orientation.swap ? kT[m] > 0 : kS[m] > 0;
  face.orientation.flip2 = face.orientation.swap ? kS[m] > 0 : kT[m] > 0;
  return face;
}

template <std::size_t n>
std::array<int, n> sorted(std::array<int, n> v) {
  std::sort(v.begin(), v.end());
  return v;
}

}  // namespace

HexTopology::HexTopology(std::vector<std::array<int, 8>> hexes, int n_nodes, std::string context)
    : n_nodes_(n_nodes), hexes_(std::move(hexes)), context_(std::move(context)) {
  HPC_REQUIRE(!hexes_.empty(), MeshError, context_, ": the mesh has no elements");
  const int n = n_hexes();
  hex_edges_.resize(n);
  hex_edge_reversed_.resize(n);
  hex_faces_.resize(n);
  hex_face_orientation_.resize(n);
  std::map<std::array<int, 8>, int> node_sets;  // sorted nodes -> element
  for (int h = 0; h < n; ++h) {
    const auto& v = hexes_[h];
    for (int k = 0; k < 8; ++k)
      HPC_REQUIRE(v[k] >= 0 && v[k] < n_nodes_, MeshError, context_, ": element ", h, " vertex V",
                  k, " refers to node ", v[k], ", outside [0, ", n_nodes_, ")");
    for (int a = 0; a < 8; ++a)
      for (int b = a + 1; b < 8; ++b)
        HPC_REQUIRE(v[a] != v[b], MeshError, context_, ": element ", h, " has node ", v[a],
                    " twice (as its vertices V", a, " and V", b,
                    "): a hexahedron needs 8 distinct nodes");
    const auto [it, inserted] = node_sets.emplace(sorted(v), h);
    HPC_REQUIRE(inserted, MeshError, context_, ": elements ", it->second, " and ", h,
                " have the same nodes: an element is given twice");

    for (int le = 0; le < 12; ++le) {
      const int a = v[basis::kHexEdgeVertices[le][0]], b = v[basis::kHexEdgeVertices[le][1]];
      const auto key = std::minmax(a, b);
      const auto [edge, added] = edge_of_pair_.emplace(std::pair(key.first, key.second), n_edges());
      if (added) edges_.push_back({key.first, key.second});
      hex_edges_[h][le] = edge->second;
      hex_edge_reversed_[h][le] = a > b;
    }

    for (int lf = 0; lf < 6; ++lf) {
      std::array<int, 4> corners;
      for (int k = 0; k < 4; ++k) corners[k] = v[basis::kHexFaceVertices[lf][k]];
      const OrientedFace oriented = orient_face(corners);
      const auto [face, added] = face_of_corners_.emplace(sorted(corners), n_faces());
      if (added) faces_.push_back({oriented.vertices, {h, -1}, {lf, -1}});
      HexFace& f = faces_[face->second];
      if (!added) {
        HPC_REQUIRE(f.hexes[1] < 0, MeshError, context_, ": the face with nodes ", corners[0], " ",
                    corners[1], " ", corners[2], " ", corners[3], " belongs to elements ",
                    f.hexes[0], ", ", f.hexes[1], " and ", h, ": a face has at most two");
        // Same corners in another cyclic order: the two faces are different quadrilaterals.
        HPC_REQUIRE(f.vertices == oriented.vertices, MeshError, context_, ": elements ", f.hexes[0],
                    " and ", h, " go round the face with nodes ", corners[0], " ", corners[1], " ",
                    corners[2], " ", corners[3],
                    " in different orders (a twisted or non-conforming face)");
        f.hexes[1] = h;
        f.local_face[1] = lf;
      }
      hex_faces_[h][lf] = face->second;
      hex_face_orientation_[h][lf] = oriented.orientation;
    }
  }
}

std::vector<int> HexTopology::boundary_faces() const {
  std::vector<int> boundary;
  for (int f = 0; f < n_faces(); ++f)
    if (faces_[f].on_boundary()) boundary.push_back(f);
  return boundary;
}

int HexTopology::find_edge(int a, int b) const {
  const auto it = edge_of_pair_.find(std::minmax(a, b));
  return it == edge_of_pair_.end() ? -1 : it->second;
}

int HexTopology::find_face(std::array<int, 4> corners) const {
  const auto it = face_of_corners_.find(sorted(corners));
  return it == face_of_corners_.end() ? -1 : it->second;
}

}  // namespace hpcontact::mesh
