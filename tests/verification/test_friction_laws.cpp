// *CONTACT_FRICTION laws COULOMB (static and dynamic coefficients) and TRESCA (shear limit
// independent of the pressure) against elementary mechanics.
//
// Coulomb: a block on a slope at angle theta (Meriam & Kraige, "Engineering Mechanics:
// Dynamics", ch. 3, block on an incline; Metafor CoulombContactMaterial, seed 002). The slope is
// modelled by a horizontal plane and gravity with two components, g sin(theta) along +x (down
// the slope) and -g cos(theta) along z (*LOAD_GRAVITY X and Z), so the geometry stays
// axis-aligned. With mu_d < tan(theta) < mu_s a block at rest stays at rest; with
// tan(theta) < mu_d a block sliding down at v0 decelerates at a = g (mu_d cos - sin) and stops
// after t = v0 / a having slid v0^2 / (2 a); with tan(theta) > mu_s it breaks away and then
// accelerates at g (sin - mu_d cos).
//
// Tresca (Metafor TrescaContactMaterial, seed 002): the slip limit is tau A with tau = m_d k,
// independent of the normal pressure, so a block of mass M sliding at v0 stops after
// v0^2 M / (2 tau A), the same distance under gravity g and 2 g.
//
// Model (as the sliding block of test_contact_sliding_block.cpp): both bodies *MAT_RIGID, a steel
// block 0.1 x 0.1 x 0.02 m (2 x 2 x 1 elements, M = 1.56 kg, A = 0.01 m^2) starting in touch with
// a 0.5 x 0.2 m plane (10 x 4 elements) held by *BC_MOTION; pfac = 6.2e9 Pa/m gives a contact
// frequency sqrt(pfac A / M) of about 1 kHz, far above the few Hz of the sliding, and the run
// takes a few thousand cycles. Symmetric contact (the default): the block's footprint always
// covers exactly 4 x 4 of the plane's Gauss points (it spans two element periods), so the plane's
// points carry the same area as the block's while it slides.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>

#include "run_to.hpp"

namespace abut {
namespace {

constexpr double kG = 9.81, kMass = 7800.0 * 0.1 * 0.1 * 0.02, kArea = 0.01;

std::string num(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// The block on the plane: gravity curves 1 (x) and 2 (z), initial velocity v0 along x, and the
// *CONTACT_FRICTION lines of contact 1; `upright`: the block's rotations are held.
std::string block_deck(double end_time, const std::string& gravity_x, const std::string& gravity_z,
                       double v0, const std::string& friction, bool upright = false) {
  return R"(
*UNIT_SYSTEM
SI
*TIME
)" + num(end_time) +
         R"(
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, -0.05, 0.0, 0.1, 0.05, 0.02
*COMPONENT_BOX
2, 2, 10, 4, 1
-0.05, -0.1, -0.02, 0.45, 0.1, 0.0
*MAT_RIGID
1, 7800.0
*MAT_RIGID
2, 7800.0
*PART
"block"
1, 1
"plane"
2, 2
*INITIAL_VELOCITY
P, 1, )" +
         num(v0) +
         R"(, 0.0, 0.0
*BC_MOTION
P, 2, XYZ, XYZ
)" + (upright ? "*BC_MOTION\nP, 1, 0, XYZ\n" : "") +
         R"(*CURVE
1
)" + gravity_x +
         R"(
*CURVE
2
)" + gravity_z +
         R"(
*LOAD_GRAVITY
X, 1
Z, 2
*CONTACT
"block on slope"
1
P, 1, P, 2, , 6.2e9
*CONTACT_FRICTION
)" + friction +
         R"(
*END
)";
}

std::string constant_curve(double value) { return "0.0, " + num(value) + "\n1.0, " + num(value); }

// Gravity along the slope switched on gradually once the block has settled on the plane (the
// plane tilted from 0 to theta between t1 and t2, 20 contact periods): the block starts with no
// normal force, and a tangential load applied at once would swing the (undamped) tangential
// contact springs to twice the static friction force.
constexpr double kTiltStart = 0.02, kTiltEnd = 0.04;
std::string tilt_curve(double value) {
  return "0.0, 0.0\n" + num(kTiltStart) + ", 0.0\n" + num(kTiltEnd) + ", " + num(value) +
         "\n1.0, " + num(value);
}

