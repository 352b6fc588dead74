// The normal laws of *CONTACT_NORMAL (issue 7): contact sense BILATERAL and NEGATIVE (Metafor
// TYPE_CONT, seed 002), the gap-dependent penalty law CURVE (Metafor
// FrictionlessVariablePenaltyContactMaterial, seed 002) and the clearance (OptiStruct CLEARANCE,
// seed 003).
//
// Every model is a rigid block against a rigid plate held by *BC_MOTION, one way (one_way = 1:
// the block is surface 1, its 2 x 2 facets with 2 x 2 Gauss points each act against the plate's
// facets), so the contact is a set of parallel springs of total stiffness k = pfac A on the
// block's bottom (or top) face of area A, and the block is a mass M on that spring. Analytical
// solutions are those of a mass on a linear spring (e.g. Meriam & Kraige, "Engineering
// Mechanics: Dynamics", ch. 8: x(t) = (v0/omega) sin(omega t), omega = sqrt(k/M)), of a static
// force balance (p(d) A = M g) and of free fall (s = g t^2 / 2). Where the spring's dynamics is
// compared with the analytical one the contact damping is off (xi = 0) and dt_max of *TIME is
// set so that omega dt = 0.05: the central-difference solution of x'' = -omega^2 x then has an
// amplitude (omega dt)^2/24 = 1e-4 and a sampled maximum 1 - cos(omega dt / 2) = 3e-4 (relative)
// off the exact one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "run_to.hpp"

namespace abut {
namespace {

constexpr double kPfac = 1.0e9;                          // [Pa/m]
constexpr double kArea = 0.01;                           // block face 0.1 x 0.1 m
constexpr double kMass = 7800.0 * 0.0002;                // steel block 0.1 x 0.1 x 0.02 m: 1.56 kg
const double kOmega = std::sqrt(kPfac * kArea / kMass);  // 2532 rad/s
const double kStep = 0.05 / kOmega;                      // dt_max: omega dt = 0.05

std::string num(double v) {
  std::ostringstream s;
  s << std::setprecision(17) << v;
  return s.str();
}

// A rigid block 0.1 x 0.1 x 0.02 m (2 x 2 x 1 elements) with its bottom face at z = z0 over a
// fixed rigid plate 0.2 x 0.2 x 0.02 m (4 x 4 x 1 elements) whose top face is z = 0. `contact`
// is everything after line 1 of *CONTACT 1 (line 2 onwards) plus any contact-law keyword;
// `extra` more keywords (velocities, gravity).
std::string block_on_plate(double t_end, double z0, const std::string& contact,
                           const std::string& extra) {
  return "*TIME\n" + num(t_end) + ", 0.9, 0.0, " + num(kStep) + R"(
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, 0.0, )" +
         num(z0) + ", 0.1, 0.1, " + num(z0 + 0.02) + R"(
*COMPONENT_BOX
2, 2, 4, 4, 1
-0.05, -0.05, -0.02, 0.15, 0.15, 0.0
*MAT_RIGID
1, 7800.0
*PART
"block"
1, 1
"plate"
2, 1
*BC_MOTION
P, 2, XYZ, XYZ
*CONTACT
1
)" + contact +
         "\n" + extra + "\n*END\n";
}

// *CONTACT lines 2 to 4: pfac 1e9, damping xi, one way.
std::string one_way_contact(double xi) {
  return "P, 1, P, 2, 0.0, " + num(kPfac) + "\n0, " + num(xi) + "\n, , , , 1";
}

// ---------------------------------------------------------------------------------------------
// 1. BILATERAL: the block touching the plate is launched away from it at v0 = 1 m/s. The
// bilateral contact holds it on the surface in tension as in compression, so it oscillates about
// contact as a mass on the spring k = pfac A: x(t) = (v0/omega) sin(omega t), the separation
// never exceeds v0/omega = 0.395 mm and the block comes back and presses into the plate by as
// much. With sense POSITIVE (the default) the contact never pulls and the block leaves at v0.
// Both runs last 1.5 periods (3.7 ms, 190 cycles).

struct Excursion {
  double largest = -1e300, smallest = 1e300, final_speed = 0.0, final_separation = 0.0;
  double largest_overall = 0.0;  // largest |separation| over the whole run
  double time_of_largest = 0.0, time_of_smallest = 0.0;
  int cycles_with_force = 0;
};

