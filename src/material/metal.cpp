#include "abut/material/metal.hpp"

#include <algorithm>
#include <cmath>

#include "abut/material/point_law.hpp"

namespace abut {

double homologous_temperature(const MetalParams& p, double temperature) {
  if (!(p.melting_temperature > p.room_temperature)) return 0.0;
  return std::clamp(
      (temperature - p.room_temperature) / (p.melting_temperature - p.room_temperature), 0.0, 1.0);
}

double thermal_softening(const MetalParams& p, double temperature) {
  if (!p.softens()) return 1.0;
  return 1.0 - std::pow(homologous_temperature(p, temperature), p.softening_m);
}

double FlowStress::operator()(double plastic_strain, double plastic_strain_rate) const {
  const MetalParams& p = *p_;
  if (!p.johnson_cook) {
    Variables v;
    v.epsp = plastic_strain;
    return thermal_factor_ * table_->value(p.flow_curve, plastic_strain, v);
  }
  // Johnson & Cook (1983): the rate factor only strengthens, from the reference rate on.
  const double hardening = p.a + (plastic_strain > 0.0 ? p.b * std::pow(plastic_strain, p.n) : 0.0);
  const double ratio = plastic_strain_rate / p.rate0;
  return thermal_factor_ * hardening * (ratio > 1.0 ? 1.0 + p.c * std::log(ratio) : 1.0);
}

PlasticUpdate radial_return(const Sym3& trial, double shear_modulus, double plastic_strain,
                            double dt, const FlowStress& flow) {
  const Sym3 s = deviator(trial);
  const double q = std::sqrt(1.5 * double_dot(s, s));
  const auto yield = [&](double dp) { return flow(plastic_strain + dp, dt > 0.0 ? dp / dt : 0.0); };
  if (q <= yield(0.0)) return {trial, 0.0};
  const double g3 = 3.0 * shear_modulus;
  // f(dp) = q - 3 G dp - sigma_y(dp): f(0) > 0, f(q / 3G) = -sigma_y < 0 (sigma_y >= 0).
  auto f = [&](double dp) { return q - g3 * dp - yield(dp); };
  double lo = 0.0, hi = q / g3, dp = 0.0;
  for (int iteration = 0; iteration < 60; ++iteration) {
    const double value = f(dp);
    if (value > 0.0)
      lo = dp;
    else
      hi = dp;
    if (std::abs(value) <= 1e-12 * q || hi - lo <= 1e-15 * (hi + lo)) break;
    const double h = std::max(1e-8 * (plastic_strain + dp), 1e-14);
    const double slope = (f(dp + h) - value) / h;  // < 0: -3G - H
    double next = slope < 0.0 ? dp - value / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    dp = next;
  }
  const double scale = (q - g3 * dp) / q;
  const double pressure = trace(trial) / 3.0;
  return {{{pressure + scale * s[0], pressure + scale * s[1], pressure + scale * s[2], scale * s[3],
            scale * s[4], scale * s[5]}},
          dp};
}

double failure_strain(const DuctileFailure& f, const Sym3& stress, double plastic_strain_rate) {
  const double q = von_mises(stress);
  const double triaxiality = q > 0.0 ? trace(stress) / (3.0 * q) : 0.0;
  const double ratio = plastic_strain_rate / f.rate0;
  return (f.d1 + f.d2 * std::exp(f.d3 * triaxiality)) *
         (1.0 + f.d4 * std::log(ratio > 1.0 ? ratio : 1.0)) * f.thermal_factor;
}

}  // namespace abut
