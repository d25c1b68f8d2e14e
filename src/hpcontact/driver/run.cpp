// The pipeline of a run, read top to bottom: discretise -> solve -> post -> write.
#include "hpcontact/driver/run.hpp"
#include "hpcontact/driver/run_solid.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "hpcontact/adapt/hp.hpp"
#include "hpcontact/adapt/rp.hpp"
#include "hpcontact/analytic/lame.hpp"
#include "hpcontact/analytic/lame_sphere.hpp"
#include "hpcontact/driver/contact_compare.hpp"
#include "hpcontact/driver/contact_history.hpp"
#include "hpcontact/driver/contact_json.hpp"
#include "hpcontact/driver/reaction_report.hpp"
#include "hpcontact/driver/run_report.hpp"
#include "hpcontact/driver/solution_warnings.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/core/stop.hpp"
#include "hpcontact/model/contact_carrier.hpp"
#include "hpcontact/model/contact_solve.hpp"
#include "hpcontact/model/linear_solve.hpp"
#include "hpcontact/model/reactions.hpp"
#include "hpcontact/model/rigid_motion.hpp"
#include "hpcontact/post/fields.hpp"
#include "hpcontact/post/contact_vtu.hpp"
#include "hpcontact/post/output_file.hpp"
#include "hpcontact/post/vtu.hpp"

