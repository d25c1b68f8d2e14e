// The adaptive loops on the Hertz examples, whole: the rp relocation loop (rp5, rp8), the
// 8-step hp loop (hp.yaml with factor 0.17 and the seed's 0.5) and the hp loop to a tolerance
// (hp-tolerance.yaml, 1e-3 and 1e-4, beside one linear solve of its final mesh), as `hpcontact
// run` does them without post-processing or files.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "hpcontact/adapt/hp.hpp"
#include "hpcontact/adapt/rp.hpp"
#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/model/discretization.hpp"
#include "hpcontact/model/linear_solve.hpp"

namespace {

using namespace hpcontact;

std::string example(const std::string& name) {
  return std::string(HPC_SOURCE_DIR) + "/examples/hertz/" + name + ".yaml";
}

// range(0) = p of examples/hertz/rp<p>.yaml.
void BM_RpLoop(benchmark::State& state) {
  const auto spec = io::read_problem(example("rp" + std::to_string(state.range(0))), {});
  adapt::RpOptions o;
  o.tolerance = spec.adapt.tolerance;
  o.max_iterations = spec.adapt.max_iterations;
  adapt::RpOutcome out;
  for (auto _ : state) {
    out = adapt::relocate_nodes(spec, o);
    if (!out.converged) state.SkipWithError(out.message.c_str());
  }
  int newton = 0;
  for (const auto& it : out.history) newton += it.solve.newton_iterations;
  state.counters["p"] = state.range(0);
  state.counters["dofs"] = out.history.empty() ? 0 : out.history.back().solve.dofs;
  state.counters["solves"] = static_cast<double>(out.history.size());
  state.counters["newton_iterations"] = newton;
}
BENCHMARK(BM_RpLoop)->ArgName("p")->Arg(5)->Arg(8)->Unit(benchmark::kMillisecond)->UseRealTime();

// range(0) = 100 × the refinement factor.
void BM_HpLoop(benchmark::State& state) {
  const auto spec = io::read_problem(example("hp"), {});
  adapt::HpOptions o;
  o.factor = state.range(0) / 100.0;
  o.steps = spec.adapt.steps;
  adapt::HpOutcome out;
  for (auto _ : state) {
    out = adapt::refine_towards_zone_ends(spec, o);
    if (!out.converged) state.SkipWithError(out.message.c_str());
  }
  int newton = 0, solves = 0;
  for (const auto& it : out.history) newton += it.solve.newton_iterations, solves += 1 + it.recentred;
  state.counters["factor"] = o.factor;
  state.counters["dofs"] = out.history.empty() ? 0 : out.history.back().solve.dofs;
  state.counters["solves"] = solves;
  state.counters["newton_iterations"] = newton;
}
BENCHMARK(BM_HpLoop)->ArgName("factor_percent")->Arg(17)->Arg(50)->Unit(benchmark::kMillisecond)->UseRealTime();

// range(0) = k of the tolerance 10^-k: examples/hertz/hp-tolerance.yaml's loop (the defaults
// with a tolerance: factor 0.15, the error of each step estimated by a solve one degree higher,
// goal-oriented degrees in the trunk space; range(1) = 1: the rising degree in the tensor space).
adapt::HpOutcome hp_to_tolerance(const model::ProblemSpec& spec) {
  return adapt::refine_towards_zone_ends(spec, adapt::hp_options(spec.adapt));
}

/// range(1) = 1: the rising degree in the tensor space (the defaults before goal-oriented degrees).
model::ProblemSpec tolerance_case(int k, bool rising = false) {
  std::vector<std::string> sets = {"adapt.tolerance=1e-" + std::to_string(k)};
  if (rising) sets.insert(sets.end(), {"adapt.degree=rising", "discretization.space=tensor"});
  return io::read_problem(example("hp-tolerance"), sets);
}

void BM_HpToTolerance(benchmark::State& state) {
  const auto spec = tolerance_case(static_cast<int>(state.range(0)), state.range(1) == 1);
  adapt::HpOutcome out;
  for (auto _ : state) {
    out = hp_to_tolerance(spec);
    if (!out.converged) state.SkipWithError(out.message.c_str());
  }
  int newton = 0, solves = 0;
  for (const auto& it : out.history)
    newton += it.solve.newton_iterations + it.estimate.newton_iterations, solves += 2 + it.recentred;
  state.counters["dofs"] = out.last ? out.last->discretization.n_free : 0;
  state.counters["steps"] = static_cast<double>(out.history.size()) - 1;
  state.counters["solves"] = solves;
  state.counters["newton_iterations"] = newton;
  state.counters["estimate"] = out.estimate.pressure;
}
BENCHMARK(BM_HpToTolerance)->ArgNames({"tol_exp", "rising"})->ArgsProduct({{3, 4}, {0, 1}})->Unit(benchmark::kMillisecond)->UseRealTime();

// One linear elastic solve of the final mesh of that loop (its prescribed displacement, no
// contact): the unit of "the loop costs N linear solves".
void BM_HpToToleranceFinalLinearSolve(benchmark::State& state) {
  const auto out = hp_to_tolerance(tolerance_case(static_cast<int>(state.range(0))));
  if (!out.last) {
    state.SkipWithError(out.message.c_str());
    return;
  }
  const auto d = model::discretize(out.last->spec);
  for (auto _ : state)
    benchmark::DoNotOptimize(model::solve_linear(d, {.condense = out.last->spec.discretization.condense}).u);
  state.counters["dofs"] = d.n_free;
}
BENCHMARK(BM_HpToToleranceFinalLinearSolve)->ArgName("tol_exp")->Arg(3)->Arg(4)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
