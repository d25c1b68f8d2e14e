// The interface curve of a solved contact problem: one row per contact point (contact.csv).
#pragma once

#include <string>
#include <vector>

#include "hpcontact/model/contact_solve.hpp"

namespace hpcontact::driver {

/// Column by column, the rows of contact.csv: every pair's contact points, pair by pair, each
/// pair's points in the order of its boundary, then (a pair between two bodies) the other
/// body's points. All columns have the same length. Definitions: docs/input.md, "contact.csv".
struct ContactTable {
  std::vector<int> pair;                 ///< index of the pair in the problem's contact list
  std::vector<std::string> body;         ///< the name of the body the point lies on
  std::vector<double> X, Y;              ///< undeformed position
  std::vector<double> x, y;              ///< deformed position
  std::vector<double> s;                 ///< position along the obstacle (ContactPair::coordinate)
  std::vector<double> gap;               ///< signed normal gap (negative: penetration)
  /// The contact pressure: normal contact force per unit length along the obstacle.
  std::vector<double> pressure;
  /// The same from the body's stresses.
  std::vector<double> pressure_from_stress;
  /// The normal traction the method carries per unit undeformed boundary length: the
  /// multiplier (exact enforcement) or eps_N <-g_N> (penalty).
  std::vector<double> traction;
  std::vector<double> minus_sigma_nn;    ///< −n·σ·n, n the body's undeformed outward normal
  std::vector<double> tangential_gap, tangential_traction, slip;  ///< zero without friction
  /// The unit tangent τ that tangential_gap, tangential_traction and slip are signed along:
  /// contact::friction_tangent of the outward normal of what the point touches (the row's body
  /// receives −t_T τ); zero where the point has no foot on it.
  std::vector<double> tangent_x, tangent_y;
  /// The tangential traction from the body's stresses along τ, per unit length along the
  /// obstacle (as pressure_from_stress): t_T dS/ds as the stresses say it.
  std::vector<double> shear_from_stress;
  std::vector<std::string> state;        ///< "open", "contact", "stick" or "slip"
  size_t size() const { return pair.size(); }
};

/// The table of a solved state: `contact[k]` is the result of `pairs[k]`.
ContactTable contact_table(const model::Discretization& d,
                           const std::vector<model::ContactResult>& contact,
                           const std::vector<model::ContactPair>& pairs);

/// The table as CSV text (header pair,X,Y,x,y,gap,pressure,pressure_from_stress,tangential_gap,
/// tangential_traction,slip,state,body,s,traction,minus_sigma_nn,tangent_x,tangent_y,
/// shear_from_stress; 12 significant digits): the columns of earlier versions first, in their
/// order.
std::string contact_csv(const ContactTable& table);

}  // namespace hpcontact::driver
