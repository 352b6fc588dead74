#include "abut/material/mooney_rivlin.hpp"

#include <cmath>

namespace abut {

Sym3 mooney_rivlin_stress(const MooneyRivlinParams& p, const Mat3& f) {
  const double det = f[0] * (f[4] * f[8] - f[5] * f[7]) - f[1] * (f[3] * f[8] - f[5] * f[6]) +
                     f[2] * (f[3] * f[7] - f[4] * f[6]);
  const double iso = std::pow(det, -2.0 / 3.0);
  const auto row_dot = [&](int i, int j) {
    return iso * (f[3 * i] * f[3 * j] + f[3 * i + 1] * f[3 * j + 1] + f[3 * i + 2] * f[3 * j + 2]);
  };
  const Sym3 b_bar{
      {row_dot(0, 0), row_dot(1, 1), row_dot(2, 2), row_dot(0, 1), row_dot(1, 2), row_dot(2, 0)}};
  const SymEigen e = eigen_symmetric(b_bar);
  const double l1 = e.values[0], l2 = e.values[1], l3 = e.values[2];
  const double a = 2.0 * p.c1 / 3.0, b = 2.0 * p.c2 / 3.0;
  const double inv_j = 1.0 / det;
  const std::array<double, 3> principal{
      inv_j * (a * (2.0 * l1 - l2 - l3) - b * (2.0 / l1 - 1.0 / l2 - 1.0 / l3)),
      inv_j * (a * (2.0 * l2 - l3 - l1) - b * (2.0 / l2 - 1.0 / l3 - 1.0 / l1)),
      inv_j * (a * (2.0 * l3 - l1 - l2) - b * (2.0 / l3 - 1.0 / l1 - 1.0 / l2))};
  Sym3 s = from_spectral(principal, e.vectors);
  const double pressure_part = p.bulk * (det - 1.0);  // -p with p = -K eps_v, eps_v = J - 1
  s[0] += pressure_part;
  s[1] += pressure_part;
  s[2] += pressure_part;
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
