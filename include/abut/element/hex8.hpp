#pragma once
// Geometry of the 8-node hexahedron with one-point integration (Flanagan and Belytschko 1981,
// "A uniform strain hexahedron and quadrilateral with orthogonal hourglass control",
// IJNME 17:679-706, hereafter FB81). Node order as in mesh.hpp (VTK_HEXAHEDRON).
#include <array>

#include "abut/core/vec3.hpp"

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

// Default hourglass coefficient c_hg of the one-point hexahedron (stiffness c_hg 2 G (b:b) / V,
// solid_block.cpp explains the scaling), shared by the explicit and the implicit element.
inline constexpr double kHex8HourglassCoefficient = 0.05;

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

// The modes c_k of the coordinates (component-wise) and the modal gradient G_k = (1/8) dV/dc_k,
// so that b_a = sum_k phi_k(a) G_k (G_0 = G_7 = 0: translation and the xi eta zeta mode leave V
// unchanged). By orthogonality, for any nodal vector field u with modes u_k:
//   sum_a u_a (x) b_a = 8 sum_k u_k (x) G_k,   sum_a b_a . b_a = 8 sum_k G_k . G_k,
// which is how the element forms velocity gradients, F and the hourglass stiffness without b_a.
//
// T is double, or a SIMD vector of doubles holding one element per lane (lanes.hpp), so that the
// kernel evaluates several elements with the same arithmetic, operation for operation.
template <class T>
struct Hex8ModesOf {
  T x[8], y[8], z[8];
};
template <class T>
struct Hex8ModalGradientOf {
  T gx[8], gy[8], gz[8];
  T volume;
};
using Hex8Modes = Hex8ModesOf<double>;
using Hex8ModalGradient = Hex8ModalGradientOf<double>;

// Inline: the element kernel calls these for every element and step.
// u_k = 1/8 sum_a phi_k(a) u_a.
template <class T>
inline void hex8_to_modes(const T u[8], T m[8]) {
  // Butterflies along xi (node pairs 0-1, 3-2, 4-5, 7-6), eta, then zeta: each stage splits a
  // pair into its sum (factor 1) and its difference, + side minus - side (factor xi, eta or zeta).
  const T a0 = u[1] + u[0], a1 = u[1] - u[0], a2 = u[2] + u[3], a3 = u[2] - u[3];
  const T a4 = u[5] + u[4], a5 = u[5] - u[4], a6 = u[6] + u[7], a7 = u[6] - u[7];
  const T b0 = a2 + a0, b2 = a2 - a0, b1 = a3 + a1, b3 = a3 - a1;  // zeta = -1 face
  const T b4 = a6 + a4, b6 = a6 - a4, b5 = a7 + a5, b7 = a7 - a5;  // zeta = +1 face
  // In the order 1, xi, eta, zeta, eta zeta, zeta xi, xi eta, xi eta zeta.
  m[0] = 0.125 * (b4 + b0);
  m[1] = 0.125 * (b5 + b1);
  m[2] = 0.125 * (b6 + b2);
  m[3] = 0.125 * (b4 - b0);
  m[4] = 0.125 * (b6 - b2);
  m[5] = 0.125 * (b5 - b1);
  m[6] = 0.125 * (b7 + b3);
  m[7] = 0.125 * (b7 - b3);
}

// u_a = sum_k phi_k(a) u_k.
template <class T>
inline void hex8_from_modes(const T m[8], T u[8]) {
  // The transpose of the butterflies above, stages in reverse order.
  const T b0 = m[0] - m[3], b4 = m[0] + m[3], b1 = m[1] - m[5], b5 = m[1] + m[5];
  const T b2 = m[2] - m[4], b6 = m[2] + m[4], b3 = m[6] - m[7], b7 = m[6] + m[7];
  const T a0 = b0 - b2, a2 = b0 + b2, a1 = b1 - b3, a3 = b1 + b3;
  const T a4 = b4 - b6, a6 = b4 + b6, a5 = b5 - b7, a7 = b5 + b7;
  u[0] = a0 - a1;
  u[1] = a0 + a1;
  u[2] = a2 + a3;
  u[3] = a2 - a3;
  u[4] = a4 - a5;
  u[5] = a4 + a5;
  u[6] = a6 + a7;
  u[7] = a6 - a7;
}

// G_k = (1/8) dV/dc_k of the closed form at hex8_gradient above.
template <class T>
inline void hex8_modal_gradient(const Hex8ModesOf<T>& c, Hex8ModalGradientOf<T>& g) {
  // The twelve cross products c_A x c_B of the closed form, component by component over the
  // list so that the compiler can vectorise them; c7 (xi eta zeta) does not change the volume.
  constexpr int kA[12] = {2, 6, 3, 4, 1, 5, 6, 3, 4, 1, 2, 5};
  constexpr int kB[12] = {3, 5, 1, 6, 2, 4, 2, 5, 3, 6, 4, 1};
  T px[12], py[12], pz[12];
  for (int n = 0; n < 12; ++n) {
    const int a = kA[n], b = kB[n];
    px[n] = c.y[a] * c.z[b] - c.z[a] * c.y[b];
    py[n] = c.z[a] * c.x[b] - c.x[a] * c.z[b];
    pz[n] = c.x[a] * c.y[b] - c.y[a] * c.x[b];
  }
  constexpr double third = 1.0 / 3.0;
  T* gs[3] = {g.gx, g.gy, g.gz};
  const T* ps[3] = {px, py, pz};
  for (int i = 0; i < 3; ++i) {
    T* gi = gs[i];
    const T* p = ps[i];
    gi[0] = T{};
    gi[1] = p[0] + third * p[1];      // c2 x c3 + (c6 x c5) / 3
    gi[2] = p[2] + third * p[3];      // c3 x c1 + (c4 x c6) / 3
    gi[3] = p[4] + third * p[5];      // c1 x c2 + (c5 x c4) / 3
    gi[4] = third * (p[6] + p[7]);    // (c6 x c2 + c3 x c5) / 3
    gi[5] = third * (p[8] + p[9]);    // (c4 x c3 + c1 x c6) / 3
    gi[6] = third * (p[10] + p[11]);  // (c2 x c4 + c5 x c1) / 3
    gi[7] = T{};
  }
  // V is homogeneous of degree 3 in the c_k (Euler): 3 V = sum_k c_k . dV/dc_k.
  T v{};
  for (int k = 1; k < 7; ++k) v += c.x[k] * g.gx[k] + c.y[k] * g.gy[k] + c.z[k] * g.gz[k];
  g.volume = (8.0 / 3.0) * v;
}

// FB81 hourglass shape vectors (gamma, with the 1/8 normalisation):
// gamma_alpha(a) = (1/8) [h_alpha(a) - (sum_c h_alpha(c) x_c) . b_a / V], orthogonal to every
// linear field (sum_a gamma_alpha(a) x_a = 0, sum_a gamma_alpha(a) = 0).
void hex8_hourglass_shape(const Hex8Gradient& g, double gamma[4][8]);

// Characteristic length for the stable step: volume over the largest face area (LS-DYNA
// convention for solids, LS-DYNA Theory Manual, "Time Step Control", L_e = V_e / A_e,max).
// Face areas are half the norm of the cross product of the face diagonals.
double hex8_characteristic_length(const Hex8Coords& x, double volume);

}  // namespace abut
