// Plasticity coupled to the temperature field (issue 11), on the single-element uniaxial tension
// of test_metal_tension.cpp (10 mm cube, symmetry faces held, the top pulled at 0.5 m/s after a
// 0.2 ms ramp, Johnson-Cook steel E = 210 GPa, nu = 0.3, rho = 7800 kg/m^3, c = 460 J/(kg K)):
//  - adiabatic heating: the share chi = 0.9 of the plastic work becomes heat (Taylor & Quinney
//    1934, Proc. R. Soc. A 143:307). The element flows at q = sigma_y(epsp), so the plastic work
//    per volume is W_p = int sigma_y d epsp = A epsp + B epsp^(n+1) / (n + 1) (rate-independent,
//    C = 0), and a uniform, insulated element warms by dT = chi W_p V / (rho c V0) (V / V0: the
//    elastic volume change, 7e-4). Checked to 1%; and the heat the solver received equals chi
//    times the plastic work sum q d epsp V of the run to 1e-6;
//  - thermal softening: a perfectly plastic Johnson-Cook element (B = 0) held at T* = 0.5 flows
//    at A (1 - 0.5^m) (Johnson & Cook 1983, Proc. 7th Int. Symp. Ballistics, p. 541), 1%;
//  - a softening metal without thermal properties is an input error at the material, and so are
//    the couplings not supported yet (shells, expansion of Mooney-Rivlin);
//  - a coupled run (expansion, plastic heat, softening) is bitwise identical on 1 and 2 threads.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "run_to.hpp"

namespace abut {
namespace {

constexpr double kH = 0.01, kRho = 7800.0, kC = 460.0;

// The cube of test_metal_tension.cpp with `material` (material 1) pulled to `end`.
std::string tension_deck(double end, const std::string& material) {
  char text[2048];
  std::snprintf(text, sizeof text, R"(
*TIME
%.9g
*NODE
1, 0.0, 0.0, 0.0, XYZ
2, %.9g, 0.0, 0.0, YZ
3, %.9g, %.9g, 0.0, Z
4, 0.0, %.9g, 0.0, ZX
5, 0.0, 0.0, %.9g, XY
6, %.9g, 0.0, %.9g, Y
7, %.9g, %.9g, %.9g, 0
8, 0.0, %.9g, %.9g, X
*ELEMENT_SOLID
1, 1, 1, 2, 3, 4, 5, 6, 7, 8
*SET_NODE
1
5, 6, 7, 8
*PART
"cube"
1, 1
*BC_MOTION
NS, 1
V, Z, 1
*CURVE
1
0.0, 0.0
2.0e-4, 0.5
1.0, 0.5
)",
                end, kH, kH, kH, kH, kH, kH, kH, kH, kH, kH, kH, kH);
  return text + material + "*END\n";
}

void add_thermal(Model& m, double chi, double expansion, double initial) {
  m.materials.at(0).thermal_id = 4;
  ThermalProperties p;
  p.id = 4;
  p.conductivity = 45.0;
  p.specific_heat = kC;
  p.expansion = expansion;
  p.taylor_quinney = chi;
  m.thermal.properties.push_back(p);
  m.thermal.initial_temperature = initial;
}

TEST(HeatCoupling, AdiabaticHeatingIsChiTimesThePlasticWork) {
  const double a = 200e6, b = 300e6, n = 0.3, chi = 0.9, t0 = 20.0;
  Model model = read_deck_string(
      tension_deck(2.2e-3, "*MAT_JC\n1, 7800.0, 210.0e9, 0.3\n200e6, 300e6, 0.3\n"), "adiabatic.k");
  add_thermal(model, chi, 0.0, t0);
  Simulation sim(model);
  // The plastic work sum q d epsp V over the cycles (the element's own formula, with the volume
  // at the end of the step rather than at mid-step).
  std::vector<double> q, ep;
  double previous = 0.0, work = 0.0;
  const auto volume = [](const Simulation& s) {
    return (s.x()[1] - s.x()[0]) * (s.y()[3] - s.y()[0]) * (s.z()[4] - s.z()[0]);
  };
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    s.von_mises_stress(q);
    s.plastic_strain(ep);
    work += q[0] * (ep[0] - previous) * volume(s);
    previous = ep[0];
  });
  const double epsp = ep[0];
  const double density_work = a * epsp + b * std::pow(epsp, n + 1.0) / (n + 1.0);
  const double expected = t0 + chi * density_work / (kRho * kC) * volume(sim) / (kH * kH * kH);
  double mean = 0.0;
  for (const double t : sim.temperature()) mean += t / 8.0;
  const double error = (mean - expected) / (expected - t0);
  const HeatBalance balance = sim.heat_balance();
  std::cout << "adiabatic heating: epsp = " << epsp << ", dT = " << mean - t0
            << " K, chi W_p / (rho c) = " << expected - t0 << " K, relative error " << error
            << "; heat sources " << balance.sources << " J, chi x plastic work " << chi * work
            << " J (" << balance.sources / (chi * work) - 1.0 << ")\n";
  EXPECT_GT(epsp, 0.05);
  EXPECT_LT(std::abs(error), 0.01);
  EXPECT_NEAR(balance.sources, chi * work, 1e-6 * chi * work);
  EXPECT_NEAR(balance.error(), 0.0, 1e-9 * balance.stored);
}

