// ns per face of contact set-up (issue 28): the constructor of a self contact on the exterior of
// a box of hexahedra, which builds the integration points, the broad phase and the initial state.
// Two shapes: a slab of 2 x n x 1 elements in a unit cube (its long sides are n strips 1/n wide
// lying side by side: the case that was quadratic) and a plate of n x n x 1 elements 10 times
// wider than thick. The time per face must stay flat as the faces grow 1k -> 1M.
#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <vector>

#include "abut/contact/interface.hpp"

namespace {

struct BoxSkin {
  std::vector<double> x, y, z, mass;
  abut::ContactSurface surface;
};

// The six sides of a box of nx x ny x nz hexahedra of size (lx, ly, lz), as outward quads.
BoxSkin box_skin(int nx, int ny, int nz, double lx, double ly, double lz) {
  BoxSkin b;
  const int n[3] = {nx, ny, nz};
  const double h[3] = {lx / nx, ly / ny, lz / nz};
  auto id = [&](int i, int j, int k) {
    return static_cast<std::int32_t>((k * (ny + 1) + j) * (nx + 1) + i);
  };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        b.x.push_back(i * h[0]);
        b.y.push_back(j * h[1]);
        b.z.push_back(k * h[2]);
      }
  b.mass.assign(b.x.size(), 1e-3);
  // Side `axis` at its low (outward -e_axis) or high end: the quads over the other two axes, in
  // the order whose normal points outward.
  for (int axis = 0; axis < 3; ++axis)
    for (const bool high : {false, true}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      for (int a = 0; a < n[u]; ++a)
        for (int c = 0; c < n[v]; ++c) {
          auto node = [&](int du, int dv) {
            int ijk[3];
            ijk[axis] = high ? n[axis] : 0;
            ijk[u] = a + du;
            ijk[v] = c + dv;
            return id(ijk[0], ijk[1], ijk[2]);
          };
          // (u, v, axis) is right-handed: counter-clockwise in (u, v) faces +e_axis.
          std::array<std::int32_t, 4> q{node(0, 0), node(1, 0), node(1, 1), node(0, 1)};
          if (!high) std::swap(q[1], q[3]);
          b.surface.add(q, 1, 1e12, h[axis]);
        }
    }
  return b;
}

void run(benchmark::State& state, const BoxSkin& skin) {
  const abut::ContactInput in{skin.x, skin.y, skin.z, {}, {}, {}, 0.0, 1e-7, {}};
  std::size_t points = 0;
  for (auto _ : state) {
    // Defaults: S2S, symmetric (self contact: one pass).
    abut::ContactInterface contact(abut::ContactSettings{}, skin.surface, skin.surface, skin.mass,
                                   in);
    points = contact.point_count();
    benchmark::DoNotOptimize(&contact);
  }
  const auto faces = static_cast<double>(skin.surface.size());
  state.counters["faces"] = faces;
  state.counters["points"] = static_cast<double>(points);
  state.counters["ns_per_face"] = benchmark::Counter(
      faces, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_ContactSetupSlab(benchmark::State& state) {
  const auto n = static_cast<int>(state.range(0));
  run(state, box_skin(2, n, 1, 1.0, 1.0, 1.0));
}
// 6n + 4 faces: 1.2k to 1M.
BENCHMARK(BM_ContactSetupSlab)
    ->Arg(200)
    ->Arg(1600)
    ->Arg(12800)
    ->Arg(166666)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_ContactSetupPlate(benchmark::State& state) {
  const auto n = static_cast<int>(state.range(0));
  run(state, box_skin(n, n, 1, 1.0, 1.0, 0.1));
}
// 2n^2 + 4n faces: 1.2k to 1M.
BENCHMARK(BM_ContactSetupPlate)
    ->Arg(24)
    ->Arg(64)
    ->Arg(256)
    ->Arg(707)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
