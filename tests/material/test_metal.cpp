// J2 radial return of *MAT_METAL / *MAT_JC (metal.hpp) against closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "abut/core/error.hpp"
#include "abut/material/metal.hpp"
#include "abut/material/point_law.hpp"

namespace abut {
namespace {

constexpr double kE = 200e9, kNu = 0.3;
constexpr double kG = kE / (2.0 * (1.0 + kNu));

MetalParams johnson_cook(double a, double b, double n, double c = 0.0) {
  MetalParams p;
  p.density = 7800.0;
  p.young = kE;
  p.poisson = kNu;
  p.johnson_cook = true;
  p.a = a;
  p.b = b;
  p.n = n;
  p.c = c;
  return p;
}

// Linear hardening sigma_y = A + H epsp (JC with n = 1): the return has the closed form
// dp = (q_trial - sigma_y(epsp)) / (3G + H) (Simo & Hughes 1998, box 3.2), and the returned
// deviator is the trial one scaled by (q_trial - 3G dp) / q_trial; the pressure is unchanged.
TEST(RadialReturn, LinearHardeningClosedForm) {
  const double a = 300e6, h = 1e9, epsp = 0.01;
  const MetalParams p = johnson_cook(a, h, 1.0);
  const FlowStress flow(p, nullptr);
  const Sym3 trial{{500e6, 100e6, -50e6, 80e6, 0.0, -30e6}};
  const Sym3 s = deviator(trial);
  const double q = std::sqrt(1.5 * double_dot(s, s));
  const double dp_expected = (q - (a + h * epsp)) / (3.0 * kG + h);
  const PlasticUpdate u = radial_return(trial, kG, epsp, 0.0, flow);
  EXPECT_NEAR(u.plastic_strain_increment, dp_expected, 1e-12 * dp_expected);
  EXPECT_NEAR(von_mises(u.stress), a + h * (epsp + dp_expected), 1e-9 * a);  // on the yield surface
  EXPECT_NEAR(trace(u.stress), trace(trial), 1e-6);
  const double scale = (q - 3.0 * kG * dp_expected) / q;
  const Sym3 sd = deviator(u.stress);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(sd[i], scale * s[i], 1e-6 * q);  // radial
}

TEST(RadialReturn, ElasticInsideTheYieldSurface) {
  const MetalParams p = johnson_cook(300e6, 1e9, 1.0);
  const FlowStress flow(p, nullptr);
  const Sym3 trial{{200e6, 0.0, 0.0, 10e6, 0.0, 0.0}};
  const PlasticUpdate u = radial_return(trial, kG, 0.0, 1e-6, flow);
  EXPECT_EQ(u.plastic_strain_increment, 0.0);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(u.stress[i], trial[i]);
}

// Power-law hardening (n = 0.3) and the Johnson-Cook rate factor: the returned state satisfies
// the consistency condition q_trial - 3G dp = (A + B (epsp + dp)^n)(1 + C ln(dp / dt / rate0)).
TEST(RadialReturn, PowerLawWithRateSatisfiesConsistency) {
  const double a = 90e6, b = 292e6, n = 0.31, c = 0.025, epsp = 0.05, dt = 1e-7;
  const MetalParams p = johnson_cook(a, b, n, c);
  const FlowStress flow(p, nullptr);
  const Sym3 trial{{900e6, 0.0, 0.0, 0.0, 0.0, 0.0}};
  const Sym3 s = deviator(trial);
  const double q = std::sqrt(1.5 * double_dot(s, s));
  const PlasticUpdate u = radial_return(trial, kG, epsp, dt, flow);
  const double dp = u.plastic_strain_increment;
  ASSERT_GT(dp, 0.0);
  const double rate = dp / dt;
  const double sigma_y = (a + b * std::pow(epsp + dp, n)) * (1.0 + c * std::log(rate));
  EXPECT_NEAR(q - 3.0 * kG * dp, sigma_y, 1e-9 * sigma_y);
  EXPECT_NEAR(von_mises(u.stress), sigma_y, 1e-9 * sigma_y);
}

// Below the reference rate the Johnson-Cook factor is 1 (it only strengthens).
TEST(FlowStress, JohnsonCookRateFactorFromTheReferenceRateOn) {
  const MetalParams p = johnson_cook(100e6, 200e6, 0.5, 0.1);
  const FlowStress flow(p, nullptr);
  EXPECT_DOUBLE_EQ(flow(0.04, 0.5), 100e6 + 200e6 * 0.2);
  EXPECT_NEAR(flow(0.04, 100.0), (100e6 + 200e6 * 0.2) * (1.0 + 0.1 * std::log(100.0)), 1e-6);
}

// The slope the radial return's Newton steps use: d sigma_y / d dp of sigma_y(epsp + dp, dp / dt)
// against a central difference of the flow stress itself, for power laws below, at and above
// n = 1, with and without the rate term, and thermally softened.
TEST(FlowStress, JohnsonCookSlopeAlongAStepIsTheDerivativeOfTheFlowStress) {
  struct Case {
    double a, b, n, c, epsp, dp, dt;
  };
  const Case cases[] = {{90e6, 292e6, 0.31, 0.025, 0.05, 1e-4, 1e-7},
                        {300e6, 1e9, 1.0, 0.0, 0.01, 2e-3, 0.0},
                        {200e6, 500e6, 1.7, 0.1, 0.2, 5e-5, 1e-6},
                        {300e6, 0.0, 0.5, 0.0, 0.3, 1e-3, 1e-7},
                        {100e6, 50e6, 0.2, 0.05, 0.0, 1e-3, 1e-5}};
  for (const Case& k : cases) {
    MetalParams p = johnson_cook(k.a, k.b, k.n, k.c);
    p.softening_m = 1.0, p.room_temperature = 293.0, p.melting_temperature = 1793.0;
    const FlowStress flow = FlowStress(p, nullptr).at_temperature(593.0);  // T* = 0.2
    const auto sigma = [&](double dp) { return flow(k.epsp + dp, k.dt > 0.0 ? dp / k.dt : 0.0); };
    const FlowPoint y = flow.along_step(k.epsp, k.dp, k.dt);
    ASSERT_TRUE(y.has_slope);
    EXPECT_EQ(y.stress, sigma(k.dp));
    const double h = 1e-6 * k.dp;
    const double difference = (sigma(k.dp + h) - sigma(k.dp - h)) / (2.0 * h);
    EXPECT_NEAR(y.slope, difference, 1e-6 * std::abs(difference) + 1e-9 * k.a) << k.n;
  }
  // A curve has no closed-form slope: the return differentiates it.
  MetalParams curve;
  FunctionTable table;
  table.add_curve(1, Curve{{0.0, 1.0}, {250e6, 450e6}}, SourceLocation{});
  table.resolve();
  curve.flow_curve = table.find(1, SourceLocation{});
  EXPECT_FALSE(FlowStress(curve, &table).along_step(0.1, 0.0, 0.0).has_slope);
}

// Elastic-perfectly plastic (B = 0): sigma_y = A after the return, any trial (the closed form of
// the return is dp = (q - A) / 3G).
TEST(RadialReturn, PerfectlyPlasticReturnsOntoTheYieldStress) {
  const MetalParams p = johnson_cook(300e6, 0.0, 0.5);
  const FlowStress flow(p, nullptr);
  const Sym3 trial{{700e6, -100e6, 20e6, 150e6, -40e6, 60e6}};
  const Sym3 s = deviator(trial);
  const double q = std::sqrt(1.5 * double_dot(s, s));
  const PlasticUpdate u = radial_return(trial, kG, 0.02, 1e-7, flow);
  EXPECT_NEAR(u.plastic_strain_increment, (q - 300e6) / (3.0 * kG), 1e-12 * q / kG);
  EXPECT_NEAR(von_mises(u.stress), 300e6, 1e-9 * 300e6);
}

// *MAT_METAL's flow curve from a function table: a *FUNCTION of epsp, and a *CURVE.
TEST(FlowStress, MetalCurveFromTheFunctionTable) {
  FunctionTable table;
  table.add_function(1, "167e6 + 415e6 * epsp^0.3", SourceLocation{});
  table.add_curve(2, Curve{{0.0, 0.2}, {250e6, 400e6}}, SourceLocation{});
  table.resolve();
  MetalParams p;
  p.flow_curve = table.find(1, SourceLocation{});
  EXPECT_NEAR(FlowStress(p, &table)(0.1, 0.0), 167e6 + 415e6 * std::pow(0.1, 0.3), 1e-3);
  p.flow_curve = table.find(2, SourceLocation{});
  EXPECT_NEAR(FlowStress(p, &table)(0.1, 0.0), 325e6, 1e-3);
}

// Johnson & Cook (1985): eps_f = [d1 + d2 exp(d3 sigma*)][1 + d4 ln(rate / rate0)], sigma* the
// mean stress over the von Mises stress.
TEST(DuctileFailure, JohnsonCookFailureStrain) {
  DuctileFailure f;
  f.active = true, f.d1 = 0.05, f.d2 = 3.44, f.d3 = -2.12, f.d4 = 0.002, f.rate0 = 1.0;
  const Sym3 uniaxial{{400e6, 0, 0, 0, 0, 0}};  // sigma* = 1/3
  EXPECT_NEAR(failure_strain(f, uniaxial, 0.5), 0.05 + 3.44 * std::exp(-2.12 / 3.0), 1e-12);
  EXPECT_NEAR(failure_strain(f, uniaxial, 1000.0),
              (0.05 + 3.44 * std::exp(-2.12 / 3.0)) * (1.0 + 0.002 * std::log(1000.0)), 1e-12);
  const Sym3 shear{{0, 0, 0, 200e6, 0, 0}};  // sigma* = 0
  EXPECT_NEAR(failure_strain(f, shear, 0.0), 0.05 + 3.44, 1e-12);
}

TEST(DuctileFailure, APointFailsWhenItsDamageReachesOneAndThenCarriesNoStress) {
  // Uniaxial plastic straining at constant triaxiality 1/3: D = epsp / eps_f.
  FunctionTable table;
  MetalParams p;
  p.density = 7800, p.young = 2e11, p.poisson = 0.3, p.johnson_cook = true, p.a = 3e8;
  DuctileFailure f;
  f.active = true, f.d1 = 0.1;
  const LameConstants lame{2e11 * 0.3 / (1.3 * 0.4), 2e11 / 2.6};
  const MetalPoint law{lame, FlowStress(p, &table), f};
  PointHistory h;
  Sym3 stress;
  int steps = 0;
  while (!h.failed() && steps < 10000) {
    // deviatoric strain increment of uniaxial plastic flow (incompressible), 1e-4 axial
    const Sym3 increment{{1e-4, -0.5e-4, -0.5e-4, 0, 0, 0}};
    stress = law.update(stress, increment, 1e-3, h);
    if (!h.failed()) {
      EXPECT_NEAR(h.damage, h.plastic_strain / 0.1, 1e-12);
    }
    ++steps;
  }
  ASSERT_TRUE(h.failed());
  EXPECT_NEAR(h.plastic_strain, 0.1, 2e-4);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(stress[i], 0.0);
  const Sym3 after = law.update(stress, Sym3{{1e-4, 0, 0, 0, 0, 0}}, 1e-3, h);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(after[i], 0.0);
}

// The thermal factor of Johnson & Cook (1985, Eng. Fract. Mech. 21:31, eq. 2): eps_f times
// 1 + d5 T*, T* = (T - T0) / (Tm - T0) the homologous temperature of the metal (clamped to [0, 1],
// as for the softening), set by the point law at its temperature. A point at T* = 0.5 with d5 = 0.6
// fails at 1.3 times the strain, and the damage it accumulates shows it.
TEST(DuctileFailure, ThermalFactorOfTheFailureStrain) {
  FunctionTable table;
  MetalParams p;
  p.density = 7800, p.young = 2e11, p.poisson = 0.3, p.johnson_cook = true, p.a = 3e8;
  p.room_temperature = 20.0, p.melting_temperature = 1520.0;
  DuctileFailure f;
  f.active = true, f.d1 = 0.1, f.d5 = 0.6;
  const LameConstants lame{2e11 * 0.3 / (1.3 * 0.4), 2e11 / 2.6};
  const MetalPoint law{lame, FlowStress(p, &table), f};
  const Sym3 uniaxial{{400e6, 0, 0, 0, 0, 0}};
  EXPECT_NEAR(failure_strain(law.at_temperature(770.0).failure, uniaxial, 0.0), 0.1 * 1.3, 1e-15);
  EXPECT_NEAR(failure_strain(law.at_temperature(-100.0).failure, uniaxial, 0.0), 0.1, 1e-15);
  EXPECT_NEAR(failure_strain(law.at_temperature(5000.0).failure, uniaxial, 0.0), 0.16, 1e-15);
  EXPECT_EQ(failure_strain(law.failure, uniaxial, 0.0), 0.1);  // no temperature: the factor is 1
  // Uniaxial plastic flow at T* = 0.5: D = epsp / (1.3 eps_f).
  const MetalPoint hot = law.at_temperature(770.0);
  PointHistory h;
  Sym3 stress;
  for (int i = 0; i < 200; ++i)
    stress = hot.update(stress, Sym3{{1e-4, -0.5e-4, -0.5e-4, 0, 0, 0}}, 1e-3, h);
  ASSERT_GT(h.plastic_strain, 0.0);
  EXPECT_NEAR(h.damage, h.plastic_strain / 0.13, 1e-12);
}

}  // namespace
}  // namespace abut