TEST(HeatCoupling, JohnsonCookSofteningAtHalfTheMeltingRange) {
  const double a = 300e6, m = 0.8, t0 = 20.0, tm = 1520.0;
  char jc[256];
  std::snprintf(jc, sizeof jc, "*MAT_JC\n1, 7800.0, 210.0e9, 0.3\n%g, 0, 1, 0, %g, %g, %g\n", a, m,
                t0, tm);
  Model model = read_deck_string(tension_deck(1.0e-3, jc), "softening.k");
  add_thermal(model, 0.0, 0.0, t0 + 0.5 * (tm - t0));  // T* = 0.5, no heat: T stays
  Simulation sim(model);
  std::vector<double> q, ep;
  verification::run_to(sim, sim.end_time());
  sim.von_mises_stress(q);
  sim.plastic_strain(ep);
  const double expected = a * (1.0 - std::pow(0.5, m));
  const double error = (q[0] - expected) / expected;
  std::cout << "softening at T* = 0.5: flow stress " << q[0] / 1e6
            << " MPa, A (1 - 0.5^m) = " << expected / 1e6 << " MPa, relative error " << error
            << " (epsp " << ep[0] << ")\n";
  EXPECT_GT(ep[0], 0.01);
  EXPECT_LT(std::abs(error), 0.01);
}

TEST(HeatCoupling, SofteningNeedsThermalProperties) {
  const Model model = read_deck_string(
      tension_deck(1.0e-3, "*MAT_JC\n1, 7800.0, 210.0e9, 0.3\n300e6, 0, 1, 0, 1, 20, 1520\n"),
      "softening.k");
  try {
    Simulation sim(model);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("thermal softening"), std::string::npos) << e.what();
    EXPECT_GT(e.where().line, 0u);
  }
}

// Not supported yet, so errors rather than silently uncoupled: shells with thermal properties (the
// heat solver refuses them; softening shells without them are refused by the coupling),
// expansion of Mooney-Rivlin.
TEST(HeatCoupling, UnsupportedCouplingsAreErrors) {
  const std::string shells = R"(
*TIME
1.0e-3
*COMPONENT_SHELL_TUBE
1, 1, 4, 4, SQUARE
0.0, 0.0, 0.0, 0.0, 0.0, 0.2
0.025
*MAT_JC
1, 7800.0, 210.0e9, 0.3
300e6, 500e6, 0.5
*PART
"tube"
1, 1, , 0.0015
*END
)";
  const std::string rubber = R"(
*TIME
1.0e-3
*COMPONENT_BOX
1, 1, 2, 2, 2
0.0, 0.0, 0.0, 0.01, 0.01, 0.01
*MAT_MOONEY_RIVLIN
1, 1500.0, 3.0e9
1.0e6, 0, 1.0e2
*PART
"rubber"
1, 1
*END
)";
  for (const auto& [deck, expected] :
       {std::pair{shells, "not supported yet"},
        std::pair{rubber, "*MAT_MOONEY_RIVLIN is not supported yet"}}) {
    Model model = read_deck_string(deck, "unsupported.k");
    add_thermal(model, 0.9, 1.2e-5, 20.0);
    try {
      Simulation sim(model);
      FAIL() << "expected an InputError: " << expected;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  }
}

// 1024 hexahedra (above the parallel threshold of the element loop) of a softening, expanding
// Johnson-Cook metal stretched by an initial velocity field; the conductivity makes a thermal
// step every few cycles.
std::vector<double> coupled_run(int threads) {
  omp_set_num_threads(threads);
  Model model = read_deck_string(R"(
*TIME
1.0
*COMPONENT_BOX
1, 1, 16, 8, 8
0.0, 0.0, 0.0, 0.016, 0.008, 0.008
*MAT_JC
1, 7800.0, 210.0e9, 0.3
300e6, 500e6, 0.5, 0, 1.0, 293, 1793
*PART
"block"
1, 1
*END
)",
                                 "threads.k");
  add_thermal(model, 0.9, 1.2e-5, 300.0);
  model.thermal.properties[0].conductivity = 1e6;
  const Nodes& nodes = model.mesh.nodes;
  model.vx0.resize(nodes.size());
  model.vy0.assign(nodes.size(), 0.0);
  model.vz0.assign(nodes.size(), 0.0);
  for (std::size_t i = 0; i < nodes.size(); ++i)
    model.vx0[i] = 200.0 * (nodes.x[i] / 0.016 - 0.5) + 30.0 * nodes.y[i] / 0.008;
  Simulation sim(model);
  while (sim.cycle() < 60) sim.advance();
  std::vector<double> out(sim.x());
  out.insert(out.end(), sim.y().begin(), sim.y().end());
  out.insert(out.end(), sim.temperature().begin(), sim.temperature().end());
  std::vector<double> ep;
  sim.plastic_strain(ep);
  out.insert(out.end(), ep.begin(), ep.end());
  EXPECT_GE(sim.thermal_steps(), 5);
  EXPECT_GT(sim.heat_balance().sources, 0.0);
  return out;
}

TEST(HeatCoupling, OneAndTwoThreadsGiveBitwiseIdenticalResults) {
  const int saved = omp_get_max_threads();
  const std::vector<double> one = coupled_run(1);
  const std::vector<double> two = coupled_run(2);
  omp_set_num_threads(saved);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) ASSERT_EQ(one[i], two[i]) << i;
}

}  // namespace
}  // namespace abut
