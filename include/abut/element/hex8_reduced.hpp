#pragma once
// The one-point hexahedron for the implicit solver: Abaqus / CalculiX C3D8R, the element the
// explicit solver uses (hex8.hpp, solid_block.hpp), with its Flanagan-Belytschko hourglass control
// in stiffness form, so that a model runs with the same element in both procedures.
//
// One Gauss point at the centroid with the mean gradient of FB81 (b_a / V, exact for linear
// fields); small strain or total Lagrangian (NLGEOM) exactly as hex8_full.hpp with that one point
// of weight V0. Hourglass (FB81 stiffness form, as solid_block.cpp): the generalized hourglass
// displacements q_alpha = sum_a gamma_alpha(a) u_a (gamma of the reference configuration, which
// are orthogonal to every linear field, so a rigid motion or a uniform strain -- finite rotations
// included -- excites none) resist with Q_alpha = k q_alpha, k = hourglass_modulus (b:b) / V0,
// f_a = sum_alpha gamma_alpha(a) Q_alpha, K_hg = k sum_alpha gamma_alpha (x) gamma_alpha (x) I.
// The explicit solver uses hourglass_modulus = c_hg 2 G (kHex8HourglassCoefficient).
//
// Results: Hex8FullResult with the one point's stress, strain and energy density copied to all
// eight slots (so that averaging over the slots gives the element value); min_jacobian is
// det F V0 / 8, the Jacobian at the centroid, and the volume det F V0 (F at the centroid).
#include "abut/element/hex8_full.hpp"

namespace abut {

template <Hex8MaterialPoint M>
void hex8_reduced_with(const Hex8FullInput& in, const M& material, double hourglass_modulus,
                       Hex8FullResult& out);

}  // namespace abut
