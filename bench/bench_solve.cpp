// Whole-problem timings: discretisation, the full and condensed linear solve, and the Lamé run.
#include <benchmark/benchmark.h>

#include "hpcontact/driver/run.hpp"
#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/model/discretization.hpp"
#include "hpcontact/model/linear_solve.hpp"
#include "problems.hpp"

namespace {

using namespace hpcontact;

// Assembly runs OpenMP-parallel: everything here is timed by wall clock (UseRealTime), and the
// CPU time is that of the whole process, all threads (MeasureProcessCPUTime).

// The problem spec is built once; discretize() (mesh, maps, mode numbering, loads) is timed.
void BM_Discretize(benchmark::State& state) {
  const int p = static_cast<int>(state.range(0));
  const model::ProblemSpec spec = test_problems::quarter_circle_2x2(p);
  int n_free = 0;
  for (auto _ : state) {
    model::Discretization d = model::discretize(spec);
    n_free = d.n_free;
    benchmark::DoNotOptimize(d.n_free);
  }
  state.counters["p"] = p;
  state.counters["dofs"] = n_free;
}
BENCHMARK(BM_Discretize)
    ->Arg(8)
    ->Arg(15)
    ->Unit(benchmark::kMicrosecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

// discretize + assemble + factorise + solve; state.range(1) = 1 condenses the internal modes.
// The counters assembly_ms and solve_ms are solve_linear()'s own split, averaged over iterations.
void BM_LinearSolve(benchmark::State& state) {
  const int p = static_cast<int>(state.range(0));
  const bool condense = state.range(1) != 0;
  const model::ProblemSpec spec = test_problems::quarter_circle_2x2(p);
  int n_free = 0, n_system = 0;
  double assembly = 0, solve = 0;
  for (auto _ : state) {
    const model::Discretization d = model::discretize(spec);
    const model::LinearSolution s = model::solve_linear(d, {.condense = condense});
    benchmark::DoNotOptimize(s.u.data());
    n_free = d.n_free;
    n_system = s.n_system;
    assembly += s.assembly_seconds;
    solve += s.solve_seconds;
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["p"] = p;
  state.counters["condense"] = condense;
  state.counters["dofs"] = n_free;
  state.counters["n_system"] = n_system;
  state.counters["assembly_ms"] = 1e3 * assembly / n;
  state.counters["solve_ms"] = 1e3 * solve / n;
}
BENCHMARK(BM_LinearSolve)
    ->ArgNames({"p", "condense"})
    ->ArgsProduct({{8, 15}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

// End to end as the command line does it, minus writing: read the YAML, discretise, solve,
// post-process (stresses, energy, error against the closed form).
void BM_LameEndToEnd(benchmark::State& state) {
  const std::string path = std::string(HPC_SOURCE_DIR) + "/examples/lame/thick-cylinder.yaml";
  int n_free = 0, p = 0;
  for (auto _ : state) {
    const model::ProblemSpec spec = io::read_problem(path);
    const driver::RunResult r = driver::run_problem(spec, {});
    benchmark::DoNotOptimize(r.u.data());
    n_free = r.discretization.n_free;
    p = spec.discretization.degree[0];
  }
  state.counters["p"] = p;
  state.counters["dofs"] = n_free;
}
BENCHMARK(BM_LameEndToEnd)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

}  // namespace
