// The contact laws called alone, each against a reference written out in the test from the seed
// formulas (never by calling the code under test):
//   seed 004 = ../shared/seeds/004_5ae881f05f7a02ff.clean.txt (Radioss /INTER/TYPE25), decoded in
//              ../shared/seeds/README.md;
//   seed 002 = ../shared/seeds/002_eae778be99fda782.txt (Metafor contact materials);
//   seed 000 = ../shared/seeds/000_d01a334eb94119ef.txt (IMPETUS *CONTACT).
// Tolerances: kRoundOff (1e-12 relative) where the code and the reference do the same arithmetic
// in a different order; looser, stated values where the code approximates (numerical slope).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <variant>

#include "abut/contact/laws/adhesion.hpp"
#include "abut/contact/laws/friction_model.hpp"
#include "abut/contact/laws/normal.hpp"
#include "abut/contact/laws/tangential.hpp"
#include "abut/core/vec3.hpp"

namespace abut {
namespace {

constexpr double kRoundOff = 1e-12;  // relative
constexpr double kInf = std::numeric_limits<double>::infinity();

// Absolute tolerance for a relative one around an expected value.
double rel(double expected, double tol = kRoundOff) { return tol * std::abs(expected); }

void expect_vec_near(const Vec3& actual, const Vec3& expected, double tol) {
  EXPECT_NEAR(actual.x, expected.x, tol);
  EXPECT_NEAR(actual.y, expected.y, tol);
  EXPECT_NEAR(actual.z, expected.z, tol);
}

// ---------------------------------------------------------------------------------------------
// Normal laws
// ---------------------------------------------------------------------------------------------

// Seed 000 / seed 002 (PEN_NORMALE): p = pfac d; dp/dd = pfac; energy = int_0^d pfac x dx
// = pfac d^2 / 2 (also for d < 0, bilateral: the energy stays positive). Tolerance: round-off.
TEST(LinearPenalty, PressureStiffnessAndEnergy) {
  const double pfac = 2.5e12;
  for (const double d : {0.0, 1e-6, 3.7e-4, -2e-5}) {
    const NormalResponse r = LinearPenalty{}.evaluate(d, pfac);
    EXPECT_NEAR(r.pressure, pfac * d, rel(pfac * d)) << "d = " << d;
    EXPECT_NEAR(r.stiffness, pfac, rel(pfac)) << "d = " << d;
    EXPECT_NEAR(r.energy, pfac * d * d / 2.0, rel(pfac * d * d / 2.0)) << "d = " << d;
    EXPECT_GE(r.energy, 0.0);
    // The variant dispatcher gives the same response.
    const NormalResponse v = evaluate(NormalLaw{LinearPenalty{}}, d, pfac);
    EXPECT_EQ(v.pressure, r.pressure);
    EXPECT_EQ(v.stiffness, r.stiffness);
    EXPECT_EQ(v.energy, r.energy);
  }
  // Literal spot value: 2.5e12 Pa/m * 3.7e-4 m = 9.25e8 Pa, energy 0.5 * 2.5e12 * 1.369e-7 J/m^2.
  const NormalResponse r = LinearPenalty{}.evaluate(3.7e-4, pfac);
  EXPECT_NEAR(r.pressure, 9.25e8, rel(9.25e8));
  EXPECT_NEAR(r.energy, 171125.0, rel(171125.0));
}

// Seed 002 (FrictionlessVariablePenaltyContactMaterial: PEN_NORMALE a function of the gap), with
// the curve f(d) = a d + b d^3, applied as an odd function f(-d) = -f(d) (normal.hpp):
//   pressure  p(d) = sign(d) f(|d|)                                   tolerance: round-off
//   slope     dp/dd = f'(|d|) = a + 3 b d^2  (the code differentiates numerically; a central
//             difference of step 1e-4 |d| errs by b h^2 <= 3e-9 relative)  tolerance: 1e-6 rel.
//   energy    int_0^|d| f = a d^2/2 + b d^4/4 (Simpson is exact for a cubic) tolerance: 1e-12 rel.
TEST(CurvePenalty, CubicCurvePressureSlopeEnergyAndOddExtension) {
  const double a = 3e9, b = 7e17;
  const CurvePenalty law{[=](double x) { return a * x + b * x * x * x; }};
  for (const double d : {2e-4, 1e-5, 1.3e-3, -2e-4, -7e-4}) {
    const double m = std::abs(d);
    const double sign = d < 0.0 ? -1.0 : 1.0;
    const double p_ref = sign * (a * m + b * m * m * m);
    const double k_ref = a + 3.0 * b * m * m;
    const double e_ref = a * m * m / 2.0 + b * m * m * m * m / 4.0;
    const NormalResponse r = law.evaluate(d, /*pfac unused*/ 123.0);
    EXPECT_NEAR(r.pressure, p_ref, rel(p_ref)) << "d = " << d;
    EXPECT_NEAR(r.stiffness, k_ref, rel(k_ref, 1e-6)) << "d = " << d;
    EXPECT_NEAR(r.energy, e_ref, rel(e_ref)) << "d = " << d;
    const NormalResponse v = evaluate(NormalLaw{law}, d, 123.0);
    EXPECT_EQ(v.pressure, r.pressure);
    EXPECT_EQ(v.energy, r.energy);
  }
  // Odd extension: p(-d) = -p(d), equal slope and (positive) energy.
  const NormalResponse plus = law.evaluate(4e-4, 0.0), minus = law.evaluate(-4e-4, 0.0);
  EXPECT_EQ(minus.pressure, -plus.pressure);
  EXPECT_NEAR(minus.stiffness, plus.stiffness, rel(plus.stiffness));
  EXPECT_EQ(minus.energy, plus.energy);
  // Literal spot value at d = 2e-4: p = 6e5 + 5.6e6 = 6.2e6;
  // E = 3e9 * 4e-8 / 2 + 7e17 * 1.6e-15 / 4 = 60 + 280 = 340.
  const NormalResponse r = law.evaluate(2e-4, 0.0);
  EXPECT_NEAR(r.pressure, 6.2e6, rel(6.2e6));
  EXPECT_NEAR(r.energy, 340.0, rel(340.0));
  // At d = 0: no pressure, no energy, slope f'(0) = a (one-sided difference).
  const NormalResponse zero = law.evaluate(0.0, 0.0);
  EXPECT_EQ(zero.pressure, 0.0);
  EXPECT_EQ(zero.energy, 0.0);
  EXPECT_NEAR(zero.stiffness, a, rel(a, 1e-6));
}

// ---------------------------------------------------------------------------------------------
// return_to_limit: seed 004 comment 7, F_t,new = min(mu F_n, |F_adh|) with the elastic predictor
// F_adh = F_t,old + dF, dF = -k V_t dt (the sign: the force opposes the slip), projected back on
// the limit along F_adh's direction; slip increment (|F_adh| - limit) / k, slip work = limit times
// slip increment. Static/dynamic limits: seed 002 (CoulombContactMaterial, COEF_FROT_STA sets the
// largest tangential force before sliding, COEF_FROT_DYN the sliding force).
// ---------------------------------------------------------------------------------------------

const Vec3 kNormalZ{0.0, 0.0, 1.0};
constexpr double kTangentialK = 1000.0, kDt = 1e-3;  // k dt = 1
const SlipLimits kLimits{10.0, 6.0};                 // stick (static) 10, slide (dynamic) 6

TEST(ReturnToLimit, StickingInsideTheLimitKeepsTheExactTrialForce) {
  // previous (10, -4, 7): its normal component 7 is dropped; trial = (10, -4, 0) - (3, 1, 0) * 1.
  const TangentialResult r = return_to_limit({10.0, -4.0, 7.0}, kNormalZ, {3.0, 1.0, 0.0}, kDt,
                                             kTangentialK, kLimits, /*was_sliding=*/false);
  // |(7, -5, 0)| = sqrt(74) = 8.60 <= 10 (static): sticks, the trial force exactly.
  EXPECT_FALSE(r.sliding);
  expect_vec_near(r.force, {7.0, -5.0, 0.0}, 1e-12);
  EXPECT_EQ(r.slip_work, 0.0);
}

TEST(ReturnToLimit, ASlidingPointIsHeldAgainstTheDynamicLimit) {
  // Same trial (7, -5, 0), |trial| = sqrt(74) > 6 (dynamic): slides, F = 6 trial / |trial|.
  const TangentialResult r = return_to_limit({10.0, -4.0, 7.0}, kNormalZ, {3.0, 1.0, 0.0}, kDt,
                                             kTangentialK, kLimits, /*was_sliding=*/true);
  const double size = std::sqrt(74.0);
  EXPECT_TRUE(r.sliding);
  expect_vec_near(r.force, Vec3{7.0, -5.0, 0.0} * (6.0 / size), 1e-12);
  EXPECT_NEAR(norm(r.force), 6.0, rel(6.0));
  // Slip work = limit * (|trial| - limit) / k = 6 (sqrt(74) - 6) / 1000 = 0.0156139516...
  const double work = 6.0 * (size - 6.0) / kTangentialK;
  EXPECT_NEAR(r.slip_work, work, rel(work));
  EXPECT_NEAR(r.slip_work, 0.01561395160225576, 1e-15);
}

TEST(ReturnToLimit, BreakingTheStaticLimitSlidesOnTheDynamicOne) {
  // trial = (10, -4, 0) - (-8, 5, 0) = (18, -9, 0), |trial| = sqrt(405) = 20.12 > 10 (static).
  const TangentialResult r = return_to_limit({10.0, -4.0, 7.0}, kNormalZ, {-8.0, 5.0, 0.0}, kDt,
                                             kTangentialK, kLimits, /*was_sliding=*/false);
  const double size = std::sqrt(405.0);
  EXPECT_TRUE(r.sliding);
  expect_vec_near(r.force, Vec3{18.0, -9.0, 0.0} * (6.0 / size), 1e-12);
  const double work = 6.0 * (size - 6.0) / kTangentialK;
  EXPECT_NEAR(r.slip_work, work, rel(work));
}

TEST(ReturnToLimit, ForceOnTheLimitStillSticks) {
  // |(3, 4, 0)| = 5 exactly against a static limit of 5: min(mu F_n, |F_adh|) is F_adh.
  const TangentialResult r =
      return_to_limit({3.0, 4.0, 0.0}, kNormalZ, {}, kDt, kTangentialK, {5.0, 2.0}, false);
  EXPECT_FALSE(r.sliding);
  expect_vec_near(r.force, {3.0, 4.0, 0.0}, 0.0);
}

TEST(ReturnToLimit, NormalComponentOfThePreviousForceIsRemoved) {
  // A tilted normal n = (1, 1, 1)/sqrt(3); no slip, no limit: the force is the tangential part of
  // previous, F = P - n (n . P).
  const Vec3 n = normalized({1.0, 1.0, 1.0});
  const Vec3 previous{4.0, -1.0, 2.5};
  const double pn = (4.0 - 1.0 + 2.5) / std::sqrt(3.0);
  const Vec3 expected{4.0 - pn / std::sqrt(3.0), -1.0 - pn / std::sqrt(3.0),
                      2.5 - pn / std::sqrt(3.0)};
  const TangentialResult r =
      return_to_limit(previous, n, {}, kDt, kTangentialK, {kInf, kInf}, false);
  expect_vec_near(r.force, expected, 1e-12);
  EXPECT_NEAR(dot(r.force, n), 0.0, 1e-12);
}

TEST(ReturnToLimit, FrictionlessAndStickingLimits) {
  // Zero limits: nothing is held, nothing is dissipated.
  const TangentialResult loose =
      return_to_limit({2.0, 0.0, 0.0}, kNormalZ, {1.0, 1.0, 0.0}, kDt, kTangentialK, {}, false);
  EXPECT_EQ(norm(loose.force), 0.0);
  EXPECT_EQ(loose.slip_work, 0.0);
  // Infinite limits: any trial force is held (Sticking).
  const TangentialResult stuck = return_to_limit({2.0, 0.0, 0.0}, kNormalZ, {-1e6, 0.0, 0.0}, kDt,
                                                 kTangentialK, {kInf, kInf}, true);
  EXPECT_FALSE(stuck.sliding);
  expect_vec_near(stuck.force, {2.0 + 1e6, 0.0, 0.0}, 1e-6);
  EXPECT_EQ(stuck.slip_work, 0.0);
}

// ---------------------------------------------------------------------------------------------
// Slip limits of the laws
// ---------------------------------------------------------------------------------------------

// SlipState used below: F_n = 2000 N on 0.04 m^2 (p = 5e4 Pa), V = 1.5 m/s, t = 0.25 s,
// x = (0.1, 0.2, 0.3).
SlipState state() { return {2000.0, 0.04, 1.5, 0.25, {0.1, 0.2, 0.3}}; }

// Seed 002 (CoulombContactMaterial): stick = mu_s F_n, slide = mu_d F_n.
TEST(Coulomb, StaticAndDynamicLimits) {
  const Coulomb law{0.3, 0.2, {}, {}, {}, {}};
  const SlipLimits l = law.limits(state());
  EXPECT_NEAR(l.stick, 0.3 * 2000.0, rel(600.0));
  EXPECT_NEAR(l.slide, 0.2 * 2000.0, rel(400.0));
  const SlipLimits v = slip_limits(TangentialLaw{law}, state());
  EXPECT_EQ(v.stick, l.stick);
  EXPECT_EQ(v.slide, l.slide);
  // No normal force, no friction.
  SlipState open = state();
  open.normal_force = 0.0;
  EXPECT_EQ(law.limits(open).stick, 0.0);
  EXPECT_EQ(law.limits(open).slide, 0.0);
}

// Seed 000 (friction "mu = fcn(fid)" of pres, vtang, t, x, y, z): mu_s = mu_d = the function,
// called with p = F_n / area. mu = 0.1 + 1e-6 p + 0.01 V + 0.02 t + 0.03 x + 0.04 y + 0.05 z
// = 0.1 + 0.05 + 0.015 + 0.005 + 0.003 + 0.008 + 0.015 = 0.196 at state().
TEST(Coulomb, FrictionFunctionOfPressureSpeedTimeAndPosition) {
  Coulomb law{0.9, 0.8, {}, {}, {}, {}};  // the constants are overridden by the function
  law.function = [](double p, double v, double t, double x, double y, double z) {
    return 0.1 + 1e-6 * p + 0.01 * v + 0.02 * t + 0.03 * x + 0.04 * y + 0.05 * z;
  };
  const SlipLimits l = law.limits(state());
  EXPECT_NEAR(l.stick, 0.196 * 2000.0, rel(392.0));
  EXPECT_NEAR(l.slide, 0.196 * 2000.0, rel(392.0));
}

// Seed 004 comment 7: with Ifric > 0, mu = mu(p, V) (p the pressure, V the sliding speed) and
// the limit is mu F_n for both sticking and sliding.
TEST(Coulomb, WithEachRadiossFrictionModel) {
  const SlipState s = state();  // p = 5e4, V = 1.5
  {
    // Ifric 1: 0.1 + 2e-7 p + 0.01 V + 1e-8 p V + 1e-13 p^2 + 0.002 V^2 = 0.1305 (by hand).
    const Coulomb law{0.0, 0.0, {}, ViscousFriction{0.1, {2e-7, 0.01, 1e-8, 1e-13, 0.002, 0.0}},
                      {},  {}};
    const SlipLimits l = law.limits(s);
    EXPECT_NEAR(l.stick, 0.1305 * 2000.0, rel(261.0));
    EXPECT_NEAR(l.slide, 0.1305 * 2000.0, rel(261.0));
  }
  {
    // Ifric 2: 0.05 + 1e-12 e^{-0.75} p^2 + 2e-7 e^{-0.3} p + 0.1 e^{-1.5}.
    const Coulomb law{0.0, 0.0, {}, DarmstadFriction{0.05, {1e-12, -0.5, 2e-7, -0.2, 0.1, -1.0}},
                      {},  {}};
    const double mu =
        0.05 + 1e-12 * std::exp(-0.75) * 2.5e9 + 2e-7 * std::exp(-0.3) * 5e4 + 0.1 * std::exp(-1.5);
    const SlipLimits l = law.limits(s);
    EXPECT_NEAR(l.stick, mu * 2000.0, rel(mu * 2000.0));
    EXPECT_NEAR(l.slide, mu * 2000.0, rel(mu * 2000.0));
  }
  {
    // Ifric 3 (Renard) with V = 1.5 in [C5, C6] = [0.5, 2]: s = 2/3,
    // mu = 0.5 - 0.4 s^2 (3 - 2 s) = 0.5 - 0.4 * (4/9) * (5/3) = 0.5 - 8/27.
    const Coulomb law{0.0, 0.0, {}, RenardFriction{{0.3, 0.2, 0.5, 0.1, 0.5, 2.0}}, {}, {}};
    const double mu = 0.5 - 8.0 / 27.0;
    const SlipLimits l = law.limits(s);
    EXPECT_NEAR(l.stick, mu * 2000.0, rel(mu * 2000.0));
    EXPECT_NEAR(l.slide, mu * 2000.0, rel(mu * 2000.0));
  }
  {
    // The pressure really is F_n / area: with Ifric 1 and only C1, mu = C1 p = 1e-6 * 5e4 = 0.05.
    const Coulomb law{0.0, 0.0, {}, ViscousFriction{0.0, {1e-6, 0.0, 0.0, 0.0, 0.0, 0.0}}, {}, {}};
    EXPECT_NEAR(law.limits(s).stick, 0.05 * 2000.0, rel(100.0));
  }
}

// Seed 002 (TrescaContactMaterial): threshold m k (usually m sigma_0 / sqrt(3)) on the area,
// independent of the pressure: stick = m_s k A, slide = m_d k A.
TEST(Tresca, LimitsAreShearTimesAreaIndependentOfTheNormalForce) {
  const double k = 250e6 / std::sqrt(3.0);
  const Tresca law{0.6, 0.4, k, {}, {}, {}};
  for (const double fn : {0.0, 2000.0, 1e9}) {
    SlipState s = state();
    s.normal_force = fn;
    const SlipLimits l = slip_limits(TangentialLaw{law}, s);
    EXPECT_NEAR(l.stick, 0.6 * k * 0.04, rel(0.6 * k * 0.04)) << "F_n = " << fn;
    EXPECT_NEAR(l.slide, 0.4 * k * 0.04, rel(0.4 * k * 0.04)) << "F_n = " << fn;
  }
}

// Seed 002 (StickingContactMaterial, no slip) and (FrictionlessContactMaterial, no friction).
TEST(Sticking, InfiniteLimitsAndFrictionlessZeroLimits) {
  const SlipLimits stick = slip_limits(TangentialLaw{Sticking{}}, state());
  EXPECT_EQ(stick.stick, kInf);
  EXPECT_EQ(stick.slide, kInf);
  const SlipLimits none = slip_limits(TangentialLaw{Frictionless{}}, state());
  EXPECT_EQ(none.stick, 0.0);
  EXPECT_EQ(none.slide, 0.0);
}

// ---------------------------------------------------------------------------------------------
// Radioss friction models (seed 004 comment 7, decoded in seeds/README.md)
// ---------------------------------------------------------------------------------------------

// Ifric 1: mu = Fric + C1 p + C2 V + C3 p V + C4 p^2 + C5 V^2. Literal values by hand (Python).
TEST(ViscousFriction, MatchesTheSeedFormula) {
  const ViscousFriction law{0.1, {2e-7, 0.01, 1e-8, 1e-13, 0.002, 0.0}};
  struct Point {
    double p, v, mu;
  };
  for (const Point& q : {Point{5e4, 1.5, 0.1305}, Point{0.0, 0.0, 0.1}, Point{2e5, 0.2, 0.14648},
                         Point{1e3, 10.0, 0.4003001}}) {
    const double formula =
        0.1 + 2e-7 * q.p + 0.01 * q.v + 1e-8 * q.p * q.v + 1e-13 * q.p * q.p + 0.002 * q.v * q.v;
    EXPECT_NEAR(formula, q.mu, rel(q.mu));  // the written-out formula against the hand value
    EXPECT_NEAR(law.mu(q.p, q.v), q.mu, rel(q.mu)) << "p = " << q.p << ", V = " << q.v;
  }
  // C6 is not used by Ifric 1.
  ViscousFriction with_c6 = law;
  with_c6.c[5] = 99.0;
  EXPECT_EQ(with_c6.mu(5e4, 1.5), law.mu(5e4, 1.5));
}

// Ifric 2: mu = Fric + C1 exp(C2 V) p^2 + C3 exp(C4 V) p + C5 exp(C6 V). Literal values (Python).
TEST(DarmstadFriction, MatchesTheSeedFormula) {
  const DarmstadFriction law{0.05, {1e-12, -0.5, 2e-7, -0.2, 0.1, -1.0}};
  struct Point {
    double p, v, mu;
  };
  for (const Point& q :
       {Point{5e4, 1.5, 0.08090211460351271}, Point{0.0, 0.0, 0.15},
        Point{2e5, 0.2, 0.2064981495953295}, Point{1e3, 10.0, 0.050031613787570574}}) {
    const double formula = 0.05 + 1e-12 * std::exp(-0.5 * q.v) * q.p * q.p +
                           2e-7 * std::exp(-0.2 * q.v) * q.p + 0.1 * std::exp(-1.0 * q.v);
    EXPECT_NEAR(formula, q.mu, rel(q.mu));
    EXPECT_NEAR(law.mu(q.p, q.v), q.mu, rel(q.mu)) << "p = " << q.p << ", V = " << q.v;
  }
}

// Ifric 3 (Renard), C1 = mu_s, C2 = mu_d, C3 = mu_max, C4 = mu_min, C5 = Vcr1, C6 = Vcr2:
//   V in [0, C5]:  mu = C1 + (C3 - C1) (V/C5) (2 - V/C5)
//   V in [C5, C6]: mu = C3 - (C3 - C4) s^2 (3 - 2 s), s = (V - C5)/(C6 - C5)
//   V >= C6:       mu = C2 - 1 / (1/(C2 - C4) + (V - C6)^2)
// Here mu_s 0.3, mu_d 0.2, mu_max 0.5, mu_min 0.1, Vcr1 0.5, Vcr2 2 (mu_min < mu_s, mu_d < mu_max).
TEST(RenardFriction, ThreeBranchesContinuityAndLimits) {
  const RenardFriction law{{0.3, 0.2, 0.5, 0.1, 0.5, 2.0}};
  const auto reference = [](double v) {
    const double c1 = 0.3, c2 = 0.2, c3 = 0.5, c4 = 0.1, c5 = 0.5, c6 = 2.0;
    if (v <= c5) return c1 + (c3 - c1) * (v / c5) * (2.0 - v / c5);
    if (v <= c6) {
      const double s = (v - c5) / (c6 - c5);
      return c3 - (c3 - c4) * s * s * (3.0 - 2.0 * s);
    }
    return c2 - 1.0 / (1.0 / (c2 - c4) + (v - c6) * (v - c6));
  };
  for (const double v : {0.0, 0.1, 0.25, 0.4, 0.5, 0.8, 1.25, 1.9, 2.0, 2.5, 3.0, 10.0})
    EXPECT_NEAR(law.mu(1e5, v), reference(v), rel(reference(v))) << "V = " << v;
  // Values by hand: mu(0) = mu_s; mu(0.25) = 0.3 + 0.2 * 0.5 * 1.5 = 0.45; mu(C5) = mu_max;
  // mu(1.25) = 0.5 - 0.4 * 0.25 * 2 = 0.3; mu(C6) = mu_min; mu(3) = 0.2 - 1/11.
  EXPECT_NEAR(law.mu(0.0, 0.0), 0.3, rel(0.3));
  EXPECT_NEAR(law.mu(0.0, 0.25), 0.45, rel(0.45));
  EXPECT_NEAR(law.mu(0.0, 0.5), 0.5, rel(0.5));
  EXPECT_NEAR(law.mu(0.0, 1.25), 0.3, rel(0.3));
  EXPECT_NEAR(law.mu(0.0, 2.0), 0.1, rel(0.1));
  EXPECT_NEAR(law.mu(0.0, 3.0), 0.2 - 1.0 / 11.0, rel(0.2 - 1.0 / 11.0));
  // Continuity at C5 and C6 (values mu_max and mu_min from both sides): a step of 1e-9 changes
  // mu by O(1e-9) (the slopes vanish there, so by O(1e-18) in exact arithmetic).
  const double eps = 1e-9;
  EXPECT_NEAR(law.mu(0.0, 0.5 - eps), 0.5, 1e-12);
  EXPECT_NEAR(law.mu(0.0, 0.5 + eps), 0.5, 1e-12);
  EXPECT_NEAR(law.mu(0.0, 2.0 - eps), 0.1, 1e-12);
  EXPECT_NEAR(law.mu(0.0, 2.0 + eps), 0.1, 1e-12);
  // Independent of the pressure.
  EXPECT_EQ(law.mu(0.0, 1.25), law.mu(3e8, 1.25));
  // Large V: tends to mu_d from below; at V = 1e4, mu_d - mu = 1/(10 + 9998^2) ~ 1.0004e-8.
  const double far = law.mu(0.0, 1e4);
  EXPECT_LT(far, 0.2);
  EXPECT_NEAR(far, 0.2, 1.1e-8);
  EXPECT_NEAR(0.2 - far, 1.0 / (10.0 + 9998.0 * 9998.0), 1e-15);
}

// ---------------------------------------------------------------------------------------------
// Friction filter, seed 004 comment 8 (decoded in seeds/README.md): F_t = a F_t + (1 - a) F_t,prev
// with a = Xfreq (Ifiltr 1), a = 2 pi dt / T, T = Xfreq the period (Ifiltr 2), a = 2 pi fc dt,
// fc = Xfreq the cut-off frequency (Ifiltr 3); clamped to [0, 1].
// ---------------------------------------------------------------------------------------------

TEST(FrictionFilter, AlphaOfEachKindAndTheClamp) {
  using K = FrictionFilter::Kind;
  EXPECT_EQ((FrictionFilter{K::None, 0.3}.alpha(1e-5)), 1.0);
  // Simple: a = Xfreq whatever dt.
  EXPECT_EQ((FrictionFilter{K::Simple, 0.3}.alpha(1e-5)), 0.3);
  EXPECT_EQ((FrictionFilter{K::Simple, 0.3}.alpha(1.0)), 0.3);
  EXPECT_EQ((FrictionFilter{K::Simple, 1.7}.alpha(1e-5)), 1.0);
  EXPECT_EQ((FrictionFilter{K::Simple, -0.5}.alpha(1e-5)), 0.0);
  // Period T = 1e-3 s, dt = 2e-5 s: a = 2 pi * 0.02 = 0.12566370614359174.
  EXPECT_NEAR((FrictionFilter{K::Period, 1e-3}.alpha(2e-5)), 0.12566370614359174,
              rel(0.12566370614359174));
  EXPECT_EQ((FrictionFilter{K::Period, 1e-3}.alpha(1e-3)), 1.0);  // 2 pi > 1: clamped
  // Frequency fc = 500 Hz, dt = 1e-5 s: a = 2 pi * 5e-3 = 0.031415926535897934.
  EXPECT_NEAR((FrictionFilter{K::Frequency, 500.0}.alpha(1e-5)), 0.031415926535897934,
              rel(0.031415926535897934));
  EXPECT_EQ((FrictionFilter{K::Frequency, 500.0}.alpha(1e-3)), 1.0);  // 2 pi 0.5 > 1: clamped
  // A period T and a frequency 1/T give the same filter.
  EXPECT_NEAR((FrictionFilter{K::Period, 1.0 / 500.0}.alpha(1e-5)),
              (FrictionFilter{K::Frequency, 500.0}.alpha(1e-5)), rel(0.0314159));
}

// The first-order filter F_n = a F_new + (1 - a) F_{n-1} on a unit step from 0: F_n = 1 - (1-a)^n.
TEST(FrictionFilter, StepResponseOfTheFirstOrderFilter) {
  const double a = FrictionFilter{FrictionFilter::Kind::Frequency, 500.0}.alpha(1e-5);
  ASSERT_GT(a, 0.0);
  ASSERT_LT(a, 1.0);
  double f = 0.0;
  for (int n = 1; n <= 200; ++n) {
    f = a * 1.0 + (1.0 - a) * f;
    const double expected = 1.0 - std::pow(1.0 - a, n);
    ASSERT_NEAR(f, expected, 1e-12) << "step " << n;
  }
}

// Ifiltr 3 is a "standard -3dB filter with cutting frequency" (seed 004): a sine at fc comes out
// of the filter with amplitude 1/sqrt(2). With dt small against 1/fc (2000 steps per period),
// the discrete filter's gain is 1/sqrt(2) within O(2 pi fc dt) = 3e-3: tolerance 2e-3 relative
// (the exact discrete gain |a / (1 - (1-a) e^{-i w dt})| is 0.70766).
TEST(FrictionFilter, CutOffFrequencyGivesMinus3dB) {
  const double fc = 50.0, dt = 1e-5;
  const double a = FrictionFilter{FrictionFilter::Kind::Frequency, fc}.alpha(dt);
  const double w = 2.0 * std::numbers::pi * fc;
  double f = 0.0, peak = 0.0;
  const int per_period = 2000, periods = 20;
  for (int n = 0; n < per_period * periods; ++n) {
    f = a * std::sin(w * n * dt) + (1.0 - a) * f;
    if (n >= per_period * (periods - 1)) peak = std::max(peak, std::abs(f));
  }
  EXPECT_NEAR(peak, 1.0 / std::sqrt(2.0), 2e-3 / std::sqrt(2.0));
  const std::complex<double> h =
      a / (1.0 - (1.0 - a) * std::exp(std::complex<double>(0.0, -w * dt)));
  EXPECT_NEAR(peak, std::abs(h), 1e-5);  // the simulation agrees with the transfer function
}

// ---------------------------------------------------------------------------------------------
// Adhesion, seed 004 comment 12 (IVIS2 = -1): in the zone of width Gap/2 outside the surface,
//   F_N = SigMaxAdh Area (Gap/2 - P_adh) / (Gap/2), P_adh = Gap/2 - s (s the opening),
// a pull (pressure -F_N / Area), 0 at s = 0, SigMaxAdh at the border s = Gap/2, none beyond;
//   F_T = -ViscAdhFact ViscFluid Area V_rel / (Gap/2), opposing the relative velocity.
// Gap 2 mm (zone 1 mm), SigMaxAdh 5 MPa, ViscFluid 100 Pa s, ViscAdhFact 0.8, Area 4e-4 m^2.
// ---------------------------------------------------------------------------------------------

TEST(Adhesion, LinearPullAcrossTheZoneAndNoneBeyond) {
  const Adhesion law{2e-3, 5e6, 100.0, 0.8};
  const double half = 2e-3 / 2.0, area = 4e-4;
  EXPECT_NEAR(law.zone(), 1e-3, rel(1e-3));
  EXPECT_EQ(law.pressure(0.0), 0.0);                // at the surface: no pull
  EXPECT_NEAR(law.pressure(half), -5e6, rel(5e6));  // at the border: -SigMaxAdh
  for (const double s : {1e-5, 2.5e-4, 5e-4, 9.99e-4}) {
    const double p_adh = half - s;
    const double fn = 5e6 * area * (half - p_adh) / half;
    EXPECT_NEAR(law.pressure(s) * area, -fn, rel(fn)) << "opening " << s;
  }
  EXPECT_NEAR(law.pressure(2.5e-4), -1.25e6, rel(1.25e6));  // by hand: a quarter of the zone
  EXPECT_EQ(law.pressure(1.0001e-3), 0.0);                  // beyond the zone: spring broken
  EXPECT_EQ(law.pressure(5e-3), 0.0);
  EXPECT_EQ(law.pressure(-1e-4), 0.0);  // penetrating: the contact law, not adhesion
}

TEST(Adhesion, ViscousTangentialForceOpposesTheSlip) {
  const Adhesion law{2e-3, 5e6, 100.0, 0.8};
  const double area = 4e-4;
  const Vec3 v{0.3, -0.4, 0.0};
  // 0.8 * 100 * 4e-4 / 1e-3 = 32 N s/m: F = -32 V = (-9.6, 12.8, 0).
  const Vec3 f = law.viscous_force(v, area);
  expect_vec_near(f, {-9.6, 12.8, 0.0}, 1e-12);
  const double c = 0.8 * 100.0 * area / (2e-3 / 2.0);
  expect_vec_near(f, v * -c, 1e-12);
  EXPECT_LT(dot(f, v), 0.0);
}

}  // namespace
}  // namespace abut

