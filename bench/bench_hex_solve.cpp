// One condensed linear solve of a box of trilinear hexahedra at p = 4 (tensor space): assembly
// (element stiffness, static condensation, the sparse matrix), CHOLMOD's factorisation and solve,
// and the memory they take. The box is built here (a structured-mesh generator is to come).
#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include <array>
#include <ctime>
#include <chrono>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "hpcontact/basis/hex_modes.hpp"
#include "hpcontact/fem/hex_assembly.hpp"
#include "hpcontact/mesh/hex_map.hpp"
#include "hpcontact/mesh/hex_topology.hpp"
#include "hpcontact/solve/fixed_dofs.hpp"

namespace {

using namespace hpcontact;

/// An nx × ny × nz box of unit cubes, its nodes moved by up to 0.15 (a smooth function of the
/// place, boundary nodes too), so that no element is affine, and its elements on z = 0.
struct Box {
  mesh::HexTopology topology;
  std::vector<mesh::HexMap> maps;
  std::vector<int> bottom;  ///< global faces on z = 0
};

Box box(int nx, int ny, int nz) {
  auto node = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
  std::vector<mesh::Vec3> nodes;
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        nodes.push_back(mesh::Vec3(i + 0.15 * std::sin(1.3 * j + 0.7 * k),
                                   j + 0.15 * std::sin(0.9 * i + 1.1 * k),
                                   k + 0.15 * std::sin(1.7 * i + 0.5 * j) * (k > 0)));
  std::vector<std::array<int, 8>> hexes;
  Box b;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        std::array<int, 8> h;
        std::array<mesh::Vec3, 8> x;
        for (int v = 0; v < 8; ++v) {
          const auto* c = basis::kHexVertexCoordinates[v];
          h[v] = node(i + (c[0] > 0), j + (c[1] > 0), k + (c[2] > 0));
          x[v] = nodes[h[v]];
        }
        hexes.push_back(h);
        b.maps.push_back(mesh::HexMap::trilinear(x));
      }
  b.topology = mesh::HexTopology(hexes, static_cast<int>(nodes.size()), "box");
  for (int h = 0; h < nx * ny; ++h) b.bottom.push_back(b.topology.hex_face(h, 4));
  return b;
}

/// The CPU time of the process, all threads, in seconds.
double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// The process's peak resident memory since reset_peak_memory() (VmHWM), in bytes; where the
/// kernel cannot reset it, the peak of the whole process (ru_maxrss).
bool reset_peak_memory() { return static_cast<bool>(std::ofstream("/proc/self/clear_refs") << "5"); }
double peak_memory() {
  std::ifstream status("/proc/self/status");
  std::string key;
  double kilobytes;
  while (status >> key)
    if (key == "VmHWM:" && status >> kilobytes) return 1024 * kilobytes;
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return 1024.0 * usage.ru_maxrss;
}

// A box nx × ny × nz clamped on z = 0 under its weight (body force (0, 0, −1)), E = 1, ν = 0.3.
// Counters: dofs (all modes' dofs) and n_system (the condensed system's), assembly_s
// (element matrices, condensation, the sparse matrix) and solve_s (the free block, CHOLMOD's
// analysis, factorisation and solve) averaged over the iterations, wall clock, and
// assembly_cpu_s, solve_cpu_s the CPU time of the process in each, factor_entries and
// factor_gflop (CHOLMOD's analysis), estimate_gb, cholmod_peak_gb (its peak allocation),
// peak_rss_gb (the process's peak resident memory during the iteration).
void BM_HexBoxSolve(benchmark::State& state) {
  const int nx = static_cast<int>(state.range(0)), ny = static_cast<int>(state.range(1)),
            nz = static_cast<int>(state.range(2));
  const Box b = box(nx, ny, nz);
  fem::HexSpaceOptions space;
  space.degrees.assign(b.maps.size(), {4, 4, 4});
  const fem::HexDofMap dofs(b.topology, space);
  fem::HexBody body;
  body.dofs = &dofs;
  body.maps = b.maps;
  body.material.youngs_modulus = 1;
  body.material.poisson_ratio = 0.3;
  body.body_force = mesh::Vec3(0, 0, -1);
  std::set<int> fixed_set;
  for (int face : b.bottom)
    for (int mode : dofs.modes_on_face(b.topology, face))
      for (int c = 0; c < 3; ++c) fixed_set.insert(3 * mode + c);
  const std::vector<int> fixed(fixed_set.begin(), fixed_set.end());
  const Eigen::MatrixXd zero = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(fixed.size()), 1);

  using Clock = std::chrono::steady_clock;
  double assembly = 0, solve = 0, assembly_cpu = 0, solve_cpu = 0, peak_rss = 0;
  solve::FactorMemory memory;
  int n_system = 0;
  bool rss_reset = true;
  for (auto _ : state) {
    rss_reset = reset_peak_memory() && rss_reset;
    const auto t0 = Clock::now();
    const double c0 = cpu_seconds();
    const fem::HexSystem system = fem::assemble_hex_elasticity(body, {.condense_internal = true});
    const auto t1 = Clock::now();
    const double c1 = cpu_seconds();
    solve::LinearSolver solver(solve::LinearSolverKind::cholmod);
    const Eigen::MatrixXd u = solve::solve_with_fixed_dofs(system.K, system.f, fixed, zero, solver);
    const auto t2 = Clock::now();
    const double c2 = cpu_seconds();
    benchmark::DoNotOptimize(u.data());
    assembly_cpu += c1 - c0;
    solve_cpu += c2 - c1;
    assembly += std::chrono::duration<double>(t1 - t0).count();
    solve += std::chrono::duration<double>(t2 - t1).count();
    memory = solver.memory();
    n_system = static_cast<int>(system.K.rows());
    peak_rss = std::max(peak_rss, peak_memory());
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["elements"] = nx * ny * nz;
  state.counters["dofs"] = dofs.n_dofs();
  state.counters["n_system"] = n_system;
  state.counters["n_free"] = n_system - static_cast<double>(fixed.size());
  state.counters["assembly_s"] = assembly / n;
  state.counters["solve_s"] = solve / n;
  state.counters["assembly_cpu_s"] = assembly_cpu / n;
  state.counters["solve_cpu_s"] = solve_cpu / n;
  state.counters["factor_entries"] = memory.factor_entries;
  state.counters["factor_gflop"] = memory.flops / 1e9;
  state.counters["estimate_gb"] = memory.estimate_bytes / 1e9;
  state.counters["cholmod_peak_gb"] = memory.peak_bytes / 1e9;
  state.counters["peak_rss_gb"] = peak_rss / 1e9;
  state.counters["peak_rss_of_iteration"] = rss_reset;
}
// Boxes whose condensed systems have about 10⁴, 5·10⁴ and 10⁵ unknowns (9555, 51507, 102777);
// one iteration and three repetitions each (the largest takes half a minute and 3.4 GB).
BENCHMARK(BM_HexBoxSolve)
    ->ArgNames({"nx", "ny", "nz"})
    ->Args({4, 4, 4})
    ->Args({8, 7, 7})
    ->Args({10, 9, 9})
    ->Iterations(1)
    ->Repetitions(3)
    ->Unit(benchmark::kSecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

}  // namespace