Excursion launch_from_plate(const std::string& sense) {
  const double period = 2.0 * std::acos(-1.0) / kOmega;
  const std::string deck = block_on_plate(
      1.5 * period, 0.0, one_way_contact(0.0) + "\n*CONTACT_NORMAL\n1, LINEAR, , " + sense,
      "*INITIAL_VELOCITY\nP, 1, 0.0, 0.0, 1.0");
  const Model model = read_deck_string(deck, "launch_" + sense + ".k");
  Simulation sim(model);
  const double z0 = sim.part_states().at(0).centre_of_mass.z;
  Excursion e;
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    const double separation = s.part_states()[0].centre_of_mass.z - z0;
    e.largest_overall = std::max(e.largest_overall, std::abs(separation));
    if (s.time() <= 0.5 * period && separation > e.largest) {  // first half period: away
      e.largest = separation;
      e.time_of_largest = s.time();
    }
    if (s.time() > 0.5 * period && s.time() <= period && separation < e.smallest) {  // back
      e.smallest = separation;
      e.time_of_smallest = s.time();
    }
    if (s.contact_reports()[0].stats.force.z != 0.0) ++e.cycles_with_force;
    e.final_separation = separation;
    e.final_speed = s.part_states()[0].velocity.z;
  });
  return e;
}

TEST(ContactNormalBilateral, HoldsABlockLaunchedAwayFromThePlane) {
  const double v0 = 1.0, amplitude = v0 / kOmega, period = 2.0 * std::acos(-1.0) / kOmega;
  const Excursion e = launch_from_plate("BILATERAL");
  const double error_up = (e.largest - amplitude) / amplitude;
  const double error_down = (-e.smallest - amplitude) / amplitude;
  std::cout << "bilateral: largest separation " << e.largest << " m at " << e.time_of_largest
            << " s (v0/omega = " << amplitude << " m at T/4 = " << 0.25 * period << " s), error "
            << 100.0 * error_up << "%; back into the plate by " << -e.smallest << " m at "
            << e.time_of_smallest << " s (3T/4 = " << 0.75 * period << " s), error "
            << 100.0 * error_down << "%; largest |separation| over 1.5 periods "
            << e.largest_overall << " m\n";
  EXPECT_NEAR(e.largest, amplitude, 0.01 * amplitude);
  EXPECT_NEAR(e.time_of_largest, 0.25 * period, 0.02 * period);
  // It comes back: it crosses the surface and presses into the plate by the same amplitude.
  EXPECT_NEAR(-e.smallest, amplitude, 0.01 * amplitude);
  EXPECT_NEAR(e.time_of_smallest, 0.75 * period, 0.02 * period);
  EXPECT_LT(e.largest_overall, 1.01 * amplitude);  // bounded over the whole 1.5 periods
}

TEST(ContactNormalBilateral, PositiveSenseLetsTheBlockLeave) {
  const double v0 = 1.0, period = 2.0 * std::acos(-1.0) / kOmega;
  const Excursion e = launch_from_plate("POSITIVE");
  const double expected = v0 * 1.5 * period;
  std::cout << "positive (control): separation after 1.5 periods " << e.final_separation
            << " m (v0 t = " << expected << " m), speed " << e.final_speed
            << " m/s, cycles with a contact force " << e.cycles_with_force << "\n";
  EXPECT_EQ(e.cycles_with_force, 0);
  EXPECT_NEAR(e.final_speed, v0, 1e-12);
  EXPECT_NEAR(e.final_separation, expected, 1e-9);
}

// ---------------------------------------------------------------------------------------------
// 2. NEGATIVE: a point must stay behind (inside) the partner surface. The plate is now a thick
// rigid slab, z in [-0.2, 0], and the block (the same 0.1 x 0.1 x 0.02 m rigid block) is inside
// it, its top face 2 mm below the slab's top face, moving up at v0 = 1 m/s. With sense NEGATIVE
// the block's top face (outward normal +z) faces the back of the slab's top facets (normal +z):
// it is an ordinary penalty spring pushing the block back down, along -n, once the block's top
// passes the slab's top. So it is the mass-spring impact: the block overshoots the surface by at
// most v0/omega = 0.395 mm and rebounds at -v0 (xi = 0, elastic), staying inside. With sense
// POSITIVE the same faces are parallel, not facing each other, and the block passes through
// untouched.
//
// The control needs gid_0 (*CONTACT line 3), a thin box about z = 0 that keeps only the facets of
// the two top faces in the contact: with every face in it, POSITIVE would see the block's bottom
// face 22 mm deep behind the slab's top face at t = 0 and release those points (deeper than
// delta0_max), so the pass-through would not show the sense alone. The NEGATIVE run is made both
// with gid_0 and without it (every face of both parts: the block's other faces meet the slab's
// other faces from behind, inside, and stay open). Run time 5 ms: the block reaches the surface
// at 2 ms and is back below it half a period (1.24 ms) later.

