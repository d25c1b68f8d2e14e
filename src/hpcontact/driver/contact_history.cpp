// Per-step contact figures of every pair, and their CSV.
#include "hpcontact/driver/contact_history.hpp"

#include <iomanip>
#include <sstream>

namespace hpcontact::driver {

ContactHistoryRow contact_history_row(int step, const model::NonlinearSolution::PathPoint& at,
                                      int k, const std::string& body,
                                      const model::ContactPair& pair,
                                      const model::ContactResult& result) {
  ContactHistoryRow r;
  r.step = step;
  r.displacement_factor = at.displacements;
  r.displacement_factors = at.displacement_factors;
  r.load_factor = at.loads;
  r.pair = k;
  r.body = body;
  r.resultant = result.resultant;
  const Vec2 n = pair.force_normal(result.resultant);
  r.normal_force = result.resultant.dot(n);
  r.tangential_force = pair.force_direction ? result.resultant.dot(Vec2(n.y(), -n.x())) : 0.0;
  r.contact_length = result.contact_length;
  r.pressure_max = result.pressure_max;
  r.traction_max = result.p_max;
  r.max_penetration = result.max_penetration;
  for (const auto& s : result.states) {
    const auto state = contact::contact_state(s);
    r.contact_points += state != contact::ContactState::open;
    r.stick_points += state == contact::ContactState::stick;
    r.slip_points += state == contact::ContactState::slip;
  }
  return r;
}

std::string contact_history_csv(const std::vector<ContactHistoryRow>& rows, bool per_direction) {
  std::ostringstream csv;
  csv << std::setprecision(12)
      << "step,displacement_factor,load_factor,pair,body,resultant_x,resultant_y,normal_force,"
         "tangential_force,contact_length,pressure_max,traction_max,max_penetration,"
         "contact_points,stick_points,slip_points"
      << (per_direction ? ",displacement_factor_x,displacement_factor_y\n" : "\n");
  for (const auto& r : rows) {
    csv << r.step << ',' << r.displacement_factor << ',' << r.load_factor << ',' << r.pair << ','
        << r.body << ',' << r.resultant.x() << ',' << r.resultant.y() << ',' << r.normal_force << ','
        << r.tangential_force << ',' << r.contact_length << ',' << r.pressure_max << ','
        << r.traction_max << ',' << r.max_penetration << ',' << r.contact_points << ','
        << r.stick_points << ',' << r.slip_points;
    if (per_direction) csv << ',' << r.displacement_factors.x() << ',' << r.displacement_factors.y();
    csv << '\n';
  }
  return csv.str();
}

}  // namespace hpcontact::driver