constexpr double kMuS = 0.6, kMuD = 0.4;
const std::string kCoulomb = "1, COULOMB, " + num(kMuS) + ", " + num(kMuD);

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST(FrictionCoulomb, BlockBetweenDynamicAndStaticAngleStaysAtRest) {
  // tan(theta) = 0.5: theta = 26.6 deg, between atan(mu_d) = 21.8 deg and atan(mu_s) = 31.0 deg.
  // The textbook block is a particle; here the friction law holds point by point, so the block
  // is kept from tipping (rotations held) and the slope is tilted gradually (tilt_curve). Else
  // the pressure is not uniform: the friction at the base and the weight at the centre of mass
  // (h/2 = 0.01 m above it) tilt it, the pressure varies linearly by +-12 tan(theta) (h/2) x/L^2,
  // +-24% at the outer Gauss points, so the uphill points reach F_t / F_n = 0.5/0.76 > mu_s,
  // slip, drop to mu_d, and shed their load onto the others until all slide (measured: 1.6 mm
  // and 0.05 m/s after 0.1 s). Without the gradual tilt the block, with no normal force at
  // t = 0, slips at once and never sticks again since tan(theta) > mu_d (4.3 mm, 0.09 m/s).
  const auto start = std::chrono::steady_clock::now();
  const double theta = std::atan(0.5), end = 0.1;
  const double gx = kG * std::sin(theta), gz = -kG * std::cos(theta);
  const Model model = read_deck_string(
      block_deck(end, tilt_curve(gx), constant_curve(gz), 0.0, kCoulomb, true), "slope_static.k");
  Simulation sim(model);
  const Vec3 x0 = sim.part_states()[0].centre_of_mass;
  double largest_ratio = 0.0;  // largest tangential / normal force once the block is loaded
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    const ContactStats& c = s.contact_reports()[0].stats;
    if (s.time() > kTiltStart && c.normal_force > 0.0)
      largest_ratio = std::max(largest_ratio, c.tangential_force / c.normal_force);
  });
  const PartState block = sim.part_states()[0];
  const double moved = norm(block.centre_of_mass - x0);
  // Without friction the block would slide x = gx [(t2-t1)^2/6 + (t2-t1)(T-t2)/2 + (T-t2)^2/2].
  const double ramp = kTiltEnd - kTiltStart, after = end - kTiltEnd;
  const double frictionless = gx * (ramp * ramp / 6.0 + ramp * after / 2.0 + after * after / 2.0);
  std::cout << "static: moved " << moved << " m in " << end << " s (frictionless " << frictionless
            << " m, ratio " << moved / frictionless << "); speed " << norm(block.velocity)
            << " m/s; largest F_t / F_n " << largest_ratio << " (tan theta 0.5, mu_s " << kMuS
            << "); " << sim.cycle() << " cycles, " << seconds_since(start) << " s\n";
  EXPECT_LT(moved, 1e-3 * frictionless);
  EXPECT_LT(largest_ratio, kMuS);
}

TEST(FrictionCoulomb, BlockAboveStaticAngleBreaksAwayAndSlidesWithDynamicFriction) {
  // tan(theta) = 0.7 > mu_s: the block breaks away during the tilt and then accelerates at
  // g (sin - mu_d cos) (measured over [0.05, 0.1] s, after the tilt).
  const auto start = std::chrono::steady_clock::now();
  const double theta = std::atan(0.7), end = 0.1, t_a = 0.05;
  const double gx = kG * std::sin(theta), gz = -kG * std::cos(theta);
  const Model model = read_deck_string(
      block_deck(end, tilt_curve(gx), constant_curve(gz), 0.0, kCoulomb), "slope_slides.k");
  Simulation sim(model);
  verification::run_to(sim, t_a);
  const double t0 = sim.time(), v0 = sim.part_states()[0].velocity.x;
  verification::run_to(sim, end);
  const double acceleration = (sim.part_states()[0].velocity.x - v0) / (sim.time() - t0);
  const double expected = kG * (std::sin(theta) - kMuD * std::cos(theta));
  std::cout << "breakaway: acceleration " << acceleration
            << " m/s^2, g (sin - mu_d cos) = " << expected << " m/s^2, error "
            << 100.0 * (acceleration - expected) / expected << "% (speed " << v0 << " m/s at " << t0
            << " s); " << sim.cycle() << " cycles, " << seconds_since(start) << " s\n";
  EXPECT_GT(v0, 0.0);
  EXPECT_NEAR(acceleration, expected, 0.01 * expected);
}