namespace hpcontact::driver {

namespace {

/// The exact strain of the closed form named in the input (the reader matched its type to the
/// bodies: lame to plane ones, lame_sphere to axisymmetric ones).
post::ExactStrain exact_strain(const model::ExactSpec& exact, const material::LinearElastic& mat) {
  const Eigen::Vector2d center(exact.center[0], exact.center[1]);
  if (exact.type == "lame_sphere") {
    const analytic::LameSphere sphere{exact.inner_radius,  exact.outer_radius,
                                      exact.inner_pressure, exact.outer_pressure,
                                      mat.youngs_modulus,  mat.poisson_ratio, center};
    return {[sphere](const Vec2& x) { return sphere.strain(x); },
            [sphere](const Vec2& x) { return sphere.hoop_strain(x); }};
  }
  HPC_REQUIRE(exact.type == "lame", InputError, exact.where.str(), ": unknown exact solution '",
              exact.type, "' (expected lame or lame_sphere)");
  const analytic::Lame lame{exact.inner_radius,  exact.outer_radius,
                            exact.inner_pressure, exact.outer_pressure,
                            mat.youngs_modulus,  mat.poisson_ratio,
                            mat.plane == material::Plane::strain, center};
  return {[lame](const Vec2& x) { return lame.strain(x); }, {}};
}

/// The energy error against a closed form named in the input, if any.
std::optional<post::ErrorSummary> exact_error(const model::ProblemSpec& spec,
                                              const model::Discretization& d,
                                              const Eigen::VectorXd& u, double U) {
  if (spec.exact.type.empty()) return std::nullopt;
  const post::ExactStrain strain = exact_strain(spec.exact, d.bodies.front().material);
  // U_ref = ½ B(u_ex, u_ex) over the exact domain, by the same high-order quadrature.
  const double U_ref = post::energy_error_squared(d, Eigen::VectorXd::Zero(u.size()), strain, 8);
  const double E2 = post::energy_error_squared(d, u, strain, 8);
  post::ErrorSummary e;
  e.reference = "analytic:" + spec.exact.type;
  e.reference_energy = U_ref;
  e.energy_rel_percent = std::sqrt(std::abs(U_ref - U) / U_ref) * 100;
  e.energy_norm_rel_percent = std::sqrt(E2 / U_ref) * 100;
  return e;
}

}  // namespace

namespace {

/// `name` is prefix, digits, suffix: pressure-3.csv, step-0012.vtu.
bool numbered(const std::string& name, const std::string& prefix, const std::string& suffix) {
  if (name.size() <= prefix.size() + suffix.size() || name.rfind(prefix, 0) != 0 ||
      name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
    return false;
  const auto digits = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
  return std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
}

bool run_output(const std::string& relative, bool folder) {
  if (relative == "last-good") return folder;
  const std::string r = relative.rfind("last-good/", 0) == 0 ? relative.substr(10) : relative;
  const auto slash = r.find('/');
  if (slash == std::string::npos) {
    if (folder) return r == "rp" || r == "hp" || r == "steps";
    for (const char* name : {"summary.json", "report.html", "input.yaml", "contact.csv", "pressure.csv", "path.csv",
                             "contact_history.csv", "mesh.yaml", "solution.vtu", "contact.vtu", "solution.pvd",
                             "contact.pvd"})
      if (r == name) return true;
    return false;
  }
  const std::string sub = r.substr(0, slash), name = r.substr(slash + 1);
  if (folder || name.find('/') != std::string::npos) return false;
  if (sub == "rp" || sub == "hp") return numbered(name, "pressure-", ".csv");
  if (sub == "steps") return numbered(name, "step-", ".vtu") || numbered(name, "contact-", ".vtu");
  return false;
}

}  // namespace

FolderLayout run_layout() { return {"summary.json", &run_output, "a run"}; }

namespace {





/// The comparisons of a problem, on its discretisation before the solve.
/// exact (Lamé's energy error) measures linear elasticity: a body of finite strain is refused
/// before the solve, naming the key and the body's (the reader matched lame to plane bodies and
/// lame_sphere to axisymmetric ones).
void require_exact_applies(const model::ProblemSpec& spec, const model::Discretization& d) {
  if (spec.exact.type.empty()) return;
  for (size_t b = 0; b < d.bodies.size(); ++b) {
    const auto& body = d.bodies[b];
    const std::string key = "bodies[" + std::to_string(b) + "].material.";
    HPC_REQUIRE(!body.finite_strain(), InputError, spec.exact.where.str(),
                ": does not apply to a finite-strain body: Lamé's closed form is linear "
                "elasticity, and body '", body.name, "' is ", material::law_name(body.law), " (",
                key, "model)");
  }
}

Comparisons comparisons_of(const model::ProblemSpec& spec, const model::Discretization& d) {
  require_exact_applies(spec, d);
  bool any = false;
  for (const auto& c : spec.contact) any = any || c.compare.has_value();
  if (!any) return {};
  return make_comparisons(spec, d, model::make_contact_pairs(spec, d));
}


/// The first pair with a comparison (its curve is pressure.csv), or -1.
int compared_pair(const Comparisons& c) {
  for (size_t k = 0; k < c.size(); ++k)
    if (c[k]) return static_cast<int>(k);
  return -1;
}

/// The units of the results (summary.json "units"): the input's; an axisymmetric problem's
/// integrals are over the whole solid of revolution.
nlohmann::json units_note(const model::ProblemSpec& spec) {
  const bool axisymmetric = std::any_of(spec.bodies.begin(), spec.bodies.end(), [](const auto& b) {
    return b.material.plane == model::PlaneMode::axisymmetric;
  });
  if (axisymmetric)
    return {{"note",
             "hpcontact has no unit system: every result is in the units of the input's numbers "
             "(consistent units, e.g. N and mm: lengths and displacements mm; axisymmetric: "
             "forces, resultants and loads' totals over the whole circle N, edge loads per unit "
             "area N/mm²; stresses and moduli N/mm²; strain energy of the whole solid N·mm)"},
            {"axisymmetric", "integrals over the whole solid of revolution, dV = 2 pi r dA"}};
  return {{"note",
           "hpcontact has no unit system: every result is in the units of the input's numbers "
           "(consistent units, e.g. N and mm: lengths and displacements mm; forces per unit "
           "thickness, resultants and compare.force N/mm; stresses, pressures, tractions and "
           "moduli N/mm²; strain energy N·mm per unit thickness)"}};
}





/// A warning into summary.json's `warnings` and to the caller (RunOptions::warning), once.
void warn(const std::string& warning, const RunOptions& options, post::Summary& s) {
  auto& list = s.extra["warnings"];
  if (!list.is_array()) list = nlohmann::json::array();
  for (const auto& w : list)
    if (w == warning) return;
  list.push_back(warning);
  if (options.warning) options.warning(warning);
}

/// summary.json's `penetration`: per follower load with pressure penetration, where its pressure
/// stops and the wetted length (undeformed), and a warning for each that reached the far end of
/// its edges (the seal leaks).
void report_penetration(const model::Discretization& d, const model::NonlinearSolution& sol,
                        const RunOptions& options, post::Summary& s) {
  auto list = nlohmann::json::array();
  for (size_t i = 0; i < d.follower_loads.size() && i < sol.wet_ranges.size(); ++i) {
    const model::FollowerLoad& L = d.follower_loads[i];
    if (!L.penetration) continue;
    const model::WetRange& range = sol.wet_ranges[i];
    const model::WetExtent extent = model::wetted_extent(d, L, range);
    list.push_back({{"load", L.where},
                    {"contact", L.penetration->pair},
                    {"from", L.penetration->from_end ? "end" : "start"},
                    {"wetted_length", extent.length},
                    {"stop", {extent.stop.x(), extent.stop.y()}},
                    {"leaks", range.leaks}});
    if (range.leaks)
      warn(L.where + ".penetration: the pressure reaches the far end of the loaded edges: no point of "
           "contact[" + std::to_string(L.penetration->pair) + "] on them presses harder than the "
           "pressure, so nothing seals (the seal leaks)", options, s);
  }
  if (!list.empty()) s.extra["penetration"] = list;
}

/// A file of the output folder as a progress line names it: with last-good/ in front when it
/// went there (a failed run's last converged state), so that it is not taken for a result.
std::string shown_as(const std::filesystem::path& folder, const std::string& file) {
  return folder.filename() == "last-good" ? "last-good/" + file + " (the last converged state)" : file;
}

/// The progress event "wrote <file>" of a file written into `folder` (the staging folder or
/// last-good/): its path relative to the output folder.
ProgressEvent wrote(const std::filesystem::path& folder, const std::string& file) {
  const std::string path = folder.filename() == "last-good" ? "last-good/" + file : file;
  return {"wrote " + shown_as(folder, file), FileWrittenProgress{path}};
}

void post_process(const model::ProblemSpec& spec, const SolvedState& st, const std::string& out_dir,
                  const RunOptions& options, const Comparisons& comparisons, RunResult& r) {
  namespace fs = std::filesystem;
  auto say = [&](const ProgressEvent& e) {
    if (options.progress) options.progress(e);
  };
  const auto& disc = *st.d;
  post::Summary& s = r.summary;
  s.case_name = spec.case_name;
  if (s.method.empty()) s.method = disc.method;
  s.dofs = disc.n_free;
  s.strain_energy = post::strain_energy(disc, st.u);
  // Whatever the solver checked, a result that is not finite is never reported as one.
  HPC_REQUIRE(std::isfinite(s.strain_energy) && st.u.allFinite(), NumericalError, spec.file,
              ": the solution is not finite (strain energy ", s.strain_energy, ", largest |u| ",
              st.u.cwiseAbs().maxCoeff(), "): a load, prescribed displacement, length or material "
              "value of the input is too large for double precision");
  s.error = exact_error(spec, disc, st.u, s.strain_energy);
  for (const auto& w : solution_warnings(spec, disc, st.u, st.pairs, st.contact)) warn(w, options, s);
  s.extra["units"] = units_note(spec);
  // The p-version's shape space: its default depends on the adaptivity (docs/input.md).
  if (spec.discretization.method == model::Method::p)
    s.extra["shape_space"] =
        spec.discretization.space == model::ShapeSpace::trunk ? "trunk" : "tensor";
  if (!st.contact.empty()) {
    // Every pair; "contact" is the first (as before several pairs were reported).
    s.extra["contact_pairs"] = contact_pairs_json(st, comparisons);
    s.extra["contact"] = s.extra["contact_pairs"][0];
    r.contact = contact_table(disc, st.contact, st.pairs);
    if (const int k = compared_pair(comparisons); k >= 0)
      r.pressure_curve = comparisons[k]->curve(disc, st.pairs[k], st.contact[k], st.u, st.multipliers_of(k));
  }
  if (!r.reaction_history.empty()) {
    const model::Reactions& reactions = r.reaction_history.back();
    s.extra["reactions"] = reactions_json(spec, reactions);
    s.extra["equilibrium_residual"] = reactions.equilibrium_residual;
    if (const auto w = equilibrium_warning(spec, reactions)) warn(*w, options, s);
  }
  if (out_dir.empty()) return;
  const fs::path out(out_dir);
  if (!options.effective_input.empty())
    post::write_text_file((out / "input.yaml").string(), options.effective_input);
  if (!st.contact.empty())
    post::write_text_file((out / "contact.csv").string(), contact_csv(r.contact));
  if (r.pressure_curve)
    post::write_text_file((out / "pressure.csv").string(), pressure_csv(*r.pressure_curve));
  if (spec.output.vtu) {
    post::write_vtu((out / "solution.vtu").string(), disc, st.u, spec.output.vtu_subdivisions);
    say(wrote(out, "solution.vtu"));
    if (!st.contact.empty()) post::write_contact_vtu((out / "contact.vtu").string(), st.pairs, st.contact);
  }
}

/// The load path (path.csv): a row per converged step, with the monitored node and the first
/// pair's resultant, then every further pair's (pair1_resultant_x, ...; from the contact
/// history, a row per pair and step), then the supports' reactions and the balance (from the
/// reactions' history, a row per step). Nothing without an output folder.
void write_path(const model::ProblemSpec& spec, const model::NonlinearSolution& sol,
                const std::vector<ContactHistoryRow>& history,
                const std::vector<model::Reactions>& reactions, const std::string& out_dir) {
  if (out_dir.empty() || sol.path.empty()) return;
  std::ostringstream csv;
  const bool per_direction = std::any_of(spec.solver.stages.begin(), spec.solver.stages.end(),
                                         [](const model::LoadStageSpec& st) { return st.per_direction(); });
  csv << std::setprecision(12) << "step,displacement_factor,load_factor,iterations,arc_length";
  if (!spec.solver.monitor_body.empty()) csv << ",monitor_ux,monitor_uy";
  csv << ",resultant_x,resultant_y";
  int n_pairs = 0;
  for (const auto& h : history) n_pairs = std::max(n_pairs, h.pair + 1);
  for (int k = 1; k < n_pairs; ++k) csv << ",pair" << k << "_resultant_x,pair" << k << "_resultant_y";
  if (per_direction) csv << ",displacement_factor_x,displacement_factor_y";
  const bool with_reactions = !reactions.empty() && reactions.size() == sol.path.size();
  if (with_reactions) csv << reaction_header(spec, reactions.front());
  csv << '\n';
  for (size_t i = 0; i < sol.path.size(); ++i) {
    const auto& p = sol.path[i];
    csv << i + 1 << ',' << p.displacements << ',' << p.loads << ',' << p.iterations << ','
        << p.arc_length;
    if (!spec.solver.monitor_body.empty()) csv << ',' << p.monitor.x() << ',' << p.monitor.y();
    csv << ',' << p.resultant.x() << ',' << p.resultant.y();
    for (int k = 1; k < n_pairs; ++k) {
      const size_t row = i * n_pairs + k;
      if (row < history.size()) csv << ',' << history[row].resultant.x() << ',' << history[row].resultant.y();
      else csv << ",,";
    }
    if (per_direction) csv << ',' << p.displacement_factors.x() << ',' << p.displacement_factors.y();
    if (with_reactions) csv << reaction_row(reactions[i]);
    csv << '\n';
  }
  post::write_text_file((std::filesystem::path(out_dir) / "path.csv").string(), csv.str());
  if (!history.empty())
    post::write_text_file((std::filesystem::path(out_dir) / "contact_history.csv").string(),
                          contact_history_csv(history, per_direction));
}

/// The final adapted mesh of every body as a problem-file fragment (nodes, elements, curves,
/// edge sets, element degrees): paste it over the bodies' mesh keys to rerun that mesh.
std::string mesh_yaml(const model::ProblemSpec& spec) {
  std::ostringstream os;
  os << std::setprecision(17);
  os << "# The adapted mesh, body by body: replace the keys of bodies[i] of the problem file.\n";
  for (const auto& b : spec.bodies) {
    os << b.name << ":\n  nodes:\n";
    for (size_t i = 0; i < b.nodes.size(); ++i)
      os << "    " << b.node_ids[i] << ": [" << b.nodes[i][0] << ", " << b.nodes[i][1] << "]\n";
    os << "  elements:\n";
    for (size_t q = 0; q < b.elements.size(); ++q) {
      const auto& e = b.elements[q];
      os << "    " << b.element_ids[q] << ": [" << e[0] << ", " << e[1] << ", " << e[2] << ", "
         << e[3] << "]\n";
    }
    if (!b.curves.empty()) os << "  curves:\n";
    for (const auto& c : b.curves) {
      os << "    - {nodes: [" << c.node_a << ", " << c.node_b << "], ";
      if (c.kind == model::CurveKind::arc)
        os << "arc: {center: [" << c.center[0] << ", " << c.center[1] << "], radius: " << c.radius
           << (c.ccw ? std::string(", ccw: ") + (c.ccw > 0 ? "true" : "false") : "") << "}}\n";
      else
        os << "parametric: {x: \"" << c.x_expr << "\", y: \"" << c.y_expr << "\"}}\n";
    }
    if (!b.edge_sets.empty()) os << "  edge_sets:\n";
    for (const auto& set : b.edge_sets) {
      os << "    " << set.name << ": [";
      for (size_t k = 0; k < set.edges.size(); ++k)
        os << (k ? ", " : "") << "[" << set.edges[k][0] << ", " << set.edges[k][1] << "]";
      os << "]\n";
    }
    if (!b.element_degrees.empty()) {
      os << "  degrees: {";
      bool first = true;
      for (const auto& [id, p] : b.element_degrees) {
        os << (first ? "" : ", ") << id << ": [" << p[0] << ", " << p[1] << "]";
        first = false;
      }
      os << "}\n";
    }
  }
  return os.str();
}

/// The figures every adaptive iteration records.
nlohmann::json solve_json(const adapt::SolveFigures& f) {
  return {{"dofs", f.dofs},
          {"elements", f.elements},
          {"degree_range", {f.min_degree, f.max_degree}},
          {"strain_energy", f.strain_energy},
          {"newton_iterations", f.newton_iterations},
          {"gamma_star", points_json(f.gamma_star)},
          {"solve_time_s", f.seconds}};
}

nlohmann::json rp_iteration_json(const adapt::RpIteration& it) {
  nlohmann::json j = solve_json(it.solve);
  j["iteration"] = it.iteration;
  j["nodes"] = nlohmann::json::array();
  for (const auto& n : it.nodes)
    j["nodes"].push_back({{"body", n.body}, {"node", n.node_id},
                          {"position", {n.position.x(), n.position.y()}},
                          {"gamma_star", n.has_target ? nlohmann::json{n.gamma_star.x(), n.gamma_star.y()}
                                                      : nlohmann::json()},
                          {"follows", adapt::kind_name(n.kind)}});
  j["zone_ends_found"] = it.zone_ends_found;
  j["distance"] = it.distance;
  return j;
}

/// An error estimate as summary.json keeps it (null where there is none).
nlohmann::json estimate_json(const adapt::ErrorEstimate& e) {
  auto number = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
  nlohmann::json j = {{"pressure_rel_L2", number(e.pressure)},
                      {"energy_rel", number(e.energy)},
                      {"from", "one degree more on the same mesh"},
                      {"dofs", e.dofs},
                      {"newton_iterations", e.newton_iterations},
                      {"solve_time_s", e.seconds}};
  if (!std::isnan(e.shear)) j["shear_rel_L2"] = number(e.shear);
  return j;
}

nlohmann::json hp_iteration_json(const adapt::HpIteration& it) {
  nlohmann::json j = solve_json(it.solve);
  j["step"] = it.step;
  j["centres"] = points_json(it.centres);
  j["recentred"] = it.recentred;
  j["gamma_star_inside"] = it.inside;
  if (it.estimate.dofs > 0) j["estimated_error"] = estimate_json(it.estimate);
  if (it.degrees_learnt)
    j["degrees"] = {{"raised", it.degrees_raised}, {"lowered", it.degrees_lowered},
                    {"weights", it.weights_left_out.empty() ? "goal-oriented"
                                                           : "energy surplus alone: " + it.weights_left_out}};
  if (!it.left_out.empty()) j["left_out"] = it.left_out;
  if (it.step == 0) {
    j["resolve_rounds"] = it.resolve_rounds;
    j["resolved_towards"] = points_json(it.resolved_towards);
  }
  return j;
}

/// solve(), whose assembly (or a linear solve's factorisation) a stop request may give up before
/// anything has converged (core/stop.hpp: Stopped): the run then ends as stopped with nothing to
/// keep, the output folder as it was.
template <class Solve>
auto unless_stopped(const model::ProblemSpec& spec, const Solve& solve) {
  try {
    return solve();
  } catch (const Stopped& e) {
    throw NumericalError(spec.file + ": the solver stopped: " + e.what() +
                         ", before anything had converged; the output folder is left as it was");
  }
}

}  // namespace

RunResult run_problem(const model::ProblemSpec& input, const RunOptions& options) {
  using Clock = std::chrono::steady_clock;
  namespace fs = std::filesystem;
  const auto t0 = Clock::now();
  auto say = [&](const ProgressEvent& e) {
    if (options.progress) options.progress(e);
  };
  // contact[].carrier: auto, chosen once on the input's mesh (an adaptive step keeps the choice)
  const model::ProblemSpec spec = model::with_chosen_carriers(input);
  for (const auto& pair : spec.contact)
    if (!pair.carrier_choice.empty()) say(pair.where.str() + ": " + pair.carrier_choice);

  // Every file goes into the folder's staging folder (`stage`); the folder moves them in at
  // the end, the run's last-good/ alone if it failed.
  std::optional<OutputFolder> own_folder;
  OutputFolder* folder = options.folder;
  if (!folder && !options.out_dir.empty()) {
    own_folder.emplace(options.out_dir, run_layout(),
                       std::vector<OutputFolder::Input>{{spec.file, "the problem file"}});
    folder = &*own_folder;
  }
  if (folder)
    for (const auto& pair : spec.contact)
      if (pair.compare && !pair.compare->reference.empty())
        folder->refuse_if_inside(reference_path(spec, *pair.compare),
                                 "the reference file of " + pair.compare->where.str());
  require_references(spec);  // a reference that cannot be read fails before the solve
  const std::string stage = folder ? folder->begin() : "";
  const std::string last_good = folder ? (fs::path(folder->target()) / "last-good").string() : "";
  if (spec.solid) return run_solid(spec, options, folder, stage);

  RunResult result;
  post::Summary& s = result.summary;
  // summary.json and report.html of the state `st` of `solved` (the input, or hp's last mesh)
  auto write_summary = [&](const std::string& out_dir, const model::ProblemSpec& solved,
                           const SolvedState& st) {
    s.wall_time_s = std::chrono::duration<double>(Clock::now() - t0).count();
    if (out_dir.empty()) return;
    post::write_summary((fs::path(out_dir) / "summary.json").string(), s);
    say(wrote(fs::path(out_dir), "summary.json"));
    write_run_report(out_dir, {solved, post::to_json(s), result.contact, *st.d, st.u});
  };

  // The comparisons' preconditions are checked before anything is solved (on the input's mesh).
  std::optional<model::Discretization> d0;
  if (spec.adapt.method != model::AdaptMethod::none) {
    d0.emplace(model::discretize(spec));
    for (const auto& w : d0->warnings) warn(w, options, s);
  }
  Comparisons comparisons;
  if (spec.adapt.method != model::AdaptMethod::none) comparisons = comparisons_of(spec, *d0);

  if (spec.adapt.method != model::AdaptMethod::none) {
    // rp / hp: every iteration's pressure curve and errors are kept; the final mesh is the result.
    const bool rp = spec.adapt.method == model::AdaptMethod::rp;
    const std::string method = rp ? "rp" : "hp";
    const std::string iter_dir = stage.empty() ? "" : (fs::path(stage) / method).string();
    if (!iter_dir.empty()) fs::create_directories(iter_dir);
    nlohmann::json history = nlohmann::json::array();
    // The pressure errors of one iteration into its record, its curve into iter_dir.
    auto add_pressure = [&](nlohmann::json& j, int iteration, const adapt::Solved& solved) {
      const auto& sol = solved.solution;
      const SolvedState st{&solved.discretization, sol.u, sol.contact, sol.pairs, sol.multipliers};
      const int k = compared_pair(comparisons);
      if (k < 0) return;
      const std::string csv =
          iter_dir.empty() ? ""
                           : (fs::path(iter_dir) / ("pressure-" + std::to_string(iteration) + ".csv"))
                                 .string();
      const nlohmann::json cj = contact_json(st, k, &*comparisons[k], csv);
      for (const char* key : {"half_width", "e_L2_hertz_percent", "e_L2_shtayerman_percent",
                              "e_seed_hertz_percent", "e_seed_shtayerman_percent",
                              "e_L2_reference_percent", "multiplier", "penalty_traction"})
        if (cj.contains(key)) j[key] = cj[key];
    };
    adapt::SolvedPtr last;
    int kept = -1;  // the history entry of `last`
    bool converged = false;
    std::string message;
    nlohmann::json aj = {{"method", method}};
    if (rp) {
      const auto outcome = adapt::relocate_nodes(
          spec, adapt::rp_options(spec.adapt), options.progress, [&](const adapt::RpIteration& it, const adapt::Solved& solved) {
            nlohmann::json j = rp_iteration_json(it);
            add_pressure(j, it.iteration, solved);
            history.push_back(j);
          });
      last = outcome.last;
      converged = outcome.converged;
      message = outcome.message;
      aj["stopped"] = converged ? "tolerance reached" : outcome.message.empty() ? "error" : "not converged";
      aj["tolerance"] = spec.adapt.tolerance;
      aj["update"] = spec.adapt.secant ? "secant" : "relocate";
    } else {
      const auto outcome = adapt::refine_towards_zone_ends(
          spec, adapt::hp_options(spec.adapt), options.progress, [&](const adapt::HpIteration& it, const adapt::Solved& solved) {
            nlohmann::json j = hp_iteration_json(it);
            add_pressure(j, it.step, solved);
            history.push_back(j);
          });
      last = outcome.last;
      kept = outcome.last_step;
      converged = outcome.converged;
      message = outcome.message;
      aj["stopped"] = outcome.stopped.empty() ? "error" : outcome.stopped;
      if (spec.adapt.tolerance_given) {
        aj["tolerance"] = spec.adapt.tolerance;
        aj["max_dofs"] = spec.adapt.max_dofs;
        aj["estimated_error"] = estimate_json(outcome.estimate);
      }
      aj["factor"] = spec.adapt.factor;
      aj["steps"] = spec.adapt.steps;
      aj["degree"] = spec.adapt.degree == model::HpDegree::goal       ? "goal"
                     : spec.adapt.degree == model::HpDegree::constant ? "constant"
                                                                       : "rising";
      if (spec.adapt.degree != model::HpDegree::constant) aj["min_degree"] = spec.adapt.min_degree;
    }
    HPC_REQUIRE(last, AdaptError, message);
    if (kept < 0) kept = static_cast<int>(history.size()) - 1;
    aj["result_step"] = kept;
    s.method = method;
    s.newton_iterations = last->solution.newton_iterations;
    s.load_steps = last->solution.load_steps;
    s.extra["load_factor"] = last->solution.load_factor;
    report_penetration(last->discretization, last->solution, options, s);
    aj["iterations"] = static_cast<int>(history.size()) - 1;
    {
      // every solve of the loop: its steps and, with a tolerance, their estimates' solves
      int total = 0;
      for (const auto& h : history) {
        total += h.value("newton_iterations", 0);
        if (h.contains("estimated_error")) total += h["estimated_error"].value("newton_iterations", 0);
      }
      s.extra["newton_iterations_total"] = total;
    }
    // Asked to stop after the loop's last solve (no iteration left to end at): stopped all the
    // same, as its scheduler reports it; the result is kept as the last good one.
    if (converged && stop_requested()) {
      converged = false;
      message = std::string(stop_reason()) + " after the loop's last solve";
    }
    aj["converged"] = converged;
    aj["message"] = message;
    aj["history"] = history;
    s.extra["adapt"] = aj;
    // A failed loop keeps its last good result apart, so it cannot pass for the run's result.
    const std::string out_dir = stage.empty() ? ""
                                : converged ? stage
                                            : (fs::path(stage) / "last-good").string();
    if (!out_dir.empty()) fs::create_directories(out_dir);
    SolvedState st{&last->discretization, last->solution.u, last->solution.contact,
                   last->solution.pairs, last->solution.multipliers};
    result.reaction_history = {model::reactions(
        last->discretization, model::pairs_of_last_step(last->solution), last->solution.u,
        last->solution.multipliers, last->solution.loads_factor)};
    post_process(last->spec, st, out_dir, options, comparisons, result);
    // the load path of the final mesh's solve (its first pair's resultant: no contact history,
    // no reactions per step)
    write_path(last->spec, last->solution, {}, {}, out_dir);
    result.path = last->solution.path;
    if (!out_dir.empty())
      post::write_text_file((fs::path(out_dir) / "mesh.yaml").string(), mesh_yaml(last->spec));
    s.converged = converged;
    write_summary(out_dir, last->spec, st);
    if (folder) {
      if (converged)
        folder->commit();
      else
        folder->commit_subfolder("last-good");
    }
    HPC_REQUIRE(converged, AdaptError, message,
                folder ? "; the last good result (" + std::string(rp ? "iteration " : "step ") +
                             std::to_string(kept) +
                             ") is in " + last_good
                       : std::string());
    result.discretization = last->discretization;
    result.u = last->solution.u;
    return result;
  }

  model::Discretization d = model::discretize(spec);
  model::require_held(spec, d);
  for (const auto& w : d.warnings) warn(w, options, s);
  comparisons = comparisons_of(spec, d);
  {
    std::ostringstream os;
    int n_el = 0;
    for (const auto& b : d.bodies) n_el += b.mesh.n_quads();
    os << "discretised: " << d.bodies.size() << " body(ies), " << n_el << " elements, "
       << d.n_free << " free dofs (" << d.method << "-version)";
    say(os.str());
  }
  SolvedState st;
  if (spec.contact.empty() && !d.finite_strain() && spec.solver.control == "load") {
    model::LinearSolveOptions lo;
    lo.condense = spec.discretization.condense;
    lo.solver = solve::linear_solver_kind(spec.solver.linear, spec.solver.where.str() + ".linear");
    const auto sol = unless_stopped(spec, [&] {
      try {
        return model::solve_linear(d, lo);
      } catch (const NumericalError& e) {  // named as the nonlinear solve's failures are
        throw NumericalError(spec.file + ": the solver stopped: " + e.what());
      }
    });
    std::ostringstream os;
    os << "solved: system of " << sol.n_system << " unknowns, assembly " << sol.assembly_seconds
       << " s, factorisation and solve " << sol.solve_seconds << " s";
    say(os.str());
    st.u = sol.u;
    result.reaction_history = {model::reactions(d, {}, st.u, {}, 1.0)};
    s.newton_iterations = 1;
    s.extra["newton_iterations_total"] = 1;
    s.load_steps = 1;
    s.extra["system_size"] = sol.n_system;
    s.extra["condensed"] = spec.discretization.condense;
    s.extra["solve_time_s"] = sol.solve_seconds;
    s.extra["assembly_time_s"] = sol.assembly_seconds;
  } else {
    // output.steps: every converged load step as steps/step-NNNN.vtu (and contact-NNNN.vtu),
    // collected in solution.pvd (contact.pvd) at time = the step's number (the row of path.csv).
    std::vector<std::string> step_files, contact_files;
    std::vector<double> step_times;
    // Every converged step: each pair's row of contact_history.csv.
    std::vector<ContactHistoryRow> history;
    int n_steps = 0;
    auto record_history = [&](const Eigen::VectorXd& u, const model::NonlinearSolution::PathPoint& at,
                              const std::vector<model::ContactPair>& pairs,
                              const std::vector<Eigen::VectorXd>& multipliers) {
      ++n_steps;
      result.reaction_history.push_back(model::reactions(d, pairs, u, multipliers, at.loads));
      for (size_t k = 0; k < pairs.size(); ++k)
        history.push_back(contact_history_row(
            n_steps, at, static_cast<int>(k), d.bodies[pairs[k].body].name, pairs[k],
            model::evaluate_contact(d, pairs[k], u, multipliers[k].size() ? &multipliers[k] : nullptr)));
    };
    model::StepFn on_step = record_history;
    if (spec.output.steps && spec.output.vtu && !stage.empty()) {
      fs::create_directories(fs::path(stage) / "steps");
      on_step = [&](const Eigen::VectorXd& u, const model::NonlinearSolution::PathPoint& at,
                    const std::vector<model::ContactPair>& pairs,
                    const std::vector<Eigen::VectorXd>& multipliers) {
        record_history(u, at, pairs, multipliers);
        std::ostringstream name;
        name << std::setw(4) << std::setfill('0') << step_files.size() + 1 << ".vtu";
        step_files.push_back("steps/step-" + name.str());
        step_times.push_back(static_cast<double>(step_files.size()));
        post::write_vtu((fs::path(stage) / step_files.back()).string(), d, u,
                        spec.output.vtu_subdivisions);
        if (pairs.empty()) return;
        std::vector<model::ContactResult> results;
        for (size_t k = 0; k < pairs.size(); ++k)
          results.push_back(model::evaluate_contact(
              d, pairs[k], u, multipliers[k].size() ? &multipliers[k] : nullptr));
        contact_files.push_back("steps/contact-" + name.str());
        post::write_contact_vtu((fs::path(stage) / contact_files.back()).string(), pairs,
                                results);
      };
    }
    auto sol = unless_stopped(
        spec, [&] { return model::solve_contact(spec, d, options.progress, {}, on_step); });
    if (!step_files.empty()) {
      post::write_pvd((fs::path(stage) / "solution.pvd").string(), step_files, step_times);
      if (!contact_files.empty())
        post::write_pvd((fs::path(stage) / "contact.pvd").string(), contact_files, step_times);
      say({"wrote " + std::to_string(step_files.size()) + " load steps: solution.pvd",
           FileWrittenProgress{"solution.pvd"}});
    }
    s.newton_iterations = sol.newton_iterations;
    s.extra["newton_iterations_total"] = sol.newton_iterations;
    s.load_steps = sol.load_steps;
    s.extra["load_factor"] = sol.load_factor;
    report_penetration(d, sol, options, s);
    if (sol.loads_factor != sol.load_factor || !spec.solver.stages.empty() ||
        spec.solver.control != "load")
      s.extra["loads_factor"] = sol.loads_factor;
    if (sol.displacement_factors.x() != sol.displacement_factors.y())
      s.extra["displacement_factors"] = {sol.displacement_factors.x(), sol.displacement_factors.y()};
    if (!sol.converged) {
      // The last converged load step is kept apart, in last-good/, with converged: false: it
      // cannot pass for the run's result (no summary.json in the output folder).
      std::string kept;
      if (folder && sol.load_steps > 0) {
        const std::string good = (fs::path(stage) / "last-good").string();
        fs::create_directories(good);
        const SolvedState last{&d, sol.u, sol.contact, sol.pairs, sol.multipliers};
        post_process(spec, last, good, options, comparisons, result);
        write_path(spec, sol, history, result.reaction_history, good);
        s.converged = false;
        s.extra["message"] = sol.message;
        write_summary(good, spec, last);
        std::ostringstream os;
        os << "; the last converged load step (";
        if (sol.displacement_factors.x() != sol.displacement_factors.y())
          os << "displacement factors (" << sol.displacement_factors.x() << ", "
             << sol.displacement_factors.y() << "), load factor " << sol.loads_factor;
        else if (sol.loads_factor != sol.load_factor)
          os << "displacement factor " << sol.load_factor << ", load factor " << sol.loads_factor;
        else
          os << "factor " << sol.load_factor;
        os << ") is in " << last_good;
        kept = os.str();
        folder->commit_subfolder("last-good");
      }
      throw NumericalError(spec.file + ": the solver stopped: " + sol.message + kept);
    }
    write_path(spec, sol, history, result.reaction_history, stage);
    result.path = sol.path;
    result.contact_history = history;
    st.u = sol.u;
    st.contact = std::move(sol.contact);
    st.pairs = std::move(sol.pairs);
    st.multipliers = std::move(sol.multipliers);
  }
  result.discretization = std::move(d);
  st.d = &result.discretization;
  post_process(spec, st, stage, options, comparisons, result);
  s.converged = true;
  result.u = st.u;
  write_summary(stage, spec, st);
  // Asked to stop while solving a step that has no Newton iteration left to end at (a linear
  // solve, the last iteration): the run still ends as stopped, as its scheduler reports it, and
  // the folder keeps what it held (the adaptive loops' result above goes to last-good/).
  HPC_REQUIRE(!stop_requested(), NumericalError, spec.file, ": ", stop_reason(),
              " before the results were written; the output folder is left as it was");
  if (folder) folder->commit();
  return result;
}

}  // namespace hpcontact::driver
