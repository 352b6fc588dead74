// The seed deck as a whole (examples/rubber_sphere.k, the project's main example, `make run`): a
// rubber sphere of 3645 cubic-resolution hexahedra hitting a steel block of 4 at 100 m/s, one
// symmetric S2S *CONTACT with friction (13912 contact points), timed cycle by cycle in the middle
// of the impact. The deck is read and run to t0 = 0.3 ms once (3824 cycles, shared by every
// registration); its state there is kept (Simulation::archive) and each iteration loads it into
// the benchmark's simulation, takes one cycle untimed (a loaded contact evaluates every point once
// before it can pass over the quiet ones again) and then times the same kCycles cycles
// (0.3001-0.3043 ms: the step is about 4.2e-8 s there, against 1.9e-7 s at the start), so that
// every iteration and every run measures the same work.
//
// Why 0.3 ms: the sphere (10 mm radius, its bottom 10 mm above the block) touches at 0.1 ms and
// leaves at 0.59 ms; its centre of mass stops (deepest compression) at 0.29 ms, and 0.2-0.35 ms
// hold the most active points (about 1000 of the 13912). The window is the impact at its fullest.
//
// Counters (the times printed with an SI prefix: "425n" = 425 ns):
//   per_element_cycle: whole cycle (elements, contact, integration) per element-cycle, as the run
//     log's "ns per element-cycle" (hexahedra + shells), but without output;
//   contact_per_point_cycle: the contact's own wall time (Simulation::contact_seconds, what the run
//     log's "contact took N% of the wall time" divides) per contact point-cycle, over all contact
//     points of the interface (ContactReport::points, both passes: 13912), active or not;
//   contact_per_active_point_cycle: the same time per active point-cycle (ContactStats::
//     active_points after each cycle, mean over the timed cycles: active_points);
//   contact_share: the contact's share of the timed wall time (the log's N% / 100).
// Run: build/bench/abut_bench --benchmark_filter=SeedDeck (about 15 s for both thread counts on
// an idle machine)
#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <omp.h>

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "abut/core/state_archive.hpp"
#include "abut/io/deck.hpp"
#include "abut/solver/simulation.hpp"

namespace {

constexpr double kStartTime = 0.3e-3;  // model time of the timed window [s]
constexpr int kCycles = 100;           // cycles timed per iteration

// The deck's model and the simulation's state at kStartTime, made once per process (the run to
// kStartTime takes longer than the timed cycles).
struct SeedDeck {
  abut::Model model;
  std::vector<char> state;

  SeedDeck() : model(abut::read_deck(std::string(ABUT_SOURCE_DIR) + "/examples/rubber_sphere.k")) {
    abut::Simulation sim(model);
    while (!sim.finished() && sim.time() < kStartTime) sim.advance();
    abut::StateArchive a = abut::StateArchive::for_saving();
    sim.archive(a);
    state = a.bytes();
  }
  static const SeedDeck& get() {
    static const SeedDeck deck;
    return deck;
  }
};

void BM_SeedDeckCycle(benchmark::State& state) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  const SeedDeck& deck = SeedDeck::get();
  abut::Simulation sim(deck.model);
  // Loads the state at t0 and takes the untimed cycle; true if every byte of it was read.
  const auto load = [&] {
    abut::StateArchive a = abut::StateArchive::for_loading(deck.state);
    sim.archive(a);
    sim.advance();
    return a.exhausted();
  };
  if (!load()) {
    state.SkipWithError("the saved state does not fit the simulation");
    return;
  }
  if (sim.contact_reports().empty() || sim.contact_reports()[0].stats.active_points == 0) {
    state.SkipWithError("no contact at the start of the timed cycles");
    return;
  }
  const double window_start = sim.time();
  const std::int64_t first_cycle = sim.cycle();

  double wall = 0.0, contact = 0.0, active = 0.0;
  for (auto _ : state) {
    state.PauseTiming();
    load();
    state.ResumeTiming();
    const double contact_before = sim.contact_seconds();
    const auto start = std::chrono::steady_clock::now();
    for (int c = 0; c < kCycles; ++c) {
      sim.advance();
      for (const abut::ContactReport& r : sim.contact_reports())
        active += static_cast<double>(r.stats.active_points);
    }
    wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    contact += sim.contact_seconds() - contact_before;
  }

  state.SetLabel(fmt::format("t = {:.4f}-{:.4f} ms, cycles {}-{}", 1e3 * window_start,
                             1e3 * sim.time(), first_cycle, sim.cycle()));
  const double cycles = static_cast<double>(kCycles) * static_cast<double>(state.iterations());
  const double elements =
      static_cast<double>(deck.model.mesh.hex_count() + deck.model.mesh.shell_count());
  double points = 0.0;
  for (const abut::ContactReport& r : sim.contact_reports())
    points += static_cast<double>(r.points);
  const double mean_active = active / cycles;
  state.counters["elements"] = elements;
  state.counters["points"] = points;
  state.counters["active_points"] = mean_active;
  state.counters["per_element_cycle"] = benchmark::Counter(
      elements * cycles, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  // The contact's own time, not the benchmark's: given as seconds per point-cycle directly.
  state.counters["contact_per_point_cycle"] = contact / (points * cycles);
  state.counters["contact_per_active_point_cycle"] = contact / (mean_active * cycles);
  state.counters["contact_share"] = wall > 0.0 ? contact / wall : 0.0;
  omp_set_num_threads(omp_get_num_procs());
}
// Fixed iterations: 10 x 100 cycles, about 3 s on one thread (plus the loads and the shared run to
// t0, about 8 s).
BENCHMARK(BM_SeedDeckCycle)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->Iterations(10)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
