#include "rigid_body.hpp"

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
  inertia0 = Mat3{};
  for (const std::int32_t n : nodes) {
    const Vec3 r = Vec3{x[n], y[n], z[n]} - centre;
    arm0.push_back(r);
    // Point-mass inertia about the centre: m (r.r I - r (x) r).
    const double rr = dot(r, r);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        inertia0(i, j) += nodal_mass[n] * ((i == j ? rr : 0.0) - r[i] * r[j]);
  }
  rotation = Mat3::identity();
}

Mat3 RigidBody::spatial_inertia() const { return rotation * inertia0 * transpose(rotation); }

double RigidBody::kinetic_energy(const Vec3& v, const Vec3& omega) const {
  return 0.5 * mass * dot(v, v) + 0.5 * dot(omega, spatial_inertia() * omega);
}

}  // namespace abut
