// The pipeline of a run, read top to bottom: discretise -> solve -> post -> write.
#include "hpcontact/driver/run.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "hpcontact/analytic/lame.hpp"
#include "hpcontact/driver/contact_compare.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/model/contact_solve.hpp"
#include "hpcontact/model/linear_solve.hpp"
#include "hpcontact/post/fields.hpp"
#include "hpcontact/post/vtu.hpp"

namespace hpcontact::driver {

namespace {

/// The energy error against a closed form named in the input, if any.
std::optional<post::ErrorSummary> exact_error(const model::ProblemSpec& spec,
                                              const model::Discretization& d,
                                              const Eigen::VectorXd& u, double U) {
  if (spec.exact.type.empty()) return std::nullopt;
  HPC_REQUIRE(spec.exact.type == "lame", InputError, spec.exact.where.str(),
              ": unknown exact solution '", spec.exact.type, "' (expected lame)");
  const auto& mat = d.bodies.front().material;
  analytic::Lame lame{spec.exact.inner_radius, spec.exact.outer_radius, spec.exact.inner_pressure,
                      spec.exact.outer_pressure, mat.youngs_modulus, mat.poisson_ratio,
                      mat.plane == material::Plane::strain,
                      Eigen::Vector2d(spec.exact.center[0], spec.exact.center[1])};
  const post::StrainField strain = [&](const Vec2& x) { return lame.strain(x); };
  // U_ref = ½ B(u_ex, u_ex) over the exact domain, by the same high-order quadrature.
  const double U_ref = post::energy_error_squared(d, Eigen::VectorXd::Zero(u.size()), strain, 8);
  const double E2 = post::energy_error_squared(d, u, strain, 8);
  post::ErrorSummary e;
  e.reference = "analytic:lame";
  e.reference_energy = U_ref;
  e.energy_rel_percent = std::sqrt(std::abs(U_ref - U) / U_ref) * 100;
  e.energy_norm_rel_percent = std::sqrt(E2 / U_ref) * 100;
  return e;
}

}  // namespace

void prepare_output_folder(const std::string& out_dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  HPC_REQUIRE(!ec, IoError, out_dir, ": cannot create the output folder: ", ec.message());
  fs::remove(fs::path(out_dir) / "summary.json", ec);
  HPC_REQUIRE(!ec, IoError, out_dir, ": cannot remove the previous summary.json: ", ec.message());
}

RunResult run_problem(const model::ProblemSpec& spec, const RunOptions& options) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  auto say = [&](const std::string& s) {
    if (options.progress) options.progress(s);
  };

  if (!options.out_dir.empty()) prepare_output_folder(options.out_dir);
  model::Discretization d = model::discretize(spec);
  {
    std::ostringstream os;
    int n_el = 0;
    for (const auto& b : d.bodies) n_el += b.mesh.n_quads();
    os << "discretised: " << d.bodies.size() << " body(ies), " << n_el << " elements, "
       << d.n_free << " free dofs (" << d.method << "-version)";
    say(os.str());
  }

  RunResult result{{}, {}, {}};
  post::Summary& s = result.summary;
  std::vector<model::ContactResult> contact;
  std::vector<model::ContactPair> pairs;
  if (spec.contact.empty()) {
    model::LinearSolveOptions lo;
    lo.condense = spec.discretization.condense;
    lo.solver = solve::linear_solver_kind(spec.solver.linear, spec.solver.where.str() + "linear");
    const auto sol = model::solve_linear(d, lo);
    std::ostringstream os;
    os << "solved: system of " << sol.n_system << " unknowns, assembly " << sol.assembly_seconds
       << " s, factorisation and solve " << sol.solve_seconds << " s";
    say(os.str());
    result.u = sol.u;
    s.newton_iterations = 1;
    s.load_steps = 1;
    s.extra["system_size"] = sol.n_system;
    s.extra["condensed"] = spec.discretization.condense;
    s.extra["solve_time_s"] = sol.solve_seconds;
    s.extra["assembly_time_s"] = sol.assembly_seconds;
  } else {
    const auto sol = model::solve_contact(spec, d, options.progress);
    HPC_REQUIRE(sol.converged, NumericalError, spec.file, ": the solver stopped: ", sol.message);
    result.u = sol.u;
    s.newton_iterations = sol.newton_iterations;
    s.load_steps = sol.load_steps;
    s.extra["load_factor"] = sol.load_factor;
    contact = sol.contact;
    pairs = sol.pairs;
  }
  result.discretization = std::move(d);
  const auto& disc = result.discretization;
  s.case_name = spec.case_name;
  s.method = disc.method;
  s.dofs = disc.n_free;
  s.strain_energy = post::strain_energy(disc, result.u);
  s.converged = true;
  s.error = exact_error(spec, disc, result.u, s.strain_energy);
  if (!contact.empty()) {
    nlohmann::json cj;
    const auto& c = contact.front();
    cj["half_width"] = c.half_width;
    cj["gamma_star"] = nlohmann::json::array();
    for (const auto& g : c.gamma_star) cj["gamma_star"].push_back({g.x(), g.y()});
    cj["gamma_star_deformed"] = nlohmann::json::array();
    for (const auto& g : c.gamma_star_deformed) cj["gamma_star_deformed"].push_back({g.x(), g.y()});
    cj["p_max"] = c.p_max;
    cj["resultant"] = {c.resultant.x(), c.resultant.y()};
    cj["max_penetration"] = c.max_penetration;
    if (const auto& cmp = spec.contact.front().compare) {
      namespace fs = std::filesystem;
      const std::string csv =
          options.out_dir.empty() ? "" : (fs::path(options.out_dir) / "pressure.csv").string();
      std::vector<double> zone_ends;
      for (const auto& g : c.gamma_star)
        zone_ends.push_back(pairs.front().coordinate(g));
      cj.update(compare_pressure(spec, *cmp, disc, pairs.front(), result.u, zone_ends, csv));
    }
    s.extra["contact"] = cj;
  }

  if (!options.out_dir.empty()) {
    namespace fs = std::filesystem;
    const fs::path out(options.out_dir);
    if (!options.effective_input.empty())
      post::write_text_file((out / "input.yaml").string(), options.effective_input);
    if (!contact.empty()) {
      // The interface curve: one row per contact Gauss point.
      std::ostringstream csv;
      csv << std::setprecision(12) << "pair,X,Y,x,y,gap,pressure,pressure_from_stress\n";
      for (size_t k = 0; k < contact.size(); ++k)
        for (size_t i = 0; i < contact[k].states.size(); ++i) {
          const auto& st = contact[k].states[i];
          const auto& X = pairs[k].points[i].X;
          csv << k << ',' << X.x() << ',' << X.y() << ',' << st.x.x() << ',' << st.x.y() << ','
              << st.gap << ',' << st.pressure << ',' << contact[k].stress_pressure[i] << '\n';
        }
      post::write_text_file((out / "contact.csv").string(), csv.str());
    }
    if (spec.output.vtu) {
      post::write_vtu((out / "solution.vtu").string(), disc, result.u, spec.output.vtu_subdivisions);
      say("wrote " + (out / "solution.vtu").string());
    }
    s.wall_time_s = std::chrono::duration<double>(Clock::now() - t0).count();
    post::write_summary((out / "summary.json").string(), s);
    say("wrote " + (out / "summary.json").string());
  } else {
    s.wall_time_s = std::chrono::duration<double>(Clock::now() - t0).count();
  }
  return result;
}

}  // namespace hpcontact::driver
