// The Hertz contact problem by the seed's penalty: whole solves with the analytic tangent and with the seed's
// finite-difference tangent (eq. 3.36), one tangent evaluation of each at the solution; the
// examples end to end as `hpcontact run` does them (read, solve, write every file).
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

#include "hpcontact/driver/run.hpp"

#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/model/contact_solve.hpp"
#include "hpcontact/model/discretization.hpp"

namespace {

using namespace hpcontact;

std::string hertz(int p) { return std::string(HPC_SOURCE_DIR) + "/examples/hertz/p" + std::to_string(p) + ".yaml"; }

const char* kTangent[] = {"analytic", "finite-difference"};

// range(0) = p (5 or 8, the examples), range(1) = tangent (0 analytic, 1 FD), range(2) = condense.
// Discretisation is outside the timed region; the solve includes force control (six load
// steps, about 45 Newton iterations) exactly as `hpcontact run` does.
void BM_HertzSolve(benchmark::State& state) {
  const int p = static_cast<int>(state.range(0));
  const auto spec = io::read_problem(
      hertz(p), {"contact[0].enforcement=penalty", std::string("solver.tangent=") + kTangent[state.range(1)],
                 std::string("discretization.condense=") + (state.range(2) ? "true" : "false")});
  const auto d = model::discretize(spec);
  int iterations = 0;
  for (auto _ : state) {
    const auto sol = model::solve_contact(spec, d);
    if (!sol.converged) state.SkipWithError(sol.message.c_str());
    iterations = sol.newton_iterations;
  }
  state.counters["p"] = p;
  state.counters["dofs"] = d.n_free;
  state.counters["newton_iterations"] = iterations;
}
BENCHMARK(BM_HertzSolve)
    ->ArgNames({"p", "fd", "condense"})
    ->Args({5, 0, 1})
    ->Args({5, 0, 0})
    ->Args({5, 1, 0})
    ->Args({8, 0, 1})
    ->Args({8, 0, 0})
    ->Args({8, 1, 0})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

// One Newton tangent (residual included) at the converged state, without condensation.
void BM_HertzTangent(benchmark::State& state) {
  const int p = static_cast<int>(state.range(0));
  const bool fd = state.range(1) != 0;
  const auto spec =
      io::read_problem(hertz(p), {"contact[0].enforcement=penalty", "discretization.condense=false"});
  const auto d = model::discretize(spec);
  const auto sol = model::solve_contact(spec, d);
  for (auto _ : state) benchmark::DoNotOptimize(model::contact_tangent(spec, d, sol, fd));
  state.counters["p"] = p;
  state.counters["dofs"] = d.n_free;
}
BENCHMARK(BM_HertzTangent)
    ->ArgNames({"p", "fd"})
    ->Args({5, 0})
    ->Args({5, 1})
    ->Args({8, 0})
    ->Args({8, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// End to end as `hpcontact run` does it, files included: read the YAML, discretise, solve
// (force control), post-process, write summary.json, contact.csv, pressure.csv, solution.vtu and
// input.yaml into a temporary folder. range(0) indexes kEndToEnd; `without_compare` leaves out
// the pairs' comparisons with the closed forms and reference files (a user's own problem).
struct EndToEnd {
  const char* path;
  bool without_compare;
};
const EndToEnd kEndToEnd[] = {{"hertz/p15.yaml", false},
                              {"hertz/bilateral.yaml", false},
                              {"curve-obstacle/crowned-rail.yaml", false},
                              {"hertz/hp-tolerance.yaml", false},
                              {"hertz/hp-tolerance.yaml", true}};

void BM_ExampleEndToEnd(benchmark::State& state) {
  const EndToEnd& example = kEndToEnd[state.range(0)];
  const std::string path = std::string(HPC_SOURCE_DIR) + "/examples/" + example.path;
  const auto out = std::filesystem::temp_directory_path() / "hpcontact-bench-end-to-end";
  int n_free = 0, iterations = 0;
  for (auto _ : state) {
    auto read = io::read_problem_full(path, {});
    if (example.without_compare)
      for (auto& pair : read.spec.contact) pair.compare.reset();
    driver::RunOptions options;
    options.out_dir = out.string();
    options.effective_input = read.effective_yaml;
    const auto r = driver::run_problem(read.spec, options);
    n_free = r.discretization.n_free;
    // all the solves' iterations (an adaptive loop's too), as summary.json newton_iterations_total
    iterations = r.summary.extra.value("newton_iterations_total", r.summary.newton_iterations);
  }
  std::filesystem::remove_all(out);
  state.counters["dofs"] = n_free;
  state.counters["newton_iterations"] = iterations;
}
BENCHMARK(BM_ExampleEndToEnd)
    ->ArgName("example")
    ->DenseRange(0, 4)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

}  // namespace
