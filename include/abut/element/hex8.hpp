#pragma once
// Geometry of the 8-node hexahedron with one-point integration (Flanagan and Belytschko 1981,
// "A uniform strain hexahedron and quadrilateral with orthogonal hourglass control",
// IJNME 17:679-706, hereafter FB81). Node order as in mesh.hpp (VTK_HEXAHEDRON).
#include <array>

namespace abut {

// Natural coordinates of the nodes and the four hourglass base vectors of FB81:
// h1 = eta zeta, h2 = zeta xi, h3 = xi eta, h4 = xi eta zeta.
inline constexpr std::array<double, 8> kHex8Xi{-1, 1, 1, -1, -1, 1, 1, -1};
inline constexpr std::array<double, 8> kHex8Eta{-1, -1, 1, 1, -1, -1, 1, 1};
inline constexpr std::array<double, 8> kHex8Zeta{-1, -1, -1, -1, 1, 1, 1, 1};
inline constexpr std::array<std::array<double, 8>, 4> kHex8Hourglass{
    {{1, 1, -1, -1, -1, -1, 1, 1},    // eta zeta
     {1, -1, -1, 1, -1, 1, 1, -1},    // zeta xi
     {1, -1, 1, -1, 1, -1, 1, -1},    // xi eta
     {-1, 1, -1, 1, 1, -1, 1, -1}}};  // xi eta zeta

struct Hex8Coords {
  double x[8], y[8], z[8];
};

// The integrated gradient b_a = int_V grad N_a dV = dV/dx_a (FB81), the volume V of
// the trilinear element, and the hourglass moments m_alpha = (1/8) sum_a h_alpha(a) x_a.
// b / V is the mean-gradient B matrix: sum_a x_a (x) b_a = V I, so it is exact for linear fields.
struct Hex8Gradient {
  double bx[8], by[8], bz[8];
  double volume;
  double mx[4], my[4], mz[4];
};

// Closed form: with x(xi) = sum_k c_k phi_k(xi) (phi = 1, xi, eta, zeta, eta zeta, zeta xi,
// xi eta, xi eta zeta; c_k = 1/8 sum_a phi_k(a) x_a), integrating det J exactly over the cube gives
// V = 8 ([c1,c2,c3] + ([c6,c2,c4] + [c5,c4,c3] + [c1,c6,c5]) / 3), [.,.,.] the triple product;
// b_a = sum_k (1/8) dV/dc_k phi_k(a) follows by differentiation (our derivation; it reproduces
// the volume and B matrix of FB81, checked against 2x2x2 Gauss quadrature in tests).
void hex8_gradient(const Hex8Coords& x, Hex8Gradient& g);

// FB81 hourglass shape vectors (gamma, with the 1/8 normalisation):
// gamma_alpha(a) = (1/8) [h_alpha(a) - (sum_c h_alpha(c) x_c) . b_a / V], orthogonal to every
// linear field (sum_a gamma_alpha(a) x_a = 0, sum_a gamma_alpha(a) = 0).
void hex8_hourglass_shape(const Hex8Gradient& g, double gamma[4][8]);

// Characteristic length for the stable step: volume over the largest face area (LS-DYNA
// convention for solids, LS-DYNA Theory Manual, "Time Step Control", L_e = V_e / A_e,max).
// Face areas are half the norm of the cross product of the face diagonals.
double hex8_characteristic_length(const Hex8Coords& x, double volume);

}  // namespace abut
