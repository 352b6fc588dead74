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
#include "abut/core/lanes.hpp"
#include "abut/element/hex8.hpp"
#include "abut/mesh/mesh.hpp"

namespace abut {

// The length L such that L / c, c = sqrt((lambda + 2 mu) / rho), equals 2 / omega_max above,
// from the modal gradient (G = sum_a b_a b_a^T = 8 sum_k G_k G_k^T, hex8.hpp).
double hex8_critical_length(const Hex8ModalGradient& g, double lambda, double mu);

// The same from G's six components (xx, yy, zz, xy, yz, xz) and the volume, for one element
// (T = double) or several at once (T = Lanes, lanes.hpp), with the same arithmetic per element.
template <class T>
inline void hex8_gradient_products(const Hex8ModalGradientOf<T>& g, T product[6]) {
  T gxx{}, gyy{}, gzz{}, gxy{}, gyz{}, gxz{};
  for (int k = 1; k < 7; ++k) {
    gxx += g.gx[k] * g.gx[k];
    gyy += g.gy[k] * g.gy[k];
    gzz += g.gz[k] * g.gz[k];
    gxy += g.gx[k] * g.gy[k];
    gyz += g.gy[k] * g.gz[k];
    gxz += g.gx[k] * g.gz[k];
  }
  product[0] = 8.0 * gxx;
  product[1] = 8.0 * gyy;
  product[2] = 8.0 * gzz;
  product[3] = 8.0 * gxy;
  product[4] = 8.0 * gyz;
  product[5] = 8.0 * gxz;
}

// Largest eigenvalue of a symmetric positive semi-definite 3x3 matrix a (xx, yy, zz, xy, yz, xz).
// Closed form of O. K. Smith ("Eigenvalues of a symmetric 3x3 matrix", Comm. ACM 4(4), 1961):
// with q = tr a / 3, p^2 = |a - q I|^2 / 6 and r = det(a - q I) / (2 p^3) in [-1, 1], it is
// q + 2 p cos(acos(r) / 3). Without trigonometry: t = cos(acos(r) / 3) is the root in [1/2, 1] of
// 4 t^3 - 3 t = r (the triple-angle formula); with t = (1 + u) / 2 that is u^2 (3 + u) = 2 (1 + r),
// whose root u in [0, 1] Newton's method finds from above (the function is convex and increasing
// for u > 0) starting at min(1, sqrt(2 (1 + r) / 3)), within 16% of it; the relative error then
// squares with factor <= 2/3 each step: 0.16, 1.6e-2, 1.7e-4, 2e-8, 3e-16 after four steps.
// So the eigenvalue is q + p (1 + u), approached from above (a conservative stable step).
template <class T>
inline T largest_eigenvalue(const T a[6]) {
  const T off = a[3] * a[3] + a[4] * a[4] + a[5] * a[5];
  const T q = (a[0] + a[1] + a[2]) / 3.0;
  const T b00 = a[0] - q, b11 = a[1] - q, b22 = a[2] - q;
  const T p = sqrt_of((b00 * b00 + b11 * b11 + b22 * b22 + 2.0 * off) / 6.0);
  const T det = b00 * (b11 * b22 - a[4] * a[4]) - a[3] * (a[3] * b22 - a[4] * a[5]) +
                a[5] * (a[3] * a[4] - b11 * a[5]);
  const T zero{};
  const T two_rho = 2.0 * min_of(max_of(zero, 1.0 + det / (2.0 * p * p * p)), zero + 2.0);
  T u = min_of(zero + 1.0, sqrt_of(two_rho / 3.0));
  for (int step = 0; step < 4; ++step) {
    const T excess = u * u * (3.0 + u) - two_rho;
    u = excess > 0.0 ? u - excess / (3.0 * u * (2.0 + u)) : u;  // u = 0: r = -1, the root
  }
  // A diagonal matrix (no off-diagonal part: p may be 0) has its largest entry.
  const T diagonal = max_of(max_of(a[0], a[1]), a[2]);
  return off <= 1e-300 ? diagonal : q + p * (1.0 + u);
}

template <class T>
inline T hex8_critical_length(const T product[6], T volume, double lambda, double mu) {
  const T trace = product[0] + product[1] + product[2];
  // A negative lambda (nu < 0) only lowers lambda (tr eps)^2: leave it out, conservatively.
  const T stiffness = max_of(lambda, 0.0) * trace + 2.0 * mu * largest_eigenvalue(product);
  return volume * sqrt_of((lambda + 2.0 * mu) / (2.0 * stiffness));
}

// Modal gradient (hex8.hpp) of a hex at the given node coordinates.
Hex8ModalGradient hex8_modal_gradient_at(const Hex8& hex, const Nodes& nodes);

}  // namespace abut
