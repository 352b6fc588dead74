// Transient heat conduction (issue 11), the heat solver alone (solver/heat.hpp) on a bar of
// hexahedra, steel (k = 45 W/(m K), rho = 7800 kg/m^3, c = 460 J/(kg K), diffusivity
// a = k / (rho c) = 1.254e-5 m^2/s), against closed forms:
//  - a semi-infinite body whose surface is brought to T_s at t = 0:
//      T(x, t) = T_s + (T_0 - T_s) erf(x / (2 sqrt(a t)))
//    (Carslaw & Jaeger, Conduction of Heat in Solids, 2nd ed., 1959, section 2.4), 1%;
//  - steady conduction between two held temperatures: the linear profile and Fourier's flux
//    k (T_1 - T_2) / L, 0.1%;
//  - a body cooling by convection with a small Biot number (lumped capacitance):
//      T = T_inf + (T_0 - T_inf) exp(-h A t / (rho c V))
//    (Incropera & DeWitt, Fundamentals of Heat and Mass Transfer, section 5.1), 1%;
//  - a heat flux into an insulated bar: the stored heat equals the heat put in (round-off).
// Each run also checks the heat balance of the solver (stored = boundary + prescribed + sources).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "abut/core/error.hpp"
#include "abut/mesh/generators.hpp"
#include "abut/mesh/skin.hpp"
#include "abut/solver/heat.hpp"
#include "abut/solver/simulation.hpp"

