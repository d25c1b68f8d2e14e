// The adaptive loops on the Hertz examples, whole: the rp relocation loop (rp5, rp8) and the
// 8-step hp loop (hp.yaml with factor 0.17 and the seed's 0.5), as `hpcontact run` does them
// without post-processing or files.
#include <benchmark/benchmark.h>

#include <string>

#include "hpcontact/adapt/hp.hpp"
#include "hpcontact/adapt/rp.hpp"
#include "hpcontact/io/problem_reader.hpp"

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

}  // namespace
