// Exact contact (augmented Lagrangian multipliers at Gauss–Lobatto nodes, the default) against
// the seed's penalty, same input otherwise: whole solves and adaptive loops as `hpcontact run`
// does them without files, and one linear elastic solve of the Hertz p8 mesh (the unit of the
// "a contact solve costs a few linear solves" ratio).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <string>
#include <vector>

#include "hpcontact/adapt/hp.hpp"
#include "hpcontact/adapt/rp.hpp"
#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/model/contact_solve.hpp"
#include "hpcontact/model/discretization.hpp"
#include "hpcontact/model/linear_solve.hpp"

namespace {

using namespace hpcontact;

std::string source(const std::string& path) { return std::string(HPC_SOURCE_DIR) + "/" + path; }

/// The overrides that turn every contact pair of the case to the penalty; a pair whose input
/// gives no penalty gets the one its example had before exact contact (bilateral: 1.05e8 = 500 E),
/// and the other body's normal (normal: mean is exact enforcement's).
std::vector<std::string> penalty_overrides(const std::string& path) {
  const auto spec = io::read_problem(source(path), {});
  std::vector<std::string> o;
  for (std::size_t i = 0; i < spec.contact.size(); ++i) {
    const std::string pair = "contact[" + std::to_string(i) + "].";
    o.push_back(pair + "enforcement=penalty");
    if (spec.contact[i].penalty == 0) o.push_back(pair + "penalty=1.05e8");
    if (spec.contact[i].mean_normal) o.push_back(pair + "normal=other");  // the penalty's one
  }
  return o;
}

/// What one run of a case cost: Newton iterations over every solve, solves, the final unknowns,
/// and for rp the most iterations of one relocation after the first solve.
struct Cost {
  int newton = 0, solves = 0, dofs = 0, load_steps = 0, most_per_relocation = 0;
};

Cost run_case(const model::ProblemSpec& spec) {
  Cost c;
  if (spec.adapt.method == model::AdaptMethod::rp) {
    const auto out = adapt::relocate_nodes(spec, adapt::rp_options(spec.adapt));
    if (!out.converged) throw std::runtime_error(out.message);
    for (const auto& it : out.history) {
      c.newton += it.solve.newton_iterations;
      if (it.iteration > 0) c.most_per_relocation = std::max(c.most_per_relocation, it.solve.newton_iterations);
    }
    c.solves = static_cast<int>(out.history.size());
    c.dofs = out.history.back().solve.dofs;
  } else if (spec.adapt.method == model::AdaptMethod::hp) {
    const auto out = adapt::refine_towards_zone_ends(spec, adapt::hp_options(spec.adapt));
    if (!out.converged) throw std::runtime_error(out.message);
    for (const auto& it : out.history) c.newton += it.solve.newton_iterations, c.solves += 1 + it.recentred;
    c.dofs = out.history.back().solve.dofs;
  } else {
    const auto d = model::discretize(spec);
    const auto sol = model::solve_contact(spec, d);
    if (!sol.converged) throw std::runtime_error(sol.message);
    c.newton = sol.newton_iterations;
    c.solves = 1;
    c.dofs = d.n_free;
    c.load_steps = sol.load_steps;
  }
  return c;
}

void enforcement_case(benchmark::State& state, const std::string& path, bool penalty) {
  const auto spec = io::read_problem(source(path), penalty ? penalty_overrides(path) : std::vector<std::string>{});
  Cost c;
  for (auto _ : state) {
    try {
      c = run_case(spec);
    } catch (const std::exception& e) {
      state.SkipWithError(e.what());
      return;
    }
  }
  state.counters["dofs"] = c.dofs;
  state.counters["solves"] = c.solves;
  state.counters["load_steps"] = c.load_steps;
  state.counters["newton_iterations"] = c.newton;
  state.counters["most_per_relocation"] = c.most_per_relocation;
}

// One linear elastic solve of the Hertz p8 mesh (its prescribed displacement, no contact),
// condensed as the contact solve is: discretise, assemble, factorise, solve.
void BM_HertzP8LinearSolve(benchmark::State& state) {
  auto spec = io::read_problem(source("examples/hertz/p8.yaml"), {});
  spec.contact.clear();
  for (auto _ : state) {
    const auto d = model::discretize(spec);
    benchmark::DoNotOptimize(model::solve_linear(d, {.condense = spec.discretization.condense}).u);
  }
}
BENCHMARK(BM_HertzP8LinearSolve)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();

/// The cases of issue 15's before/after table, in its order.
const char* kCases[] = {"examples/hertz/p8.yaml",
                        "examples/hertz/rp8.yaml",
                        "examples/hertz/hp.yaml",
                        "examples/hertz/bilateral.yaml",
                        "examples/curve-obstacle/crowned-rail.yaml",
                        "examples/two-bars/stick.yaml",
                        "examples/two-bars/coulomb.yaml",
                        "examples/axle-ring/ring12-p4.yaml",
                        "examples/ring-foundation/ring.yaml"};

const int registered = [] {
  for (const char* path : kCases)
    for (const bool penalty : {true, false})
      benchmark::RegisterBenchmark(
          (std::string("BM_Enforcement/") + (penalty ? "penalty/" : "exact/") + path).c_str(),
          [p = std::string(path), penalty](benchmark::State& s) { enforcement_case(s, p, penalty); })
          ->Unit(benchmark::kMillisecond)
          ->MeasureProcessCPUTime()
          ->UseRealTime();
  return 0;
}();

}  // namespace
