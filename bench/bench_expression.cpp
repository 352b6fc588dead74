// Cost of evaluating a compiled *FUNCTION per contact point: a pressure- and velocity-dependent
// friction coefficient mu(pres, vtang), against the same formula written in C++.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "abut/core/functions.hpp"

namespace {

constexpr int kPoints = 1024;  // contact points per iteration, with varying pres and vtang

std::vector<abut::Variables> contact_points() {
  std::vector<abut::Variables> points(kPoints);
  for (int i = 0; i < kPoints; ++i) {
    points[i].pres = 1e5 * (1 + i % 37);
    points[i].vtang = 0.01 * (i % 101);
  }
  return points;
}

void BM_FrictionExpression(benchmark::State& state) {
  abut::FunctionTable table;
  table.add_function(1, "0.1+0.05*exp(-vtang/10)*pres/1e6", {});
  table.resolve();
  const abut::FunctionRef mu = table.find(1, {});
  const std::vector<abut::Variables> points = contact_points();
  for (auto _ : state) {
    double sum = 0.0;
    for (const abut::Variables& p : points) sum += table.value(mu, p);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * kPoints);
  state.counters["ns_per_eval"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * kPoints,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_FrictionExpression);

// A function calling a curve and another function through crv()/fcn().
void BM_ExpressionWithReferences(benchmark::State& state) {
  abut::FunctionTable table;
  table.add_curve(2, abut::Curve{{0.0, 1.0, 2.0, 5.0}, {0.3, 0.25, 0.2, 0.1}}, {});
  table.add_function(3, "1e-6*pres", {});
  table.add_function(1, "crv(2, vtang)*min(1, fcn(3))", {});
  table.resolve();
  const abut::FunctionRef mu = table.find(1, {});
  const std::vector<abut::Variables> points = contact_points();
  for (auto _ : state) {
    double sum = 0.0;
    for (const abut::Variables& p : points) sum += table.value(mu, p);
    benchmark::DoNotOptimize(sum);
  }
  state.counters["ns_per_eval"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * kPoints,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_ExpressionWithReferences);

// The floor: the same friction law compiled by the C++ compiler.
void BM_FrictionNative(benchmark::State& state) {
  const std::vector<abut::Variables> points = contact_points();
  for (auto _ : state) {
    double sum = 0.0;
    for (const abut::Variables& p : points)
      sum += 0.1 + 0.05 * std::exp(-p.vtang / 10) * p.pres / 1e6;
    benchmark::DoNotOptimize(sum);
  }
  state.counters["ns_per_eval"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * kPoints,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_FrictionNative);

}  // namespace
