// *CONTACT_DEPENDENCY (Metafor's TM dependencies, seed 002) in explicit runs, against elementary
// mechanics. The model is the sliding block of test_friction_laws.cpp: a rigid steel block
// 0.1 x 0.1 x 0.02 m (M = 1.56 kg, A = 0.01 m^2) on a rigid plane, pfac = 6.2e9 Pa/m (contact
// frequency about 1 kHz, far above the rates of the time functions, so each state is
// quasi-static), rotations of the block held so that the pressure stays uniform.
//  - Dragged at a constant 0.1 m/s with COEF_FROT_DYN times f(t): a sliding point carries
//    mu_d f(t) F_n (Coulomb's law of sliding friction, Meriam & Kraige, "Engineering Mechanics:
//    Statics", ch. 6), so the friction force over the normal force follows mu_d f(t) at every
//    cycle once the block slides; the energy balance holds (friction work = work of the drag).
//  - At rest on a slope tan(theta) = 0.45 with COEF_FROT_STA times f(t) falling: static friction
//    holds the block while mu_s f(t) >= tan(theta) (ibid., ch. 6, the angle of friction), so it
//    starts to slide at the t* where mu_s f(t*) = tan(theta), then accelerates at most at
//    a = g (sin(theta) - mu_d cos(theta)) (Meriam & Kraige, "Dynamics", ch. 3).
//  - Pressed by its weight with PEN_NORMALE times f(t): the pressure M g / A = pfac f(t) d, so the
//    penetration is d = M g / (A pfac f(t)).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>

#include "run_to.hpp"

