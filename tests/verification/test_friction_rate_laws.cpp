// *CONTACT_FRICTION laws that depend on the contact pressure p and the sliding speed V (Radioss
// /INTER/TYPE25 Ifric = 1 generalised viscous, Ifric = 2 Darmstad and Ifric = 3 Renard), and the
// friction filter (Ifiltr), at prescribed sliding: the formulas of seed 004 (comments 7 and 8), as
// decoded in
// ../shared/seeds/README.md, written out here (not taken from the library).
//
// Model: a rigid steel block 0.1 x 0.1 x 0.02 m (2 x 2 x 1 elements, M = 1.56 kg, A = 0.01 m^2)
// on a fixed rigid plane (10 x 4 elements), pfac = 6.2e9 Pa/m (contact frequency about 1 kHz).
// The block is dragged along x at a constant speed V (*INITIAL_VELOCITY and *BC_MOTION velocity),
// with y and its rotations held, so its pressure stays uniform. One way contact (one_way = 1):
// only the block's points act, each with p = its normal force / its area and V = |v_t|, so the
// uniform pressure is exactly p = N / A.
//
// Laws: the block hangs on the plane under gravity, N = M g, p = M g / A = 1530 Pa; after the
// contact's vertical transient (damped by xi = 0.1: time constant 1/(xi omega) = 1.6 ms, 30 ms
// allowed) the mean tangential / normal contact force is mu(p, V).
//
// Filter: the block starts pressed into the plane by d = 1 um (*CONTACT_INITIAL FORCE) and is
// held there, so the normal force pfac A d = 62 N acts from the first cycle, while it slides
// from t = 0: the unfiltered force is mu F_n at every cycle, and the filtered force starts at
// zero and follows F_n = F_ss (1 - (1 - a)^n) after n cycles (a first-order filter's step
// response); with a = 2 pi f_c dt small, F(t) = F_ss (1 - exp(-2 pi f_c t)).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <numbers>
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

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The block dragged at speed v along x, its bottom at z = -depth; `gravity`: pressed by its
// weight (z free), else held at z (normal force from the initial penetration).
std::string dragged_block_deck(double end_time, double v, double depth, bool gravity,
                               const std::string& friction, const std::string& extra = "") {
  return R"(
*UNIT_SYSTEM
SI
*TIME
)" + num(end_time) +
         R"(
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, -0.05, )" +
         num(-depth) + ", 0.1, 0.05, " + num(0.02 - depth) + R"(
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
         num(v) +
         R"(, 0.0, 0.0
*CURVE
1
0.0, )" + num(v) +
         R"(
1.0, )" + num(v) +
         R"(
*BC_MOTION
P, 1, )" +
         (gravity ? "Y" : "YZ") +
         R"(, XYZ
V, X, 1
*BC_MOTION
P, 2, XYZ, XYZ
*CURVE
2
0.0, -9.81
1.0, -9.81
)" + (gravity ? "*LOAD_GRAVITY\nZ, 2\n" : "") +
         R"(*CONTACT
"dragged block"
1
P, 1, P, 2, , )" +
         num(kPfac) + R"(
0, 0.1
, , , , 1
*CONTACT_FRICTION
)" + friction +
         "\n" + extra + "*END\n";
}

// Mean -F_x / F_z of the contact force on the block over [t_from, t_to] (ratio of the means);
// `normal`: the mean F_z there.
double dragged_mu(double v, const std::string& friction, std::int64_t& cycles, double& normal) {
  constexpr double t_from = 0.03, t_to = 0.04;
  const Model model = read_deck_string(dragged_block_deck(t_to, v, 0.0, true, friction), "drag.k");
  Simulation sim(model);
  double fx = 0.0, fz = 0.0;
  int n = 0;
  verification::run_to(sim, t_to, [&](const Simulation& s) {
    if (s.time() < t_from) return;
    fx += s.contact_reports()[0].stats.force.x;
    fz += s.contact_reports()[0].stats.force.z;
    ++n;
  });
  cycles += sim.cycle();
  normal = fz / n;
  return -fx / fz;
}

// Renard (Ifric = 3): C1 = mu_s, C2 = mu_d, C3 = mu_max, C4 = mu_min, C5 = Vcr1, C6 = Vcr2.
constexpr double kC[6] = {0.2, 0.15, 0.3, 0.1, 0.5, 2.0};
double renard_mu(double v) {
  if (v <= kC[4]) return kC[0] + (kC[2] - kC[0]) * (v / kC[4]) * (2.0 - v / kC[4]);
  if (v <= kC[5]) {
    const double s = (v - kC[4]) / (kC[5] - kC[4]);
    return kC[2] - (kC[2] - kC[3]) * s * s * (3.0 - 2.0 * s);
  }
  return kC[1] - 1.0 / (1.0 / (kC[1] - kC[3]) + (v - kC[5]) * (v - kC[5]));
}

