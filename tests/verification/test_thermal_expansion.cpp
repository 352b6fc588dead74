// Thermal expansion of hexahedra coupled to the temperature field (issue 11; ThermalCoupling in
// element/solid_block.hpp). Steel: E = 210 GPa, nu = 0.3, rho = 7800 kg/m^3, alpha = 1.2e-5 /K,
// heated by 100 K.
//  - A free bar: every node follows the same temperature ramp, so the bar expands without
//    stress. The hypoelastic rate form takes out alpha dT I from the rate of deformation, which
//    integrates to the logarithmic strain: ln(L / L0) = alpha dT, L - L0 = L0 (exp(alpha dT) - 1).
//    Its small-strain limit alpha dT L0 (the textbook one, e.g. Timoshenko & Goodier, Theory of
//    Elasticity, 3rd ed., 1970, section 150) is smaller by alpha dT / 2 = 6e-4 relative. Checked to
//    1e-6 relative: the ramp is the quintic smoothstep 10 s^3 - 15 s^4 + 6 s^5 over 200 periods
//    of the bar's first axial mode, whose first three derivatives are continuous at both ends, so
//    the free vibration it leaves is of order 60 / (omega t_ramp)^3 = 2e-7 of the expansion.
//  - The same bar between two fixed rigid walls (frictionless penalty contact): the axial
//    expansion is prevented, and the bar carries the uniaxial stress -E alpha dT (same section).
//    With the penalty pfac [stress/length] each wall gives way by sigma / pfac, so
//      alpha dT L = |sigma| L / E + 2 |sigma| / pfac,  sigma = -E alpha dT / (1 + 2 E / (pfac L)),
//    checked to 1%; pfac = 1000 E / L makes the correction 0.2%.
// All nodes of the bar have their temperature prescribed; the conductivity is large only to
// keep the thermal step below the mechanical one, so that the temperature follows the ramp
// smoothly (the temperature is uniform: conduction carries nothing).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "run_to.hpp"

