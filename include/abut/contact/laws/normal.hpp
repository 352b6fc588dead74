#pragma once
// Normal laws: contact pressure from the penetration d (> 0 when the point is inside the other
// body, measured along the partner facet's normal). Each law returns the pressure, its slope
// dp/dd (the spring per unit area, for damping and the stable step) and the energy stored per
// unit area, so that explicit and implicit procedures can share it.
#include <functional>
#include <variant>

namespace abut {

struct NormalResponse {
  double pressure = 0.0;   // [stress]; negative = tension (bilateral or adhesive contact)
  double stiffness = 0.0;  // dp/dd [stress / length]
  double energy = 0.0;     // integral of p dd from 0 to d [energy / area]
};

// Which side of the partner surface a point must stay on (Metafor TYPE_CONT, seed 002):
// Positive: outside (ordinary contact; default); Negative: inside, the surface is approached from
// behind; Bilateral: on the surface, held in tension as well as in compression, free to slide.
enum class ContactSense { Positive, Negative, Bilateral };

// p = pfac d, with pfac the penalty of the facet pair (seed 000, Metafor PEN_NORMALE).
struct LinearPenalty {
  NormalResponse evaluate(double d, double pfac) const {
    return {pfac * d, pfac, 0.5 * pfac * d * d};
  }
};

// p = f(d) from a user curve of the penetration (Metafor
// FrictionlessVariablePenaltyContactMaterial: PEN_NORMALE as a function of the gap). f is applied
// as an odd function, f(-d) = -f(d), so a bilateral contact pulls back as it pushes. The slope and
// energy are evaluated numerically.
struct CurvePenalty {
  std::function<double(double penetration)> pressure;  // f(d) for d >= 0; f(0) should be 0
  NormalResponse evaluate(double d, double pfac) const;
};

// Soft contact with a pressure at clearance (CalculiX *SURFACE BEHAVIOR,
// PRESSURE-OVERCLOSURE=EXPONENTIAL; CalculiX User's Manual, "Node-to-Face Penalty Contact",
// eqs. 108-109): p = p0 exp(beta d), beta = ln(100) / c0, so p = p0 at zero distance and 1% of
// p0 at the clearance c0; no pressure beyond c0 (d < -c0). Acts at clearance: d may be negative.
// The energy is measured from d = -c0. pfac is not used.
struct ExponentialOverclosure {
  double c0 = 0.0, p0 = 0.0;
  NormalResponse evaluate(double d, double /*pfac*/) const;
};

using NormalLaw = std::variant<LinearPenalty, CurvePenalty, ExponentialOverclosure>;

// How far outside the surface (clearance) a law still pushes: 0 except for the exponential law.
inline double reach_at_clearance(const NormalLaw& law) {
  const auto* e = std::get_if<ExponentialOverclosure>(&law);
  return e ? e->c0 : 0.0;
}

inline NormalResponse evaluate(const NormalLaw& law, double d, double pfac) {
  return std::visit([&](const auto& l) { return l.evaluate(d, pfac); }, law);
}

// The law's response times a factor f (Metafor PEN_NORMALE with a time dependency TM,
// laws/dependency.hpp: for LinearPenalty exactly the law with pfac f). Pressure, slope and energy
// scale alike, so the slope stays the derivative of the pressure at a fixed f.
inline NormalResponse scaled(const NormalResponse& r, double f) {
  return {r.pressure * f, r.stiffness * f, r.energy * f};
}

}  // namespace abut
