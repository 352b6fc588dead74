#include "abut/contact/laws/normal.hpp"

#include <cmath>

namespace abut {

NormalResponse CurvePenalty::evaluate(double d, double) const {
  const double sign = d < 0.0 ? -1.0 : 1.0;
  const double a = std::abs(d);
  // Slope by a central difference on a step small against d (one-sided at 0); energy by
  // Simpson's rule on 8 intervals, exact for curves up to cubic in d.
  const double h = a > 0.0 ? 1e-4 * a : 1e-12;
  const double lo = a > h ? a - h : 0.0;
  const double slope = (pressure(a + h) - pressure(lo)) / (a + h - lo);
  double energy = 0.0;
  if (a > 0.0) {
    constexpr int n = 8;
    const double step = a / n;
    double s = pressure(0.0) + pressure(a);
    for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * pressure(i * step);
    energy = s * step / 3.0;
  }
  return {sign * pressure(a), slope, energy};
}

NormalResponse ExponentialOverclosure::evaluate(double d, double) const {
  if (!(c0 > 0.0) || d < -c0) return {};
  const double beta = std::log(100.0) / c0;
  const double p = p0 * std::exp(beta * d);
  return {p, beta * p, (p - 0.01 * p0) / beta};
}

}  // namespace abut