namespace abut {
namespace {

// CalculiX's exponential pressure-overclosure (User's Manual, eqs. 108-109): p = p0 at zero
// distance, 1% of p0 at the clearance c0, nothing beyond; slope beta p; energy measured from -c0.
TEST(NormalLaws, ExponentialOverclosureIsCalculixForm) {
  const ExponentialOverclosure law{0.5, 2.0};
  EXPECT_DOUBLE_EQ(law.evaluate(0.0, 123.0).pressure, 2.0);
  EXPECT_NEAR(law.evaluate(-0.5, 0.0).pressure, 0.02, 1e-15);
  EXPECT_EQ(law.evaluate(-0.51, 0.0).pressure, 0.0);
  const double beta = std::log(100.0) / 0.5, d = 0.1, h = 1e-6;
  const NormalResponse r = law.evaluate(d, 0.0);
  EXPECT_NEAR(r.pressure, 2.0 * std::exp(beta * d), 1e-12);
  EXPECT_NEAR(r.stiffness,
              (law.evaluate(d + h, 0).pressure - law.evaluate(d - h, 0).pressure) / (2 * h),
              1e-6 * r.stiffness);
  EXPECT_NEAR((law.evaluate(d + h, 0).energy - law.evaluate(d - h, 0).energy) / (2 * h), r.pressure,
              1e-6 * r.pressure);
  EXPECT_NEAR(law.evaluate(-0.5, 0).energy, 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(reach_at_clearance(NormalLaw{law}), 0.5);
  EXPECT_DOUBLE_EQ(reach_at_clearance(NormalLaw{LinearPenalty{}}), 0.0);
}

}  // namespace
}  // namespace abut
