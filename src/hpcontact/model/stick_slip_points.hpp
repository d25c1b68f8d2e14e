// The stick–slip points of an exactly enforced pair with Coulomb friction: where the friction
// state changes between neighbouring active multiplier nodes (docs/theory.md §8a).
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "hpcontact/model/contact_pairs.hpp"
#include "hpcontact/model/contact_results.hpp"

namespace hpcontact::model {

/// The stick–slip points of an exactly enforced pair with Coulomb friction. The exact tangential
/// traction t and slip ġ of the step satisfy |t| ≤ μ p, ġ = 0 where the point sticks and
/// |t| = μ p, ġ t ≥ 0 where it slips, so that for any stiffness κ > 0
///   ψ = |λ_T + κ ĝ_T| − μ λ
/// is negative in the stick zone, positive in the slip zone and zero at the point between them
/// (the complementarity function of friction; κ = E' p / h as for the zone ends). Between
/// neighbouring active nodes of one edge where ψ changes sign the root of ψ along the
/// interpolated multiplier and slip fields (Pegasus) is the estimate. A node within round-off of
/// the cone (|ψ| ≤ 1e-8 μ λ_max: a node rp has put on the point) counts as slipping and is itself
/// the point when its neighbour sticks: its state is then a matter of round-off, and the point
/// must not jump to the next interval with it.
ZoneEnds stick_slip_points(const Body& body, const ContactPair& pair,
                           const std::vector<ContactResult::Node>& nodes, const Eigen::VectorXd& u,
                           const Eigen::VectorXd& lambda, const Eigen::VectorXd& lambda_t,
                           const Eigen::VectorXd& slips);

}  // namespace hpcontact::model