TEST(FrictionRenard, MeasuredCoefficientFollowsTheLawAtPrescribedSpeeds) {
  const auto start = std::chrono::steady_clock::now();
  std::string friction = "1, RENARD\n";
  for (int i = 0; i < 6; ++i) friction += (i ? ", " : "") + num(kC[i]);
  std::int64_t cycles = 0;
  double normal = 0.0;
  // Two speeds in each branch: rising [0, Vcr1], falling [Vcr1, Vcr2], recovering > Vcr2.
  for (const double v : {0.1, 0.35, 0.9, 1.6, 2.5, 4.0}) {
    const double mu = dragged_mu(v, friction, cycles, normal), expected = renard_mu(v);
    std::cout << "Renard: V = " << v << " m/s: F_t / F_n = " << mu << ", mu(V) = " << expected
              << ", error " << 100.0 * (mu - expected) / expected << "%\n";
    EXPECT_NEAR(mu, expected, 0.01 * expected) << "V = " << v;
  }
  std::cout << "Renard: " << cycles << " cycles, " << seconds_since(start) << " s\n";
}

// Darmstad (Ifric = 2): mu = Fric + C1 exp(C2 V) p^2 + C3 exp(C4 V) p + C5 exp(C6 V); each term
// is a sizeable share of mu at p = 1530 Pa.
constexpr double kFric = 0.1, kD[6] = {2.0e-8, -0.5, 5.0e-5, -1.0, 0.1, -2.0};
double darmstad_mu(double p, double v) {
  return kFric + kD[0] * std::exp(kD[1] * v) * p * p + kD[2] * std::exp(kD[3] * v) * p +
         kD[4] * std::exp(kD[5] * v);
}

// The dragged block's F_t / F_n at 0.1, 0.5 and 1.5 m/s on the law `friction` (the
// *CONTACT_FRICTION lines) against mu(p, V) of its formula `mu_of`, to 1%, and its normal force
// M g to 1e-4.
template <class Mu>
void expect_law_at_speeds(const std::string& name, const std::string& friction, Mu mu_of) {
  const auto start = std::chrono::steady_clock::now();
  const double p = kMass * kG / kArea;
  std::int64_t cycles = 0;
  for (const double v : {0.1, 0.5, 1.5}) {
    double normal = 0.0;
    const double mu = dragged_mu(v, friction, cycles, normal), expected = mu_of(p, v);
    std::cout << name << ": p = " << p << " Pa (measured F_n / A = " << normal / kArea
              << " Pa), V = " << v << " m/s: F_t / F_n = " << mu << ", mu(p, V) = " << expected
              << ", error " << 100.0 * (mu - expected) / expected << "%\n";
    EXPECT_NEAR(mu, expected, 0.01 * expected) << name << ", V = " << v;
    EXPECT_NEAR(normal, kMass * kG, 1e-4 * kMass * kG) << name << ", V = " << v;
  }
  std::cout << name << ": " << cycles << " cycles, " << seconds_since(start) << " s\n";
}

TEST(FrictionDarmstad, MeasuredCoefficientFollowsTheLawAtPrescribedSpeeds) {
  std::string friction = "1, DARMSTAD, " + num(kFric) + "\n";
  for (int i = 0; i < 6; ++i) friction += (i ? ", " : "") + num(kD[i]);
  expect_law_at_speeds("Darmstad", friction, darmstad_mu);
}

// Generalised viscous law (Ifric = 1): mu = Fric + C1 p + C2 V + C3 p V + C4 p^2 + C5 V^2; each
// term a sizeable share of mu at p = 1530 Pa and the speeds below.
constexpr double kViscousFric = 0.1, kV[5] = {5.0e-5, 0.1, 2.0e-5, 2.0e-8, 0.05};
double viscous_mu(double p, double v) {
  return kViscousFric + kV[0] * p + kV[1] * v + kV[2] * p * v + kV[3] * p * p + kV[4] * v * v;
}

TEST(FrictionViscous, MeasuredCoefficientFollowsTheLawAtPrescribedSpeeds) {
  std::string friction = "1, VISCOUS, " + num(kViscousFric) + "\n";
  for (int i = 0; i < 5; ++i) friction += (i ? ", " : "") + num(kV[i]);
  expect_law_at_speeds("viscous", friction, viscous_mu);
}

