// Mesh construction and topology checks.
#include "hpcontact/mesh/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "hpcontact/core/error.hpp"

namespace hpcontact::mesh {

namespace {
long long pair_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<long long>(a) << 32) | static_cast<unsigned>(b);
}

std::array<int, 4> sorted_corners(std::array<int, 4> v) {
  std::sort(v.begin(), v.end());
  return v;
}

/// Corners closer than this fraction of the element's diameter are one point.
constexpr double kCornerTolerance = 1e-8;
}  // namespace

Mesh::Mesh(std::vector<Vec2> nodes, std::vector<int> node_ids, std::vector<std::array<int, 4>> quads,
           std::vector<int> quad_ids, const std::vector<EdgeCurve>& curves, std::string context)
    : nodes_(std::move(nodes)),
      node_ids_(std::move(node_ids)),
      quads_(std::move(quads)),
      quad_ids_(std::move(quad_ids)),
      context_(std::move(context)) {
  HPC_ASSERT(nodes_.size() == node_ids_.size(), "ids ", node_ids_.size(), " nodes ", nodes_.size());
  HPC_ASSERT(quads_.size() == quad_ids_.size(), "ids ", quad_ids_.size(), " quads ", quads_.size());
  HPC_REQUIRE(!quads_.empty(), MeshError, context_, ": the mesh has no elements");
  for (int i = 0; i < n_nodes(); ++i) {
    HPC_REQUIRE(node_of_id_.emplace(node_ids_[i], i).second, MeshError, context_,
                ": duplicate node id ", node_ids_[i]);
  }
  quad_edges_.resize(quads_.size());
  quad_edge_reversed_.resize(quads_.size());
  std::map<std::array<int, 4>, int> corner_sets;  // sorted corners -> element id
  for (int q = 0; q < n_quads(); ++q) {
    HPC_REQUIRE(quad_of_id_.emplace(quad_ids_[q], q).second, MeshError, context_,
                ": duplicate element id ", quad_ids_[q]);
    const auto& v = quads_[q];
    for (int k = 0; k < 4; ++k) {
      HPC_REQUIRE(v[k] >= 0 && v[k] < n_nodes(), MeshError, context_, ": element ", quad_ids_[q],
                  " refers to a missing node");
    }
    // Distinct corners: two closer than a round-off of the element's size make it a triangle
    // (det J = 0 at that corner), whatever the sign test below says of the tiny edge.
    double diameter = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        diameter = std::max(diameter, (nodes_[v[i]] - nodes_[v[j]]).norm());
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        HPC_REQUIRE((nodes_[v[i]] - nodes_[v[j]]).norm() > kCornerTolerance * diameter, MeshError,
                    context_, ": element ", quad_ids_[q], " is degenerate: its corners ",
                    node_ids_[v[i]], " and ", node_ids_[v[j]], " are at one point (",
                    (nodes_[v[i]] - nodes_[v[j]]).norm(), " apart, the element's size is ",
                    diameter, ")");
    HPC_REQUIRE(corner_sets.emplace(sorted_corners(v), quad_ids_[q]).second, MeshError, context_,
                ": elements ", corner_sets[sorted_corners(v)], " and ", quad_ids_[q],
                " have the same corners: an element is given twice");
    // Counter-clockwise corners: every corner turns left (a convex, positively oriented polygon
    // of the vertices; curved edges are checked later through the Jacobian).
    for (int k = 0; k < 4; ++k) {
      const Vec2 a = nodes_[v[k]], b = nodes_[v[(k + 1) % 4]], c = nodes_[v[(k + 3) % 4]];
      const double cross = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
      HPC_REQUIRE(cross > 0, MeshError, context_, ": element ", quad_ids_[q],
                  " is inverted or degenerate at node ", node_ids_[v[k]],
                  " (its corners must be distinct and counter-clockwise, with every angle below 180°)");
    }
    for (int e = 0; e < 4; ++e) {
      const int a = v[kEdgeVertices[e][0]], b = v[kEdgeVertices[e][1]];
      auto [it, inserted] = edge_of_pair_.emplace(pair_key(a, b), n_edges());
      if (inserted) {
        Edge edge;
        edge.v0 = std::min(a, b);
        edge.v1 = std::max(a, b);
        edge.quads[0] = q;
        edge.local_edge[0] = e;
        edges_.push_back(edge);
      } else {
        Edge& edge = edges_[it->second];
        HPC_REQUIRE(edge.quads[1] < 0, MeshError, context_, ": the edge between nodes ",
                    node_ids_[a], " and ", node_ids_[b], " belongs to more than two elements");
        edge.quads[1] = q;
        edge.local_edge[1] = e;
      }
      quad_edges_[q][e] = it->second;
      quad_edge_reversed_[q][e] = a > b;
    }
  }
  refuse_stacked_elements();
  for (const auto& c : curves) {
    const int e = find_edge(c.a, c.b);
    HPC_REQUIRE(e >= 0, MeshError, context_, ": a curve is given between nodes ", node_ids_[c.a],
                " and ", node_ids_[c.b], ", which are not joined by an element edge");
    HPC_REQUIRE(!edges_[e].curve, MeshError, context_, ": two curves are given for the edge ",
                node_ids_[c.a], "-", node_ids_[c.b]);
    edges_[e].curve = c.a == edges_[e].v0 ? c.curve : c.curve->reversed();
    const double tol = 1e-8 * std::max(1.0, (nodes_[c.a] - nodes_[c.b]).norm());
    HPC_REQUIRE((c.curve->point(0.0) - nodes_[c.a]).norm() <= tol &&
                    (c.curve->point(1.0) - nodes_[c.b]).norm() <= tol,
                MeshError, context_, ": the curve ", c.curve->describe(), " of edge ",
                node_ids_[c.a], "-", node_ids_[c.b], " does not end at its nodes");
  }
}