namespace abut {
namespace {

constexpr double kK = 45.0, kRho = 7800.0, kC = 460.0;
constexpr double kDiffusivity = kK / (kRho * kC);

// A bar [0, length] x [0, w] x [0, w] of n x 1 x 1 hexes of steel with thermal properties.
Model bar(double length, int n, double w) {
  Model m;
  generate_box(m.mesh, {1, n, 1, 1, {0, 0, 0}, {length, w, w}});
  Material mat;
  mat.id = 1;
  mat.params = ElasticParams{kRho, 2.1e11, 0.3};
  mat.thermal_id = 7;
  m.materials.push_back(mat);
  Part p;
  p.id = 1;
  p.material_id = 1;
  m.parts.push_back(p);
  ThermalProperties t;
  t.id = 7;
  t.conductivity = kK;
  t.specific_heat = kC;
  m.thermal.properties.push_back(t);
  return m;
}

std::vector<std::int32_t> nodes_at_x(const Model& m, double x) {
  std::vector<std::int32_t> out;
  for (std::size_t i = 0; i < m.mesh.nodes.size(); ++i)
    if (std::abs(m.mesh.nodes.x[i] - x) < 1e-12) out.push_back(static_cast<std::int32_t>(i));
  return out;
}

// Runs to `end` with 0.9 of the stable step.
void run(HeatSolver& heat, const Model& m, double end) {
  const Nodes& n = m.mesh.nodes;
  double t = 0.0;
  while (t < end * (1.0 - 1e-12)) {
    const double dt = std::min(0.9 * heat.stable_step(), end - t);
    heat.advance(t, dt, n.x, n.y, n.z, {});
    t += dt;
  }
}

double mean_at_x(const Model& m, const HeatSolver& heat, double x) {
  double sum = 0.0;
  const auto nodes = nodes_at_x(m, x);
  for (const std::int32_t i : nodes) sum += heat.temperature()[static_cast<std::size_t>(i)];
  return sum / static_cast<double>(nodes.size());
}

TEST(HeatConduction, SemiInfiniteBodyFollowsTheErfSolution) {
  const double length = 0.2, t0 = 20.0, ts = 120.0, end = 60.0;
  Model m = bar(length, 200, 0.001);  // 1 mm elements; 2 sqrt(a t) = 55 mm << 200 mm
  m.thermal.initial_temperature = t0;
  m.thermal.prescribed.push_back({nodes_at_x(m, 0.0), {}, ts, {}});
  HeatSolver heat(m);
  run(heat, m, end);
  double worst = 0.0;
  for (const double x : {0.005, 0.01, 0.02, 0.03, 0.05, 0.08}) {
    const double exact = ts + (t0 - ts) * std::erf(x / (2.0 * std::sqrt(kDiffusivity * end)));
    const double error = (mean_at_x(m, heat, x) - exact) / (ts - t0);
    worst = std::max(worst, std::abs(error));
  }
  std::cout << "semi-infinite body: worst error " << 100 * worst << "% of the temperature step\n";
  EXPECT_LT(worst, 0.01);
  EXPECT_NEAR(heat.balance().error(), 0.0, 1e-9 * std::abs(heat.balance().stored));
}

// The safety net of issue 29: the first step on the bar whose end is brought to 120 from 20
// changes the node next to the end by about step / stable_step times the range of 100 K; at 100
// stable steps that is far beyond what any stable step can do (four times the range): the step
// is refused (InstabilityError) before it is taken. At 0.9 of the stable step it is taken.
TEST(HeatConduction, AStepBeyondTheStableOneIsRefused) {
  Model m = bar(0.02, 20, 0.001);
  m.thermal.initial_temperature = 20.0;
  m.thermal.prescribed.push_back({nodes_at_x(m, 0.0), {}, 120.0, {}});
  HeatSolver heat(m), stable_heat(m);
  const Nodes& n = m.mesh.nodes;
  EXPECT_NO_THROW(stable_heat.advance(0.0, 0.9 * heat.stable_step(), n.x, n.y, n.z, {}));
  const std::vector<double> before(heat.temperature().begin(), heat.temperature().end());
  EXPECT_THROW(heat.advance(0.0, 100.0 * heat.stable_step(), n.x, n.y, n.z, {}), InstabilityError);
  EXPECT_TRUE(std::equal(before.begin(), before.end(), heat.temperature().begin()));
}

TEST(HeatConduction, SteadyStateBetweenHeldTemperatures) {
  const double length = 0.05, w = 0.01;
  Model m = bar(length, 10, w);
  m.thermal.initial_temperature = 20.0;
  m.thermal.prescribed.push_back({nodes_at_x(m, 0.0), {}, 100.0, {}});
  m.thermal.prescribed.push_back({nodes_at_x(m, length), {}, 20.0, {}});
  HeatSolver heat(m);
  run(heat, m, 20.0 * length * length / kDiffusivity);  // 20 diffusion times: steady
  for (int i = 1; i < 10; ++i) {
    const double x = length * i / 10.0;
    EXPECT_NEAR(mean_at_x(m, heat, x), 100.0 - 80.0 * x / length, 0.001 * 80.0) << x;
  }
  // Fourier: the heat entering at x = 0 is k A dT / L.
  double flow_in = 0.0;
  for (const std::int32_t i : nodes_at_x(m, 0.0))
    flow_in -= heat.conduction_rate()[static_cast<std::size_t>(i)];
  EXPECT_NEAR(flow_in, kK * w * w * 80.0 / length, 0.001 * kK * w * w * 80.0 / length);
}

TEST(HeatConduction, LumpedBodyCoolsExponentially) {
  // A 10 mm steel cube, h = 20 W/(m^2 K) on all faces: Biot h L / k = 2e-5 << 0.1.
  const double side = 0.01, h = 20.0;
  Model m = bar(side, 2, side);
  m.thermal.initial_temperature = 500.0;
  SurfaceConvection c;
  c.coefficient = h;
  c.ambient = 20.0;
  for (const SkinFace& f : exterior_faces(m.mesh, false)) c.faces.push_back(f.nodes);
  m.thermal.convection.push_back(c);
  HeatSolver heat(m);
  const double end = 600.0;  // tau = rho c V / (h A) = 299 s
  run(heat, m, end);
  const double tau = kRho * kC * side / (6.0 * h);
  const double exact = 20.0 + 480.0 * std::exp(-end / tau);
  EXPECT_NEAR(mean_at_x(m, heat, 0.5 * side), exact, 0.01 * 480.0);
  EXPECT_NEAR(heat.balance().error(), 0.0, 1e-9 * std::abs(heat.balance().stored));
}

TEST(HeatConduction, FluxIntoAnInsulatedBarIsStored) {
  const double length = 0.02, w = 0.005, q = 2.0e5;  // W/m^2
  Model m = bar(length, 8, w);
  SurfaceHeatFlux f;
  f.scale = q;
  for (const SkinFace& face : exterior_faces(m.mesh, false)) {
    bool at_end = true;
    for (const std::int32_t n : face.nodes) at_end = at_end && m.mesh.nodes.x[n] == 0.0;
    if (at_end) f.faces.push_back(face.nodes);
  }
  ASSERT_EQ(f.faces.size(), 1u);
  m.thermal.fluxes.push_back(f);
  HeatSolver heat(m);
  run(heat, m, 3.0);
  EXPECT_NEAR(heat.balance().boundary, q * w * w * 3.0, 1e-12 * q * w * w * 3.0);
  EXPECT_NEAR(heat.balance().stored, q * w * w * 3.0, 1e-9 * q * w * w * 3.0);
}

// Steady state solved directly (HeatSolver::solve_steady): the bar between held temperatures is
// linear to round-off (linear elements reproduce the linear solution exactly), and a bar held at
// T_1 at x = 0 and convecting to T_inf at x = L has the Robin solution T(L) = T_inf + (T_1 - T_inf)
// / (1 + h L / k) (Incropera & DeWitt, section 3.1; exact at the nodes for the same reason).
TEST(HeatConduction, SteadyStateSolvedDirectly) {
  const double length = 0.2, w = 0.01, t1 = 100.0, t2 = 20.0;
  {
    Model m = bar(length, 20, w);
    m.thermal.prescribed.push_back({nodes_at_x(m, 0.0), {}, t1, {}});
    m.thermal.prescribed.push_back({nodes_at_x(m, length), {}, t2, {}});
    HeatSolver heat(m);
    const Nodes& n = m.mesh.nodes;
    heat.solve_steady(0.0, n.x, n.y, n.z, {});
    for (std::size_t i = 0; i < n.size(); ++i)
      EXPECT_NEAR(heat.temperature()[i], t1 + (t2 - t1) * n.x[i] / length, 1e-10 * t1);
  }
  {
    Model m = bar(length, 20, w);
    const double h = 500.0, t_inf = 20.0;
    m.thermal.prescribed.push_back({nodes_at_x(m, 0.0), {}, t1, {}});
    SurfaceConvection c;
    c.coefficient = h;
    c.ambient = t_inf;
    const auto end = nodes_at_x(m, length);  // the end face's 4 nodes, outward +x
    ASSERT_EQ(end.size(), 4u);
    c.faces.push_back({end[0], end[1], end[3], end[2]});
    m.thermal.convection.push_back(c);
    HeatSolver heat(m);
    const Nodes& n = m.mesh.nodes;
    heat.solve_steady(0.0, n.x, n.y, n.z, {});
    const double exact = t_inf + (t1 - t_inf) / (1.0 + h * length / kK);
    EXPECT_NEAR(mean_at_x(m, heat, length), exact, 1e-10 * t1);
  }
  {  // nothing held: an input error rather than an arbitrary level
    Model m = bar(length, 4, w);
    HeatSolver heat(m);
    const Nodes& n = m.mesh.nodes;
    EXPECT_THROW(heat.solve_steady(0.0, n.x, n.y, n.z, {}), InputError);
  }
}

// A strip of shells (2 mm thick, in a plane tilted about the x axis) whose end is brought to T_s:
// conduction in the mid-surface follows the same erf solution (Carslaw & Jaeger, section 2.4).
TEST(HeatConduction, ShellStripFollowsTheErfSolution) {
  const double length = 0.1, w = 0.002, t0 = 20.0, ts = 120.0, end = 10.0;
  const int n = 100;
  Model m;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j < 2; ++j)
      m.mesh.nodes.add(2 * i + j + 1, {length * i / n, 0.6 * w * j, 0.8 * w * j});
  for (int i = 0; i < n; ++i) m.mesh.add_shell(i + 1, 1, {2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1});
  Material mat;
  mat.id = 1;
  mat.params = ElasticParams{kRho, 2.1e11, 0.3};
  mat.thermal_id = 7;
  m.materials.push_back(mat);
  Part p;
  p.id = 1;
  p.material_id = 1;
  p.thickness = 0.002;
  m.parts.push_back(p);
  ThermalProperties t;
  t.id = 7;
  t.conductivity = kK;
  t.specific_heat = kC;
  m.thermal.properties.push_back(t);
  m.thermal.initial_temperature = t0;
  m.thermal.prescribed.push_back({nodes_at_x(m, 0.0), {}, ts, {}});
  HeatSolver heat(m);
  run(heat, m, end);
  double worst = 0.0;
  for (const double x : {0.002, 0.004, 0.008, 0.012, 0.02}) {
    const double exact = ts + (t0 - ts) * std::erf(x / (2.0 * std::sqrt(kDiffusivity * end)));
    worst = std::max(worst, std::abs(mean_at_x(m, heat, x) - exact) / (ts - t0));
  }
  std::cout << "shell strip: worst error " << 100 * worst << "% of the temperature step\n";
  EXPECT_LT(worst, 0.01);
  EXPECT_NEAR(heat.balance().error(), 0.0, 1e-9 * std::abs(heat.balance().stored));
  double capacity = 0.0;
  for (const double c : heat.capacity()) capacity += c;
  EXPECT_NEAR(capacity, kRho * kC * length * w * 0.002, 1e-12 * capacity);
}

// The explicit solver carries the heat along (simulation.cpp, advance_heat): with a stiff
// material many mechanical steps make one thermal step, with a very soft one a mechanical step is
// split into thermal ones; either way the temperature follows the erf solution (1%), and the heat
// balance closes.
TEST(HeatConduction, ExplicitRunSubCyclesTheHeat) {
  for (const double young : {2.1e5, 1e-2}) {  // mechanical step ~1/450 and ~10x the thermal one
    const double t0 = 20.0, ts = 120.0, end = 10.0;
    Model m = bar(0.1, 50, 0.002);  // 2 mm elements; 2 sqrt(a t) = 22 mm << 100 mm
    std::get<ElasticParams>(m.materials[0].params).young = young;
    m.time.end_time = end;
    m.thermal.initial_temperature = t0;
    m.thermal.prescribed.push_back({nodes_at_x(m, 0.0), {}, ts, {}});
    Simulation sim(m);
    while (!sim.finished()) sim.advance();
    ASSERT_NEAR(sim.temperature_time(), end, 1e-9 * end);
    double worst = 0.0;
    for (const double x : {0.002, 0.004, 0.008, 0.012, 0.02}) {
      double sum = 0.0;
      const auto nodes = nodes_at_x(m, x);
      for (const std::int32_t i : nodes) sum += sim.temperature()[static_cast<std::size_t>(i)];
      const double exact = ts + (t0 - ts) * std::erf(x / (2.0 * std::sqrt(kDiffusivity * end)));
      worst =
          std::max(worst, std::abs(sum / static_cast<double>(nodes.size()) - exact) / (ts - t0));
    }
    std::cout << "E = " << young << ": " << sim.cycle() << " mechanical steps, "
              << sim.thermal_steps() << " thermal steps, worst error " << 100 * worst << "%\n";
    EXPECT_LT(worst, 0.01);
    if (young > 1.0)
      EXPECT_LT(sim.thermal_steps() * 10, sim.cycle());
    else
      EXPECT_GT(sim.thermal_steps(), sim.cycle());
    const HeatBalance b = sim.heat_balance();
    EXPECT_NEAR(b.error(), 0.0, 1e-9 * std::abs(b.stored));
  }
}

}  // namespace
}  // namespace abut
