#pragma once
// Contact stabilization of static steps (OptiStruct CNTSTB, seed 003 comment 7; the same idea as
// Abaqus/Standard's contact stabilization, Analysis User's Guide "Stabilization for general
// contact"): viscous damping of the relative motion of nearby surfaces, so that a part held only
// by contact that is not closed yet (a gap to cross, a frictionless side) has a stiffness until
// the contact holds it. Over an increment of length dt the damping c v, v = du / dt, is a spring on
// the relative incremental displacement du of a contact point on its partner:
//   t = -k P du,   k = factor c s_gap(g) / dt,   P = n (x) n + f_t (I - n (x) n),
// with c per unit area, f_t the tangential fraction (TFRAC), s_gap 1 for a closed point, falling
// linearly to 0 at the opening LMTGAP (range), and `factor` the step's ramp from S0 to S1 times
// the step period (set by the solver for each increment). Its work, k du . P du per unit area and
// increment, is dissipated: the solver reports it beside the friction work.
#include "abut/core/vec3.hpp"

namespace abut {

struct ContactStabilization {
  double coefficient = 0.0;       // c [stress / length] per unit of step time over dt
  double range = 0.0;             // no damping at openings >= range [length]
  double tangent_fraction = 1.0;  // f_t: tangential over normal damping

  // k of a point at gap g (negative: closed) for an increment dt, with the step's factor.
  double stiffness(double gap, double factor, double dt) const {
    if (!(dt > 0.0) || !(factor > 0.0) || !(coefficient > 0.0)) return 0.0;
    const double s_gap = gap <= 0.0 ? 1.0 : gap >= range ? 0.0 : 1.0 - gap / range;
    return factor * coefficient * s_gap / dt;
  }
  // P du for a unit normal n.
  Vec3 project(const Vec3& du, const Vec3& n) const {
    const Vec3 normal_part = n * dot(du, n);
    return normal_part + (du - normal_part) * tangent_fraction;
  }
  // P_ij.
  double projector(const Vec3& n, int i, int j) const {
    return n[i] * n[j] + tangent_fraction * ((i == j ? 1.0 : 0.0) - n[i] * n[j]);
  }
};

}  // namespace abut
