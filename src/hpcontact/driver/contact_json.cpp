// summary.json's figures of the contact pairs of a solved state.
#include "hpcontact/driver/contact_json.hpp"

namespace hpcontact::driver {

namespace {

/// The singular points of a pair: where, the peak (no converged value) and the fitted strength.
nlohmann::json singular_points_json(const std::vector<model::SingularPoint>& points) {
  nlohmann::json all = nlohmann::json::array();
  for (const auto& p : points) {
    nlohmann::json j = {{"at", {p.X.x() + 0.0, p.X.y() + 0.0}},  // + 0.0: no -0
                        {"at_deformed", {p.x.x() + 0.0, p.x.y() + 0.0}},
                        {"s", p.s},
                        {"where", p.where},
                        {"peak", p.peak},
                        {"peak_converged", false},
                        {"excluded_within", p.excluded},
                        {"pressure_max_beyond", p.pressure_max_beyond}};
    if (p.fit)
      j["fit"] = {{"exponent", p.fit->exponent}, {"strength", p.fit->strength},
                  {"from", p.fit->from},         {"to", p.fit->to},
                  {"points", p.fit->points},     {"rms_log_residual", p.fit->rms},
                  {"square_root_strength", p.fit->square_root_strength},
                  {"square_root_rms_log_residual", p.fit->square_root_rms}};
    else
      j["fit"] = nullptr;
    all.push_back(j);
  }
  return all;
}


/// The contact zone's extent along the pair's surface: its ends as frame coordinates (arc
/// length from the frame's origin) and its length.
nlohmann::json zone_json(const model::ContactPair& pair, const model::ContactResult& c) {
  const auto [lo, hi] = *c.zone;
  nlohmann::json z = {{"from", lo + 0.0}, {"to", hi + 0.0}, {"length", hi - lo}};  // + 0.0: no -0
  if (c.zone_deformed) {
    const auto [dlo, dhi] = *c.zone_deformed;
    z["deformed"] = {{"from", dlo + 0.0}, {"to", dhi + 0.0}, {"length", dhi - dlo}};
  }
  return z;
}


}  // namespace

nlohmann::json points_json(const std::vector<Vec2>& points) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& g : points) j.push_back({g.x(), g.y()});
  return j;
}

const PressureComparison* comparison_of(const Comparisons& c, size_t k) {
  return k < c.size() && c[k] ? &*c[k] : nullptr;
}