int Mesh::find_edge(int a, int b) const {
  auto it = edge_of_pair_.find(pair_key(a, b));
  return it == edge_of_pair_.end() ? -1 : it->second;
}

int Mesh::node_index(int id) const {
  auto it = node_of_id_.find(id);
  return it == node_of_id_.end() ? -1 : it->second;
}

int Mesh::quad_index(int id) const {
  auto it = quad_of_id_.find(id);
  return it == quad_of_id_.end() ? -1 : it->second;
}

void Mesh::refuse_stacked_elements() const {
  // Elements of distinct nodes at the same points (the same corners by node number are refused
  // above): every corner of one within a round-off of its size of a corner of the other. By
  // centroid along x, each against those whose centroid is as close (the tolerance is relative
  // to the element, so that the tiny elements of a geometric grading are compared at their
  // own scale).
  struct Shape {
    double cx, diameter;
    int q;
  };
  std::vector<Shape> shapes;
  for (int q = 0; q < n_quads(); ++q) {
    Vec2 c = Vec2::Zero();
    double diameter = 0;
    for (int k = 0; k < 4; ++k) {
      c += 0.25 * nodes_[quads_[q][k]];
      for (int m = k + 1; m < 4; ++m)
        diameter = std::max(diameter, (nodes_[quads_[q][k]] - nodes_[quads_[q][m]]).norm());
    }
    shapes.push_back({c.x(), diameter, q});
  }
  std::sort(shapes.begin(), shapes.end(), [](const Shape& a, const Shape& b) { return a.cx < b.cx; });
  auto same_corners = [&](int a, int b, double tol) {
    for (int k = 0; k < 4; ++k) {
      bool found = false;
      for (int m = 0; m < 4 && !found; ++m)
        found = (nodes_[quads_[a][k]] - nodes_[quads_[b][m]]).norm() <= tol;
      if (!found) return false;
    }
    return true;
  };
  for (size_t i = 0; i < shapes.size(); ++i) {
    const double tol = kCornerTolerance * shapes[i].diameter;
    for (size_t j = i + 1; j < shapes.size() && shapes[j].cx - shapes[i].cx <= tol; ++j) {
      const int a = shapes[i].q, b = shapes[j].q;
      HPC_REQUIRE(!same_corners(a, b, tol), MeshError, context_, ": elements ", quad_ids_[a], " and ",
                  quad_ids_[b], " lie on one another (their corners are at the same points, nodes ",
                  node_ids_[quads_[a][0]], ", ", node_ids_[quads_[a][1]], ", ", node_ids_[quads_[a][2]],
                  ", ", node_ids_[quads_[a][3]], " and ", node_ids_[quads_[b][0]], ", ",
                  node_ids_[quads_[b][1]], ", ", node_ids_[quads_[b][2]], ", ", node_ids_[quads_[b][3]],
                  "): an element given twice, or nodes repeated under other numbers");
    }
  }
}

double Mesh::size() const {
  if (nodes_.empty()) return 0;
  Vec2 lo = nodes_.front(), hi = lo;
  for (const Vec2& x : nodes_) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  return (hi - lo).norm();
}

Vec2 Mesh::edge_point(int e, double t) const {
  const Edge& edge = edges_[e];
  if (edge.curve) return edge.curve->point(0.5 * (t + 1));
  return 0.5 * (1 - t) * nodes_[edge.v0] + 0.5 * (1 + t) * nodes_[edge.v1];
}

}  // namespace hpcontact::mesh
