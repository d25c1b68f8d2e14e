// A 3D run: the body's mesh and modes, one condensed linear solve, its fields and files.
#include "hpcontact/driver/run_solid.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <sstream>

#include "hpcontact/core/error.hpp"
#include "hpcontact/core/stop.hpp"
#include "hpcontact/model/solid_model.hpp"
#include "hpcontact/post/output_file.hpp"
#include "hpcontact/post/solid_fields.hpp"

namespace hpcontact::driver {

namespace {

nlohmann::json point_json(const std::array<double, 3>& x) { return {x[0], x[1], x[2]}; }

}  // namespace

RunResult run_solid(const model::ProblemSpec& spec, const RunOptions& options,
                    OutputFolder* folder, const std::string& stage) {
  namespace fs = std::filesystem;
  const auto t0 = std::chrono::steady_clock::now();
  auto say = [&](const ProgressEvent& e) {
    if (options.progress) options.progress(e);
  };
  const model::SolidSpec& solid = *spec.solid;
  const model::SolidDiscretization d = model::discretize_solid(solid, spec.file);
  {
    std::ostringstream os;
    os << "discretised: body '" << solid.body.name << "', " << d.mesh.topology.n_hexes()
       << " hexahedra, degree " << solid.degree[0] << "," << solid.degree[1] << ","
       << solid.degree[2] << " (" << (solid.tensor_space ? "tensor" : "trunk") << "), "
       << d.n_free() << " free dofs";
    say(os.str());
  }
  const model::SolidSolution sol = model::solve_solid(solid, d, spec.file);
  HPC_REQUIRE(sol.u.allFinite(), NumericalError, spec.file,
              ": the solution is not finite (a material or load value out of range?)");
  {
    std::ostringstream os;
    os << "solved: system of " << sol.n_system << " unknowns (internal modes condensed), assembly "
       << sol.assembly_seconds << " s, factorisation and solve " << sol.solve_seconds << " s";
    say(os.str());
  }
  const post::SolidFields fields = post::solid_fields(d, sol.u);

  RunResult result;
  post::Summary& s = result.summary;
  s.case_name = spec.case_name;
  s.method = "p";
  s.dofs = d.n_free();
  s.strain_energy = fields.strain_energy;
  s.newton_iterations = 1;
  s.load_steps = 1;
  s.converged = true;
  s.extra["dimension"] = 3;
  s.extra["elements"] = d.mesh.topology.n_hexes();
  s.extra["degree"] = {solid.degree[0], solid.degree[1], solid.degree[2]};
  s.extra["space"] = solid.tensor_space ? "tensor" : "trunk";
  s.extra["system_size"] = sol.n_system;
  s.extra["condensed"] = true;
  s.extra["assembly_time_s"] = sol.assembly_seconds;
  s.extra["solve_time_s"] = sol.solve_seconds;
  s.extra["volume"] = fields.volume;
  s.extra["displacement_max"] = fields.displacement_max;
  s.extra["von_mises_max"] = {{"value", fields.von_mises_max},
                              {"at", point_json(fields.von_mises_max_at)},
                              {"element", fields.von_mises_max_element},
                              {"where", "the largest at the elements' Gauss points"}};
  if (solid.exact_strain_energy) {
    const double U = *solid.exact_strain_energy;
    post::ErrorSummary e;
    e.reference_energy = U;
    e.energy_rel_percent = std::sqrt(std::abs(U - fields.strain_energy) / U) * 100;
    e.reference = "input: exact.strain_energy";
    s.error = e;
  }
  result.u = sol.u;
  if (!stage.empty()) {
    if (spec.output.vtu) {
      post::write_solid_vtu((fs::path(stage) / "solution.vtu").string(), d, sol.u,
                            spec.output.vtu_subdivisions);
      say({"wrote solution.vtu", FileWrittenProgress{"solution.vtu"}});
    }
    if (!options.effective_input.empty())
      post::write_text_file((fs::path(stage) / "input.yaml").string(), options.effective_input);
    s.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    post::write_summary((fs::path(stage) / "summary.json").string(), s);
    say({"wrote summary.json", FileWrittenProgress{"summary.json"}});
  }
  s.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  HPC_REQUIRE(!stop_requested(), NumericalError, spec.file, ": ", stop_reason(),
              " before the results were written; the output folder is left as it was");
  if (folder) folder->commit();
  return result;
}

}  // namespace hpcontact::driver
