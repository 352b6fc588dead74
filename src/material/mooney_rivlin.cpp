#include "abut/material/mooney_rivlin.hpp"

#include <cmath>

namespace abut {

Sym3 mooney_rivlin_stress(const MooneyRivlinParams& p, const Mat3& f) {
  // Invariant form (mooney_rivlin.hpp): sigma = (2/J) dev[(C1 + C2 I1_bar) b_bar - C2 b_bar^2]
  // + K (J - 1) I, no eigen-decomposition.
  const double det = f[0] * (f[4] * f[8] - f[5] * f[7]) - f[1] * (f[3] * f[8] - f[5] * f[6]) +
                     f[2] * (f[3] * f[7] - f[4] * f[6]);
  const double iso = std::pow(det, -2.0 / 3.0);
  const auto row_dot = [&](int i, int j) {
    return iso * (f[3 * i] * f[3 * j] + f[3 * i + 1] * f[3 * j + 1] + f[3 * i + 2] * f[3 * j + 2]);
  };
  // b_bar in Sym3 order xx, yy, zz, xy, yz, zx.
  const double b[6] = {row_dot(0, 0), row_dot(1, 1), row_dot(2, 2),
                       row_dot(0, 1), row_dot(1, 2), row_dot(2, 0)};
  // b_bar^2, same order.
  const double b2[6] = {
      b[0] * b[0] + b[3] * b[3] + b[5] * b[5], b[3] * b[3] + b[1] * b[1] + b[4] * b[4],
      b[5] * b[5] + b[4] * b[4] + b[2] * b[2], b[0] * b[3] + b[3] * b[1] + b[5] * b[4],
      b[3] * b[5] + b[1] * b[4] + b[4] * b[2], b[5] * b[0] + b[4] * b[3] + b[2] * b[5]};
  const double i1 = b[0] + b[1] + b[2];
  const double factor = p.c1 + p.c2 * i1;
  const double two_over_j = 2.0 / det;
  Sym3 s;
  for (int c = 0; c < 6; ++c) s[c] = two_over_j * (factor * b[c] - p.c2 * b2[c]);
  const double mean = (s[0] + s[1] + s[2]) / 3.0;
  const double pressure_part = p.bulk * (det - 1.0);  // -p with p = -K eps_v, eps_v = J - 1
  for (int c = 0; c < 3; ++c) s[c] += pressure_part - mean;
  return s;
}

int viscous_term_count(const MooneyRivlinParams& p) {
  int n = 0;
  for (double alpha : p.alpha) n += alpha > 0.0 ? 1 : 0;
  return n;
}

ViscousStep viscous_step(const MooneyRivlinParams& p, double dt) {
  ViscousStep s;
  for (std::size_t k = 0; k < p.alpha.size(); ++k) {
    if (!(p.alpha[k] > 0.0)) continue;
    const double decay = p.beta[k] > 0.0 ? std::exp(-dt / p.beta[k]) : 0.0;
    s.decay[s.count] = decay;
    s.gain[s.count] = 2.0 * p.alpha[k] * (1.0 - decay) / dt;
    ++s.count;
  }
  return s;
}

}  // namespace abut
