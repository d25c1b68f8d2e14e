// Hexahedral mode numbering: minimum rule on shared edges and faces, orientations from the mesh.
#include "hpcontact/fem/hex_dof_map.hpp"

#include <algorithm>
#include <climits>

#include "hpcontact/core/error.hpp"

namespace hpcontact::fem {

namespace {

/// Degrees of element face lf along the face's global axes (S, T): its degrees along the local
/// face axes (s, t), exchanged when the orientation swaps them.
std::array<int, 2> global_face_degrees(const std::array<int, 3>& p, int lf,
                                       const basis::HexFaceOrientation& o) {
  const int along_s = p[basis::kHexFaceAxes[lf][0]], along_t = p[basis::kHexFaceAxes[lf][1]];
  return o.swap ? std::array<int, 2>{along_t, along_s} : std::array<int, 2>{along_s, along_t};
}

}  // namespace

int HexDofMap::n_face_modes(int face) const {
  return basis::hex_face_mode_count(face_degree_[face][0], face_degree_[face][1], space_);
}

HexDofMap::HexDofMap(const mesh::HexTopology& topology, const HexSpaceOptions& options)
    : space_(options.space) {
  const int n_hexes = topology.n_hexes();
  HPC_REQUIRE(static_cast<int>(options.degrees.size()) == n_hexes, InputError,
              "hexahedral space: one triple of polynomial degrees per element is needed (got ",
              options.degrees.size(), " for ", n_hexes, " elements)");
  for (int h = 0; h < n_hexes; ++h) {
    const auto& p = options.degrees[h];
    HPC_REQUIRE(p[0] >= 1 && p[1] >= 1 && p[2] >= 1, InputError, "hexahedral space: element ", h,
                ": polynomial degrees must be >= 1 (got ", p[0], ", ", p[1], ", ", p[2], ")");
  }

  // Vertex modes: one per node used by an element, in order of first use.
  vertex_mode_.assign(topology.n_nodes(), -1);
  for (int h = 0; h < n_hexes; ++h)
    for (int v : topology.hex(h))
      if (vertex_mode_[v] < 0) vertex_mode_[v] = n_modes_++;

  // Minimum rule: an edge takes the smallest degree along it of its elements; a face the smaller
  // of its two elements' degrees along each of its global axes.
  edge_degree_.assign(topology.n_edges(), INT_MAX);
  face_degree_.assign(topology.n_faces(), {INT_MAX, INT_MAX});
  for (int h = 0; h < n_hexes; ++h) {
    const auto& p = options.degrees[h];
    for (int le = 0; le < 12; ++le) {
      int& degree = edge_degree_[topology.hex_edge(h, le)];
      degree = std::min(degree, p[basis::kHexEdgeAxis[le]]);
    }
    for (int lf = 0; lf < 6; ++lf) {
      const auto along = global_face_degrees(p, lf, topology.hex_face_orientation(h, lf));
      auto& degree = face_degree_[topology.hex_face(h, lf)];
      degree = {std::min(degree[0], along[0]), std::min(degree[1], along[1])};
    }
  }
  edge_first_mode_.resize(topology.n_edges());
  for (int e = 0; e < topology.n_edges(); ++e) {
    edge_first_mode_[e] = n_modes_;
    n_modes_ += edge_degree_[e] - 1;
  }
  face_first_mode_.resize(topology.n_faces());
  for (int f = 0; f < topology.n_faces(); ++f) {
    face_first_mode_[f] = n_modes_;
    n_modes_ += n_face_modes(f);
  }
  n_external_modes_ = n_modes_;

  // Element spaces: the element's degrees with the mesh's edge and face degrees (face degrees
  // back in the element's local face axes) and orientations; internal modes numbered last.
  elements_.resize(n_hexes);
  for (int h = 0; h < n_hexes; ++h) {
    HexElementSpace& es = elements_[h];
    basis::HierarchicHex& hex = es.hierarchic;
    hex.p = options.degrees[h];
    hex.space = options.space;
    for (int v : topology.hex(h)) es.modes.push_back(vertex_mode_[v]);
    for (int le = 0; le < 12; ++le) {
      const int e = topology.hex_edge(h, le);
      hex.edge_degree[le] = edge_degree_[e];
      hex.edge_reversed[le] = topology.hex_edge_reversed(h, le);
      for (int k = 2; k <= edge_degree_[e]; ++k) es.modes.push_back(edge_mode(e, k));
    }
    for (int lf = 0; lf < 6; ++lf) {
      const int f = topology.hex_face(h, lf);
      const auto o = topology.hex_face_orientation(h, lf);
      hex.face_orientation[lf] = o;
      hex.face_degree[lf] =
          o.swap ? std::array<int, 2>{face_degree_[f][1], face_degree_[f][0]} : face_degree_[f];
      for (int k = 0; k < n_face_modes(f); ++k) es.modes.push_back(face_first_mode_[f] + k);
    }
    es.n_internal = hex.n_internal_modes();
    for (int i = 0; i < es.n_internal; ++i) es.modes.push_back(n_modes_++);
    HPC_ASSERT(es.n_modes() == hex.n_modes(), "element ", h, ": ", es.n_modes(),
               " global modes for ", hex.n_modes(), " local ones");
  }
}

std::vector<int> HexDofMap::modes_on_face(const mesh::HexTopology& topology, int face) const {
  const auto& corners = topology.face(face).vertices;
  std::vector<int> modes;
  for (int c = 0; c < 4; ++c) {
    modes.push_back(vertex_mode(corners[c]));
    const int e = topology.find_edge(corners[c], corners[(c + 1) % 4]);
    for (int k = 2; k <= edge_degree(e); ++k) modes.push_back(edge_mode(e, k));
  }
  for (int k = 0; k < n_face_modes(face); ++k) modes.push_back(face_first_mode(face) + k);
  return modes;
}

}  // namespace hpcontact::fem
