// Thermal contact in the contact library (heat_exchange.cpp): the heat a contact conducts between
// two facets at different temperatures, q = h A (T_1 - T_2) (Metafor's q_N = h_c (T^S - T^M),
// seed 002), with h from each law of laws/thermal.hpp, and the friction work turned into heat and
// shared between the surfaces (IMPETUS fric_heat, seed 000; Radioss Fheat, seed 004).
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "abut/contact/interface.hpp"
#include "fixtures.hpp"

namespace abut {
namespace {

using testing::add_plate;
using testing::World;

// Two 1 x 1 facets (2 x 2 facets below, 1 above: non-matching), the upper one (surface 1) at
// temperature t1, the lower one (surface 2) at t2, the upper created at z = 0.1 and moved to
// z = -d (d > 0 overlaps).
struct HotPair {
  World w;
  ContactSurface lower, upper;
  std::int32_t upper_first = 0, end = 0;
  std::vector<double> temperature, heat, conductance;
  HotPair() {
    lower = add_plate(w, 2, 2, 0, 0, 1, 1, 0.0, true, 1e6, 1.0, 1.0, 2);
    upper_first = static_cast<std::int32_t>(w.x.size());
    upper = add_plate(w, 1, 1, 0, 0, 1, 1, 0.1, false, 1e6, 1.0, 1.0, 1);
    end = static_cast<std::int32_t>(w.x.size());
  }
  ContactInterface make(ContactSettings s) {
    s.damping = 0.0;
    return ContactInterface(std::move(s), upper, lower, w.mass, w.input());
  }
  // Applies the contact with the upper facet at z = -d, upper at t1 and lower at t2.
  void apply(ContactInterface& c, double d, double t1, double t2, double dt = 1e-3) {
    for (std::int32_t i = upper_first; i < end; ++i) w.z[i] = -d;
    temperature.assign(w.x.size(), t2);
    std::fill(temperature.begin() + upper_first, temperature.end(), t1);
    heat.assign(w.x.size(), 0.0);
    conductance.assign(w.x.size(), 0.0);
    w.clear_forces();
    ContactInput in = w.input(0.0, dt);
    in.temperature = temperature;
    ContactForces out = w.forces();
    out.heat = heat;
    out.conductance = conductance;
    c.apply(in, out);
  }
  double heat_into_upper() const {
    return std::accumulate(heat.begin() + upper_first, heat.end(), 0.0);
  }
  double heat_into_lower() const {
    return std::accumulate(heat.begin(), heat.begin() + upper_first, 0.0);
  }
};

// Closed facets of area 1 conduct h (T_1 - T_2) from the hot side to the cold one, whatever the
// sides' meshes, and what one side loses the other gains (symmetric contact, both passes).
TEST(ContactHeat, ClosedFacetsConductHTimesAreaTimesTheJump) {
  const double h = 250.0;
  for (const bool one_way : {false, true}) {
    HotPair pair;
    ContactSettings s;
    s.one_way = one_way;
    s.thermal.conductance = OpenClosedConductance{h, 0.0};
    ContactInterface c = pair.make(s);
    pair.apply(c, 0.01, 80.0, 20.0);
    EXPECT_NEAR(pair.heat_into_upper(), -h * 60.0, 1e-9 * h * 60.0) << one_way;
    EXPECT_NEAR(pair.heat_into_lower(), h * 60.0, 1e-9 * h * 60.0) << one_way;
    EXPECT_NEAR(c.stats().heat_flow, h * 60.0, 1e-9 * h * 60.0) << one_way;
    EXPECT_NEAR(c.stats().conducted_heat, h * 60.0 * 1e-3, 1e-9 * h * 60.0 * 1e-3);
    // Each node's conductance to the other side: the sums are h A on each side.
    const double g_upper =
        std::accumulate(pair.conductance.begin() + pair.upper_first, pair.conductance.end(), 0.0);
    EXPECT_NEAR(g_upper, h, 1e-9 * h);
  }
}

// Metafor's law h = h_c0 (p / H_v)^w (seed 002): with the linear penalty, doubling the
// penetration doubles the pressure, and the conducted heat grows by 2^w.
TEST(ContactHeat, DoublingThePressureMultipliesTheHeatByTwoToTheW) {
  for (const double w : {0.5, 1.0, 1.7}) {
    HotPair pair;
    ContactSettings s;
    s.thermal.conductance = PressureConductance{1e4, 2e9, w};
    ContactInterface c = pair.make(s);
    pair.apply(c, 0.004, 300.0, 100.0);
    const double q1 = c.stats().heat_flow;
    const double p1 = c.stats().normal_force;  // area 1
    pair.apply(c, 0.008, 300.0, 100.0);
    const double q2 = c.stats().heat_flow;
    EXPECT_NEAR(c.stats().normal_force / p1, 2.0, 1e-12);
    EXPECT_NEAR(q2 / q1, std::pow(2.0, w), 1e-9 * std::pow(2.0, w)) << "w = " << w;
    EXPECT_NEAR(q1, 1e4 * std::pow(p1 / 2e9, w) * 200.0, 1e-9 * q1);
  }
}

// An open pair within the detection depth conducts with the open conductance (OptiStruct) or the
// distance law (Radioss); the pressure law conducts nothing without pressure.
TEST(ContactHeat, OpenPairsConductWithTheOpenAndDistanceLaws) {
  const double gap = 0.05;  // within the default detection depth, half the thickness 1
  {
    HotPair pair;
    ContactSettings s;
    s.thermal.conductance = OpenClosedConductance{1000.0, 10.0};
    ContactInterface c = pair.make(s);
    pair.apply(c, -gap, 50.0, 10.0);
    EXPECT_EQ(c.stats().active_points, 0u);
    EXPECT_NEAR(c.stats().heat_flow, 10.0 * 40.0, 1e-9 * 400.0);
  }
  {
    HotPair pair;
    ContactSettings s;
    s.thermal.conductance = DistanceConductance{[](double g) { return 100.0 * (1.0 - g / 0.1); }};
    ContactInterface c = pair.make(s);
    pair.apply(c, -gap, 50.0, 10.0);
    EXPECT_NEAR(c.stats().heat_flow, 50.0 * 40.0, 1e-9 * 2000.0);
    pair.apply(c, 0.001, 50.0, 10.0);  // closed: h(0)
    EXPECT_NEAR(c.stats().heat_flow, 100.0 * 40.0, 1e-9 * 4000.0);
  }
  {
    HotPair pair;
    ContactSettings s;
    s.thermal.conductance = PressureConductance{1e4, 2e9, 1.0};
    ContactInterface c = pair.make(s);
    pair.apply(c, -gap, 50.0, 10.0);
    EXPECT_EQ(c.stats().heat_flow, 0.0);
  }
}

// The friction work of a sliding step becomes heat, a share to_side1 on surface 1 and the rest on
// surface 2; as power over the step, it sums to the friction energy of the step.
TEST(ContactHeat, FrictionWorkBecomesHeatSharedAsSpecified) {
  for (const double share : {0.5, 0.2, 1.0}) {
    HotPair pair;
    ContactSettings s;
    s.tangential_law = Coulomb{0.3, 0.3, {}, {}, {}, {}};
    s.thermal.friction_heat = FrictionHeatSplit{share};
    ContactInterface c = pair.make(s);
    const double dt = 1e-4;
    for (std::int32_t i = pair.upper_first; i < pair.end; ++i) pair.w.vx[i] = 2.0;
    // The tangential spring (k_t = pfac A = 1e6) reaches mu F_n = 3000 after 15 steps of
    // 2e-4 slip: then it slides.
    for (int step = 0; step < 20; ++step) pair.apply(c, 0.01, 20.0, 20.0, dt);
    const double before = c.stats().friction_energy;
    pair.apply(c, 0.01, 20.0, 20.0, dt);
    const double work = c.stats().friction_energy - before;
    ASSERT_GT(work, 0.0);
    // Sliding: the friction force mu F_n times the slip v dt.
    EXPECT_NEAR(work, 0.3 * c.stats().normal_force * 2.0 * dt, 1e-9 * work);
    EXPECT_NEAR(pair.heat_into_upper() * dt, share * work, 1e-12 * work) << share;
    EXPECT_NEAR(pair.heat_into_lower() * dt, (1.0 - share) * work, 1e-12 * work) << share;
    EXPECT_NEAR(c.stats().friction_heat, c.stats().friction_energy,
                1e-12 * c.stats().friction_energy);
  }
}

}  // namespace
}  // namespace abut
