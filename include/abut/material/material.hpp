#pragma once
// Material parameters as read from the deck (plain values, deck units).
#include <array>
#include <cstdint>
#include <variant>

#include "abut/core/functions.hpp"

namespace abut {

// *MAT_ELASTIC: isotropic linear elasticity (objective rate form for large rotations).
struct ElasticParams {
  double density = 0.0;
  double young = 0.0;
  double poisson = 0.0;
};

// *MAT_MOONEY_RIVLIN (IMPETUS form): deviatoric Mooney-Rivlin on the eigenvalues of dev C,
// pressure p = -K*eps_v, plus up to four viscous terms
//   sigma_v = sum_k (2 alpha_k / beta_k) int_0^t dev(eps_dot)(tau) exp((tau - t)/beta_k) dtau.
// A term with alpha_k > 0 and beta_k == 0 is the limit beta -> 0: sigma_v = 2 alpha_k dev(eps_dot).
struct MooneyRivlinParams {
  double density = 0.0;
  double bulk = 0.0;
  double c1 = 0.0;
  double c2 = 0.0;
  std::array<double, 4> alpha{};
  std::array<double, 4> beta{};
};

// *MAT_RIGID: the part moves as one rigid body; only the density matters.
struct RigidParams {
  double density = 0.0;
};

// *MAT_METAL and *MAT_JC: isotropic elasticity with von Mises (J2) plasticity and isotropic
// hardening; the flow stress sigma_y(epsp, epsp_rate) is
//   *MAT_METAL  a *CURVE or *FUNCTION of the plastic strain (cid; a function reads `epsp`),
//   *MAT_JC     Johnson-Cook (A + B epsp^n)(1 + C ln(epsp_rate / rate0)) for epsp_rate > rate0.
// See metal.hpp for the return mapping.
// *PROP_DAMAGE_JC, the ductile failure of Johnson & Cook (1985, Eng. Fract. Mech. 21:31): the
// failure strain eps_f = [d1 + d2 exp(d3 sigma*)] [1 + d4 ln max(epsp_rate / rate0, 1)] with the
// triaxiality sigma* = mean stress / von Mises stress; the damage D = sum d epsp / eps_f grows
// with the plastic strain, and a point with D >= 1 has failed: it carries no stress from then on.
// d1 alone is a constant plastic failure strain. With a temperature field the product has the
// third factor 1 + d5 T*, T* the homologous temperature of the metal's T0 and Tm (metal.hpp).
struct DuctileFailure {
  bool active = false;
  double d1 = 0.0, d2 = 0.0, d3 = 0.0, d4 = 0.0, d5 = 0.0, rate0 = 1.0;
  double thermal_factor = 1.0;  // 1 + d5 T* at the point's temperature (MetalPoint::at_temperature)
};

struct MetalParams {
  double density = 0.0;
  double young = 0.0;
  double poisson = 0.0;
  bool johnson_cook = false;
  FunctionRef flow_curve;                                  // *MAT_METAL cid
  double a = 0.0, b = 0.0, n = 1.0, c = 0.0, rate0 = 1.0;  // *MAT_JC
  DuctileFailure failure;                                  // did: *PROP_DAMAGE_JC
  // Thermal softening (m, T0, Tm of both keywords; metal.hpp): the flow stress times 1 - T*^m.
  // m = 0 switches it off; it needs a temperature field (the material's thermal properties).
  double softening_m = 0.0, room_temperature = 0.0, melting_temperature = 0.0;
  bool softens() const { return softening_m > 0.0; }
  // The law depends on the temperature: softening, or a failure strain with d5.
  bool thermal() const { return softens() || (failure.active && failure.d5 != 0.0); }
};

using MaterialParams = std::variant<ElasticParams, MooneyRivlinParams, RigidParams, MetalParams>;

inline double density_of(const MaterialParams& m) {
  return std::visit([](const auto& p) { return p.density; }, m);
}
inline bool is_rigid(const MaterialParams& m) { return std::holds_alternative<RigidParams>(m); }

// Initial linear bulk and shear moduli (for wave speeds, time step and contact stiffness).
struct ElasticModuli {
  double bulk = 0.0;
  double shear = 0.0;
};
ElasticModuli initial_moduli(const MaterialParams& m);

}  // namespace abut
