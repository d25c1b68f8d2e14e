// Issue 5's examples, whole nonlinear solves (finite strain, friction, arc-length) as
// `hpcontact run` does them without files; and the linear solve of one Newton step with the
// unsymmetric friction tangent (LU) against the symmetric stick tangent (CHOLMOD and LU), same mesh.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/model/contact_solve.hpp"
#include "hpcontact/model/discretization.hpp"
#include "hpcontact/solve/linear_solver.hpp"

namespace {

using namespace hpcontact;

std::string source(const std::string& path) { return std::string(HPC_SOURCE_DIR) + "/" + path; }

void solve_case(benchmark::State& state, const std::string& path,
                const std::vector<std::string>& overrides = {}) {
  const auto spec = io::read_problem(source(path), overrides);
  const auto d = model::discretize(spec);
  model::NonlinearSolution sol;
  for (auto _ : state) {
    sol = model::solve_contact(spec, d);
    if (!sol.converged) state.SkipWithError(sol.message.c_str());
  }
  state.counters["dofs"] = d.n_free;
  state.counters["load_steps"] = sol.load_steps;
  state.counters["newton_iterations"] = sol.newton_iterations;
}

// The tangent of the converged two-bar state (p = [15, 5]), factorised and solved once.
void linear_step(benchmark::State& state, const std::string& law, solve::LinearSolverKind kind) {
  const auto spec =
      io::read_problem(source("examples/two-bars/" + law + ".yaml"), {"contact[0].enforcement=penalty"});
  const auto d = model::discretize(spec);
  const auto sol = model::solve_contact(spec, d);
  const auto K = model::contact_tangent(spec, d, sol, false);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(K.rows());
  for (auto _ : state) {
    solve::LinearSolver s(kind);
    s.factorize(K);
    benchmark::DoNotOptimize(s.solve(b));
  }
  state.counters["dofs"] = K.rows();
  state.counters["nonzeros"] = K.nonZeros();
}

const int registered = [] {
  for (const char* path :
       {"examples/axle-ring/ring2-p4.yaml", "examples/axle-ring/ring12-p4.yaml",
        "examples/axle-ring/ring16-p5.yaml", "examples/two-bars/stick.yaml",
        "examples/two-bars/coulomb.yaml", "tests/cli/data/shallow-arch.yaml",
        "examples/ring-foundation/ring.yaml"})
    benchmark::RegisterBenchmark((std::string("BM_Nonlinear/") + path).c_str(),
                                 [p = std::string(path)](benchmark::State& s) { solve_case(s, p); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  benchmark::RegisterBenchmark("BM_ArcLength/tests/cli/data/shallow-arch.yaml", [](benchmark::State& s) {
    solve_case(s, "tests/cli/data/shallow-arch.yaml", {"solver.control=arc-length"});
  })->Unit(benchmark::kMillisecond)->UseRealTime();
  using K = solve::LinearSolverKind;
  const std::vector<std::tuple<std::string, std::string, K>> steps = {
      {"coulomb", "lu", K::lu}, {"stick", "lu", K::lu}, {"stick", "cholmod", K::cholmod}};
  for (const auto& [law, name, kind] : steps)
    benchmark::RegisterBenchmark(("BM_TwoBarsLinearStep/" + law + "/" + name).c_str(),
                                 [law = law, kind = kind](benchmark::State& s) { linear_step(s, law, kind); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  return 0;
}();

}  // namespace
