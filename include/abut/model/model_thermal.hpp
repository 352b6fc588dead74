#pragma once
// The thermal side of the model (issue 11): thermal properties of the materials, initial and
// prescribed temperatures, heat flux and convection on exterior faces. Filled by the deck reader
// (entities resolved to node indices and face node quads, as the static side does); read by the
// heat solver (solver/heat.hpp). Temperatures in the deck's temperature unit: only differences
// matter, except in user functions of the temperature.
#include <array>
#include <cstdint>
#include <vector>

#include "abut/core/error.hpp"
#include "abut/core/functions.hpp"

namespace abut {

// *PROP_THERMAL, referred to by the thpid of a material line (IMPETUS style).
struct ThermalProperties {
  std::int64_t id = 0;
  double conductivity = 0.0;    // k [power / (length temperature)] >= 0
  double specific_heat = 0.0;   // c [energy / (mass temperature)] > 0
  double expansion = 0.0;       // alpha [1 / temperature]
  double taylor_quinney = 0.9;  // share of the plastic work that becomes heat, in [0, 1]
  SourceLocation where;
};

// The temperature of some nodes at t = 0.
struct InitialTemperature {
  std::vector<std::int32_t> nodes;
  double value = 0.0;
  SourceLocation where;
};

// Nodes held at T(t) = scale * curve(t) (T = scale without a curve).
struct PrescribedTemperature {
  std::vector<std::int32_t> nodes;
  FunctionRef curve;
  double scale = 1.0;
  SourceLocation where;
};

// Exterior faces (node quads, counter-clockwise seen from outside; a triangle repeats its last
// node) with a heat flux into the body q(t) = scale * curve(t) [power / area], or convection to
// an ambient temperature, q = h (T_ambient - T) [power / area]. Without a curve q = scale.
struct SurfaceHeatFlux {
  std::vector<std::array<std::int32_t, 4>> faces;
  FunctionRef curve;
  double scale = 1.0;
  SourceLocation where;
};

struct SurfaceConvection {
  std::vector<std::array<std::int32_t, 4>> faces;
  double coefficient = 0.0;  // h [power / (area temperature)]
  double ambient = 0.0;      // T_ambient
  SourceLocation where;
};

struct ThermalModel {
  std::vector<ThermalProperties> properties;
  double initial_temperature = 0.0;  // every node without an InitialTemperature
  std::vector<InitialTemperature> initial;
  std::vector<PrescribedTemperature> prescribed;
  std::vector<SurfaceHeatFlux> fluxes;
  std::vector<SurfaceConvection> convection;
  const ThermalProperties* find(std::int64_t id) const {
    for (const ThermalProperties& p : properties)
      if (p.id == id) return &p;
    return nullptr;
  }
};

}  // namespace abut