/// The contact figures of pair k of a state for summary.json; with a comparison also the
/// pressure errors, and the pressure curve into csv_path if not empty.
nlohmann::json contact_json(const SolvedState& st, size_t k, const PressureComparison* comparison,
                            const std::string& csv_path) {
  nlohmann::json cj;
  const auto& c = st.contact[k];
  const auto& pair = st.pairs[k];
  cj["pair"] = k;
  cj["body"] = st.d->bodies[pair.body].name;
  cj["obstacle"] = pair.other >= 0 ? "body '" + st.d->bodies[pair.other].name + "'"
                                   : pair.obstacle->describe();
  cj["enforcement"] = pair.constraints ? "augmented-lagrangian" : "penalty";
  if (pair.other >= 0 && pair.constraints)
    cj["carrier"] = pair.carrier_choice.empty() ? "as written: body '" + st.d->bodies[pair.body].name + "'"
                                                : pair.carrier_choice;
  cj["surface"] = pair.frame->describe();
  if (c.half_width) cj["half_width"] = *c.half_width;
  cj["contact_length"] = c.contact_length;
  if (c.zone) cj["zone"] = zone_json(pair, c);
  cj["gamma_star"] = points_json(c.gamma_star);
  cj["gamma_star_deformed"] = points_json(c.gamma_star_deformed);
  if (pair.frame->angle(Vec2::Zero())) {
    nlohmann::json angles = nlohmann::json::array();
    for (const Vec2& g : c.gamma_star) angles.push_back(*pair.frame->angle(g));
    cj["gamma_star_angles"] = angles;
  }
  if (pair.other >= 0) cj["gamma_star_other"] = points_json(c.other_zone_ends.X);
  cj["p_max"] = c.p_max;
  cj["traction_max"] = c.p_max;
  cj["pressure_max"] = c.pressure_max;
  if (!c.singular_points.empty()) cj["singular_points"] = singular_points_json(c.singular_points);
  cj["resultant"] = {c.resultant.x(), c.resultant.y()};
  const Vec2 n = pair.force_normal(c.resultant);
  cj["normal_direction"] = {n.x() + 0.0, n.y() + 0.0};
  cj["normal_force"] = c.resultant.dot(n);
  if (pair.force_direction) {
    const Vec2 t(n.y(), -n.x());
    cj["tangential_force"] = c.resultant.dot(t);
    cj["tangent"] = {t.x() + 0.0, t.y() + 0.0};  // what tangential_force is along (+ 0.0: no -0)
  }
  cj["max_penetration"] = c.max_penetration;
  if (pair.friction.active()) {
    // Stick and slip along the interface: counts, the largest |t_T| / (mu p_N) of each state,
    // and where the state changes between neighbouring points along each side (midway
    // between them).
    nlohmann::json fj;
    const bool coulomb = pair.friction.kind == contact::FrictionLaw::Kind::coulomb;
    fj["law"] = coulomb ? "coulomb" : "stick";
    if (coulomb) fj["mu"] = pair.friction.mu;
    fj["penalty"] = pair.friction.eps_t;
    int n_stick = 0, n_slip = 0;
    double stick_ratio = 0, slip_ratio = 0;
    for (size_t i = 0; i < c.states.size(); ++i) {
      const auto& s = c.states[i];
      const double ratio = s.pressure > 0 && coulomb ? std::abs(s.t_t) / (pair.friction.mu * s.pressure) : 0;
      if (s.stick_slip == contact::StickSlip::stick) {
        ++n_stick;
        stick_ratio = std::max(stick_ratio, ratio);
      } else if (s.stick_slip == contact::StickSlip::slip) {
        ++n_slip;
        slip_ratio = std::max(slip_ratio, ratio);
      }
    }
    // What the friction carries, ∫ t_T dS, against what it could carry, mu ∫ p_N dS.
    fj["tangential_traction_integral"] = c.tangential_traction_total;
    if (coulomb) {
      const double capacity = pair.friction.mu * c.normal_traction_total;
      fj["tangential_force_capacity"] = capacity;
      if (capacity > 0) fj["tangential_force_ratio"] = std::abs(c.tangential_traction_total) / capacity;
    }
    fj["stick_points"] = n_stick;
    fj["slip_points"] = n_slip;
    if (coulomb) {
      fj["max_stick_ratio"] = stick_ratio;
      fj["max_slip_ratio"] = slip_ratio;
    }
    fj["stick_slip_transitions"] = points_json(contact::stick_slip_transitions(c.states, c.X, c.order));
    if (pair.other >= 0 && !pair.constraints)  // the other body's points carry their own states
      fj["stick_slip_transitions_other"] =
          points_json(contact::stick_slip_transitions(c.other_states, c.other_X, c.other_order));
    if (pair.constraints && coulomb) {
      fj["stick_slip_points"] = points_json(c.stick_slip.X);
      if (pair.other >= 0) fj["stick_slip_points_other"] = points_json(c.other_stick_slip.X);
      fj["memory_points"] = points_json(c.memory_points);
      if (pair.other >= 0) fj["memory_points_other"] = points_json(c.other_memory_points);
    }
    cj["friction"] = fj;
  }
  if (comparison)
    cj.update(comparison->measure(*st.d, pair, c, st.u, csv_path, st.multipliers_of(k)));
  return cj;
}

/// Every pair's figures (summary.json "contact_pairs").
nlohmann::json contact_pairs_json(const SolvedState& st, const Comparisons& comparisons) {
  nlohmann::json all = nlohmann::json::array();
  for (size_t k = 0; k < st.contact.size(); ++k)
    all.push_back(contact_json(st, k, comparison_of(comparisons, k), ""));
  return all;
}

}  // namespace hpcontact::driver