namespace abut {
namespace {

constexpr double kG = 9.81, kMass = 7800.0 * 0.1 * 0.1 * 0.02, kArea = 0.01, kPfac = 6.2e9;

std::string num(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// The block (part 1) on the plane (part 2): gravity curves 1 (x) and 2 (z), the block's extra
// *BC_MOTION lines `drag` (rotations are always held), and the contact's law keywords `laws`.
std::string deck(double end, const std::string& gx, const std::string& gz, const std::string& drag,
                 const std::string& laws) {
  return "*UNIT_SYSTEM\nSI\n*TIME\n" + num(end) +
         "\n*COMPONENT_BOX\n1, 1, 2, 2, 1\n0.0, -0.05, 0.0, 0.1, 0.05, 0.02\n"
         "*COMPONENT_BOX\n2, 2, 10, 4, 1\n-0.05, -0.1, -0.02, 0.45, 0.1, 0.0\n"
         "*MAT_RIGID\n1, 7800.0\n*MAT_RIGID\n2, 7800.0\n*PART\n\"block\"\n1, 1\n\"plane\"\n2, 2\n"
         "*BC_MOTION\nP, 2, XYZ, XYZ\n*BC_MOTION\nP, 1, 0, XYZ\n" +
         drag + "*CURVE\n1\n" + gx + "\n*CURVE\n2\n" + gz +
         "\n*LOAD_GRAVITY\nX, 1\nZ, 2\n*CONTACT\n1\nP, 1, P, 2, , " + num(kPfac) + "\n" + laws +
         "*END\n";
}

std::string constant(double v) { return "0.0, " + num(v) + "\n1.0, " + num(v); }

// f(t) of the dependencies: 1 until t0, then linear to f1 at t1, then f1.
double ramp(double t, double t0, double t1, double f1) {
  if (t <= t0) return 1.0;
  if (t >= t1) return f1;
  return 1.0 + (f1 - 1.0) * (t - t0) / (t1 - t0);
}
std::string ramp_curve(int id, double t0, double t1, double f1) {
  return "*CURVE\n" + std::to_string(id) + "\n0.0, 1.0\n" + num(t0) + ", 1.0\n" + num(t1) + ", " +
         num(f1) + "\n1.0, " + num(f1) + "\n";
}

// A smooth step from 1 at t0 to f1 at t1 (1 + (f1 - 1) s^2 (3 - 2 s)), tabulated at n + 1 points:
// started with a kink, a stiffening penalty would set the pressed block ringing at its contact
// frequency with a velocity amplitude of the rate d' it starts at (m omega d' / (M g) = 0.3% for
// a linear ramp from 1 to 3 over 0.1 s). `smooth` is the curve as the deck interpolates it.
constexpr int kSmoothPoints = 40;
double smooth_node(int i, double f1) {
  const double s = static_cast<double>(i) / kSmoothPoints;
  return 1.0 + (f1 - 1.0) * s * s * (3.0 - 2.0 * s);
}
double smooth(double t, double t0, double t1, double f1) {
  if (t <= t0) return 1.0;
  if (t >= t1) return f1;
  const double x = (t - t0) / (t1 - t0) * kSmoothPoints;
  const int i = std::min(static_cast<int>(x), kSmoothPoints - 1);
  return smooth_node(i, f1) + (smooth_node(i + 1, f1) - smooth_node(i, f1)) * (x - i);
}
std::string smooth_curve(int id, double t0, double t1, double f1) {
  std::string c = "*CURVE\n" + std::to_string(id) + "\n0.0, 1.0\n";
  for (int i = 0; i <= kSmoothPoints; ++i)
    c += num(t0 + (t1 - t0) * i / kSmoothPoints) + ", " + num(smooth_node(i, f1)) + "\n";
  return c + "1.0, " + num(f1) + "\n";
}

TEST(ContactDependency, DraggedBlockCarriesTimeDependentDynamicFriction) {
  const double mu_s = 0.6, mu_d = 0.4, t0 = 0.02, t1 = 0.1, f1 = 0.5, end = 0.1;
  const std::string laws = "*CONTACT_FRICTION\n1, COULOMB, 0.6, 0.4\n" + ramp_curve(5, t0, t1, f1) +
                           "*CONTACT_DEPENDENCY\n1\nMU_D, TIME, 5\n";
  const std::string drag = "V, X, 3\n*CURVE\n3\n" + constant(0.1) + "\n";
  const Model model =
      read_deck_string(deck(end, constant(0.0), constant(-kG), drag, laws), "drag_mu_d.k");
  Simulation sim(model);
  double worst = 0.0, worst_balance = 0.0;
  int samples = 0;
  verification::run_to(sim, end, [&](const Simulation& s) {
    const ContactStats& c = s.contact_reports()[0].stats;
    const double expected = std::min(mu_d * ramp(s.time(), t0, t1, f1), mu_s);
    if (s.time() > 0.01 && c.normal_force > 0.0) {
      worst = std::max(worst, std::abs(c.tangential_force / c.normal_force - expected) / expected);
      ++samples;
    }
    const Energies e = s.energies();
    if (std::max(std::abs(e.total()), std::abs(e.external_work)) > 1e-6)
      worst_balance = std::max(worst_balance, std::abs(s.energy_balance_error()));
  });
  std::cout << "drag, mu_d(t): largest |F_t/F_n - mu_d f(t)| / (mu_d f(t)) = " << worst << " over "
            << samples << " cycles; energy balance " << worst_balance << "\n";
  EXPECT_GT(samples, 100);
  EXPECT_LT(worst, 1e-6);
  EXPECT_LT(worst_balance, 0.01);
}

TEST(ContactDependency, BlockOnSlopeBreaksAwayWhenStaticFrictionFallsBelowTanTheta) {
  // tan(theta) = 0.45; mu_s f(t) = 0.6 f(t) with f from 1 at 0.05 s to 0.5 at 0.15 s reaches
  // 0.45 at t* = 0.05 + 0.1 (0.25 / 0.5) = 0.1 s. mu_d = 0.2. The slope is tilted gradually
  // between 0.02 and 0.04 s (test_friction_laws.cpp, tilt_curve). After t* the friction lies
  // between mu_d N and mu_s(t) N, mu_s(t) = tan(theta) - 3 (t - t*), so the distance slid since t*
  // lies between the closed forms
  //   lower (friction at mu_s(t)): g cos(theta) 3 tau^3 / 6,
  //   upper (friction at mu_d):    g (sin(theta) - mu_d cos(theta)) tau^2 / 2,   tau = t - t*,
  // and the block passes 1e-6 m between the times these give for it (0.95 and 6.1 ms after t*).
  const double theta = std::atan(0.45), t_star = 0.1, end = 0.12, mu_d = 0.2;
  const double gx = kG * std::sin(theta), gz = -kG * std::cos(theta);
  const std::string tilt = "0.0, 0.0\n0.02, 0.0\n0.04, " + num(gx) + "\n1.0, " + num(gx);
  const std::string laws = "*CONTACT_FRICTION\n1, COULOMB, 0.6, 0.2\n" +
                           ramp_curve(5, 0.05, 0.15, 0.5) +
                           "*CONTACT_DEPENDENCY\n1\nCOEF_FROT_STA, TM, 5\n";
  const Model model = read_deck_string(deck(end, tilt, constant(gz), "", laws), "slope_mu_s.k");
  Simulation sim(model);
  double x_ref = 0.0, moved_before = 0.0, breakaway = -1.0;
  verification::run_to(sim, end, [&](const Simulation& s) {
    const double x = s.part_states()[0].centre_of_mass.x;
    if (s.time() <= 0.05) x_ref = x;
    if (s.time() <= 0.05) return;
    if (s.time() < t_star) moved_before = std::max(moved_before, std::abs(x - x_ref));
    if (breakaway < 0.0 && x - x_ref > 1e-6) breakaway = s.time();
  });
  const double slid = sim.part_states()[0].centre_of_mass.x - x_ref, tau = end - t_star;
  const double a_d = kG * (std::sin(theta) - mu_d * std::cos(theta));
  const double rate = 3.0 * kG * std::cos(theta);  // d/dt of (tan(theta) - mu_s(t)) g cos(theta)
  const double most = 0.5 * a_d * tau * tau, least = rate * tau * tau * tau / 6.0;
  const double earliest = t_star + std::sqrt(2e-6 / a_d), latest = t_star + std::cbrt(6e-6 / rate);
  std::cout << "slope, mu_s(t): moved " << moved_before << " m before t*, passed 1e-6 m at "
            << breakaway << " s (closed forms: " << earliest << " to " << latest << "), slid "
            << slid << " m by " << end << " s (closed forms: " << least << " to " << most << ")\n";
  EXPECT_LT(moved_before, 1e-8);
  EXPECT_GE(breakaway, earliest);
  EXPECT_LE(breakaway, latest);
  EXPECT_LE(slid, most);
  EXPECT_GE(slid, least);
}

TEST(ContactDependency, PressedBlockPenetrationFollowsTimeDependentPenalty) {
  // f(t) = 1 until 0.05 s, then a smooth step to 3 at 0.15 s. The block starts touching, so its
  // sink is the penetration (test_contact_nonmatching.cpp): d = M g / (A pfac f(t)) once the
  // set-down has rung out (from 0.04 s). The rate d' adds the damping force 2 xi sqrt(k M) d',
  // at most 2.4e-4 of M g here.
  const double t0 = 0.05, t1 = 0.15, f1 = 3.0, end = 0.15;
  const std::string laws = "*CONTACT_FRICTION\n1, NONE\n" + smooth_curve(5, t0, t1, f1) +
                           "*CONTACT_DEPENDENCY\n1\nPFAC, TIME, 5\n";
  const Model model =
      read_deck_string(deck(end, constant(0.0), constant(-kG), "", laws), "press_pfac.k");
  Simulation sim(model);
  const double z0 = sim.part_states()[0].centre_of_mass.z;
  double worst = 0.0, reported = 0.0;
  int samples = 0;
  verification::run_to(sim, end, [&](const Simulation& s) {
    if (s.time() < 0.04) return;
    const double d = kMass * kG / (kArea * kPfac * smooth(s.time(), t0, t1, f1));
    const double sink = z0 - s.part_states()[0].centre_of_mass.z;
    worst = std::max(worst, std::abs(sink - d) / d);
    reported = std::max(reported, s.contact_reports()[0].stats.max_penetration / d);
    ++samples;
  });
  std::cout << "pressed block, pfac(t): largest |sink - M g / (A pfac f(t))| / d = " << worst
            << " over " << samples << " cycles; largest max_penetration / d " << reported << "\n";
  EXPECT_GT(samples, 100);
  EXPECT_LT(worst, 1e-3);
}

TEST(ContactDependency, StuckBlockHoldsSidewaysLoadOnGapDependentTangentialPenalty) {
  // STICK with pen_t = 1e9 Pa/m times g(d) = 1 + 2e6 d (a *FUNCTION of the penetration): resting
  // under its weight the block sinks d = M g / (A pfac) = 2.47e-7 m, so g = 1.49. A sideways
  // gravity g_x = 2 m/s^2 applied gradually once it rests (0.02 to 0.04 s) then stretches the
  // tangential springs, k_t = pen_t g(d) A in all, by u = M g_x / (pen_t g(d) A) (a linear
  // spring under a static load; the spring is loaded at the settled d).
  const double pen_t = 1e9, gx = 2.0, end = 0.1;
  const double d = kMass * kG / (kArea * kPfac), g = 1.0 + 2e6 * d;
  const std::string laws =
      "*CONTACT_FRICTION\n1, STICK, , , " + num(pen_t) +
      "\n*FUNCTION\n5\n1.0 + 2.0e6 * t\n*CONTACT_DEPENDENCY\n1\nPEN_T, GAP, 5\n";
  const std::string tilt = "0.0, 0.0\n0.02, 0.0\n0.04, " + num(gx) + "\n1.0, " + num(gx);
  const Model model = read_deck_string(deck(end, tilt, constant(-kG), "", laws), "stick_gd.k");
  Simulation sim(model);
  double x_ref = 0.0;
  verification::run_to(sim, end, [&](const Simulation& s) {
    if (s.time() <= 0.02) x_ref = s.part_states()[0].centre_of_mass.x;
  });
  const double u = sim.part_states()[0].centre_of_mass.x - x_ref;
  const double expected = kMass * gx / (pen_t * g * kArea);
  std::cout << "stuck block, k_t(d): stretch " << u << " m, M g_x / (pen_t g(d) A) = " << expected
            << " (g(d) = " << g << "), relative error " << (u - expected) / expected << "\n";
  EXPECT_NEAR(u, expected, 0.01 * expected);
}

// TRESCA's shear yield stress in time (K, TIME; Metafor's TRESCA_K, which seed 002 gives no
// dependency, abut allows TIME): the block dragged at 0.1 m/s slides at the Tresca limit m k f(t) A
// whatever its pressure (Metafor's TrescaContactMaterial), m = 1, k = 1000 Pa (10 N on 0.01 m^2,
// two thirds of the weight), f from 1 at 0.02 s to 0.5 at 0.1 s: the friction force follows
// m k f(t) A at every cycle once the block slides, as the Coulomb case above.
TEST(ContactDependency, DraggedBlockSlidesAtATimeDependentTrescaLimit) {
  const double m = 1.0, k = 1000.0, t0 = 0.02, t1 = 0.1, f1 = 0.5, end = 0.1;
  const std::string laws = "*CONTACT_FRICTION\n1, TRESCA, 1.0, 1.0\n" + num(k) + "\n" +
                           ramp_curve(5, t0, t1, f1) + "*CONTACT_DEPENDENCY\n1\nK, TIME, 5\n";
  const std::string drag = "V, X, 3\n*CURVE\n3\n" + constant(0.1) + "\n";
  const Model model =
      read_deck_string(deck(end, constant(0.0), constant(-kG), drag, laws), "drag_tresca_k.k");
  Simulation sim(model);
  double worst = 0.0;
  int samples = 0;
  verification::run_to(sim, end, [&](const Simulation& s) {
    const ContactStats& c = s.contact_reports()[0].stats;
    const double expected = m * k * ramp(s.time(), t0, t1, f1) * kArea;
    if (s.time() > 0.01 && c.normal_force > 0.0) {
      worst = std::max(worst, std::abs(c.tangential_force - expected) / expected);
      ++samples;
    }
  });
  std::cout << "drag, Tresca k(t): largest |F_t - m k f(t) A| / (m k f(t) A) = " << worst
            << " over " << samples << " cycles\n";
  EXPECT_GT(samples, 100);
  EXPECT_LT(worst, 1e-6);
}

// The tangential penalty in time (PEN_T, TIME; Metafor's PEN_TANGENT with TM): STICK with
// pen_t = 1e9 Pa/m doubled by f(t) (a smooth step from 1 at 5 ms to 2 at 15 ms, before any
// sideways load), then the sideways gravity g_x = 2 m/s^2 applied from 0.02 to 0.04 s stretches
// the springs, k_t = 2 pen_t A in all, by u = M g_x / (2 pen_t A) (a linear spring under a static
// load), held to 1% as the gap-dependent case above.
TEST(ContactDependency, StuckBlockHoldsSidewaysLoadOnTimeDependentTangentialPenalty) {
  const double pen_t = 1e9, gx = 2.0, end = 0.1;
  const std::string laws = "*CONTACT_FRICTION\n1, STICK, , , " + num(pen_t) + "\n" +
                           smooth_curve(5, 0.005, 0.015, 2.0) +
                           "*CONTACT_DEPENDENCY\n1\nPEN_T, TIME, 5\n";
  const std::string tilt = "0.0, 0.0\n0.02, 0.0\n0.04, " + num(gx) + "\n1.0, " + num(gx);
  const Model model = read_deck_string(deck(end, tilt, constant(-kG), "", laws), "stick_tm.k");
  Simulation sim(model);
  double x_ref = 0.0;
  verification::run_to(sim, end, [&](const Simulation& s) {
    if (s.time() <= 0.02) x_ref = s.part_states()[0].centre_of_mass.x;
  });
  const double u = sim.part_states()[0].centre_of_mass.x - x_ref;
  const double expected = kMass * gx / (2.0 * pen_t * kArea);
  std::cout << "stuck block, k_t(t): stretch " << u << " m, M g_x / (2 pen_t A) = " << expected
            << ", relative error " << (u - expected) / expected << "\n";
  EXPECT_NEAR(u, expected, 0.01 * expected);
}

// A dependency with nothing to act on is an error at its row, not ignored.
TEST(ContactDependency, DependencyWithoutItsParameterIsALocatedError) {
  const auto read = [](const std::string& laws) {
    return read_deck_string(deck(0.01, constant(0.0), constant(-kG), "", laws), "errors.k");
  };
  const std::string curve = ramp_curve(5, 0.1, 0.5, 0.5);
  for (const std::string& laws :
       {"*CONTACT_FRICTION\n1, STICK\n" + curve + "*CONTACT_DEPENDENCY\n1\nMU_D, TIME, 5\n",
        "*CONTACT_FRICTION\n1, NONE\n" + curve + "*CONTACT_DEPENDENCY\n1\nPEN_T, GAP, 5\n",
        "*CONTACT_FRICTION\n1, COULOMB, 0.3\n" + curve + "*CONTACT_DEPENDENCY\n1\nK, TIME, 5\n",
        curve + "*CONTACT_DEPENDENCY\n1\nPFAC, GAP, 5\n",
        curve + "*CONTACT_DEPENDENCY\n1\nMU_S, GAP, 5\n",
        curve + "*CONTACT_DEPENDENCY\n1\nPFAC, TIME, 5\nPFAC, TIME, 5\n"}) {
    try {
      read(laws);
      ADD_FAILURE() << "no error for:\n" << laws;
    } catch (const InputError& e) {
      const std::string what = e.what();
      std::cout << what << "\n";
      EXPECT_NE(what.find("errors.k:"), std::string::npos);
    }
  }
}

}  // namespace
}  // namespace abut