Excursion rise_to_the_slab_top(const std::string& sense, bool region) {
  const std::string deck = "*TIME\n0.005, 0.9, 0.0, " + num(kStep) + R"(
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, 0.0, -0.022, 0.1, 0.1, -0.002
*COMPONENT_BOX
2, 2, 4, 4, 1
-0.05, -0.05, -0.2, 0.15, 0.15, 0.0
*MAT_RIGID
1, 7800.0
*PART
"block"
1, 1
"slab"
2, 1
*BC_MOTION
P, 2, XYZ, XYZ
*INITIAL_VELOCITY
P, 1, 0.0, 0.0, 1.0
*GEOMETRY_BOX
1
-1.0, -1.0, -0.005, 1.0, 1.0, 0.005
*CONTACT
1
P, 1, P, 2, 0.0, 1.0e9
0, 0.0, )" + std::string(region ? "1" : "") +
                           R"(
, , , , 1
*CONTACT_NORMAL
1, LINEAR, , )" + sense + R"(
*END
)";
  const Model model = read_deck_string(deck, "slab_" + sense + ".k");
  Simulation sim(model);
  Excursion e;
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    const double top = s.part_states()[0].centre_of_mass.z + 0.01;  // the block's top face
    if (top > e.largest) {
      e.largest = top;
      e.time_of_largest = s.time();
    }
    if (s.contact_reports()[0].stats.force.z != 0.0) ++e.cycles_with_force;
    e.final_separation = top;
    e.final_speed = s.part_states()[0].velocity.z;
  });
  return e;
}

TEST(ContactNormalNegative, KeepsTheBlockInsideTheSlab) {
  const double v0 = 1.0, overshoot = v0 / kOmega;
  for (const bool region : {true, false}) {
    const Excursion e = rise_to_the_slab_top("NEGATIVE", region);
    const double error = (e.largest - overshoot) / overshoot;
    const double reached = 0.002 / v0, period = 2.0 * std::acos(-1.0) / kOmega;
    std::cout << "negative (" << (region ? "top faces only" : "all faces")
              << "): block top at most " << e.largest << " m beyond the slab's top at "
              << e.time_of_largest << " s (v0/omega = " << overshoot << " m at "
              << reached + 0.25 * period << " s), error " << 100.0 * error << "%; final speed "
              << e.final_speed << " m/s (-v0), final top " << e.final_separation
              << " m; cycles with a force " << e.cycles_with_force << "\n";
    EXPECT_NEAR(e.largest, overshoot, 0.01 * overshoot);
    EXPECT_NEAR(e.time_of_largest, reached + 0.25 * period, 0.02 * period);
    EXPECT_NEAR(e.final_speed, -v0, 0.01 * v0);  // elastic rebound, back into the slab
    EXPECT_LT(e.final_separation, 0.0);
    EXPECT_GT(e.cycles_with_force, 0);
  }
}

TEST(ContactNormalNegative, PositiveSenseLetsTheBlockPassThrough) {
  const double v0 = 1.0;
  const Excursion e = rise_to_the_slab_top("POSITIVE", true);
  const double expected = -0.002 + v0 * 0.005;
  std::cout << "positive (control): block top " << e.final_separation
            << " m after 5 ms (-0.002 + v0 t = " << expected << " m), speed " << e.final_speed
            << " m/s, cycles with a force " << e.cycles_with_force << "\n";
  EXPECT_EQ(e.cycles_with_force, 0);
  EXPECT_NEAR(e.final_speed, v0, 1e-12);
  EXPECT_NEAR(e.final_separation, expected, 1e-9);
}

