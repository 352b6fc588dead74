#pragma once
// Heat transfer through contact: the conductance h [power / (area temperature)] of a contact
// point, from its contact pressure p and its gap g (g > 0 open, g < 0 penetrating), so that the
// heat flux across the interface from side 1 to side 2 is q = h (T1 - T2) [power / area]; and the
// split of the friction work into heat on the two sides. Each law is a small value type a test
// can call alone; `conductance` dispatches.
#include <cmath>
#include <functional>
#include <variant>

namespace abut {

// IMPETUS *CONTACT fid_thermal (seed 000): "a FUNCTION defining the thermal contact
// conductivity", here of the contact pressure and the gap, h = f(p, g), for points that have a
// partner (open within the search distance or closed).
struct FunctionConductance {
  std::function<double(double pressure, double gap)> h;
  double operator()(double pressure, double gap) const { return h(pressure, gap); }
};

// Metafor TmFrictionlessContactMaterial and its friction variants (seed 002):
// h_c = h_c0 (p / H_v)^w, h_c0 the nominal conductance, H_v the Vickers hardness, w the exponent;
// no conduction without pressure.
struct PressureConductance {
  double nominal = 0.0;   // h_c0 [power / (area temperature)]
  double hardness = 1.0;  // H_v [stress]
  double exponent = 1.0;  // w
  double operator()(double pressure, double /*gap*/) const {
    return pressure > 0.0 ? nominal * std::pow(pressure / hardness, exponent) : 0.0;
  }
};

// OptiStruct contact-based thermal analysis (seed 003): one conductance while the contact is
// closed and another while it is open (the gap still within the search distance, where the pair
// exists).
struct OpenClosedConductance {
  double closed = 0.0;
  double open = 0.0;
  double operator()(double /*pressure*/, double gap) const { return gap <= 0.0 ? closed : open; }
};

// Radioss interface heat exchange: a conductance that depends on the distance between the
// surfaces, h = f(g) for an open pair (g >= 0) and f(0) once in contact.
struct DistanceConductance {
  std::function<double(double gap)> h;
  double operator()(double /*pressure*/, double gap) const { return h(gap > 0.0 ? gap : 0.0); }
};

using ConductanceLaw = std::variant<FunctionConductance, PressureConductance, OpenClosedConductance,
                                    DistanceConductance>;

inline double conductance(const ConductanceLaw& law, double pressure, double gap) {
  return std::visit([&](const auto& l) { return l(pressure, gap); }, law);
}

// Friction work converted to heat (IMPETUS fric_heat, seed 000; Radioss Fheat): the heat
// dW_f = |t| |slip| A of a point goes a fraction `to_side1` to side 1 (its own point, secondary
// surface) and the rest to side 2 (the partner facet); half and half by default.
struct FrictionHeatSplit {
  double to_side1 = 0.5;
  double side1(double work) const { return to_side1 * work; }
  double side2(double work) const { return (1.0 - to_side1) * work; }
};

}  // namespace abut
