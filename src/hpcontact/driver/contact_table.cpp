// Collecting the contact points' states into columns, and writing them as CSV.
#include "hpcontact/driver/contact_table.hpp"

#include <iomanip>
#include <sstream>

namespace hpcontact::driver {

ContactTable contact_table(const std::vector<model::ContactResult>& contact,
                           const std::vector<model::ContactPair>& pairs) {
  ContactTable t;
  for (size_t k = 0; k < contact.size(); ++k)
    for (size_t i = 0; i < contact[k].states.size(); ++i) {
      const auto& p = contact[k].states[i];
      const auto& X = contact[k].X[i];
      t.pair.push_back(static_cast<int>(k));
      t.X.push_back(X.x());
      t.Y.push_back(X.y());
      t.x.push_back(p.x.x());
      t.y.push_back(p.x.y());
      t.gap.push_back(p.gap);
      t.pressure.push_back(p.pressure);
      t.pressure_from_stress.push_back(contact[k].stress_pressure[i]);
      t.tangential_gap.push_back(p.g_t);
      t.tangential_traction.push_back(p.t_t);
      t.slip.push_back(p.slip);
      t.state.push_back(contact::state_name(contact::contact_state(p)));
    }
  return t;
}

std::string contact_csv(const ContactTable& t) {
  std::ostringstream csv;
  csv << std::setprecision(12)
      << "pair,X,Y,x,y,gap,pressure,pressure_from_stress,tangential_gap,tangential_traction,"
         "slip,state\n";
  for (size_t i = 0; i < t.size(); ++i)
    csv << t.pair[i] << ',' << t.X[i] << ',' << t.Y[i] << ',' << t.x[i] << ',' << t.y[i] << ','
        << t.gap[i] << ',' << t.pressure[i] << ',' << t.pressure_from_stress[i] << ','
        << t.tangential_gap[i] << ',' << t.tangential_traction[i] << ',' << t.slip[i] << ','
        << t.state[i] << '\n';
  return csv.str();
}

}  // namespace hpcontact::driver
