#include "abut/element/hex8.hpp"

#include <algorithm>
#include <cmath>

#include "abut/core/vec3.hpp"

namespace abut {

void hex8_to_modes(const double u[8], double m[8]) {
  // Butterflies along xi (node pairs 0-1, 3-2, 4-5, 7-6), eta, then zeta: each stage splits a
  // pair into its sum (factor 1) and its difference, + side minus - side (factor xi, eta or zeta).
  const double a0 = u[1] + u[0], a1 = u[1] - u[0], a2 = u[2] + u[3], a3 = u[2] - u[3];
  const double a4 = u[5] + u[4], a5 = u[5] - u[4], a6 = u[6] + u[7], a7 = u[6] - u[7];
  const double b0 = a2 + a0, b2 = a2 - a0, b1 = a3 + a1, b3 = a3 - a1;  // zeta = -1 face
  const double b4 = a6 + a4, b6 = a6 - a4, b5 = a7 + a5, b7 = a7 - a5;  // zeta = +1 face
  m[0] = 0.125 * (b4 + b0);  // 1
  m[1] = 0.125 * (b5 + b1);  // xi
  m[2] = 0.125 * (b6 + b2);  // eta
  m[3] = 0.125 * (b4 - b0);  // zeta
  m[4] = 0.125 * (b6 - b2);  // eta zeta
  m[5] = 0.125 * (b5 - b1);  // zeta xi
  m[6] = 0.125 * (b7 + b3);  // xi eta
  m[7] = 0.125 * (b7 - b3);  // xi eta zeta
}

void hex8_from_modes(const double m[8], double u[8]) {
  // The transpose of the butterflies above, stages in reverse order.
  const double b0 = m[0] - m[3], b4 = m[0] + m[3], b1 = m[1] - m[5], b5 = m[1] + m[5];
  const double b2 = m[2] - m[4], b6 = m[2] + m[4], b3 = m[6] - m[7], b7 = m[6] + m[7];
  const double a0 = b0 - b2, a2 = b0 + b2, a1 = b1 - b3, a3 = b1 + b3;
  const double a4 = b4 - b6, a6 = b4 + b6, a5 = b5 - b7, a7 = b5 + b7;
  u[0] = a0 - a1;
  u[1] = a0 + a1;
  u[2] = a2 + a3;
  u[3] = a2 - a3;
  u[4] = a4 - a5;
  u[5] = a4 + a5;
  u[6] = a6 + a7;
  u[7] = a6 - a7;
}

void hex8_modal_gradient(const Hex8Modes& c, Hex8ModalGradient& g) {
  const auto mode = [&](int k) { return Vec3{c.x[k], c.y[k], c.z[k]}; };
  const Vec3 c1 = mode(1), c2 = mode(2), c3 = mode(3), c4 = mode(4), c5 = mode(5), c6 = mode(6);
  constexpr double third = 1.0 / 3.0;
  // G_k = (1/8) dV/dc_k; c7 (the xi eta zeta mode) does not change the volume.
  const Vec3 gk[8] = {Vec3{},
                      cross(c2, c3) + third * cross(c6, c5),
                      cross(c3, c1) + third * cross(c4, c6),
                      cross(c1, c2) + third * cross(c5, c4),
                      third * (cross(c6, c2) + cross(c3, c5)),
                      third * (cross(c4, c3) + cross(c1, c6)),
                      third * (cross(c2, c4) + cross(c5, c1)),
                      Vec3{}};
  for (int k = 0; k < 8; ++k) {
    g.gx[k] = gk[k].x;
    g.gy[k] = gk[k].y;
    g.gz[k] = gk[k].z;
  }
  // V is homogeneous of degree 3 in the c_k (Euler): 3 V = sum_k c_k . dV/dc_k.
  g.volume = (8.0 / 3.0) * (dot(c1, gk[1]) + dot(c2, gk[2]) + dot(c3, gk[3]) + dot(c4, gk[4]) +
                            dot(c5, gk[5]) + dot(c6, gk[6]));
}

void hex8_gradient(const Hex8Coords& x, Hex8Gradient& g) {
  Hex8Modes c;
  hex8_to_modes(x.x, c.x);
  hex8_to_modes(x.y, c.y);
  hex8_to_modes(x.z, c.z);
  Hex8ModalGradient modal;
  hex8_modal_gradient(c, modal);
  hex8_from_modes(modal.gx, g.bx);
  hex8_from_modes(modal.gy, g.by);
  hex8_from_modes(modal.gz, g.bz);
  g.volume = modal.volume;
  for (int alpha = 0; alpha < 4; ++alpha) {
    g.mx[alpha] = c.x[4 + alpha];
    g.my[alpha] = c.y[4 + alpha];
    g.mz[alpha] = c.z[4 + alpha];
  }
}

void hex8_hourglass_shape(const Hex8Gradient& g, double gamma[4][8]) {
  const double inv_volume = 1.0 / g.volume;
  for (int alpha = 0; alpha < 4; ++alpha) {
    // (sum_c h_alpha(c) x_c) / 8 is the moment m_alpha.
    for (int a = 0; a < 8; ++a) {
      gamma[alpha][a] =
          0.125 * kHex8Hourglass[alpha][a] -
          (g.mx[alpha] * g.bx[a] + g.my[alpha] * g.by[a] + g.mz[alpha] * g.bz[a]) * inv_volume;
    }
  }
}

double hex8_characteristic_length(const Hex8Coords& x, double volume) {
  static constexpr int kFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                       {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  double largest = 0.0;  // squared norm of the diagonal cross product (one sqrt at the end)
  for (const auto& f : kFaces) {
    const Vec3 d1{x.x[f[2]] - x.x[f[0]], x.y[f[2]] - x.y[f[0]], x.z[f[2]] - x.z[f[0]]};
    const Vec3 d2{x.x[f[3]] - x.x[f[1]], x.y[f[3]] - x.y[f[1]], x.z[f[3]] - x.z[f[1]]};
    const Vec3 n = cross(d1, d2);
    largest = std::max(largest, dot(n, n));
  }
  return volume / (0.5 * std::sqrt(largest));
}

}  // namespace abut
