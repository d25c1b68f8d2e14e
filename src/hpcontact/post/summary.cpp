// JSON rendering and writing of summary.json.
#include "hpcontact/post/summary.hpp"

#include "hpcontact/post/output_file.hpp"

namespace hpcontact::post {

nlohmann::json to_json(const Summary& s) {
  nlohmann::json j;
  j["case"] = s.case_name;
  j["method"] = s.method;
  j["dofs"] = s.dofs;
  j["strain_energy"] = s.strain_energy;
  j["newton_iterations"] = s.newton_iterations;
  j["load_steps"] = s.load_steps;
  j["converged"] = s.converged;
  j["wall_time_s"] = s.wall_time_s;
  if (s.error) {
    nlohmann::json e;
    e["reference_energy"] = s.error->reference_energy;
    e["energy_rel_percent"] = s.error->energy_rel_percent;
    if (s.error->energy_norm_rel_percent)
      e["energy_norm_rel_percent"] = *s.error->energy_norm_rel_percent;
    e["reference"] = s.error->reference;
    j["error"] = e;
  }
  for (auto it = s.extra.begin(); it != s.extra.end(); ++it) j[it.key()] = it.value();
  return j;
}

void write_summary(const std::string& path, const Summary& s) {
  write_text_file(path, to_json(s).dump(2) + "\n");
}

}  // namespace hpcontact::post
