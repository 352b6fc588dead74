// Mooney-Rivlin material point: spectral IMPETUS form against the invariant form of the same
// potential, and the viscous exponential-integrator factors.
#include <gtest/gtest.h>

#include <cmath>

#include "abut/material/mooney_rivlin.hpp"

namespace abut {
namespace {

double determinant(const Mat3& f) {
  return f[0] * (f[4] * f[8] - f[5] * f[7]) - f[1] * (f[3] * f[8] - f[5] * f[6]) +
         f[2] * (f[3] * f[7] - f[4] * f[6]);
}

// Holzapfel, Nonlinear Solid Mechanics (2000), eqs. 6.103 and 6.146 for
// W = C1 (I1_bar - 3) + C2 (I2_bar - 3) + K/2 (J - 1)^2:
//   sigma = (2/J) dev[(C1 + C2 I1_bar) b_bar - C2 b_bar^2] + K (J - 1) I.
Sym3 invariant_form(const MooneyRivlinParams& p, const Mat3& f) {
  const double j = determinant(f);
  double b[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      b[r][c] = std::pow(j, -2.0 / 3.0) *
                (f[3 * r] * f[3 * c] + f[3 * r + 1] * f[3 * c + 1] + f[3 * r + 2] * f[3 * c + 2]);
  const double i1 = b[0][0] + b[1][1] + b[2][2];
  double t[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      double b2 = 0.0;
      for (int k = 0; k < 3; ++k) b2 += b[r][k] * b[k][c];
      t[r][c] = (p.c1 + p.c2 * i1) * b[r][c] - p.c2 * b2;
    }
  const double mean = (t[0][0] + t[1][1] + t[2][2]) / 3.0;
  const double vol = p.bulk * (j - 1.0);
  return {{2 / j * (t[0][0] - mean) + vol, 2 / j * (t[1][1] - mean) + vol,
           2 / j * (t[2][2] - mean) + vol, 2 / j * t[0][1], 2 / j * t[1][2], 2 / j * t[2][0]}};
}

TEST(MooneyRivlin, SpectralFormEqualsInvariantFormOfTheSamePotential) {
  const MooneyRivlinParams p{1100.0, 2.0e7, 4.0e5, 1.5e5, {}, {}};
  const Mat3 cases[] = {
      {1.5, 0, 0, 0, 0.85, 0, 0, 0, 0.8},                 // stretch
      {1.0, 0.4, 0, 0, 1.0, 0, 0, 0, 1.0},                // simple shear
      {1.2, 0.3, -0.1, 0.05, 0.9, 0.2, 0.1, -0.15, 1.1},  // general
      {1.3, 0, 0, 0, 1.3, 0, 0, 0, 0.7},                  // two equal stretches
  };
  for (const Mat3& f : cases) {
    const Sym3 s = mooney_rivlin_stress(p, f);
    const Sym3 ref = invariant_form(p, f);
    for (int c = 0; c < 6; ++c) EXPECT_NEAR(s[c], ref[c], 1e-9 * p.c1);
  }
  // Undeformed: no stress.
  const Sym3 zero = mooney_rivlin_stress(p, {1, 0, 0, 0, 1, 0, 0, 0, 1});
  for (int c = 0; c < 6; ++c) EXPECT_NEAR(zero[c], 0.0, 1e-9);
}

// h(t) for constant rate r: 2 alpha r (1 - exp(-t/beta)); one step of the recursion reproduces
// it exactly; beta = 0 is Newtonian, alpha = 0 switches a term off.
TEST(MooneyRivlin, ViscousStepFactorsAreTheExactExponentialIntegrator) {
  MooneyRivlinParams p;
  p.alpha = {100.0, 0.0, 7.0, 0.0};
  p.beta = {0.01, 5.0, 0.0, 0.0};
  EXPECT_EQ(viscous_term_count(p), 2);
  const double dt = 0.004;
  const ViscousStep s = viscous_step(p, dt);
  ASSERT_EQ(s.count, 2);
  EXPECT_NEAR(s.decay[0], std::exp(-0.4), 1e-15);
  EXPECT_NEAR(s.gain[0] * dt, 2 * 100.0 * (1 - std::exp(-0.4)), 1e-12);
  EXPECT_EQ(s.decay[1], 0.0);
  EXPECT_NEAR(s.gain[1], 2 * 7.0 / dt, 1e-12);
}

}  // namespace
}  // namespace abut
