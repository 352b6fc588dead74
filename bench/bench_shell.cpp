// ns per shell element-cycle of ShellBlock::update (Belytschko-Tsay, 5 points through the
// thickness) for an elastic and a Johnson-Cook plate, 1 and 2 threads. Arguments: element count,
// thread count. The counter `per_element_cycle` is the wall time of one update divided by the
// element count.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "abut/element/shell_block.hpp"

namespace {

struct PlateMesh {
  abut::Nodes nodes;
  std::vector<abut::Quad4> shells;
  std::vector<double> x, y, z, vx, vy, vz, wx, wy, wz;
};

// A plate of 100 x (count / 100) shells of 1 mm, its current shape bent and warped a little and
// a smooth velocity and angular-velocity field, so that every point takes a general strain.
PlateMesh plate_mesh(std::int64_t count) {
  PlateMesh m;
  const int nx = 100, ny = static_cast<int>(count / 100);
  const double h = 1e-3;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      m.nodes.add(static_cast<std::int64_t>(m.nodes.size()) + 1, {i * h, j * h, 0.0});
      m.x.push_back(1.01 * i * h + 0.02 * j * h);
      m.y.push_back(0.99 * j * h);
      m.z.push_back(0.05 * h * std::sin(0.3 * i) * std::cos(0.2 * j));
      m.vx.push_back(0.1 * std::sin(0.1 * j));
      m.vy.push_back(0.05 * std::cos(0.2 * i));
      m.vz.push_back(1.0 + 0.1 * std::sin(0.05 * (i + j)));
      m.wx.push_back(10.0 * std::sin(0.1 * i));
      m.wy.push_back(-5.0 * std::cos(0.1 * j));
      m.wz.push_back(1.0);
    }
  const auto id = [&](int i, int j) { return static_cast<std::int32_t>(i + (nx + 1) * j); };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      m.shells.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return m;
}

void run_update(benchmark::State& state, const abut::MaterialParams& material) {
  const std::int64_t count = state.range(0);
  const int saved = omp_get_max_threads();
  omp_set_num_threads(static_cast<int>(state.range(1)));
  const PlateMesh mesh = plate_mesh(count);
  abut::FunctionTable functions;
  abut::ShellBlock block(1, material, {1e-3, 5, 0.05}, mesh.shells, mesh.nodes, &functions);
  const abut::ShellNodalState nodal{mesh.x.data(),  mesh.y.data(),  mesh.z.data(),
                                    mesh.vx.data(), mesh.vy.data(), mesh.vz.data(),
                                    mesh.wx.data(), mesh.wy.data(), mesh.wz.data()};
  block.update(nodal, 0.0);
  for (auto _ : state) benchmark::DoNotOptimize(block.update(nodal, 1e-7));
  state.counters["per_element_cycle"] =
      benchmark::Counter(static_cast<double>(count), benchmark::Counter::kIsIterationInvariantRate |
                                                         benchmark::Counter::kInvert);
  omp_set_num_threads(saved);
}

void BM_ElasticShellUpdate(benchmark::State& state) {
  run_update(state, abut::ElasticParams{7800.0, 210e9, 0.3});
}

// Johnson-Cook steel (A = 300 MPa, B = 500 MPa, n = 0.5): the velocity field keeps every point
// yielding after the first few hundred updates, so this is the plastic cost.
void BM_JohnsonCookShellUpdate(benchmark::State& state) {
  abut::MetalParams steel;
  steel.density = 7800.0, steel.young = 210e9, steel.poisson = 0.3;
  steel.johnson_cook = true, steel.a = 300e6, steel.b = 500e6, steel.n = 0.5;
  run_update(state, steel);
}

BENCHMARK(BM_ElasticShellUpdate)
    ->ArgNames({"elements", "threads"})
    ->ArgsProduct({{10000, 100000}, {1, 2}})
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();

BENCHMARK(BM_JohnsonCookShellUpdate)
    ->ArgNames({"elements", "threads"})
    ->ArgsProduct({{10000, 100000}, {1, 2}})
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();

}  // namespace
