// The Gauss points of a contact boundary, with the shape functions that live on them.
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "hpcontact/fem/dof_map.hpp"
#include "hpcontact/fem/out_of_plane.hpp"
#include "hpcontact/mesh/element_map.hpp"

namespace hpcontact::contact {

/// One point of a contact edge (undeformed configuration): a Gauss–Legendre point of the edge's
/// rule, or a multiplier node.
struct ContactPoint {
  int element = -1, local_edge = -1;
  int edge = -1;        ///< index of its edge in the contact boundary's list of edges
  double t = 0;         ///< local edge parameter in [-1, 1]
  double weight = 0;    ///< Gauss weight × ds/dt × thickness (2π r): ∫ f ds t ≈ Σ weight f
  Vec2 X;               ///< undeformed position
  Vec2 normal;          ///< undeformed outward unit normal of the body
  std::vector<int> modes;  ///< body modes whose shape function is non-zero on this edge
  Eigen::VectorXd N;       ///< their values at the point
};

/// The contact points of a set of boundary edges of one body, edge by edge in the order given,
/// n_points per edge (seed: 50, independent of p).
std::vector<ContactPoint> contact_points(const mesh::Mesh& mesh, const fem::DofMap& dofs,
                                         const std::vector<mesh::ElementMap>& maps,
                                         const std::vector<int>& edges, int n_points,
                                         const fem::OutOfPlane& thickness);

/// Points of one boundary edge at local edge parameters t (of the edge's first element), each
/// with weight w × ds/dt × thickness; `edge_index` is stored as ContactPoint::edge.
std::vector<ContactPoint> contact_points_at(const mesh::Mesh& mesh, const fem::DofMap& dofs,
                                            const std::vector<mesh::ElementMap>& maps, int edge,
                                            int edge_index, const std::vector<double>& t,
                                            const std::vector<double>& w, const fem::OutOfPlane& thickness);

/// A contact edge as one chain of a boundary path sees it: the mesh edge, its end vertices in
/// the chain's direction, and whether its local edge parameter runs against that direction.
struct ChainEdge {
  int edge = -1;
  int start = -1, end = -1;  ///< mesh vertices, in the chain's direction
  bool against = false;      ///< the local parameter t runs from `end` to `start`
  /// Its start is the previous edge's end (false for the first edge of a chain).
  bool continues = false;
  /// The last edge of a closed loop: its end is its chain's start.
  bool closes = false;
};

/// The edges sorted into chains through shared vertices (each chain from a vertex of one edge,
/// then closed loops), in the chain's direction.
std::vector<ChainEdge> chain_edges(const mesh::Mesh& mesh, const std::vector<int>& edges);

}  // namespace hpcontact::contact
