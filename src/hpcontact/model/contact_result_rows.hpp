// The per-point rows of a ContactResult: the states of a pair's points with their pressures and
// what the stresses say there, at its Gauss points (penalty) or its multiplier nodes (exact
// enforcement), and at the other body's points; with the figures summed over them.
#pragma once

#include <Eigen/Dense>

#include "hpcontact/model/contact_pairs.hpp"
#include "hpcontact/model/contact_results.hpp"

namespace hpcontact::model {

/// The rows of a penalty pair at the state u (all dofs): per Gauss point of its body and of the
/// other body's, its state, position, pressure and what the stresses say; with the resultant, the
/// largest traction and penetration, and the tractions' totals. `res` holds no rows yet.
void add_gauss_point_rows(ContactResult& res, const Discretization& d, const ContactPair& pair,
                          const Eigen::VectorXd& u);

/// The rows of an exactly enforced pair at the state u with all its multipliers (normal, then
/// tangential with friction): one per multiplier node, where the method carries the pressure
/// (ContactResult::nodes beside them), and per point of the other body, the multipliers at its
/// foot on this one; with the resultant, the largest multiplier and penetration, the tractions'
/// totals and, with Coulomb friction and `step_slips`, the stick–slip points. `step_slips`,
/// `total_slips` as for evaluate_contact. `res` holds no rows yet.
void add_multiplier_node_rows(ContactResult& res, const Discretization& d, const ContactPair& pair,
                              const Eigen::VectorXd& u, const Eigen::VectorXd& multipliers,
                              const Eigen::VectorXd* step_slips, const Eigen::VectorXd* total_slips);

}  // namespace hpcontact::model
