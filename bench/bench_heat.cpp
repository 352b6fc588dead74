// The thermal step (issue 11): one explicit conduction step of the heat solver
// (HeatSolver::advance: conductance of every hexahedron at the current coordinates, gathered per
// node, forward Euler with the lumped capacity) on a steel box with its left face held hot, 10k and
// 100k hexahedra, 1 and 2 threads. Reported as time per element-cycle of a thermal step (counter
// per_element_cycle). The explicit run takes one thermal step per many mechanical ones (the
// thermal stable step is usually far longer), so this cost is shared among them.
// Run: build/bench/abut_bench --benchmark_filter=ThermalStep (the contact's conduction per thermal
// step: BM_ContactConductionStep in bench_contact.cpp)
#include <benchmark/benchmark.h>
#include <omp.h>

#include <cmath>

#include "abut/mesh/generators.hpp"
#include "abut/solver/heat.hpp"

namespace {

abut::Model hot_box(int n) {
  abut::Model m;
  abut::generate_box(m.mesh, {1, n, n, n, {0, 0, 0}, {1.0, 1.0, 1.0}});
  abut::Material mat;
  mat.id = 1;
  mat.params = abut::ElasticParams{7800.0, 2.1e11, 0.3};
  mat.thermal_id = 1;
  m.materials.push_back(mat);
  abut::Part p;
  p.id = 1;
  p.material_id = 1;
  m.parts.push_back(p);
  abut::ThermalProperties t;
  t.id = 1;
  t.conductivity = 45.0;
  t.specific_heat = 460.0;
  m.thermal.properties.push_back(t);
  m.thermal.initial_temperature = 20.0;
  std::vector<std::int32_t> left;
  for (std::size_t i = 0; i < m.mesh.nodes.size(); ++i)
    if (std::abs(m.mesh.nodes.x[i]) < 1e-12) left.push_back(static_cast<std::int32_t>(i));
  m.thermal.prescribed.push_back({left, {}, 500.0, {}});
  return m;
}

void ThermalStep(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  omp_set_num_threads(static_cast<int>(state.range(1)));
  const abut::Model model = hot_box(n);
  abut::HeatSolver heat(model);
  const abut::Nodes& nodes = model.mesh.nodes;
  const double dt = 0.9 * heat.stable_step();
  double t = 0.0;
  for (auto _ : state) {
    heat.advance(t, dt, nodes.x, nodes.y, nodes.z, {});
    t += dt;
  }
  const double elements = static_cast<double>(model.mesh.hex_count());
  state.counters["elements"] = elements;
  state.counters["per_element_cycle"] = benchmark::Counter(
      elements, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

BENCHMARK(ThermalStep)
    ->ArgsProduct({{22, 46}, {1, 2}})  // 10k, 100k hexahedra
    ->ArgNames({"n", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