TEST(FrictionCoulomb, BlockSlidingDownBelowDynamicAngleStopsAndStays) {
  // tan(theta) = 0.05 < mu_d, v0 = 1 m/s down the slope: a = g (mu_d cos - sin) = 3.43 m/s^2,
  // stops after 0.292 s and 0.146 m; static friction then holds it.
  const auto start = std::chrono::steady_clock::now();
  const double theta = std::atan(0.05), v0 = 1.0;
  const double gx = kG * std::sin(theta), gz = -kG * std::cos(theta);
  const Model model = read_deck_string(
      block_deck(0.4, constant_curve(gx), constant_curve(gz), v0, kCoulomb), "slope_stops.k");
  Simulation sim(model);
  const double x0 = sim.part_states()[0].centre_of_mass.x;
  double t_stop = -1.0, t_previous = sim.time(), v_previous = v0;
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    const double v = s.part_states()[0].velocity.x;
    if (t_stop < 0.0 && v <= 0.0)
      t_stop = t_previous + (s.time() - t_previous) * v_previous / (v_previous - v);
    t_previous = s.time();
    v_previous = v;
  });
  const PartState block = sim.part_states()[0];
  const double a = kG * (kMuD * std::cos(theta) - std::sin(theta));
  const double distance = block.centre_of_mass.x - x0;
  const double expected_distance = v0 * v0 / (2.0 * a), expected_time = v0 / a;
  std::cout << "dynamic: stopping distance " << distance << " m, v0^2/(2a) = " << expected_distance
            << " m, error " << 100.0 * (distance - expected_distance) / expected_distance
            << "%; stopped at " << t_stop << " s, v0/a = " << expected_time << " s, error "
            << 100.0 * (t_stop - expected_time) / expected_time << "%; final speed "
            << block.velocity.x << " m/s; " << sim.cycle() << " cycles, " << seconds_since(start)
            << " s\n";
  EXPECT_NEAR(distance, expected_distance, 0.01 * expected_distance);
  ASSERT_GT(t_stop, 0.0);
  EXPECT_NEAR(t_stop, expected_time, 0.01 * expected_time);
  EXPECT_LT(std::abs(block.velocity.x), 1e-3 * v0);  // held by static friction at the end
}

// Tresca: m_s = 1, m_d = 0.8, k = 1000 Pa: tau A = 8 N on the 1.56 kg block, which from
// v0 = 1 m/s stops after v0^2 M / (2 tau A) = 0.0975 m (0.195 s), whatever the normal load.
// The limit acts on the points in contact only: the first half step has no friction (the block
// starts just touching), and under g the rear row of points lifts for 4 cycles of the first
// vertical bounce (the decelerating block pitches forward), both lost impulse that lengthens the
// slide by about v0 dt / 2 = 0.04% (2 g) and 0.1% (g).
constexpr double kTrescaMs = 1.0, kTrescaMd = 0.8, kTrescaK = 1000.0;

struct Stop {
  double distance = 0.0, speed = 0.0;
  std::int64_t cycles = 0;
};

Stop tresca_stop(double g, double v0) {
  const std::string friction =
      "1, TRESCA, " + num(kTrescaMs) + ", " + num(kTrescaMd) + "\n" + num(kTrescaK);
  const Model model = read_deck_string(
      block_deck(0.3, constant_curve(0.0), constant_curve(-g), v0, friction), "tresca.k");
  Simulation sim(model);
  const double x0 = sim.part_states()[0].centre_of_mass.x;
  verification::run_to(sim, sim.end_time());
  const PartState block = sim.part_states()[0];
  return {block.centre_of_mass.x - x0, block.velocity.x, sim.cycle()};
}

TEST(FrictionTresca, StoppingDistanceIndependentOfTheNormalLoad) {
  const auto start = std::chrono::steady_clock::now();
  const double v0 = 1.0, tau = kTrescaMd * kTrescaK;
  const double expected = v0 * v0 * kMass / (2.0 * tau * kArea);
  const Stop one = tresca_stop(kG, v0), two = tresca_stop(2.0 * kG, v0);
  std::cout << "Tresca: stopping distance " << one.distance << " m under g, " << two.distance
            << " m under 2 g; v0^2 M / (2 tau A) = " << expected << " m, errors "
            << 100.0 * (one.distance - expected) / expected << "% and "
            << 100.0 * (two.distance - expected) / expected << "%, g vs 2 g "
            << 100.0 * (two.distance - one.distance) / one.distance << "%; final speeds "
            << one.speed << ", " << two.speed << " m/s; " << one.cycles + two.cycles << " cycles, "
            << seconds_since(start) << " s\n";
  EXPECT_NEAR(one.distance, expected, 0.01 * expected);
  EXPECT_NEAR(two.distance, expected, 0.01 * expected);
  EXPECT_NEAR(two.distance, one.distance, 0.01 * one.distance);
  EXPECT_LT(std::abs(one.speed), 1e-3 * v0);
  EXPECT_LT(std::abs(two.speed), 1e-3 * v0);
}

