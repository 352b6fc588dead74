#pragma once
// *MAT_MOONEY_RIVLIN in the IMPETUS form (impetus-keywords.md §4).
//
// Elastic part. With l_i the eigenvalues of the isochoric left Cauchy-Green tensor
// b_bar = J^(-2/3) F F^T (the same as those of dev C = J^(-2/3) F^T F named by IMPETUS) and n_i
// its eigenvectors in the current configuration,
//   tau_1 = (2 C1/3)(2 l1 - l2 - l3) - (2 C2/3)(2/l1 - 1/l2 - 1/l3)   (cyclic for 2, 3),
//   sigma_e = (1/J) sum_i tau_i n_i (x) n_i + K (J - 1) I.
// Choice: the principal values tau_i are Kirchhoff stresses and we divide by J, and the
// volumetric strain is eps_v = J - 1. With that choice the stress derives from the decoupled
// potential W = C1 (I1_bar - 3) + C2 (I2_bar - 3) + K/2 (J - 1)^2 (Holzapfel, Nonlinear Solid
// Mechanics, 2000, §6.4-6.5: tau_iso = 2 dev[(C1 + C2 I1_bar) b_bar - C2 b_bar^2], whose principal
// values are the tau_i above), so the model conserves energy. Near incompressibility (J ~ 1) it
// coincides with the IMPETUS expression read as a Cauchy stress.
//
// Evaluation: mooney_rivlin_stress uses that invariant form, sigma_e = (2/J) dev[(C1 + C2 I1_bar)
// b_bar - C2 b_bar^2] + K (J - 1) I, which needs no eigenvectors. Its principal values are the
// tau_i / J above: with det b_bar = l1 l2 l3 = 1, (C1 + C2 I1_bar) l1 - C2 l1^2 = C1 l1 +
// C2 (1/l2 + 1/l3), whose deviator is tau_1 / 2. test_mooney_rivlin.cpp checks it against the
// spectral definition to round-off.
//
// Viscous part: sigma_v = sum_k h_k with, for alpha_k > 0,
//   h_k(t) = (2 alpha_k / beta_k) int_0^t dev(D)(tau) exp((tau - t)/beta_k) dtau,
// updated over a step with constant D by the exact recursion
//   h_k <- exp(-dt/beta_k) h_k + 2 alpha_k (1 - exp(-dt/beta_k)) dev(D).
// beta_k == 0 is the limit beta -> 0, the Newtonian term 2 alpha_k dev(D) (decay 0, gain 2
// alpha_k). alpha_k == 0 switches a term off. The element rotates h_k with the stress (objective
// update).
#include <array>

#include "abut/core/lanes.hpp"
#include "abut/material/material.hpp"
#include "abut/material/sym_tensor.hpp"

namespace abut {

// Elastic Cauchy stress of the deformation gradient F (invariant evaluation above).
Sym3 mooney_rivlin_stress(const MooneyRivlinParams& p, const Mat3& deformation_gradient);

// The same on plain arrays (f row-major, s in Sym3 order) for T = double or Lanes (lanes.hpp):
// mooney_rivlin_stress is this with T = double.
template <class T>
inline void mooney_rivlin_stress_of(const MooneyRivlinParams& p, const T f[9], T s[6]) {
  // Invariant form (above): sigma = (2/J) dev[(C1 + C2 I1_bar) b_bar - C2 b_bar^2]
  // + K (J - 1) I, no eigen-decomposition.
  const T det = f[0] * (f[4] * f[8] - f[5] * f[7]) - f[1] * (f[3] * f[8] - f[5] * f[6]) +
                f[2] * (f[3] * f[7] - f[4] * f[6]);
  const T iso = pow_of(det, -2.0 / 3.0);
  const auto row_dot = [&](int i, int j) {
    return iso * (f[3 * i] * f[3 * j] + f[3 * i + 1] * f[3 * j + 1] + f[3 * i + 2] * f[3 * j + 2]);
  };
  // b_bar in Sym3 order xx, yy, zz, xy, yz, zx.
  const T b[6] = {row_dot(0, 0), row_dot(1, 1), row_dot(2, 2),
                  row_dot(0, 1), row_dot(1, 2), row_dot(2, 0)};
  // b_bar^2, same order.
  const T b2[6] = {
      b[0] * b[0] + b[3] * b[3] + b[5] * b[5], b[3] * b[3] + b[1] * b[1] + b[4] * b[4],
      b[5] * b[5] + b[4] * b[4] + b[2] * b[2], b[0] * b[3] + b[3] * b[1] + b[5] * b[4],
      b[3] * b[5] + b[1] * b[4] + b[4] * b[2], b[5] * b[0] + b[4] * b[3] + b[2] * b[5]};
  const T i1 = b[0] + b[1] + b[2];
  const T factor = p.c1 + p.c2 * i1;
  const T two_over_j = 2.0 / det;
  for (int c = 0; c < 6; ++c) s[c] = two_over_j * (factor * b[c] - p.c2 * b2[c]);
  const T mean = (s[0] + s[1] + s[2]) / 3.0;
  const T pressure_part = p.bulk * (det - 1.0);  // -p with p = -K eps_v, eps_v = J - 1
  for (int c = 0; c < 3; ++c) s[c] += pressure_part - mean;
}

// The active viscous terms and their exponential-integrator factors for one step of length dt,
// applied to the strain increment dev(D) dt:  h_k <- decay[k] h_k + gain[k] dev(D) dt, so
// gain[k] = 2 alpha_k (1 - exp(-dt/beta_k)) / dt (2 alpha_k / dt when beta_k == 0).
struct ViscousStep {
  int count = 0;
  std::array<double, 4> decay{};
  std::array<double, 4> gain{};
};
// Number of active terms (alpha_k > 0).
int viscous_term_count(const MooneyRivlinParams& p);
// Factors for dt > 0, in the order of the active terms.
ViscousStep viscous_step(const MooneyRivlinParams& p, double dt);

}  // namespace abut