namespace abut {
namespace {

constexpr double kE = 210e9, kRho = 7800.0, kAlpha = 1.2e-5, kDeltaT = 100.0, kT0 = 20.0;

std::string ramp_function(double ramp) {
  char text[256];
  std::snprintf(text, sizeof text,
                "*FUNCTION\n5\n%g + %g*(10*min(t/%.9g,1)^3 - 15*min(t/%.9g,1)^4 + "
                "6*min(t/%.9g,1)^5)\n",
                kT0, kDeltaT, ramp, ramp, ramp);
  return text;
}

// Thermal properties on material 1 and every node of part 1 following the ramp function 5.
void heat_part_one(Model& m) {
  m.materials.at(0).thermal_id = 3;
  ThermalProperties p;
  p.id = 3;
  p.conductivity = 1e8;  // only for the thermal step (see above)
  p.specific_heat = 460.0;
  p.expansion = kAlpha;
  m.thermal.properties.push_back(p);
  m.thermal.initial_temperature = kT0;
  PrescribedTemperature held;
  for (std::size_t h = 0; h < m.mesh.hex_count(); ++h)
    if (m.mesh.hex_part[h] == 1)
      for (const std::int32_t i : m.mesh.hexes[h]) held.nodes.push_back(i);
  std::sort(held.nodes.begin(), held.nodes.end());
  held.nodes.erase(std::unique(held.nodes.begin(), held.nodes.end()), held.nodes.end());
  held.curve = m.functions.find(5, {});
  m.thermal.prescribed.push_back(held);
}

// Mean x of the nodes of part 1 that start at x = at.
double mean_x(const Simulation& sim, double at) {
  const Model& m = sim.model();
  double sum = 0.0;
  int count = 0;
  for (std::size_t h = 0; h < m.mesh.hex_count(); ++h) {
    if (m.mesh.hex_part[h] != 1) continue;
    for (const std::int32_t i : m.mesh.hexes[h]) {
      if (std::abs(m.mesh.nodes.x[static_cast<std::size_t>(i)] - at) > 1e-12) continue;
      sum += sim.x()[static_cast<std::size_t>(i)];
      ++count;
    }
  }
  return sum / count;
}

TEST(HeatCoupling, FreeBarExpandsByAlphaDeltaT) {
  const double length = 0.1;
  const double period = 2.0 * length / std::sqrt(kE / kRho);  // free-free, first axial mode
  const double ramp = 200.0 * period;
  char text[512];
  std::snprintf(text, sizeof text, R"(
*TIME
%.9g
*COMPONENT_BOX
1, 1, 10, 1, 1
0.0, 0.0, 0.0, %.9g, 0.01, 0.01
*MAT_ELASTIC
1, %.9g, %.9g, 0.3
*PART
"bar"
1, 1
)",
                ramp + 5.0 * period, length, kRho, kE);
  Model model = read_deck_string(std::string(text) + ramp_function(ramp) + "*END\n", "bar.k");
  heat_part_one(model);
  Simulation sim(model);
  verification::run_to(sim, sim.end_time());
  const double expansion = mean_x(sim, length) - mean_x(sim, 0.0) - length;
  const double exact = length * std::expm1(kAlpha * kDeltaT);
  const double error = (expansion - exact) / exact;
  std::cout << "free bar: dL = " << expansion << " m, L0 (exp(alpha dT) - 1) = " << exact
            << ", relative error " << error
            << " (against alpha dT L0: " << expansion / (kAlpha * kDeltaT * length) - 1.0 << "), "
            << sim.cycle() << " cycles, " << sim.thermal_steps() << " thermal steps\n";
  EXPECT_LT(std::abs(error), 1e-6);
}

TEST(HeatCoupling, BarBetweenRigidWallsBuildsUpEAlphaDeltaT) {
  const double length = 0.05;
  const double pfac = 1000.0 * kE / length;
  const double period = 2.0 * length / std::sqrt(kE / kRho);  // fixed-fixed, first axial mode
  const double ramp = 50.0 * period;
  char text[2048];
  std::snprintf(text, sizeof text, R"(
*TIME
%.9g
*COMPONENT_BOX
1, 1, 5, 1, 1
0.0, 0.0, 0.0, %.9g, 0.01, 0.01
*COMPONENT_BOX
2, 2, 1, 1, 1
-0.01, -0.01, -0.01, 0.0, 0.02, 0.02
*COMPONENT_BOX
3, 3, 1, 1, 1
%.9g, -0.01, -0.01, %.9g, 0.02, 0.02
*MAT_ELASTIC
1, %.9g, %.9g, 0.3
*MAT_RIGID
2, 7800.0
*PART
"bar"
1, 1
"left wall"
2, 2
"right wall"
3, 2
*BC_MOTION
P, 2, XYZ, XYZ
*BC_MOTION
P, 3, XYZ, XYZ
*CONTACT
"left"
1
P, 1, P, 2, 0.0, %.9g
*CONTACT
"right"
2
P, 1, P, 3, 0.0, %.9g
)",
                ramp + 10.0 * period, length, length, length + 0.01, kRho, kE, pfac, pfac);
  Model model = read_deck_string(std::string(text) + ramp_function(ramp) + "*END\n", "walls.k");
  heat_part_one(model);
  Simulation sim(model);
  verification::run_to(sim, sim.end_time());
  std::vector<double> p, q;
  sim.pressure(p);
  sim.von_mises_stress(q);
  // Uniaxial: sigma_xx = -3 p, and the von Mises stress is |sigma_xx|.
  double axial = 0.0, mises = 0.0;
  for (std::size_t h = 0; h < model.mesh.hex_count(); ++h) {
    if (model.mesh.hex_part[h] != 1) continue;
    axial += -3.0 * p[h] / 5.0;
    mises += q[h] / 5.0;
  }
  const double exact = -kE * kAlpha * kDeltaT / (1.0 + 2.0 * kE / (pfac * length));
  const double error = (axial - exact) / exact;
  std::cout << "bar between walls: sigma = " << axial / 1e6 << " MPa (von Mises " << mises / 1e6
            << "), -E alpha dT / (1 + 2E / (pfac L)) = " << exact / 1e6 << " MPa, relative error "
            << error << "\n";
  EXPECT_LT(std::abs(error), 0.01);
  EXPECT_NEAR(mises, -axial, 0.01 * std::abs(exact));
  // Energy (issue 29): the internal energy is the strain energy sigma^2 V / (2 E) of the bar (the
  // walls' springs hold sigma^2 A / pfac more), brought in by the expansion's work, and the
  // balance kinetic + internal + contact = thermal work closes (1%; before, the internal column
  // was the stresses' work on the total strain, about 0, and the balance read 100%).
  const double volume = length * 0.01 * 0.01;
  const double strain_energy = exact * exact * volume / (2.0 * kE);
  const Energies e = sim.energies();
  std::cout << "internal energy " << e.internal << " J (sigma^2 V / 2E = " << strain_energy
            << " J), thermal work " << e.thermal_work << " J, contact " << e.contact
            << " J, kinetic " << e.kinetic << " J, balance " << sim.energy_balance_error() << "\n";
  EXPECT_NEAR(e.internal, strain_energy, 0.02 * strain_energy);
  EXPECT_LT(std::abs(sim.energy_balance_error()), 0.01);
}

}  // namespace
}  // namespace abut
