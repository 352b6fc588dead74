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

// Modal (Walsh) form used by the element kernel. The eight functions phi_k = 1, xi, eta, zeta,
// eta zeta, zeta xi, xi eta, xi eta zeta (k = 0..7; k = 4 + alpha is the hourglass base vector
// h_alpha) take the values +-1 at the nodes and are orthogonal there: sum_a phi_k(a) phi_l(a) =
// 8 delta_kl. So any nodal field u_a has the modes u_k = (1/8) sum_a phi_k(a) u_a, and
// u_a = sum_k phi_k(a) u_k. The transforms are fast Walsh-Hadamard transforms (3 butterfly
// stages, additions only).
void hex8_to_modes(const double nodal[8], double modes[8]);    // u_k = 1/8 sum_a phi_k(a) u_a
void hex8_from_modes(const double modes[8], double nodal[8]);  // u_a = sum_k phi_k(a) u_k

// The modes c_k of the coordinates (component-wise) and the modal gradient G_k = (1/8) dV/dc_k,
// so that b_a = sum_k phi_k(a) G_k (G_0 = G_7 = 0: translation and the xi eta zeta mode leave V
// unchanged). By orthogonality, for any nodal vector field u with modes u_k:
//   sum_a u_a (x) b_a = 8 sum_k u_k (x) G_k,   sum_a b_a . b_a = 8 sum_k G_k . G_k,
// which is how the element forms velocity gradients, F and the hourglass stiffness without b_a.
struct Hex8Modes {
  double x[8], y[8], z[8];
};
struct Hex8ModalGradient {
  double gx[8], gy[8], gz[8];
  double volume;
};
void hex8_modal_gradient(const Hex8Modes& c, Hex8ModalGradient& g);

// FB81 hourglass shape vectors (gamma, with the 1/8 normalisation):
// gamma_alpha(a) = (1/8) [h_alpha(a) - (sum_c h_alpha(c) x_c) . b_a / V], orthogonal to every
// linear field (sum_a gamma_alpha(a) x_a = 0, sum_a gamma_alpha(a) = 0).
void hex8_hourglass_shape(const Hex8Gradient& g, double gamma[4][8]);

// Characteristic length for the stable step: volume over the largest face area (LS-DYNA
// convention for solids, LS-DYNA Theory Manual, "Time Step Control", L_e = V_e / A_e,max).
// Face areas are half the norm of the cross product of the face diagonals.
double hex8_characteristic_length(const Hex8Coords& x, double volume);

}  // namespace abut
