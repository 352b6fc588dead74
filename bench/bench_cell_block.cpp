// ns per element-cycle and per node-cycle of SolidCellBlock::update (the explicit block of solid
// cells of any type, element/solid_cell_block.hpp), elastic steel, 1 and 2 threads. The box is the
// element tests' grid (tests/element/cell_grid.hpp): 20 x 20 x 10 cubes of 1 mm, each kept
// (hex8, hex20), split into 6 tetrahedra (tet4, tet10) or 2 wedges, its corners moved by a few %
// and a smooth velocity field, so that every point sees a general velocity gradient. Counters:
// `per_element_cycle` (one update divided by the element count) and `per_node_cycle` (divided by
// the block's node count, midside nodes included). The one-point hexahedron of the solver's own
// meshes is BM_ElasticHexUpdate (bench_element.cpp); hex8 here is the fully integrated cell.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "../tests/element/cell_grid.hpp"
#include "abut/element/solid_cell_block.hpp"

namespace {

using namespace abut;

constexpr CellType kTypes[] = {CellType::hex8, CellType::hex20, CellType::tet4, CellType::tet10,
                               CellType::wedge6};

void CellBlockUpdate(benchmark::State& state) {
  const CellType type = kTypes[state.range(0)];
  const int saved = omp_get_max_threads();
  omp_set_num_threads(static_cast<int>(state.range(1)));
  const double h = 1e-3;
  const test::CellGrid g =
      test::cell_grid(type, 20, 20, 10, {20 * h, 20 * h, 10 * h}, [&](int i, int j, int k, Vec3 p) {
        return p + Vec3{0.1 * h * std::sin(1.3 * i + 0.7 * k), 0.1 * h * std::cos(0.9 * j),
                        0.1 * h * std::sin(0.4 * i + 1.1 * j)};
      });
  std::vector<std::int32_t> connectivity;
  for (const auto& c : g.cells) connectivity.insert(connectivity.end(), c.begin(), c.end());
  SolidCellBlock block(1, ElasticParams{7800.0, 210e9, 0.3}, type, connectivity, g.nodes);
  const std::size_t n = g.nodes.size();
  std::vector<double> x(n), y(n), z(n), vx(n), vy(n), vz(n);
  for (std::size_t a = 0; a < n; ++a) {  // stretched and sheared by a few %
    const double X = g.nodes.x[a], Y = g.nodes.y[a], Z = g.nodes.z[a];
    x[a] = 1.01 * X + 0.03 * Y;
    y[a] = 0.98 * Y + 0.02 * Z;
    z[a] = 1.02 * Z + 0.01 * X;
    vx[a] = 0.1 * std::sin(300.0 * Z);
    vy[a] = 0.05 * std::cos(200.0 * X);
    vz[a] = -0.1 + 20.0 * Y;
  }
  const NodalState nodal{x.data(), y.data(), z.data(), vx.data(), vy.data(), vz.data()};
  const double dt = 1e-8;
  block.update(nodal, 0.0);
  for (auto _ : state) benchmark::DoNotOptimize(block.update(nodal, dt));
  const auto per = [](double count) {
    return benchmark::Counter(
        count, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  };
  state.counters["per_element_cycle"] = per(static_cast<double>(block.size()));
  state.counters["per_node_cycle"] = per(static_cast<double>(n));
  state.SetLabel(std::string(topology(type).name));
  omp_set_num_threads(saved);
}

BENCHMARK(CellBlockUpdate)
    ->ArgNames({"type", "threads"})
    ->ArgsProduct({{0, 1, 2, 3, 4}, {1, 2}})
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();

}  // namespace
