#pragma once
// Adhesion of Radioss /INTER/TYPE25 with IVIS2 = -1 (seed 004, comment 12): a zone of width
// Gap/2 outside the contact surface. A point that has touched and then moves back out into the
// zone is pulled back by
//     F_N = SigMaxAdh * Area * (Gap/2 - P_adh) / (Gap/2),
// where P_adh = Gap/2 - s is its penetration into the zone counted from the zone's outer border
// (s = opening from the surface): the pull grows from 0 at the surface to SigMaxAdh * Area at the
// border, where the adhesive spring breaks until the point touches again. In the zone a viscous
// tangential force F_T = ViscAdhFact * ViscFluid * Area * V_rel / (Gap/2) replaces friction.
#include "abut/core/vec3.hpp"

namespace abut {

struct Adhesion {
  double gap = 0.0;              // Gap: the zone is gap/2 wide [length]
  double max_stress = 0.0;       // SigMaxAdh [stress]
  double fluid_viscosity = 0.0;  // ViscFluid [stress * time]
  double viscous_factor = 1.0;   // ViscAdhFact

  double zone() const { return 0.5 * gap; }
  // Adhesive pressure (<= 0, a pull) at an opening s >= 0 of an adhered point; 0 beyond the zone.
  double pressure(double opening) const {
    if (!(opening >= 0.0) || opening > zone()) return 0.0;
    return -max_stress * opening / zone();
  }
  // Viscous tangential force of an adhered point in the zone.
  Vec3 viscous_force(const Vec3& slip_velocity, double area) const {
    return slip_velocity * (-viscous_factor * fluid_viscosity * area / zone());
  }
};

}  // namespace abut
