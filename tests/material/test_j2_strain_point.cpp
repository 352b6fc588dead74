// The strain-driven J2 point of the implicit elements (j2_strain_point.hpp): uniaxial stress with
// linear hardening against its closed form, the consistent tangent against finite differences,
// elastic unloading and the plastic work.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "abut/material/j2_strain_point.hpp"

namespace abut {
namespace {

constexpr double kE = 200000.0, kNu = 0.3, kYield = 250.0, kHardening = 2000.0;  // MPa

MetalParams linear_hardening() {
  MetalParams p;
  p.density = 7.85e-9;
  p.young = kE;
  p.poisson = kNu;
  p.johnson_cook = true;  // sigma_y = A + B epsp^n with n = 1
  p.a = kYield;
  p.b = kHardening;
  p.n = 1.0;
  return p;
}

struct Point {
  MetalParams params = linear_hardening();
  std::array<J2PointHistory, 8> committed{}, trial{};
  J2StrainPoint law() const {
    return {kE, kNu, FlowStress(params, nullptr), committed.data(),
            const_cast<J2PointHistory*>(trial.data())};
  }
  double evaluate(const double strain[6], double stress[6], double d[36]) const {
    return law().evaluate(0, strain, stress, d);
  }
  void commit() { committed = trial; }
};

// Uniaxial stress: drive e_xx, find e_yy = e_zz with s_yy = 0 by Newton on the tangent (which
// tests the tangent too). Linear hardening: sigma = sigma_y + E_t (eps - sigma_y / E),
// E_t = E H / (E + H) (e.g. Simo & Hughes, Computational Inelasticity, 1998, section 1.4).
TEST(J2StrainPoint, UniaxialStressLinearHardening) {
  Point p;
  double lateral = 0.0;
  const double eps_y = kYield / kE, tangent_modulus = kE * kHardening / (kE + kHardening);
  for (int step = 1; step <= 40; ++step) {
    const double eps = 0.0005 * step;
    double stress[6], d[36];
    for (int it = 0; it < 30; ++it) {
      const double strain[6] = {eps, lateral, lateral, 0, 0, 0};
      p.evaluate(strain, stress, d);
      if (std::abs(stress[1]) < 1e-10 * kYield) break;
      lateral -= stress[1] / (d[6 * 1 + 1] + d[6 * 1 + 2]);
    }
    p.commit();
    const double expected = eps <= eps_y ? kE * eps : kYield + tangent_modulus * (eps - eps_y);
    EXPECT_NEAR(stress[0], expected, 1e-8 * expected) << eps;
    EXPECT_NEAR(stress[2], 0.0, 1e-8 * kYield);
  }
  // epsp = (sigma - sigma_y) / H; plastic work = int sigma_y depsp = sigma_y epsp + H epsp^2 / 2.
  const double sigma = kYield + tangent_modulus * (0.02 - eps_y);
  const double epsp = (sigma - kYield) / kHardening;
  EXPECT_NEAR(p.committed[0].equivalent_plastic_strain, epsp, 1e-9);
  EXPECT_NEAR(p.committed[0].plastic_strain[0], epsp, 1e-9);         // axial
  EXPECT_NEAR(p.committed[0].plastic_strain[1], -0.5 * epsp, 1e-9);  // isochoric flow
  EXPECT_NEAR(p.committed[0].plastic_work, kYield * epsp + 0.5 * kHardening * epsp * epsp,
              1e-9 * kYield);
}

// The algorithmic tangent is the derivative of the returned stress (Simo & Taylor 1985).
TEST(J2StrainPoint, ConsistentTangentMatchesFiniteDifferences) {
  Point p;
  p.committed[0].plastic_strain[0] = 0.002;
  p.committed[0].plastic_strain[1] = -0.001;
  p.committed[0].plastic_strain[2] = -0.001;
  p.committed[0].plastic_strain[3] = 0.0008;
  p.committed[0].equivalent_plastic_strain = 0.0025;
  const double strain[6] = {0.006, -0.002, 0.0005, 0.004, -0.001, 0.002};
  double stress[6], d[36];
  p.evaluate(strain, stress, d);
  ASSERT_GT(p.trial[0].equivalent_plastic_strain, 0.0025);  // plastic
  const double h = 1e-8;
  for (int j = 0; j < 6; ++j) {
    double sp[6], sm[6], dd[36];
    double plus[6], minus[6];
    for (int k = 0; k < 6; ++k) plus[k] = minus[k] = strain[k];
    plus[j] += h;
    minus[j] -= h;
    p.evaluate(plus, sp, dd);
    p.evaluate(minus, sm, dd);
    for (int i = 0; i < 6; ++i)
      EXPECT_NEAR((sp[i] - sm[i]) / (2 * h), d[6 * i + j], 1e-5 * kE) << i << " " << j;
  }
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) EXPECT_NEAR(d[6 * i + j], d[6 * j + i], 1e-9 * kE);
}

// After yielding, a smaller strain unloads elastically: Hooke's tangent, no new plastic strain.
TEST(J2StrainPoint, UnloadingIsElastic) {
  Point p;
  const double loaded[6] = {0.004, -0.0012, -0.0012, 0, 0, 0};
  double s1[6], s2[6], d[36];
  p.evaluate(loaded, s1, d);
  p.commit();
  const double epsp = p.committed[0].equivalent_plastic_strain;
  ASSERT_GT(epsp, 0.0);
  const double unloaded[6] = {0.0035, -0.0012, -0.0012, 0, 0, 0};
  p.evaluate(unloaded, s2, d);
  EXPECT_EQ(p.trial[0].equivalent_plastic_strain, epsp);
  const double lambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), mu = kE / (2 * (1 + kNu));
  EXPECT_NEAR(d[0], lambda + 2 * mu, 1e-9 * kE);
  EXPECT_NEAR(s1[0] - s2[0], (lambda + 2 * mu) * 0.0005, 1e-9 * kYield);
}

}  // namespace
}  // namespace abut
