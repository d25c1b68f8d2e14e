// Element stiffness kernel: time to form one curved p-element's stiffness matrix, p = 1..20.
#include <benchmark/benchmark.h>

#include "hpcontact/model/discretization.hpp"
#include "hpcontact/model/linear_solve.hpp"
#include "problems.hpp"

namespace {

using namespace hpcontact;

// Element 0 of the Hertz quarter circle 2×2 has an exact arc edge, so the blending map is
// evaluated at every Gauss point. Discretisation is set-up, outside the timed loop.
void BM_ElementStiffness(benchmark::State& state) {
  const int p = static_cast<int>(state.range(0));
  const model::Discretization d = model::discretize(test_problems::quarter_circle_2x2(p));
  const model::Body& body = d.bodies.at(0);
  for (auto _ : state) {
    Eigen::MatrixXd K = model::element_stiffness(body, 0);
    benchmark::DoNotOptimize(K.data());
    benchmark::ClobberMemory();
  }
  const int n_gauss = body.n_gauss[0];
  state.counters["p"] = p;
  state.counters["modes"] = body.dofs.element(0).n_modes();
  state.counters["gauss_points"] = n_gauss * n_gauss;
}
BENCHMARK(BM_ElementStiffness)->DenseRange(1, 20)->Unit(benchmark::kMicrosecond);

}  // namespace
