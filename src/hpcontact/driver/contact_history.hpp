// The contact history of a nonlinear run: per converged step and pair, the forces, the contact
// length, the peak pressure and the stick/slip counts (contact_history.csv).
#pragma once

#include <string>
#include <vector>

#include "hpcontact/model/contact_solve.hpp"

namespace hpcontact::driver {

/// One pair at one converged step (definitions: docs/input.md, "contact_history.csv").
struct ContactHistoryRow {
  int step = 0;  ///< the row of path.csv (1, 2, ...)
  double displacement_factor = 0, load_factor = 0;
  Vec2 displacement_factors = Vec2::Zero();  ///< x's and y's (y's is displacement_factor)
  int pair = 0;
  std::string body;
  Vec2 resultant = Vec2::Zero();  ///< the contact force on the body
  double normal_force = 0;        ///< resultant · the pair's normal (ContactPair::normal)
  double tangential_force = 0;    ///< resultant · the pair's tangent
  double contact_length = 0;      ///< ContactResult::contact_length
  double pressure_max = 0;        ///< the largest force per unit length along the obstacle
  double traction_max = 0;        ///< the largest multiplier or penalty traction (p_max)
  double max_penetration = 0;
  int contact_points = 0, stick_points = 0, slip_points = 0;  ///< of the pair's own points
};

/// The row of pair k at a step.
ContactHistoryRow contact_history_row(int step, const model::NonlinearSolution::PathPoint& at,
                                      int k, const std::string& body,
                                      const model::ContactPair& pair,
                                      const model::ContactResult& result);

/// The rows as CSV text (12 significant digits), header
/// step,displacement_factor,load_factor,pair,body,resultant_x,resultant_y,normal_force,
/// tangential_force,contact_length,pressure_max,traction_max,max_penetration,contact_points,
/// stick_points,slip_points; per_direction (stages with factors per direction) adds
/// displacement_factor_x,displacement_factor_y.
std::string contact_history_csv(const std::vector<ContactHistoryRow>& rows, bool per_direction = false);

}  // namespace hpcontact::driver
