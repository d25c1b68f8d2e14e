// Hexahedron stiffness kernel: time to form one hex's 3n × 3n stiffness, p = 1..8, tensor and
// trunk, on a distorted trilinear hex and on a blending hex with spherical faces, by the
// reference kernel (values at the Gauss points and the six M_kl products) and by sum
// factorisation (the map's Jacobians at the points and three 1D contractions).
#include <benchmark/benchmark.h>

#include <array>

#include "hpcontact/basis/hex_modes.hpp"
#include "hpcontact/fem/hex_elasticity.hpp"
#include "hpcontact/fem/hex_element.hpp"
#include "hpcontact/fem/hex_factored_stiffness.hpp"
#include "hpcontact/fem/hex_values.hpp"
#include "hpcontact/mesh/hex_map.hpp"
#include "hpcontact/mesh/shell_octant.hpp"

namespace {

using namespace hpcontact;

mesh::HexMap distorted_hex() {
  std::array<mesh::Vec3, 8> v;
  const double moves[8][3] = {{0.05, -0.1, 0.0}, {0.1, 0.05, -0.08}, {0.2, 0.15, 0.1},
                              {-0.1, 0.1, 0.05}, {0.0, -0.05, 0.1},  {-0.1, 0.0, 0.2},
                              {0.25, 0.2, 0.3},  {-0.05, 0.1, -0.1}};
  for (int i = 0; i < 8; ++i) {
    const auto* c = basis::kHexVertexCoordinates[i];
    v[i] = mesh::Vec3(0.5 * (c[0] + 1) + moves[i][0], 0.5 * (c[1] + 1) + moves[i][1],
                      0.5 * (c[2] + 1) + moves[i][2]);
  }
  return mesh::HexMap::trilinear(v);
}

// p; space 0 tensor, 1 trunk; map 0 distorted trilinear, 1 blending (the thick sphere's octant,
// p + 3 Gauss points per direction); kernel 0 reference (M_kl products), 1 sum factorisation.
void BM_HexElementStiffness(benchmark::State& state) {
  const int p = static_cast<int>(state.range(0));
  const auto space = state.range(1) ? basis::Space::trunk : basis::Space::tensor_product;
  const bool factored = state.range(3) != 0;
  const basis::HierarchicHex h = basis::hierarchic_hex({p, p, p}, space);
  const mesh::HexMap map =
      state.range(2) ? mesh::shell_octant_mesh(1.0, 2.0, 1).maps[0] : distorted_hex();
  material::LinearElastic m;
  m.youngs_modulus = 210000;
  m.poisson_ratio = 0.3;
  const std::array<int, 3> n_points = fem::hex_gauss_points(h, map);
  for (auto _ : state) {
    Eigen::MatrixXd K;
    if (factored) {
      K = fem::hex_stiffness_factored(h, fem::hex_grid_geometry(map, n_points), m);
    } else {
      K = fem::hex_stiffness(fem::hex_values(h, map, n_points), m);
    }
    benchmark::DoNotOptimize(K.data());
    benchmark::ClobberMemory();
  }
  state.counters["p"] = p;
  state.counters["modes"] = h.n_modes();
  state.counters["gauss_points"] = n_points[0] * n_points[1] * n_points[2];
  state.counters["automatic_factored"] =
      fem::hex_stiffness_kernel(h, n_points) == fem::HexStiffnessKernel::factored;
}
BENCHMARK(BM_HexElementStiffness)
    ->ArgNames({"p", "space", "map", "kernel"})
    ->ArgsProduct({benchmark::CreateDenseRange(1, 8, 1), {0, 1}, {0, 1}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

}  // namespace
