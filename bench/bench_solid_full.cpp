// ns per element evaluation (internal force and consistent tangent) of the static solver's solid
// elements, one per cell type and rule (element/solid_full.hpp; hex8_full.hpp for comparison), on
// one distorted element with a general displacement, small strain and NLGEOM, elastic. The
// counter `per_element` is the time of one evaluation; `per_point` divides it by the integration
// points. Single thread: the static solver evaluates elements independently (StaticElements).
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <vector>

#include "abut/element/hex8_full.hpp"
#include "abut/element/solid_full.hpp"

namespace {

using namespace abut;

struct Rule {
  CellType type;
  Integration integration;
};
constexpr Rule kRules[] = {
    {CellType::hex8, Integration::full},     {CellType::hex20, Integration::full},
    {CellType::hex20, Integration::reduced}, {CellType::tet4, Integration::full},
    {CellType::tet10, Integration::full},    {CellType::wedge6, Integration::full}};

void SolidFull(benchmark::State& state) {
  const Rule rule = kRules[state.range(0)];
  const bool nlgeom = state.range(1) != 0;
  const CellTopology& t = topology(rule.type);
  std::vector<double> X, u;
  for (int a = 0; a < t.nodes; ++a) {
    const auto& x = t.natural[static_cast<std::size_t>(a)];
    X.insert(X.end(), {x[0] + 0.1 * x[1], x[1] - 0.05 * x[2], x[2] + 0.02 * std::cos(a)});
    u.insert(u.end(),
             {0.01 * std::sin(a + 0.5), -0.01 * std::cos(2.0 * a), 0.01 * std::sin(3.0 * a)});
  }
  const IsotropicElastic steel{210000.0, 0.3};
  const auto points = quadrature(rule.type, rule.integration);
  SolidElementResult out;
  for (auto _ : state) {
    solid_full_with({rule.type, points, X, u, nlgeom}, steel, out);
    benchmark::DoNotOptimize(out.force.data());
  }
  state.SetLabel(std::string(t.abaqus) + (rule.integration == Integration::reduced ? "R" : "") +
                 (nlgeom ? " NLGEOM" : ""));
  state.counters["per_element"] =
      benchmark::Counter(static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["per_point"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * static_cast<double>(points.size()),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(SolidFull)->ArgsProduct({{0, 1, 2, 3, 4, 5}, {0, 1}});

// The fixed-size C3D8 of hex8_full.hpp, which the static solver uses for hexahedra.
void Hex8Full(benchmark::State& state) {
  auto in = std::make_unique<Hex8FullInput>();
  const CellTopology& t = topology(CellType::hex8);
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i) {
      in->X[a][i] = t.natural[static_cast<std::size_t>(a)][static_cast<std::size_t>(i)];
      in->u[a][i] = 0.01 * std::sin(3.0 * a + i);
    }
  in->nonlinear_geometry = state.range(0) != 0;
  auto out = std::make_unique<Hex8FullResult>();
  const IsotropicElastic steel{210000.0, 0.3};
  for (auto _ : state) {
    hex8_full(*in, steel, *out);
    benchmark::DoNotOptimize(out->force);
  }
  state.counters["per_element"] =
      benchmark::Counter(static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(Hex8Full)->Arg(0)->Arg(1);

}  // namespace
