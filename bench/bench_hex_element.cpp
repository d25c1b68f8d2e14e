// Hexahedron stiffness kernel: time to form one distorted trilinear hex's 3n × 3n stiffness
// (values at the (p + 1)³ Gauss points and the six M_kl products), p = 1..8, tensor and trunk.
#include <benchmark/benchmark.h>

#include <array>

#include "hpcontact/basis/hex_modes.hpp"
#include "hpcontact/fem/hex_elasticity.hpp"
#include "hpcontact/fem/hex_values.hpp"
#include "hpcontact/mesh/hex_map.hpp"

namespace {

using namespace hpcontact;

mesh::HexMap distorted_hex() {
  std::array<mesh::Vec3, 8> v;
  const double moves[8][3] = {{0.05, -0.1, 0.0},  {0.1, 0.05, -0.08}, {0.2, 0.15, 0.1},
                              {-0.1, 0.1, 0.05},  {0.0, -0.05, 0.1},  {-0.1, 0.0, 0.2},
                              {0.25, 0.2, 0.3},   {-0.05, 0.1, -0.1}};
  for (int i = 0; i < 8; ++i) {
    const auto* c = basis::kHexVertexCoordinates[i];
    v[i] = mesh::Vec3(0.5 * (c[0] + 1) + moves[i][0], 0.5 * (c[1] + 1) + moves[i][1],
                      0.5 * (c[2] + 1) + moves[i][2]);
  }
  return mesh::HexMap::trilinear(v);
}

// range(0): p; range(1): 0 tensor, 1 trunk.
void BM_HexElementStiffness(benchmark::State& state) {
  const int p = static_cast<int>(state.range(0));
  const auto space = state.range(1) ? basis::Space::trunk : basis::Space::tensor_product;
  const basis::HierarchicHex h = basis::hierarchic_hex({p, p, p}, space);
  const mesh::HexMap map = distorted_hex();
  material::LinearElastic m;
  m.youngs_modulus = 210000;
  m.poisson_ratio = 0.3;
  const std::array<int, 3> n_points = fem::hex_gauss_points(h, map);
  for (auto _ : state) {
    const fem::HexValues v = fem::hex_values(h, map, n_points);
    Eigen::MatrixXd K = fem::hex_stiffness(v, m);
    benchmark::DoNotOptimize(K.data());
    benchmark::ClobberMemory();
  }
  state.counters["p"] = p;
  state.counters["modes"] = h.n_modes();
  state.counters["gauss_points"] = n_points[0] * n_points[1] * n_points[2];
}
BENCHMARK(BM_HexElementStiffness)
    ->ArgsProduct({benchmark::CreateDenseRange(1, 8, 1), {0, 1}})
    ->Unit(benchmark::kMillisecond);

}  // namespace
