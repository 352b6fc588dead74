#pragma once
// A rigid part (*MAT_RIGID): its nodes move as one body, translation of the centre of mass
// plus rotation. Nodal forces are reduced to a force and a moment about the centre of mass;
// angular momentum is integrated in the spatial frame with the current inertia R I0 R^T and
// the orientation updated by the exponential map (Rodrigues), which keeps R orthogonal. I0 is
// kept in principal axes (principal_inertia.hpp): inverting it is a division per axis, and the
// kinetic energy is a sum of squares, never negative.
#include <cstdint>
#include <vector>

#include "abut/core/mat3.hpp"
#include "abut/core/state_archive.hpp"
#include "abut/core/vec3.hpp"

namespace abut {

struct RigidBody {
  std::int64_t part_id = 0;
  std::vector<std::int32_t> nodes;
  std::vector<Vec3> arm0;  // reference position of each node relative to the centre of mass
  double mass = 0.0;
  Vec3 principal_moments;  // of inertia about the centre of mass
  Mat3 principal_axes;     // columns: the principal axes in the reference orientation
  Vec3 centre0;            // reference centre of mass
  Vec3 centre;             // current centre of mass
  Vec3 velocity;           // of the centre of mass, at the half step
  Vec3 angular_velocity;   // spatial, at the half step
  // v^{n-1/2} and omega^{n-1/2} during the kick at t^n (velocity and angular_velocity are then
  // v^{n+1/2} and omega^{n+1/2}); set by each kick, not part of the state.
  Vec3 previous_velocity, previous_angular_velocity;
  Mat3 rotation = Mat3::identity();

  // Builds the body from its nodes' reference positions and lumped masses.
  void initialise(const std::vector<double>& x, const std::vector<double>& y,
                  const std::vector<double>& z, const std::vector<double>& nodal_mass);
  // Angular momentum R I0 R^T omega of the angular velocity omega, and the inverse map.
  Vec3 angular_momentum(const Vec3& omega) const;
  Vec3 angular_velocity_of(const Vec3& momentum) const;
  // (1/2) M v.v + (1/2) omega.(R I0 R^T) omega, as a sum of squares in the principal axes.
  double kinetic_energy(const Vec3& v, const Vec3& omega) const;
  // The motion (the rest is fixed by the reference configuration), for a restart.
  void archive(StateArchive& a) { a.values(centre, velocity, angular_velocity, rotation); }
};

}  // namespace abut
