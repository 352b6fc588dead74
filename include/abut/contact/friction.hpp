#pragma once
// Coulomb friction as an elastic predictor with return to the friction cone (the stick/slip
// rule written in the Radioss /INTER/TYPE25 page of seed 004: F_t = min(mu F_n, |F_t_old + K v_t dt|)
// along the trial direction; the same rule as radial return in plasticity).
#include "abut/core/vec3.hpp"

namespace abut {

struct CoulombFriction {
  double stiffness = 0.0;  // tangential spring of the contact point [force / length]

  struct Result {
    Vec3 force;               // tangential force on the contact point
    double slip_work = 0.0;   // energy dissipated by slip in this step (>= 0)
    bool sliding = false;
  };

  // `previous`: last step's tangential force (any normal component is removed here, so that the
  // history follows a rotating tangent plane); `slip_velocity`: relative tangential velocity of
  // the point with respect to the opposite surface; `limit` = mu * normal force.
  Result evaluate(Vec3 previous, const Vec3& normal, const Vec3& slip_velocity, double dt,
                  double limit) const {
    previous -= normal * dot(previous, normal);
    const Vec3 trial = previous - slip_velocity * (stiffness * dt);
    const double size = norm(trial);
    if (size <= limit) return {trial, 0.0, false};
    // Slip increment (size - limit) / stiffness against a force of magnitude `limit`.
    const Vec3 force = limit > 0.0 ? trial * (limit / size) : Vec3{};
    return {force, limit * (size - limit) / stiffness, true};
  }
};

}  // namespace abut