// Radioss fric_ID (/FRICTION per part pair, seed 004; *CONTACT_FRICTION_PAIR): three rigid blocks
// (as above) slide side by side at v0 = 1 m/s on one plane under g, in one contact whose own law is
// Coulomb mu = 0.3. The pair (block 1, plane) takes Coulomb mu = 0.5, the pair (plane, block 3),
// given the other way round, Tresca m_d k = 800 Pa; block 4 keeps the contact's law. Each stops
// where its own law alone would stop it: v0^2 / (2 mu g) = 0.10194 m and 0.16990 m, and
// v0^2 M / (2 tau A) = 0.0975 m (the closed forms above). Energy: the balance (friction work
// included) within 1% at every cycle.
TEST(FrictionPair, EachPartPairSlidesWithItsOwnLaw) {
  const auto start = std::chrono::steady_clock::now();
  const std::string deck = R"(*UNIT_SYSTEM
SI
*TIME
0.4
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, -0.17, 0.0, 0.1, -0.07, 0.02
*COMPONENT_BOX
3, 3, 2, 2, 1
0.0, -0.05, 0.0, 0.1, 0.05, 0.02
*COMPONENT_BOX
4, 4, 2, 2, 1
0.0, 0.07, 0.0, 0.1, 0.17, 0.02
*COMPONENT_BOX
2, 2, 10, 8, 1
-0.05, -0.2, -0.02, 0.45, 0.2, 0.0
*MAT_RIGID
1, 7800.0
*PART
"block 1"
1, 1
"plane"
2, 1
"block 3"
3, 1
"block 4"
4, 1
*SET_PART
10
1, 3, 4
*INITIAL_VELOCITY
PS, 10, 1.0, 0.0, 0.0
*BC_MOTION
P, 2, XYZ, XYZ
*CURVE
1
0.0, -9.81
1.0, -9.81
*LOAD_GRAVITY
Z, 1
*CONTACT
"blocks on the plane"
1
PS, 10, P, 2, , 6.2e9
*CONTACT_FRICTION
1, COULOMB, 0.3
*CONTACT_FRICTION_PAIR
1, P, 1, P, 2
COULOMB, 0.5
*CONTACT_FRICTION_PAIR
1, P, 2, P, 3
TRESCA, 1.0, 0.8
1000.0
*END
)";
  const Model model = read_deck_string(deck, "friction_pair.k");
  Simulation sim(model);
  std::array<double, 3> x0{};
  for (int b = 0; b < 3; ++b) x0[b] = sim.part_states()[b == 0 ? 0 : b + 1].centre_of_mass.x;
  const double kinetic0 = 3.0 * 0.5 * kMass;
  double worst = 0.0;
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    const Energies e = s.energies();
    if (std::max(std::abs(e.total()), std::abs(e.external_work)) > 1e-3 * kinetic0)
      worst = std::max(worst, std::abs(s.energy_balance_error()));
  });
  const double tau = kTrescaMd * kTrescaK;
  const struct {
    const char* name;
    int part_index;
    double expected;
  } blocks[] = {{"block 1, pair Coulomb 0.5", 0, 1.0 / (2.0 * 0.5 * kG)},
                {"block 3, pair Tresca", 2, kMass / (2.0 * tau * kArea)},
                {"block 4, the contact's Coulomb 0.3", 3, 1.0 / (2.0 * 0.3 * kG)}};
  for (int b = 0; b < 3; ++b) {
    const PartState state = sim.part_states()[blocks[b].part_index];
    const double distance = state.centre_of_mass.x - x0[b];
    std::cout << blocks[b].name << ": stopped after " << distance << " m, expected "
              << blocks[b].expected << " m, error "
              << 100.0 * (distance - blocks[b].expected) / blocks[b].expected << "%; speed "
              << state.velocity.x << " m/s\n";
    EXPECT_NEAR(distance, blocks[b].expected, 0.01 * blocks[b].expected) << blocks[b].name;
    EXPECT_LT(std::abs(state.velocity.x), 1e-3) << blocks[b].name;
  }
  std::cout << "worst energy balance " << 100.0 * worst << "%; " << sim.cycle() << " cycles, "
            << seconds_since(start) << " s\n";
  EXPECT_LT(worst, 0.01);
}

}  // namespace
}  // namespace abut
