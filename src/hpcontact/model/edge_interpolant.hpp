// A scalar field along a mesh edge in the edge's modes: the values its constraints prescribe, and
// the coordinates the moment of a reaction weighs its forces with.
#pragma once

#include <functional>
#include <vector>

#include "hpcontact/model/discretization.hpp"

namespace hpcontact::model {

/// The coefficients of g along edge e of a body beyond its vertex values g(v0), g(v1), per edge
/// mode k = 2..edge_degree(e) (index k − 2): hierarchic modes by the L2 projection of g minus its
/// linear interpolant onto φ_2..φ_p along the edge (exact for g of degree ≤ p in the edge's
/// parameter: zero for a linear field along a straight edge); the Lagrange mid-edge node (k = 2)
/// by g there. Empty for an edge of degree 1.
std::vector<double> edge_mode_values(const Body& body, int e, const std::function<double(const Vec2&)>& g);

}  // namespace hpcontact::model
