// The inertia of a rigid part is positive definite for any positive-volume body, however
// slender (issue 28: a rigid 0.1 x 0.1 x 3e7 m box ran to "completed" with NaN energies).
//
// References (lumped mass: one hexahedron puts M/8 on each corner, so a box a x b x c has the
// point-mass inertia M (a^2 + b^2) / 4 about its axis along c, three times the continuum's
// M (a^2 + b^2) / 12 (the lumping factor 1 + 2/n^2 of test_rigid_rotation.cpp with n = 1)):
// - a spin omega about a principal axis of a free body stays constant (Euler's equations;
//   Goldstein, Classical Mechanics, ch. 5), with kinetic energy (1/2) I omega^2;
// - a prescribed translation v without rotation has kinetic energy (1/2) M v^2.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "abut/io/deck.hpp"
#include "abut/solver/simulation.hpp"

namespace abut {
namespace {

bool finite(const Energies& e) {
  return std::isfinite(e.kinetic) && std::isfinite(e.internal) && std::isfinite(e.external_work) &&
         std::isfinite(e.total());
}

// A rigid hexahedron of cross-section 0.1 x 0.1 m and length `length` along the unit vector
// (cos phi, sin phi, 0), density 7800 kg/m^3, 4 steps of 2.5e-4 s; `extra` holds its motion.
std::string slender_rod(double length, double phi, const std::string& extra) {
  const double c = std::cos(phi), s = std::sin(phi);
  std::string nodes;
  int id = 1;
  for (const double w : {0.0, 0.1})  // z
    for (const auto& [u, v] : {std::pair{0.0, 0.0}, {length, 0.0}, {length, 0.1}, {0.0, 0.1}})
      nodes +=
          fmt::format("{}, {:.17g}, {:.17g}, {:.17g}\n", id++, u * c - v * s, u * s + v * c, w);
  return "*UNIT_SYSTEM\nSI\n*TIME\n1.0e-3, 0.9, 0, 2.5e-4\n*NODE\n" + nodes +
         "*ELEMENT_SOLID\n1, 1, 1, 2, 3, 4, 5, 6, 7, 8\n*MAT_RIGID\n1, 7800.0\n*PART\n\"rod\"\n"
         "1, 1\n" +
         extra + "*END\n";
}

const char* kHeldAtOneMetrePerSecond = R"(*CURVE
1
0.0, 1.0
1.0, 1.0
*BC_MOTION
P, 1, YZ, XYZ
V, X, 1
)";

TEST(RigidInertia, SlenderRodsMovedByBcMotionKeepFiniteExactEnergies) {
  const double nominal_mass = 7800.0 * 0.1 * 0.1 * 3.0e7;
  // Along x (the issue's rod) and along a diagonal of the xy plane, where the inertia tensor's
  // entries are all of order M L^2 and its smallest principal moment, M (0.1^2 + 0.1^2) / 4,
  // lies 1e-17 below them: under double precision.
  for (const double phi : {0.0, 0.6}) {
    const std::string deck = slender_rod(3.0e7, phi, kHeldAtOneMetrePerSecond);
    const Model model = read_deck_string(deck, "rod.k");
    Simulation sim(model);
    EXPECT_TRUE(finite(sim.energies()));
    // The diagonal rod's volume comes from differences of 3e7 m coordinates: its mass is the
    // nominal one to about 1e-9; the energy must be (1/2) M v^2 of the mass it has.
    const double mass = sim.part_states()[0].mass;
    EXPECT_NEAR(mass, nominal_mass, 1e-8 * nominal_mass);
    while (!sim.finished()) {
      sim.advance();
      ASSERT_TRUE(finite(sim.energies())) << "phi = " << phi << ", t = " << sim.time();
      EXPECT_NEAR(sim.energies().kinetic, 0.5 * mass, 1e-12 * mass) << "phi = " << phi;
      EXPECT_NEAR(sim.part_states()[0].velocity.x, 1.0, 1e-12);
    }
    std::cout << "rod at phi = " << phi << ": kinetic energy " << sim.energies().kinetic
              << " J ((1/2) M v^2 = " << 0.5 * mass << " J), vx " << sim.part_states()[0].velocity.x
              << " m/s\n";
  }
}

TEST(RigidInertia, SlenderRodsAtRestStayAtRest) {
  for (const double phi : {0.0, 0.6}) {
    const Model model = read_deck_string(slender_rod(3.0e7, phi, ""), "rod_at_rest.k");
    Simulation sim(model);
    while (!sim.finished()) sim.advance();
    EXPECT_EQ(sim.energies().kinetic, 0.0) << "phi = " << phi;
    // The nodes are placed at the centre plus their arms: exact to the round-off of 3e7 m.
    for (std::size_t i = 0; i < sim.node_count(); ++i) {
      EXPECT_NEAR(sim.x()[i], model.mesh.nodes.x[i], 1e-15 * 3.0e7);
      EXPECT_NEAR(sim.y()[i], model.mesh.nodes.y[i], 1e-15 * 3.0e7);
    }
  }
}

// A rod 0.1 x 0.1 x 3e4 m spinning about its long axis: that moment, M (0.1^2 + 0.1^2) / 4, is
// 1e-11 of the others, resolved in double precision when summed as m (y^2 + z^2) about the centre
// (the form m (r.r - x^2) loses it to about 1e-6).
TEST(RigidInertia, SpinAboutTheLongAxisOfASlenderRodKeepsItsEnergy) {
  const double length = 3.0e4, omega = 10.0;
  const std::string spin = fmt::format(
      "*INITIAL_VELOCITY\nP, 1, 0, 0, 0, {}, 0, 0\n{}, 0.05, 0.05\n", omega, 0.5 * length);
  const Model model = read_deck_string(slender_rod(length, 0.0, spin), "spinning_rod.k");
  Simulation sim(model);
  const double mass = 7800.0 * 0.1 * 0.1 * length;
  const double kinetic = 0.5 * (mass * (0.01 + 0.01) / 4.0) * omega * omega;
  double worst = std::abs(sim.energies().kinetic - kinetic);
  while (!sim.finished()) {
    sim.advance();
    worst = std::max(worst, std::abs(sim.energies().kinetic - kinetic));
  }
  // Node 1 starts at (0, 0, 0), at (-0.05, -0.05) from the axis; it turns by omega t about x.
  const double angle = omega * sim.time();
  const double y = 0.05 - 0.05 * std::cos(angle) + 0.05 * std::sin(angle);
  const double z = 0.05 - 0.05 * std::sin(angle) - 0.05 * std::cos(angle);
  std::cout << "spin about the long axis: worst kinetic energy error " << worst / kinetic
            << " of (1/2) I omega^2 = " << kinetic << " J; node 1 off by "
            << std::hypot(sim.y()[0] - y, sim.z()[0] - z) << " m\n";
  EXPECT_LT(worst, 1e-12 * kinetic);
  EXPECT_NEAR(sim.y()[0], y, 1e-12);
  EXPECT_NEAR(sim.z()[0], z, 1e-12);
}

}  // namespace
}  // namespace abut
