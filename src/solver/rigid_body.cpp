#include "rigid_body.hpp"

#include "principal_inertia.hpp"

namespace abut {

void RigidBody::initialise(const std::vector<double>& x, const std::vector<double>& y,
                           const std::vector<double>& z, const std::vector<double>& nodal_mass) {
  mass = 0.0;
  Vec3 first_moment;
  for (const std::int32_t n : nodes) {
    mass += nodal_mass[n];
    first_moment += nodal_mass[n] * Vec3{x[n], y[n], z[n]};
  }
  centre = first_moment / mass;
  centre0 = centre;
  arm0.clear();
  std::vector<double> masses;
  for (const std::int32_t n : nodes) {
    arm0.push_back(Vec3{x[n], y[n], z[n]} - centre);
    masses.push_back(nodal_mass[n]);
  }
  const PrincipalInertia inertia = principal_inertia(arm0, masses);
  for (int k = 0; k < 3; ++k) {
    principal_moments[k] = inertia.moments[k];
    for (int i = 0; i < 3; ++i) principal_axes(i, k) = inertia.axes[3 * i + k];
  }
  rotation = Mat3::identity();
}

Vec3 RigidBody::angular_momentum(const Vec3& omega) const {
  const Mat3 axes = rotation * principal_axes;
  Vec3 p = transpose(axes) * omega;
  for (int k = 0; k < 3; ++k) p[k] *= principal_moments[k];
  return axes * p;
}

Vec3 RigidBody::angular_velocity_of(const Vec3& momentum) const {
  const Mat3 axes = rotation * principal_axes;
  Vec3 p = transpose(axes) * momentum;
  for (int k = 0; k < 3; ++k) p[k] /= principal_moments[k];
  return axes * p;
}

double RigidBody::kinetic_energy(const Vec3& v, const Vec3& omega) const {
  const Vec3 p = transpose(rotation * principal_axes) * omega;
  double energy = 0.5 * mass * dot(v, v);
  for (int k = 0; k < 3; ++k) energy += 0.5 * principal_moments[k] * p[k] * p[k];
  return energy;
}

}  // namespace abut
