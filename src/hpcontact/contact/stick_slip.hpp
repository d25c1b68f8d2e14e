// Stick and slip along a contact boundary: which contact points are neighbours along it, and
// where the friction state changes between them (summary.json's stick_slip_transitions).
#pragma once

#include <vector>

#include "hpcontact/contact/penalty.hpp"
#include "hpcontact/mesh/mesh.hpp"

namespace hpcontact::contact {

/// The neighbours of a list of contact points of one side of a pair, listed along their chained
/// edges (the order of ContactPair::points, other_points and the multiplier nodes):
/// follows[i] (i >= 1) says point i is the next one along the boundary after point i − 1 (false
/// where a new chain of edges starts); `closed` that the points form one closed chain, so that
/// the first follows the last. follows[0] is false.
struct BoundaryOrder {
  std::vector<char> follows;
  bool closed = false;
};

/// The order of points lying on the mesh edges `point_edges` (one per point, in list order):
/// consecutive points are neighbours when they lie on one edge or on two edges with a common
/// vertex; the points form a closed chain when all are neighbours in turn and the last edge
/// closes the loop back to the first (shares a vertex with it, both vertices if the chain has
/// two edges).
BoundaryOrder boundary_order(const mesh::Mesh& mesh, const std::vector<int>& point_edges);

/// The places along one side of a pair where the friction state changes between stick and slip:
/// midway between neighbouring points (`order`) of which one sticks and the other slips, X their
/// undeformed positions. Points without a friction state (open, or in contact but not anchored
/// yet) separate the stick and slip zones: no transition is counted across them, nor across the
/// start of a new chain of edges.
std::vector<Vec2> stick_slip_transitions(const std::vector<PointState>& states,
                                         const std::vector<Vec2>& X, const BoundaryOrder& order);

}  // namespace hpcontact::contact
