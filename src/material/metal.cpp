#include "abut/material/metal.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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

namespace {

// Johnson & Cook (1983): sigma_y = T H R with H = A + B eps^n and R = 1 + C ln(rate / rate0) from
// the reference rate on (it only strengthens). No pow without hardening (B = 0) and no log
// without a rate term (C = 0). Also H' = dH / d eps = n B eps^n / eps, unbounded at eps = 0 for
// n < 1 (the return's bracket takes over from Newton there).
struct JohnsonCook {
  double hardening = 0.0, hardening_slope = 0.0, rate_factor = 1.0;
  bool rate_hardens = false;
};
JohnsonCook johnson_cook(const MetalParams& p, double strain, double rate) {
  JohnsonCook jc;
  double power = 0.0;
  if (p.b != 0.0) {
    if (strain > 0.0) {
      power = p.b * std::pow(strain, p.n);
      jc.hardening_slope = p.n * power / strain;
    } else {
      jc.hardening_slope =
          p.n < 1.0 ? std::numeric_limits<double>::infinity() : (p.n == 1.0 ? p.b : 0.0);
    }
  }
  jc.hardening = p.a + power;
  const double ratio = rate / p.rate0;
  jc.rate_hardens = ratio > 1.0 && p.c != 0.0;
  if (jc.rate_hardens) jc.rate_factor = 1.0 + p.c * std::log(ratio);
  return jc;
}

}  // namespace

double FlowStress::operator()(double plastic_strain, double plastic_strain_rate) const {
  const MetalParams& p = *p_;
  if (!p.johnson_cook) {
    Variables v;
    v.epsp = plastic_strain;
    return thermal_factor_ * table_->value(p.flow_curve, plastic_strain, v);
  }
  const JohnsonCook jc = johnson_cook(p, plastic_strain, plastic_strain_rate);
  return thermal_factor_ * jc.hardening * jc.rate_factor;
}

FlowPoint FlowStress::along_step(double plastic_strain, double dp, double dt) const {
  const double strain = plastic_strain + dp;
  const double rate = dt > 0.0 ? dp / dt : 0.0;
  const MetalParams& p = *p_;
  if (!p.johnson_cook) return {(*this)(strain, rate), 0.0, false};
  // d sigma_y / d dp = T (H' R + H R') with R' = C / dp (rate = dp / dt).
  const JohnsonCook jc = johnson_cook(p, strain, rate);
  const double rate_slope = jc.rate_hardens ? p.c / dp : 0.0;
  return {thermal_factor_ * jc.hardening * jc.rate_factor,
          thermal_factor_ * (jc.hardening_slope * jc.rate_factor + jc.hardening * rate_slope),
          true};
}

PlasticUpdate radial_return(const Sym3& trial, double shear_modulus, double plastic_strain,
                            double dt, const FlowStress& flow) {
  const Sym3 s = deviator(trial);
  const double q = std::sqrt(1.5 * double_dot(s, s));
  FlowPoint y = flow.along_step(plastic_strain, 0.0, dt);
  if (q <= y.stress) return {trial, 0.0};
  const double g3 = 3.0 * shear_modulus;
  // f(dp) = q - 3 G dp - sigma_y(dp): f(0) > 0, f(q / 3G) = -sigma_y < 0 (sigma_y >= 0).
  // Newton with f' = -3G - sigma_y', sigma_y' in closed form (Johnson-Cook) or by a forward
  // difference (a curve); bisection when a step leaves the bracket.
  double lo = 0.0, hi = q / g3, dp = 0.0;
  for (int iteration = 0; iteration < 60; ++iteration) {
    const double value = q - g3 * dp - y.stress;
    if (value > 0.0)
      lo = dp;
    else
      hi = dp;
    if (std::abs(value) <= 1e-12 * q || hi - lo <= 1e-15 * (hi + lo)) break;
    double slope = -g3 - y.slope;  // < 0: -3G - H
    if (!y.has_slope) {
      const double h = std::max(1e-8 * (plastic_strain + dp), 1e-14);
      slope = (q - g3 * (dp + h) - flow.along_step(plastic_strain, dp + h, dt).stress - value) / h;
    }
    double next = slope < 0.0 ? dp - value / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    dp = next;
    y = flow.along_step(plastic_strain, dp, dt);
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
