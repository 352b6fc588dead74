#pragma once
// Geometry of the 4-node Belytschko-Tsay shell (Belytschko, Lin & Tsay 1984, CMAME 42:225; the
// LS-DYNA Theory Manual's "Belytschko-Tsay shell"): a co-rotational frame per element, the
// projected node coordinates in it, the one-point gradient operator and the hourglass vector.
//
// Frame: e3 along the cross product of the diagonals (x3 - x1) x (x4 - x2), e1 along side 1-2
// projected on the plane normal to e3, e2 = e3 x e1. The nodes of a warped element sit at
// heights z_a = e3 . (x_a - centroid) above that plane; a flat element has z_a = 0.
//
// One-point gradient in the frame (area A): d(.)/dx = sum_a b1_a (.)_a, d(.)/dy = sum_a b2_a
// (.)_a with b1 = [y24, y31, y42, y13] / 2A and b2 = [x42, x13, x24, x31] / 2A. A triangle is the
// degenerate quad n4 == n3; the formulas then give the constant-strain triangle.
#include <array>

#include "abut/core/vec3.hpp"

namespace abut {

struct Shell4Geometry {
  Vec3 e1, e2, e3;                 // co-rotational frame
  std::array<double, 4> x{}, y{};  // node coordinates in the frame (origin at the centroid)
  std::array<double, 4> z{};       // warping heights
  std::array<double, 4> b1{}, b2{};
  double area = 0.0;
  // Hourglass shape vector gamma_a = h_a - (h.x) b1_a - (h.y) b2_a with h = [1, -1, 1, -1]: it
  // is orthogonal to every linear field, so linear (patch-test) motions excite no hourglass
  // force (Flanagan & Belytschko 1981, carried to the shell by Belytschko & Tsay 1983).
  std::array<double, 4> gamma{};
  double longest_side = 0.0;
};

// Geometry of the element with nodes p[0..3] (a triangle repeats p[2] in p[3]). The area is
// <= 0 when the element is degenerate or turned over in its own frame (it cannot be for the
// frame defined above, except for a collapsed element).
Shell4Geometry shell4_geometry(const std::array<Vec3, 4>& p);

// Characteristic length of the critical time step L / c, c = sqrt(E / (rho (1 - nu^2))):
// A / (longest side) for a quad and 2 A / (longest side) for a triangle (the LS-DYNA default).
double shell4_critical_length(const Shell4Geometry& g, bool triangle);

}  // namespace abut
