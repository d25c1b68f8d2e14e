// summary.json: the machine-readable result of a run (its keys: docs/tutorial.md §8).
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace hpcontact::post {

struct ErrorSummary {
  double reference_energy = 0;
  double energy_rel_percent = 0;  ///< seed eq. 4.3: sqrt(|U_ref - U| / U_ref) · 100
  /// ||u_ex - u||_E / ||u_ex||_E · 100 integrated from the exact strain, when a closed form is known.
  std::optional<double> energy_norm_rel_percent;
  std::string reference;  ///< where the reference came from, e.g. "analytic:lame"
};

struct Summary {
  std::string case_name;
  std::string method;
  int dofs = 0;
  double strain_energy = 0;
  int newton_iterations = 0;
  int load_steps = 0;
  bool converged = false;
  double wall_time_s = 0;
  std::optional<ErrorSummary> error;
  nlohmann::json extra = nlohmann::json::object();  ///< more keys, merged at the top level
};

nlohmann::json to_json(const Summary& s);

/// Writes summary.json (checked to the close, see OutputFile); IoError on failure. A run writes
/// it into its staging folder, which the output folder moves into place whole.
void write_summary(const std::string& path, const Summary& s);

}  // namespace hpcontact::post
