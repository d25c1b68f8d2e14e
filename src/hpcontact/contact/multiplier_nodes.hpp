// The nodes of the contact multiplier (the pressure) on a contact boundary: the p + 1
// Gauss–Lobatto points of each contact edge of trace degree p, a vertex shared by two edges
// once, so that a chain of edges has as many nodes as its trace has functions per component.
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "hpcontact/contact/contact_boundary.hpp"

namespace hpcontact::contact {

/// One node of the multiplier: where the pressure λ_j is an unknown.
struct MultiplierNode {
  int element = -1, local_edge = -1;
  int edge = -1;       ///< index of its (first) edge in the contact boundary's list of edges
  double t = 0;        ///< local edge parameter on that edge
  Vec2 X;              ///< undeformed position
  /// The node's share of the boundary, W_j = Σ_e w_i ds/dt (t_i) × thickness over the edges
  /// it lies on (w_i its Lobatto weight): ∫ λ ds ≈ Σ_j W_j λ_j.
  double weight = 0;
  /// p² / h of its edges (the largest): the scale of the boundary's stiffness, for the default
  /// augmentation E p² / h.
  double stiffness_scale = 0;
};

/// The multiplier of a contact boundary: nodes, and per edge of the boundary the nodes of its
/// Lobatto points. The multiplier field on edge k is λ_h(t) = Σ_i L_i(t) λ_{edge_nodes[k][i]},
/// L_i the Lagrange polynomials of the edge's Lobatto points: continuous along a chain, of the
/// edge's trace degree.
struct MultiplierNodes {
  std::vector<MultiplierNode> nodes;
  std::vector<std::vector<int>> edge_nodes;      ///< per edge: the node of each Lobatto point
  std::vector<std::vector<double>> edge_points;  ///< per edge: its Lobatto points t_i, ascending

  int size() const { return static_cast<int>(nodes.size()); }
  /// L_i(t) of edge k's Lobatto points, into L (resized to their number).
  void shape(int k, double t, Eigen::VectorXd& L) const;
  /// λ_h(t) on edge k for the nodal values lambda.
  /// A segment of a longer vector (the tangential multipliers after the normal ones) is taken
  /// as it is, not copied.
  double interpolate(int k, double t, const Eigen::Ref<const Eigen::VectorXd>& lambda) const;
};

/// The multiplier nodes of the chained contact edges (chain_edges(): `chain`, whose order the
/// boundary's edge list follows), the trace degree of each edge from `dofs`.
MultiplierNodes multiplier_nodes(const mesh::Mesh& mesh, const fem::DofMap& dofs,
                                 const std::vector<mesh::ElementMap>& maps,
                                 const std::vector<ChainEdge>& chain, const fem::OutOfPlane& thickness);

}  // namespace hpcontact::contact
