// ns per contact point-cycle: two flat 100 x 100 facet surfaces pressed together (symmetric,
// friction), one apply() per iteration, nodes moving slightly each cycle. Surface-to-surface with
// 2x2 points per facet (ns per point-cycle), node-to-surface (ns per node-cycle). The shell
// variants: the same plates as two-sided shells 2 mm thick (each side's surface at h/2 from the
// mid-surface), pressed by 1e-4 beyond the gap; half of the points face away (the far sides).
// Idle points (BM_ContactIdlePointCycle): the same S2S plates held apart, 5 mm (within the search
// margin: every point has candidate facets, none touches) or 10 cm (beyond it: no candidates).
#include <benchmark/benchmark.h>
#include <omp.h>

#include <vector>

#include "abut/contact/interface.hpp"

namespace {

struct Plates {
  std::vector<double> x, y, z, vx, vy, vz, mass, fx, fy, fz;
  abut::ContactSurface lower, upper;

  std::int32_t node(double px, double py, double pz) {
    x.push_back(px), y.push_back(py), z.push_back(pz), mass.push_back(1e-3);
    return static_cast<std::int32_t>(x.size() - 1);
  }
  bool shells = false;
  void plate(abut::ContactSurface& s, int n, double offset, double h, bool up) {
    const auto first = static_cast<std::int32_t>(x.size());
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) node(offset + 0.01 * i, offset + 0.01 * j, h);
    auto id = [&](int i, int j) { return first + j * (n + 1) + i; };
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        if (shells)
          s.add_shell({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}, up ? 1 : 2, 1e12,
                      kShellThickness);
        else if (up)
          s.add({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}, 1, 1e12, 0.01);
        else
          s.add({id(i, j), id(i, j + 1), id(i + 1, j + 1), id(i + 1, j)}, 2, 1e12, 0.01);
  }
  static constexpr double kShellThickness = 0.002;
  explicit Plates(int n, bool shell_plates = false) : shells(shell_plates) {
    plate(lower, n, 0.0, 0.0, true);
    // Shifted: every point overlaps a facet interior. Shells: the gap h lies between the
    // mid-surfaces.
    plate(upper, n, 0.003, 1e-4 + (shells ? kShellThickness : 0.0), false);
    for (auto* v : {&vx, &vy, &vz, &fx, &fy, &fz}) v->assign(x.size(), 0.0);
  }
  abut::ContactInput input(double t) const { return {x, y, z, vx, vy, vz, t, 1e-7, {}}; }
};

// `lift`: the upper plate's move from 1e-4 above the lower one (-2e-4: 1e-4 penetration).
void run(benchmark::State& state, abut::Discretisation discretisation, const char* counter,
         bool shells = false, double lift = -2e-4) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  Plates p(100, shells);
  abut::ContactSettings s;
  s.discretisation = discretisation;
  s.tangential_law = abut::Coulomb{0.2, 0.2, {}, {}, {}, {}};
  abut::ContactInterface contact(s, p.upper, p.lower, p.mass, p.input(0.0));
  const std::size_t upper_first = (101 * 101);
  for (std::size_t i = upper_first; i < p.x.size(); ++i) p.z[i] += lift, p.vx[i] = 1.0;
  abut::ContactForces out{p.fx, p.fy, p.fz, {}, {}};
  double t = 0.0;
  for (auto _ : state) {
    for (std::size_t i = upper_first; i < p.x.size(); ++i) p.x[i] += 1e-7;
    contact.apply(p.input(t), out);
    t += 1e-7;
    benchmark::DoNotOptimize(p.fx.data());
  }
  if ((contact.stats().active_points == 0) != (lift > 0.0))
    state.SkipWithError(lift > 0.0 ? "unexpected contact" : "no contact");
  const auto points = static_cast<double>(contact.point_count());
  state.counters["points"] = points;
  state.counters["active"] = static_cast<double>(contact.stats().active_points);
  state.counters[counter] =
      benchmark::Counter(points * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  omp_set_num_threads(omp_get_num_procs());
}

void BM_ContactPointCycle(benchmark::State& state) {
  run(state, abut::Discretisation::SurfaceToSurface, "ns_per_point_cycle");
}
BENCHMARK(BM_ContactPointCycle)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ContactNodeCycle(benchmark::State& state) {
  run(state, abut::Discretisation::NodeToSurface, "ns_per_node_cycle");
}
BENCHMARK(BM_ContactNodeCycle)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ShellContactPointCycle(benchmark::State& state) {
  run(state, abut::Discretisation::SurfaceToSurface, "ns_per_point_cycle", true);
}
BENCHMARK(BM_ShellContactPointCycle)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ShellContactNodeCycle(benchmark::State& state) {
  run(state, abut::Discretisation::NodeToSurface, "ns_per_node_cycle", true);
}
BENCHMARK(BM_ShellContactNodeCycle)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_ContactIdlePointCycle(benchmark::State& state) {
  run(state, abut::Discretisation::SurfaceToSurface, "ns_per_point_cycle", false,
      static_cast<double>(state.range(1)) * 1e-3);
}
BENCHMARK(BM_ContactIdlePointCycle)
    ->ArgsProduct({{1, 2}, {5, 100}})  // threads, gap in mm
    ->ArgNames({"threads", "gap_mm"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The contact's conduction at one thermal step (issue 29: ContactInterface::conduct_heat, which
// the explicit run calls once per thermal step with the partners of the last apply): the S2S
// plates above pressed together with a closed conductance, ns per point per thermal step.
void BM_ContactConductionStep(benchmark::State& state) {
  omp_set_num_threads(1);
  Plates p(100);
  abut::ContactSettings s;
  s.thermal.conductance = abut::OpenClosedConductance{1e5, 0.0};
  abut::ContactInterface contact(s, p.upper, p.lower, p.mass, p.input(0.0));
  const std::size_t upper_first = (101 * 101);
  for (std::size_t i = upper_first; i < p.x.size(); ++i) p.z[i] -= 2e-4;
  std::vector<double> heat(p.x.size(), 0.0), conductance(p.x.size(), 0.0);
  std::vector<double> temperature(p.x.size(), 0.0);
  for (std::size_t i = upper_first; i < p.x.size(); ++i) temperature[i] = 100.0;
  abut::ContactForces out{p.fx, p.fy, p.fz, heat, conductance};
  contact.apply(p.input(0.0), out);
  for (auto _ : state) {
    contact.conduct_heat(temperature, 1e-6, heat);
    benchmark::DoNotOptimize(heat.data());
  }
  if (!(contact.stats().heat_flow > 0.0)) state.SkipWithError("no conduction");
  const auto points = static_cast<double>(contact.point_count());
  state.counters["points"] = points;
  state.counters["per_point_step"] =
      benchmark::Counter(points * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  omp_set_num_threads(omp_get_num_procs());
}
BENCHMARK(BM_ContactConductionStep)->Unit(benchmark::kMicrosecond)->UseRealTime();

}  // namespace
