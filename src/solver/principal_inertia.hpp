#pragma once
// The inertia of a rigid body's lumped masses about their centre of mass, in principal axes.
// Kept apart from rigid_body.cpp: the Jacobi solver it uses (sym_tensor.hpp, material layer)
// comes with a Mat3 of its own that mat3.hpp's would clash with.
#include <array>
#include <vector>

#include "abut/core/vec3.hpp"

namespace abut {

struct PrincipalInertia {
  std::array<double, 3> moments{};  // never below kInertiaFloor of the largest
  std::array<double, 9> axes{};     // axes[3 * i + k]: component i of principal axis k
};

// Below this share of the largest principal moment a moment is raised to it. The moments come
// from coordinates that carry a relative round-off of 1e-16 of the body's length L; the moment
// about the long axis of a body thinner than about 1e-8 L is below that and may come out zero
// or negative (issue 28: a 0.1 x 0.1 x 3e7 m rigid box). Raised to 1e-12 of the largest, it is
// positive, and a moment that round-off puts on such an axis (its arm is exact to 1e-16 L only)
// turns the body at most 1e-4 times as fast as that force accelerates it over L.
inline constexpr double kInertiaFloor = 1e-12;

// Point masses `masses` at `arms` from their centre of mass (sum of m r = 0). The tensor
// sum m (r.r I - r (x) r) is summed with its diagonal as m (y^2 + z^2), ..., so that no entry is a
// difference of large terms, then diagonalised (Jacobi).
PrincipalInertia principal_inertia(const std::vector<Vec3>& arms,
                                   const std::vector<double>& masses);

}  // namespace abut
