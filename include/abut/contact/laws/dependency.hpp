#pragma once
// Metafor's parameter dependencies (seed 002, the "Dependency" column of its contact materials): a
// parameter is its value times a function of the time (TM) or of the gap (GD). abut takes the
// penetration d (> 0 inside, as the normal laws do) for the gap.
//   TimeFactor        value(t) = value f(t): PEN_NORMALE, PEN_TANGENT, COEF_FROT_STA,
//                     COEF_FROT_DYN, TRESCA_STA_M, TRESCA_DYN_M (TM)
//   TangentialPenalty k_t(d, t) = pen_t g(d) f(t): PEN_TANGENT (GD of the variable-penalty
//                     materials, TM of the others), with its slope dk_t/dd for the consistent
//                     tangent of static steps (static_contact.hpp)
// Both are constant within one evaluation of the contact (an explicit cycle or a Newton
// iteration of a static increment: t is the time of the evaluation), so a time factor adds no
// term to a tangent.
#include <algorithm>
#include <cmath>
#include <functional>

namespace abut {

// f(x): a function of one variable; must be thread-safe and cheap.
using ScalarFunction = std::function<double(double)>;

struct TimeFactor {
  ScalarFunction f;  // empty: 1 at all times
  double at(double t) const { return f ? f(t) : 1.0; }
  explicit operator bool() const { return static_cast<bool>(f); }
};

// The factor of the tangential penalty. The slope of g is a central difference on a step 1e-4 of
// d, at least 1e-9 (in the caller's length unit: at d = 0 a smaller step would leave only
// round-off, eps g / h).
struct TangentialPenalty {
  ScalarFunction of_penetration;  // g(d); empty: 1
  TimeFactor in_time;             // f(t)
  double factor(double d, double t) const {
    return (of_penetration ? of_penetration(d) : 1.0) * in_time.at(t);
  }
  double slope(double d, double t) const {
    if (!of_penetration) return 0.0;
    const double h = std::max(1e-4 * std::abs(d), 1e-9);
    return (of_penetration(d + h) - of_penetration(d - h)) / (2.0 * h) * in_time.at(t);
  }
  bool varies() const { return of_penetration || in_time; }
};

}  // namespace abut
