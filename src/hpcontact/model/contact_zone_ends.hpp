// The ends of a pair's contact zone (Γ*, Pegasus on the gap, seed §4.7) on both bodies, and the
// zone's extent along the pair's surface, from the points' states of a ContactResult.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "hpcontact/model/contact_pairs.hpp"
#include "hpcontact/model/contact_results.hpp"

namespace hpcontact::model {

/// The zone ends on the pair's body at the state u, from res's states (penalty: Pegasus on the
/// gap between neighbouring points where it changes sign) or its nodes (exact enforcement,
/// `multipliers` the pair's: the root of g − λ_h/κ between neighbouring nodes of which one is
/// active), ends that repeat one before them dropped, with the outer ends of the active region.
ZoneEnds own_zone_ends(const Discretization& d, const ContactPair& pair, const Eigen::VectorXd& u,
                       const Eigen::VectorXd* multipliers, const ContactResult& res);

/// The zone ends on the other body's boundary (pair.other ≥ 0): from its points' states (penalty),
/// or (exact enforcement, one-sided) the feet of res.gamma_star_deformed on it, with the same
/// outer ends.
ZoneEnds other_zone_ends(const Discretization& d, const ContactPair& pair, const Eigen::VectorXd& u,
                         const ContactResult& res);

/// The extent of a pair's contact zone along its surface frame (see ContactResult).
struct ZoneExtent {
  std::pair<double, double> zone;           ///< [lo, hi] of the undeformed points
  std::pair<double, double> zone_deformed;  ///< the same of the deformed points
  std::optional<double> half_width;         ///< where the zone's half length is its half width
};

/// The zone's extent from res's points in contact and its outer ends (gamma_star, outer_ends);
/// none where no point is in contact.
std::optional<ZoneExtent> zone_extent(const ContactPair& pair, const ContactResult& res);

/// E' p / h of a contact edge of degree p: the stiffness of the boundary over a node spacing,
/// the scale that makes a gap and a pressure (or a slip and a traction) comparable.
double edge_stiffness(const Body& body, const mesh::Edge& edge, int p);

/// Points of this body's boundary carried to their feet on the other body's (one-sided exact
/// pairs: the other side's zone ends and stick–slip points).
ZoneEnds feet_on_other(const ContactPair& pair, const std::vector<Vec2>& deformed);

}  // namespace hpcontact::model