// The filter's step response: Coulomb mu = 0.3 at V = 0.5 m/s. `check(n, t, f)` gets the
// filtered tangential force f / F_ss after n cycles, at time t.
constexpr double kDepth = 1.0e-6, kMuFilter = 0.3, kVFilter = 0.5;

template <class Check>
void filtered_start(const std::string& filter, double end, Check check) {
  const std::string friction =
      "1, COULOMB, " + num(kMuFilter) + ", " + num(kMuFilter) + ", , " + filter;
  const Model model = read_deck_string(
      dragged_block_deck(end, kVFilter, kDepth, false, friction, "*CONTACT_INITIAL\n1, FORCE\n"),
      "filter.k");
  Simulation sim(model);
  const double normal = kPfac * kArea * kDepth;
  double worst_normal = 0.0;
  verification::run_to(sim, end, [&](const Simulation& s) {
    const Vec3 f = s.contact_reports()[0].stats.force;
    worst_normal = std::max(worst_normal, std::abs(f.z - normal) / normal);
    check(s.cycle(), s.time(), -f.x / (kMuFilter * f.z));
  });
  std::cout << "  normal force pfac A d = " << normal << " N within " << worst_normal
            << " (relative); " << sim.cycle()
            << " cycles, dt = " << sim.time() / static_cast<double>(sim.cycle()) << " s\n";
  EXPECT_LT(worst_normal, 1e-6);
}

TEST(FrictionFilter, SimpleFilterFollowsTheFirstOrderResponsePerCycle) {
  // Ifiltr = 1, a = xfreq = 0.05: F(n) = F_ss (1 - 0.95^n).
  const auto start = std::chrono::steady_clock::now();
  constexpr double a = 0.05;
  int checked = 0;
  double worst = 0.0;
  filtered_start("1, " + num(a), 0.01, [&](std::int64_t n, double, double f) {
    const double expected = 1.0 - std::pow(1.0 - a, static_cast<double>(n));
    worst = std::max(worst, std::abs(f - expected));
    if (n == 1 || n == 5 || n == 10 || n == 20 || n == 50 || n == 100) {
      std::cout << "filter 1: cycle " << n << ": F / F_ss = " << f
                << ", 1 - (1 - a)^n = " << expected << ", error " << 100.0 * (f - expected)
                << "% of F_ss\n";
      ++checked;
    }
  });
  std::cout << "filter 1: largest error over all cycles " << 100.0 * worst << "% of F_ss; "
            << seconds_since(start) << " s\n";
  EXPECT_EQ(checked, 6);
  EXPECT_LT(worst, 0.01);
}

TEST(FrictionFilter, FrequencyAndPeriodFiltersFollowTheFirstOrderResponseInTime) {
  // Ifiltr = 3 with f_c = 5 Hz, and Ifiltr = 2 with the period T = 1 / f_c = 0.2 s: a = 2 pi f_c
  // dt is about 2e-3, F(t) = F_ss (1 - exp(-2 pi f_c t)), time constant 32 ms.
  const auto start = std::chrono::steady_clock::now();
  constexpr double fc = 5.0, end = 0.1;
  for (const std::string& filter : {"3, " + num(fc), std::string("2, 0.2")}) {
    double worst = 0.0;
    std::size_t next = 0;
    constexpr double times[] = {0.005, 0.01, 0.02, 0.04, 0.08};
    filtered_start(filter, end, [&](std::int64_t, double t, double f) {
      const double expected = 1.0 - std::exp(-2.0 * std::numbers::pi * fc * t);
      worst = std::max(worst, std::abs(f - expected));
      if (next < std::size(times) && t >= times[next]) {
        std::cout << "filter " << filter << ": t = " << t << " s: F / F_ss = " << f
                  << ", 1 - exp(-2 pi fc t) = " << expected << ", error " << 100.0 * (f - expected)
                  << "% of F_ss\n";
        EXPECT_NEAR(f, expected, 0.01) << "filter " << filter << ", t = " << t;
        ++next;
      }
    });
    std::cout << "filter " << filter << ": largest error over all cycles " << 100.0 * worst
              << "% of F_ss\n";
    EXPECT_EQ(next, std::size(times));
    EXPECT_LT(worst, 0.01);
  }
  std::cout << "filters 2 and 3: " << seconds_since(start) << " s\n";
}

}  // namespace
}  // namespace abut
