// The follower loads' forces at a converged state, their wetted parts judged from the contact
// pairs' multipliers (exact) or pressures (penalty): for reactions and results.
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "hpcontact/model/contact_pairs.hpp"
#include "hpcontact/model/follower_load.hpp"

namespace hpcontact::model {

struct PairForces;

/// The marks of a penalty pair's points (both bodies') with their pressures in `f`, appended.
void add_point_marks(const ContactPair& pair, const PairForces& f, std::vector<ContactMark>& marks);
/// The mark of an exact pair's multiplier node j with the contact pressure `pressure`.
ContactMark node_mark(const ContactPair& pair, int j, double pressure);

/// Where pair's multiplier nodes (exact: their multipliers, those of a converged state, a
/// negative one taken as 0) or points (penalty: their pressures) lie, on both its bodies.
std::vector<ContactMark> contact_marks(const Discretization& d, const ContactPair& pair,
                                       const Eigen::VectorXd& u, const Eigen::VectorXd& multipliers);

/// The follower loads' forces at the state u (all dofs) times loads_factor (all dofs), each
/// over its wetted range (into `ranges`, per follower load, if not null). `multipliers` per pair
/// (empty for the penalty).
Eigen::VectorXd follower_forces(const Discretization& d, const std::vector<ContactPair>& pairs,
                                const Eigen::VectorXd& u, const std::vector<Eigen::VectorXd>& multipliers,
                                double loads_factor, std::vector<WetRange>* ranges = nullptr);

}  // namespace hpcontact::model