// ---------------------------------------------------------------------------------------------
// 3. CURVE: a gap-dependent penalty p = f(d). The block rests on the plate under gravity
// (g = 9.81 m/s^2) and settles under the contact damping (xi = 0.5) from a touching start; in
// static equilibrium the contact pressure is M g / A = 1530 Pa, so the penetration is
// f^-1(M g / A). f is a *CURVE tabulating p = a d^2 (a = 1e13 Pa/m^2) every 2.5 um up to 40 um,
// interpolated linearly between its points: its inverse at 1530 Pa (12.357 um) is computed here
// from the same table (the quadratic's own sqrt(M g / (A a)) = 12.371 um differs from it by the
// tabulation, 0.11%). pfac of *CONTACT (1e9 Pa/m) only bounds the stable step here: with law
// LINEAR it would give a penetration of 1.5 um. Run time 40 ms, about 25 settling times
// 1/(xi omega) (1.7 ms at the slope of the curve at the solution).

TEST(ContactNormalCurve, StaticPenetrationIsTheInverseOfTheCurveAtMgOverA) {
  constexpr double a = 1.0e13, g = 9.81;
  std::vector<double> d, p;
  for (int i = 0; i <= 16; ++i) {
    d.push_back(2.5e-6 * i);
    p.push_back(a * d.back() * d.back());
  }
  std::string curve = "*CURVE\n2\n";
  for (std::size_t i = 0; i < d.size(); ++i) curve += num(d[i]) + ", " + num(p[i]) + "\n";
  const std::string deck = block_on_plate(
      0.04, 0.0,
      "P, 1, P, 2, 0.0, " + num(kPfac) + "\n0, 0.5\n, , , , 1\n*CONTACT_NORMAL\n1, CURVE, 2",
      curve + "*CURVE\n1\n0.0, -9.81\n1.0, -9.81\n*LOAD_GRAVITY\nZ, 1");
  const Model model = read_deck_string(deck, "curve.k");
  Simulation sim(model);
  const double z0 = sim.part_states().at(0).centre_of_mass.z;
  verification::run_to(sim, sim.end_time());
  const PartState block = sim.part_states()[0];
  const double pressure = block.mass * g / kArea;
  std::size_t i = 1;
  while (p[i] < pressure) ++i;
  const double expected = d[i - 1] + (pressure - p[i - 1]) / (p[i] - p[i - 1]) * (d[i] - d[i - 1]);
  const double sunk = z0 - block.centre_of_mass.z;
  const double reported = sim.contact_reports()[0].stats.max_penetration;
  const double force = sim.contact_reports()[0].stats.force.z;
  std::cout << "curve law: M g / A = " << pressure << " Pa; penetration from the block position "
            << sunk << " m, reported " << reported << " m, f^-1(M g / A) = " << expected
            << " m (sqrt(M g/(A a)) = " << std::sqrt(pressure / a) << " m), errors "
            << 100.0 * (sunk - expected) / expected << "%, "
            << 100.0 * (reported - expected) / expected << "%; contact force " << force
            << " N (M g = " << block.mass * g << " N); block speed " << block.velocity.z << " m/s; "
            << sim.cycle() << " cycles\n";
  EXPECT_NEAR(block.mass, kMass, 1e-9);
  EXPECT_NEAR(sunk, expected, 0.01 * expected);
  EXPECT_NEAR(reported, expected, 0.01 * expected);
  EXPECT_NEAR(force, block.mass * g, 0.01 * block.mass * g);
}

// ---------------------------------------------------------------------------------------------
// 6. CLEARANCE c: every point that finds a partner at t = 0 starts with the opening c instead of
// its geometric gap g0. Under gravity (no initial velocity) a block touching the plate (g0 = 0)
// with c = 0.5 mm falls freely by c before the contact acts, and so does one starting g0 = 2 mm
// above the plate (within the 10 mm detection depth, so found at t = 0): contact starts after a
// fall of exactly c, at t = sqrt(2 c / g) = 10.1 ms, and there is no force at t = 0. Checked: the
// fall at the last cycle without contact and at the first cycle with it bracket c, a bracket
// narrower than 1% of c.
//
// With c = -0.1 mm (an interference) a touching block is pushed out from the start: the force at
// t = 0 is pfac A |c| = 1000 N, and without gravity and damping the spring releases
// k c^2 / 2, so the block leaves the contact after rising |c| at |c| omega = 0.253 m/s.

struct FirstContact {
  double force_at_start = 0.0, points_at_start = 0.0;
  double fall_before = 0.0, fall_at = -1.0, time_at = -1.0, penetration_at = 0.0;
};

