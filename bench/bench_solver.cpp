// Whole explicit cycle (element forces, assembly, time integration) on an elastic box with an
// initial velocity field, 1k to 1M hexahedra, 1 and 2 threads. Reported as time per element-cycle
// (counter per_element_cycle, e.g. "45n" = 45 ns). ExplicitCycleWithContact: the same cycle for two
// such boxes (n x n x n/2 each) pressed together by their velocities, one symmetric *CONTACT
// between them (every face of both parts a contact surface), so that the share of contact in a
// whole cycle shows. Together they are the scaling study of docs/verification.md (Speed): the
// counter bytes_per_hex is the heap the model holds after its first cycles (mesh, model, simulation
// and contact; no output), per hexahedron: the growth of glibc's bytes in use (mallinfo2, all
// arenas) from before the deck is read. Run: build/bench/abut_bench
// --benchmark_filter=ExplicitCycle
#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <malloc.h>
#include <omp.h>

#include <algorithm>
#include <functional>

#include "abut/io/deck.hpp"
#include "abut/solver/simulation.hpp"

namespace {

abut::Model box_model(int n) {
  const std::string deck = fmt::format(R"(
*UNIT_SYSTEM
SI
*TIME
1.0
*COMPONENT_BOX
1, 1, {0}, {0}, {0}
0.0, 0.0, 0.0, 1.0, 1.0, 1.0
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
1, 1
*FUNCTION
1
10.0 * X
*INITIAL_VELOCITY
P, 1, fcn(1), 0.0, 0.0
*END
)",
                                       n);
  return abut::read_deck_string(deck, "bench_box.k");
}

// Heap bytes in use (glibc: small and mapped blocks over all arenas). The resident size would not
// do: freed blocks of the previous benchmark stay with the process and are reused.
double heap_bytes() {
  const struct mallinfo2 m = mallinfo2();
  return static_cast<double>(m.uordblks + m.hblkhd);
}

// Cycles a model's simulation under the benchmark loop (after `warm_up` cycles) and reports the
// seconds per element-cycle, printed with an SI prefix ("45n" = 45 ns per element-cycle), and the
// memory per hexahedron.
void cycle(benchmark::State& state, const std::function<abut::Model()>& make_model,
           int warm_up = 0) {
  omp_set_num_threads(static_cast<int>(state.range(1)));
  const double before = heap_bytes();
  const abut::Model model = make_model();
  abut::Simulation sim(model);
  for (int i = 0; i < std::max(warm_up, 1); ++i) sim.advance();
  const double elements = static_cast<double>(model.mesh.hex_count());
  state.counters["bytes_per_hex"] = (heap_bytes() - before) / elements;
  for (auto _ : state) sim.advance();
  state.counters["elements"] = elements;
  state.counters["per_element_cycle"] = benchmark::Counter(
      elements, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void ExplicitCycle(benchmark::State& state) {
  cycle(state, [&] { return box_model(static_cast<int>(state.range(0))); });
}

BENCHMARK(ExplicitCycle)
    ->ArgsProduct({{10, 22, 46, 100}, {1, 2}})  // 1k, 10k, 100k, 1M hexahedra
    ->ArgNames({"n", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

abut::Model two_boxes_model(int n) {
  const std::string deck = fmt::format(R"(
*UNIT_SYSTEM
SI
*TIME
1.0
*COMPONENT_BOX
1, 1, {0}, {0}, {1}
0.0, 0.0, 0.0, 1.0, 1.0, 0.5
*COMPONENT_BOX
2, 2, {0}, {0}, {1}
0.0, 0.0, 0.5, 1.0, 1.0, 1.0
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
1, 1
2, 1
*INITIAL_VELOCITY
P, 1, 0.0, 0.0, 1.0
P, 2, 0.0, 0.0, -1.0
*CONTACT
1
P, 1, P, 2
*END
)",
                                       n, n / 2);
  return abut::read_deck_string(deck, "bench_two_boxes.k");
}

void ExplicitCycleWithContact(benchmark::State& state) {
  // 20 cycles: the boxes in contact.
  cycle(
      state, [&] { return two_boxes_model(static_cast<int>(state.range(0))); }, 20);
}

BENCHMARK(ExplicitCycleWithContact)
    ->ArgsProduct({{10, 22, 46, 100}, {1, 2}})  // 1k, 10k, 100k, 1M hexahedra
    ->ArgNames({"n", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
