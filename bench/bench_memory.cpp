// The machine's memory bandwidth, measured the way STREAM does (McCalpin, "Memory bandwidth and
// machine balance in current high performance computers", IEEE TCCA Newsletter, 1995): the
// triad a[i] = b[i] + s c[i] over three arrays, 24 bytes moved per index (the write-allocate
// read of a not counted, as in STREAM). Sizes in all: 0.8 MB (in L2), 100 MB (the project's
// machine reports a 300 MB L3), 1.6 GB (main memory). The counter bytes_per_second is the
// bandwidth a memory-bound kernel can reach: an element cycle that moves B bytes per element takes
// at least B / bandwidth (docs/verification.md, Speed). Run:
//   build/bench/abut_bench --benchmark_filter=StreamTriad
#include <benchmark/benchmark.h>
#include <omp.h>

#include <cstdint>
#include <vector>

namespace {

void StreamTriad(benchmark::State& state) {
  const auto n = static_cast<std::int64_t>(state.range(0));
  omp_set_num_threads(static_cast<int>(state.range(1)));
  std::vector<double> a(static_cast<std::size_t>(n)), b(a.size()), c(a.size());
  // First touch in the same static schedule as the triad, so each thread's pages are its own.
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) a[i] = 0.0, b[i] = 1.0, c[i] = 2.0;
  const double s = 3.0;
  for (auto _ : state) {
    double* pa = a.data();
    const double* pb = b.data();
    const double* pc = c.data();
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < n; ++i) pa[i] = pb[i] + s * pc[i];
    benchmark::DoNotOptimize(pa);
    benchmark::ClobberMemory();
  }
  state.counters["bytes_per_second"] = benchmark::Counter(
      24.0 * static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate,
      benchmark::Counter::kIs1024);
  omp_set_num_threads(omp_get_num_procs());
}

BENCHMARK(StreamTriad)
    ->ArgsProduct({{1 << 15, 1 << 22, 1 << 26}, {1, 2}})  // 0.8 MB, 100 MB, 1.6 GB in all
    ->ArgNames({"n", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
