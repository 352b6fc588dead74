#pragma once
// Critical time step of a one-point hexahedron with lumped mass.
//
// The element's largest eigenfrequency is bounded by (Cauchy-Schwarz on the mean strain
// eps = sym(sum_a u_a (x) b_a) / V, masses rho V / 8 per node):
//   omega_max^2 <= 8 (lambda tr G + 2 mu lambda_max(G)) / (rho V^2),   G = sum_a b_a b_a^T,
// with b_a the integrated shape-function gradients (Flanagan & Belytschko 1981 bound the same
// quantity with (lambda + 2 mu) tr G, which is up to 1.6 times more conservative). The bound is
// attained by a cube: 2/omega = h / sqrt(3K/rho), the 3D counterpart of the 1D h/c (for
// nu = 0.3 it is 0.73 h/c: the usual L = V / A_max with c = sqrt((lambda + 2 mu)/rho) would
// exceed it, and an element one layer thick goes unstable at a scale factor of 0.9).
#include "abut/element/hex8.hpp"
#include "abut/mesh/mesh.hpp"

namespace abut {

// The length L such that L / c, c = sqrt((lambda + 2 mu) / rho), equals 2 / omega_max above,
// from the modal gradient (G = sum_a b_a b_a^T = 8 sum_k G_k G_k^T, hex8.hpp).
double hex8_critical_length(const Hex8ModalGradient& g, double lambda, double mu);

// Modal gradient (hex8.hpp) of a hex at the given node coordinates.
Hex8ModalGradient hex8_modal_gradient_at(const Hex8& hex, const Nodes& nodes);

}  // namespace abut
