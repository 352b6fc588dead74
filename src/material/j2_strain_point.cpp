// Strain-driven J2 point of the implicit elements: see j2_strain_point.hpp.
#include "abut/material/j2_strain_point.hpp"

#include <algorithm>
#include <cmath>

namespace abut {

double J2StrainPoint::evaluate(int point, const double strain[6], double stress[6],
                               double d[36]) const {
  const J2PointHistory& old = committed[point];
  J2PointHistory& now = trial[point];
  const double g = young / (2.0 * (1.0 + poisson));
  const double bulk = young / (3.0 * (1.0 - 2.0 * poisson));

  // Trial stress from the elastic strain (tensor shears are half the engineering ones).
  double e[6];
  for (int i = 0; i < 6; ++i) e[i] = strain[i] - old.plastic_strain[i];
  const double volumetric = e[0] + e[1] + e[2];
  Sym3 trial_stress;
  for (int i = 0; i < 3; ++i)
    trial_stress[i] = bulk * volumetric + 2.0 * g * (e[i] - volumetric / 3.0);
  for (int i = 3; i < 6; ++i) trial_stress[i] = g * e[i];

  const PlasticUpdate r = radial_return(trial_stress, g, old.equivalent_plastic_strain, 0.0, flow);
  const double dp = r.plastic_strain_increment;
  for (int i = 0; i < 6; ++i) stress[i] = r.stress[i];

  // Elastic tangent K 1 (x) 1 + 2 G I_dev (I_dev on engineering strains: 1/2 on the shears).
  std::fill(d, d + 36, 0.0);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) d[6 * i + j] = bulk - 2.0 * g / 3.0;
    d[6 * i + i] = bulk + 4.0 * g / 3.0;
  }
  for (int i = 3; i < 6; ++i) d[6 * i + i] = g;

  now = old;
  if (dp > 0.0) {
    const Sym3 s_trial = deviator(trial_stress);
    const double norm = std::sqrt(double_dot(s_trial, s_trial));
    const double q_trial = std::sqrt(1.5) * norm;
    const double p_new = old.equivalent_plastic_strain + dp;
    // Hardening slope at the new plastic strain by a central difference (one-sided at 0): the
    // flow stress may be a table, a function or Johnson-Cook.
    const double h = std::max(1e-6 * p_new, 1e-10);
    const double lo = std::max(p_new - h, 0.0);
    const double hardening = (flow(p_new + h, 0.0) - flow(lo, 0.0)) / (p_new + h - lo);
    const double a = 6.0 * g * g * dp / q_trial;
    const double b = 6.0 * g * g * (dp / q_trial - 1.0 / (3.0 * g + hardening));
    double n[6];
    for (int i = 0; i < 6; ++i) n[i] = s_trial[i] / norm;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) d[6 * i + j] -= a * ((i == j ? 1.0 : 0.0) - 1.0 / 3.0);
    for (int i = 3; i < 6; ++i) d[6 * i + i] -= 0.5 * a;
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) d[6 * i + j] += b * n[i] * n[j];
    // The return removed (s_trial - s) / 2G of deviatoric strain into the plastic strain.
    const Sym3 s = deviator(r.stress);
    for (int i = 0; i < 6; ++i)
      now.plastic_strain[i] += (i < 3 ? 1.0 : 2.0) * (s_trial[i] - s[i]) / (2.0 * g);
    now.equivalent_plastic_strain = p_new;
    now.plastic_work += 0.5 * (flow(old.equivalent_plastic_strain, 0.0) + flow(p_new, 0.0)) * dp;
  }
  double dw = 0.0;
  for (int i = 0; i < 6; ++i) {
    dw += 0.5 * (old.stress[i] + stress[i]) * (strain[i] - old.strain[i]);
    now.strain[i] = strain[i];
    now.stress[i] = stress[i];
  }
  now.energy = old.energy + dw;
  return now.energy;
}

}  // namespace abut
