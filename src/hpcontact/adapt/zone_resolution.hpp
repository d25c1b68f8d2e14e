// Resolving a contact zone that is small against the mesh: before hp grades around the zone
// ends, each end gets a boundary node close enough to move onto it without crushing an element.
#pragma once

#include <string>
#include <vector>

#include "hpcontact/adapt/solved.hpp"

namespace hpcontact::adapt {

/// What zone resolution did: its rounds, the boundary nodes it refined towards (all rounds), and
/// the solve of the last mesh (the input's when no round was needed).
struct Resolution {
  int rounds = 0;
  std::vector<Vec2> towards;
  SolvedPtr solved;
  /// The refinements that could not be built (an element they would make is inverted or
  /// degenerate: a vertex on a nearly straight corner of a distorted input element), each
  /// left out with its cause; the later steps' refinements around the zone ends remain.
  std::vector<std::string> left_out;
};

/// Whether the node chosen for a zone end (nearest_movable_nodes) can move onto it as it is:
/// the move along its track is at most half the shorter of its two boundary edges. A zone much
/// narrower than the edge it ends in fails this (the node would leave an element a sliver).
bool node_near_enough(const NodeForEnd& n);

/// Refines `s`'s mesh until every zone end passes node_near_enough and the two ends of a closed
/// zone around one node in its middle (nearest to both: a coarse mesh's node where two bodies
/// touch in the input) have a node each: towards the boundary
/// vertex of the contact edges nearest to each end that does not, with a factor that puts the
/// new node on the end when it is 15–50 % of the edge away (15 % or 50 % otherwise), and solves
/// again after each round (starting from the last solution). With `stick_slip` the stick–slip
/// points of exact Coulomb pairs are resolved too, also where no node can serve one (its edge
/// runs between two corners of the body: the refinement towards a corner makes the node). At
/// most `max_rounds` rounds (none when the input mesh already serves every end).
Resolution resolve_zones(const SolvedPtr& s, int max_rounds, bool stick_slip,
                         const model::ProgressFn& progress);

}  // namespace hpcontact::adapt
