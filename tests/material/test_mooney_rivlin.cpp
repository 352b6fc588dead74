// Mooney-Rivlin material point: the invariant-form evaluation against the IMPETUS spectral
// definition, and the viscous exponential-integrator factors.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "abut/material/mooney_rivlin.hpp"
#include "abut/material/sym_tensor.hpp"

namespace abut {
namespace {

double determinant(const Mat3& f) {
  return f[0] * (f[4] * f[8] - f[5] * f[7]) - f[1] * (f[3] * f[8] - f[5] * f[6]) +
         f[2] * (f[3] * f[7] - f[4] * f[6]);
}

// The IMPETUS definition itself (impetus-keywords.md §4, mooney_rivlin.hpp): principal values
//   tau_1 = (2 C1/3)(2 l1 - l2 - l3) - (2 C2/3)(2/l1 - 1/l2 - 1/l3)   (cyclic)
// on the eigenvalues l_i and eigenvectors n_i of b_bar = J^(-2/3) F F^T (Jacobi, sym_tensor.hpp,
// tested in test_sym_tensor.cpp), sigma = (1/J) sum_i tau_i n_i (x) n_i + K (J - 1) I.
Sym3 impetus_spectral_form(const MooneyRivlinParams& p, const Mat3& f) {
  const double j = determinant(f);
  const double iso = std::pow(j, -2.0 / 3.0);
  const auto row_dot = [&](int r, int c) {
    return iso * (f[3 * r] * f[3 * c] + f[3 * r + 1] * f[3 * c + 1] + f[3 * r + 2] * f[3 * c + 2]);
  };
  const SymEigen e = eigen_symmetric(
      {{row_dot(0, 0), row_dot(1, 1), row_dot(2, 2), row_dot(0, 1), row_dot(1, 2), row_dot(2, 0)}});
  std::array<double, 3> tau{};
  for (int i = 0; i < 3; ++i) {
    const double l1 = e.values[i], l2 = e.values[(i + 1) % 3], l3 = e.values[(i + 2) % 3];
    tau[i] = (2 * p.c1 / 3 * (2 * l1 - l2 - l3) - 2 * p.c2 / 3 * (2 / l1 - 1 / l2 - 1 / l3)) / j;
  }
  Sym3 s = from_spectral(tau, e.vectors);
  for (int c = 0; c < 3; ++c) s[c] += p.bulk * (j - 1.0);
  return s;
}

// Largest stress component, the scale for round-off.
double magnitude(const Sym3& s) {
  double m = 0.0;
  for (int c = 0; c < 6; ++c) m = std::max(m, std::abs(s[c]));
  return m;
}

// mooney_rivlin_stress evaluates the invariant form of the same potential (Holzapfel 2000,
// eqs. 6.103 and 6.146); it must reproduce the IMPETUS spectral definition to round-off.
TEST(MooneyRivlin, InvariantFormEqualsTheImpetusSpectralForm) {
  const MooneyRivlinParams p{1100.0, 2.0e7, 4.0e5, 1.5e5, {}, {}};
  const Mat3 cases[] = {
      {1.5, 0, 0, 0, 0.85, 0, 0, 0, 0.8},                 // stretch
      {1.0, 0.4, 0, 0, 1.0, 0, 0, 0, 1.0},                // simple shear
      {1.2, 0.3, -0.1, 0.05, 0.9, 0.2, 0.1, -0.15, 1.1},  // general
      {1.3, 0, 0, 0, 1.3, 0, 0, 0, 0.7},                  // two equal stretches
  };
  for (const Mat3& f : cases) {
    const Sym3 s = mooney_rivlin_stress(p, f);
    const Sym3 ref = impetus_spectral_form(p, f);
    for (int c = 0; c < 6; ++c) EXPECT_NEAR(s[c], ref[c], 1e-13 * magnitude(ref));
  }
  // Undeformed: no stress.
  const Sym3 zero = mooney_rivlin_stress(p, {1, 0, 0, 0, 1, 0, 0, 0, 1});
  for (int c = 0; c < 6; ++c) EXPECT_NEAR(zero[c], 0.0, 1e-9);
}

// The same on 1000 pseudo-random deformation gradients F = I + A, |A_ij| <= 0.6, det F >= 0.2,
// with C2 of both signs and without the volumetric term (K = 0), so that the isochoric part is
// compared on its own scale.
TEST(MooneyRivlin, InvariantFormEqualsTheSpectralFormOnRandomDeformations) {
  std::uint32_t seed = 2024u;
  const auto uniform = [&]() {  // deterministic LCG in [-1, 1]
    seed = seed * 1664525u + 1013904223u;
    return (static_cast<double>(seed >> 8) / static_cast<double>(1u << 24)) * 2.0 - 1.0;
  };
  const MooneyRivlinParams params[] = {{1100.0, 0.0, 4.0e5, 1.5e5, {}, {}},
                                       {1100.0, 0.0, 1.0e6, -2.0e5, {}, {}},
                                       {1100.0, 3.0e9, 1.0e6, 0.0, {}, {}}};
  int checked = 0;
  while (checked < 1000) {
    Mat3 f;
    for (int i = 0; i < 9; ++i) f[i] = (i % 4 == 0 ? 1.0 : 0.0) + 0.6 * uniform();
    if (determinant(f) < 0.2) continue;
    const MooneyRivlinParams& p = params[checked % 3];
    const Sym3 s = mooney_rivlin_stress(p, f);
    const Sym3 ref = impetus_spectral_form(p, f);
    for (int c = 0; c < 6; ++c) {
      ASSERT_NEAR(s[c], ref[c], 1e-13 * magnitude(ref)) << "case " << checked << " component " << c;
    }
    ++checked;
  }
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
