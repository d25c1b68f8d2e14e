// Collecting the contact points' states into columns, and writing them as CSV.
#include "hpcontact/driver/contact_table.hpp"

#include <iomanip>
#include <sstream>

namespace hpcontact::driver {

namespace {

/// One row per point of one side of a pair.
void add_side(ContactTable& t, int k, const std::string& body,
              const std::vector<contact::PointState>& states, const std::vector<Vec2>& X,
              const std::vector<double>& s, const std::vector<double>& pressure,
              const std::vector<double>& pressure_from_stress,
              const std::vector<double>& minus_sigma_nn,
              const std::vector<double>& shear_from_stress) {
  for (size_t i = 0; i < states.size(); ++i) {
    const auto& p = states[i];
    t.pair.push_back(k);
    t.body.push_back(body);
    t.X.push_back(X[i].x());
    t.Y.push_back(X[i].y());
    t.x.push_back(p.x.x());
    t.y.push_back(p.x.y());
    t.s.push_back(s[i]);
    t.gap.push_back(p.gap);
    t.pressure.push_back(pressure[i]);
    t.pressure_from_stress.push_back(pressure_from_stress[i]);
    t.traction.push_back(p.pressure);
    t.minus_sigma_nn.push_back(minus_sigma_nn[i]);
    t.tangential_gap.push_back(p.g_t);
    t.tangential_traction.push_back(p.t_t);
    t.slip.push_back(p.slip);
    t.tangent_x.push_back(p.tau.x());
    t.tangent_y.push_back(p.tau.y());
    t.shear_from_stress.push_back(shear_from_stress[i]);
    t.state.push_back(contact::state_name(contact::contact_state(p)));
  }
}

}  // namespace

ContactTable contact_table(const model::Discretization& d,
                           const std::vector<model::ContactResult>& contact,
                           const std::vector<model::ContactPair>& pairs) {
  ContactTable t;
  for (size_t k = 0; k < contact.size(); ++k) {
    const auto& c = contact[k];
    const int pk = static_cast<int>(k);
    add_side(t, pk, d.bodies[pairs[k].body].name, c.states, c.X, c.s, c.pressure,
             c.pressure_from_stress, c.minus_sigma_nn, c.shear_from_stress);
    if (pairs[k].other >= 0)
      add_side(t, pk, d.bodies[pairs[k].other].name, c.other_states, c.other_X, c.other_s,
               c.other_pressure, c.other_pressure_from_stress, c.other_minus_sigma_nn,
               c.other_shear_from_stress);
  }
  return t;
}

std::string contact_csv(const ContactTable& t) {
  std::ostringstream csv;
  csv << std::setprecision(12)
      << "pair,X,Y,x,y,gap,pressure,pressure_from_stress,tangential_gap,tangential_traction,"
         "slip,state,body,s,traction,minus_sigma_nn,tangent_x,tangent_y,shear_from_stress\n";
  for (size_t i = 0; i < t.size(); ++i)
    csv << t.pair[i] << ',' << t.X[i] << ',' << t.Y[i] << ',' << t.x[i] << ',' << t.y[i] << ','
        << t.gap[i] << ',' << t.pressure[i] << ',' << t.pressure_from_stress[i] << ','
        << t.tangential_gap[i] << ',' << t.tangential_traction[i] << ',' << t.slip[i] << ','
        << t.state[i] << ',' << t.body[i] << ',' << t.s[i] << ',' << t.traction[i] << ','
        << t.minus_sigma_nn[i] << ',' << t.tangent_x[i] << ',' << t.tangent_y[i] << ','
        << t.shear_from_stress[i] << '\n';
  return csv.str();
}

}  // namespace hpcontact::driver
