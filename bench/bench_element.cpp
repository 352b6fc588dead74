// ns per element-cycle of SolidBlock::update for elastic and Mooney-Rivlin hexahedra on a box
// mesh, 1 and 2 threads. Arguments: element count, thread count. The counter `per_element_cycle` is
// the wall time of one update divided by the element count (printed in seconds with an SI prefix).
#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "abut/element/solid_block.hpp"

namespace {

struct BoxMesh {
  abut::Nodes nodes;
  std::vector<abut::Hex8> hexes;
  std::vector<double> x, y, z;  // current positions: the grid sheared and stretched by a few %
  std::vector<double> vx, vy, vz;
};

// nx = ny = 10 elements of 1 mm, nz = count / 100, nodes on a grid (the reference); current
// positions deformed smoothly (strains of a few %, so that the material sees a general F) and a
// smooth velocity field.
BoxMesh box_mesh(std::int64_t count) {
  BoxMesh m;
  const int nx = 10, ny = 10, nz = static_cast<int>(count / 100);
  const double h = 1e-3;
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        m.nodes.add(static_cast<std::int64_t>(m.nodes.size()) + 1, {i * h, j * h, k * h});
        m.x.push_back(i * h + 0.08 * j * h + 0.03 * k * h + 0.1 * h * std::sin(0.5 * k));
        m.y.push_back(0.95 * j * h + 0.03 * k * h);
        m.z.push_back(1.04 * k * h + 0.02 * i * h);
        m.vx.push_back(0.1 * std::sin(300.0 * k * h));
        m.vy.push_back(0.05 * std::cos(200.0 * i * h));
        m.vz.push_back(-0.1 + 0.02 * j * h);
      }
  const auto id = [&](int i, int j, int k) {
    return static_cast<std::int32_t>(i + (nx + 1) * (j + (ny + 1) * k));
  };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        m.hexes.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                           id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
                           id(i, j + 1, k + 1)});
  return m;
}

// Runs update() on a box mesh of state.range(0) elements with state.range(1) threads.
void run_update(benchmark::State& state, const abut::MaterialParams& material) {
  const std::int64_t count = state.range(0);
  const int saved = omp_get_max_threads();
  omp_set_num_threads(static_cast<int>(state.range(1)));
  const BoxMesh mesh = box_mesh(count);
  abut::SolidBlock block(1, material, mesh.hexes, mesh.nodes);
  const abut::NodalState nodal{mesh.x.data(),  mesh.y.data(),  mesh.z.data(),
                               mesh.vx.data(), mesh.vy.data(), mesh.vz.data()};
  const double dt = 1e-8;
  block.update(nodal, 0.0);
  for (auto _ : state) {
    benchmark::DoNotOptimize(block.update(nodal, dt));
  }
  state.counters["per_element_cycle"] =
      benchmark::Counter(static_cast<double>(count), benchmark::Counter::kIsIterationInvariantRate |
                                                         benchmark::Counter::kInvert);
  omp_set_num_threads(saved);
}

void BM_ElasticHexUpdate(benchmark::State& state) {
  run_update(state, abut::ElasticParams{7800.0, 210e9, 0.3});
}

// The seed deck's rubber (examples/rubber_sphere.k): K = 3 GPa, C1 = 1 MPa and one Newtonian
// viscous term (alpha_1 = 100, beta_1 = 0).
void BM_MooneyRivlinHexUpdate(benchmark::State& state) {
  abut::MooneyRivlinParams rubber{1500.0, 3.0e9, 1.0e6, 0.0, {}, {}};
  rubber.alpha[0] = 1.0e2;
  run_update(state, rubber);
}

BENCHMARK(BM_ElasticHexUpdate)
    ->ArgNames({"elements", "threads"})
    ->ArgsProduct({{1000, 10000, 100000}, {1, 2}})
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();

BENCHMARK(BM_MooneyRivlinHexUpdate)
    ->ArgNames({"elements", "threads"})
    ->ArgsProduct({{1000, 10000, 100000}, {1, 2}})
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();

}  // namespace
