// Geometric (hp) refinement of a quadrilateral mesh towards one of its nodes (seed §4.7,
// Fig. 4.12), conforming: no hanging nodes.
#pragma once

#include <map>
#include <vector>

#include "hpcontact/model/problem_spec.hpp"

namespace hpcontact::adapt {

/// Splits every element of body `body` that has node `centre` (user id) as a corner into three:
/// the corner square of relative size `factor` in the element's own coordinates, and two
/// quadrilaterals filling the rest. The new nodes on the edges out of the centre are shared by
/// the neighbours across those edges (conforming); nodes on curved edges lie on the exact curve
/// (arcs are split into arcs), interior nodes on the element's blending map. Edge sets follow
/// the split edges; the split elements' degree entries are dropped. AdaptError on a parametric
/// curve at the centre or an element the split would invert.
model::ProblemSpec refine_towards_node(const model::ProblemSpec& spec, int body, int centre,
                                       double factor);

/// Layers of the elements of body `body` around the given nodes (user ids): 0 for the elements
/// having one of them as a corner, 1 for those sharing a node with a layer-0 element, and so
/// on (breadth-first over shared nodes). On a geometric mesh these are its refinement layers.
std::map<int, int> element_layers(const model::BodySpec& body, const std::vector<int>& centres);

}  // namespace hpcontact::adapt
