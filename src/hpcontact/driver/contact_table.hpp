// The interface curve of a solved contact problem: one row per contact Gauss point (contact.csv).
#pragma once

#include <string>
#include <vector>

#include "hpcontact/model/contact_solve.hpp"

namespace hpcontact::driver {

/// Column by column, the rows of contact.csv: every pair's contact Gauss points, pair by pair,
/// each pair's points in the order of its boundary. All columns have the same length.
struct ContactTable {
  std::vector<int> pair;                 ///< index of the pair in the problem's contact list
  std::vector<double> X, Y;              ///< undeformed position
  std::vector<double> x, y;              ///< deformed position
  std::vector<double> gap;               ///< signed normal gap (negative: penetration)
  std::vector<double> pressure;          ///< penalty pressure eps_N <-g_N>
  std::vector<double> pressure_from_stress;  ///< -n·σ·n, n the undeformed outward normal
  std::vector<double> tangential_gap, tangential_traction, slip;  ///< zero without friction
  std::vector<std::string> state;        ///< "open", "contact", "stick" or "slip"
  size_t size() const { return pair.size(); }
};

/// The table of a solved state: `contact[k]` is the result of `pairs[k]`.
ContactTable contact_table(const std::vector<model::ContactResult>& contact,
                           const std::vector<model::ContactPair>& pairs);

/// The table as CSV text (header pair,X,Y,x,y,gap,pressure,pressure_from_stress,tangential_gap,
/// tangential_traction,slip,state; 12 significant digits).
std::string contact_csv(const ContactTable& table);

}  // namespace hpcontact::driver
