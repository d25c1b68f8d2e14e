// Quadrilateral mesh of one body: nodes, elements, edges with their exact curves, topology.
#pragma once

#include <array>
#include <string>
#include <unordered_map>
#include <vector>

#include "hpcontact/geometry/curve.hpp"

namespace hpcontact::mesh {

/// An edge of the mesh, oriented from v0 to v1 with v0 < v1 (node indices): the global direction.
struct Edge {
  int v0 = -1, v1 = -1;
  geometry::CurvePtr curve;  ///< oriented v0 -> v1; null for a straight edge
  std::array<int, 2> quads{-1, -1};       ///< adjacent elements (second is -1 on the boundary)
  std::array<int, 2> local_edge{-1, -1};  ///< local edge number (0..3) in each adjacent element
  bool on_boundary() const { return quads[1] < 0; }
};

/// Local edge e of a quadrilateral runs from local vertex kEdgeVertices[e][0] to [e][1]
/// (E1: V1->V2, E2: V2->V3, E3: V4->V3, E4: V1->V4; see basis/quad_modes.hpp).
inline constexpr int kEdgeVertices[4][2] = {{0, 1}, {1, 2}, {3, 2}, {0, 3}};

/// A curve given for the edge between two nodes (indices), oriented from a to b.
struct EdgeCurve {
  int a = -1, b = -1;
  geometry::CurvePtr curve;
};

/// Nodes and quadrilaterals by index (0-based); user ids are kept for messages.
class Mesh {
public:
  /// Builds topology and checks: elements counter-clockwise with positive area, curves on edges.
  /// `context` prefixes messages (e.g. "lame.yaml: bodies[0]"). Throws MeshError.
  Mesh(std::vector<Vec2> nodes, std::vector<int> node_ids, std::vector<std::array<int, 4>> quads,
       std::vector<int> quad_ids, const std::vector<EdgeCurve>& curves, std::string context);

  int n_nodes() const { return static_cast<int>(nodes_.size()); }
  int n_quads() const { return static_cast<int>(quads_.size()); }
  int n_edges() const { return static_cast<int>(edges_.size()); }

  const Vec2& node(int i) const { return nodes_[i]; }
  const std::vector<Vec2>& nodes() const { return nodes_; }
  const std::array<int, 4>& quad(int q) const { return quads_[q]; }
  const Edge& edge(int e) const { return edges_[e]; }
  int node_id(int i) const { return node_ids_[i]; }
  int quad_id(int q) const { return quad_ids_[q]; }
  const std::string& context() const { return context_; }

  /// Global edge of local edge e of element q, and whether its global direction is opposite.
  int quad_edge(int q, int e) const { return quad_edges_[q][e]; }
  bool quad_edge_reversed(int q, int e) const { return quad_edge_reversed_[q][e]; }

  /// Edge between nodes a and b (either order), or -1.
  int find_edge(int a, int b) const;
  /// Node index of a user id, or -1.
  int node_index(int id) const;
  /// Element index of a user id, or -1.
  int quad_index(int id) const;

  /// Point of edge e at global parameter t in [-1, 1] (t = -1 at v0).
  Vec2 edge_point(int e, double t) const;

  /// Size of the mesh: the diagonal of the smallest axis-parallel box around its nodes.
  double size() const;

private:
  /// MeshError for two elements whose corners lie at the same points (distinct node numbers).
  void refuse_stacked_elements() const;

  std::vector<Vec2> nodes_;
  std::vector<int> node_ids_;
  std::vector<std::array<int, 4>> quads_;
  std::vector<int> quad_ids_;
  std::vector<Edge> edges_;
  std::vector<std::array<int, 4>> quad_edges_;
  std::vector<std::array<bool, 4>> quad_edge_reversed_;
  std::unordered_map<long long, int> edge_of_pair_;
  std::unordered_map<int, int> node_of_id_, quad_of_id_;
  std::string context_;
};

}  // namespace hpcontact::mesh