FirstContact fall_with_clearance(double g0, double clearance) {
  const std::string deck = block_on_plate(
      0.012, g0, one_way_contact(0.1) + "\n*CONTACT_NORMAL\n1, LINEAR, , , , " + num(clearance),
      "*CURVE\n1\n0.0, -9.81\n1.0, -9.81\n*LOAD_GRAVITY\nZ, 1");
  const Model model = read_deck_string(deck, "clearance.k");
  Simulation sim(model);
  FirstContact r;
  r.force_at_start = sim.contact_reports().at(0).stats.normal_force;
  r.points_at_start = static_cast<double>(sim.contact_reports()[0].stats.active_points);
  const double z0 = sim.part_states().at(0).centre_of_mass.z;
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    if (r.fall_at >= 0.0) return;
    const double fall = z0 - s.part_states()[0].centre_of_mass.z;
    if (s.contact_reports()[0].stats.active_points > 0) {
      r.fall_at = fall;
      r.time_at = s.time();
      r.penetration_at = s.contact_reports()[0].stats.max_penetration;
    } else {
      r.fall_before = fall;
    }
  });
  return r;
}

TEST(ContactClearance, BlockFallsByTheClearanceBeforeContactWhateverItsGap) {
  constexpr double c = 5e-4, g = 9.81;
  for (const double g0 : {0.0, 0.002}) {
    const FirstContact r = fall_with_clearance(g0, c);
    std::cout << "clearance " << c << " m, geometric gap " << g0 << " m: force at t = 0 "
              << r.force_at_start << " N; fall " << r.fall_before << " m before contact, "
              << r.fall_at << " m at the first contact (bracket "
              << 100.0 * (r.fall_at - r.fall_before) / c << "% of c) at " << r.time_at
              << " s (sqrt(2c/g) = " << std::sqrt(2.0 * c / g) << " s); penetration then "
              << r.penetration_at << " m (fall - c = " << r.fall_at - c << " m)\n";
    EXPECT_EQ(r.force_at_start, 0.0);
    EXPECT_EQ(r.points_at_start, 0.0);
    ASSERT_GE(r.fall_at, 0.0);
    EXPECT_LT(r.fall_before, c);
    EXPECT_GE(r.fall_at, c);
    EXPECT_LT(r.fall_at - r.fall_before, 0.01 * c);
    EXPECT_NEAR(r.penetration_at, r.fall_at - c, 1e-6 * c);
    EXPECT_NEAR(r.time_at, std::sqrt(2.0 * c / g), 0.01 * std::sqrt(2.0 * c / g));
  }
}

TEST(ContactClearance, NegativeClearanceIsAnInterferencePushedOutFromTheStart) {
  constexpr double c = -1e-4;
  const std::string deck = block_on_plate(
      0.002, 0.0, one_way_contact(0.0) + "\n*CONTACT_NORMAL\n1, LINEAR, , , , " + num(c), "");
  const Model model = read_deck_string(deck, "interference.k");
  Simulation sim(model);
  const double force0 = sim.contact_reports().at(0).stats.force.z;
  const double expected_force = kPfac * kArea * -c;
  const double z0 = sim.part_states().at(0).centre_of_mass.z;
  double rise_at_release = -1.0;
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    if (rise_at_release < 0.0 && s.contact_reports()[0].stats.active_points == 0)
      rise_at_release = s.part_states()[0].centre_of_mass.z - z0;
  });
  const double speed = sim.part_states()[0].velocity.z, expected_speed = -c * kOmega;
  std::cout << "clearance " << c << " m: force at t = 0 " << force0
            << " N (pfac A |c| = " << expected_force << " N), error "
            << (force0 - expected_force) / expected_force << "; released after rising "
            << rise_at_release << " m (|c| = " << -c << " m); exit speed " << speed
            << " m/s (|c| omega = " << expected_speed << " m/s), error "
            << 100.0 * (speed - expected_speed) / expected_speed << "%\n";
  EXPECT_NEAR(force0, expected_force, 1e-9 * expected_force);
  EXPECT_NEAR(speed, expected_speed, 0.01 * expected_speed);
  EXPECT_GE(rise_at_release, -c);
  EXPECT_LT(rise_at_release, -c + kStep * expected_speed * 1.01);
}

}  // namespace
}  // namespace abut
