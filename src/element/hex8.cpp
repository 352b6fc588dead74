#include "abut/element/hex8.hpp"

#include <algorithm>
#include <cmath>

#include "abut/core/vec3.hpp"

namespace abut {

namespace {

Vec3 moment(const Hex8Coords& x, const std::array<double, 8>& phi) {
  Vec3 c;
  for (int a = 0; a < 8; ++a) {
    c.x += phi[a] * x.x[a];
    c.y += phi[a] * x.y[a];
    c.z += phi[a] * x.z[a];
  }
  return c * 0.125;
}

}  // namespace

void hex8_gradient(const Hex8Coords& x, Hex8Gradient& g) {
  const Vec3 c1 = moment(x, kHex8Xi), c2 = moment(x, kHex8Eta), c3 = moment(x, kHex8Zeta);
  const Vec3 c4 = moment(x, kHex8Hourglass[0]), c5 = moment(x, kHex8Hourglass[1]);
  const Vec3 c6 = moment(x, kHex8Hourglass[2]), c7 = moment(x, kHex8Hourglass[3]);
  constexpr double third = 1.0 / 3.0;
  // G_k = (1/8) dV/dc_k; c7 (the xi eta zeta mode) does not change the volume.
  const Vec3 g1 = cross(c2, c3) + third * cross(c6, c5);
  const Vec3 g2 = cross(c3, c1) + third * cross(c4, c6);
  const Vec3 g3 = cross(c1, c2) + third * cross(c5, c4);
  const Vec3 g4 = third * (cross(c6, c2) + cross(c3, c5));
  const Vec3 g5 = third * (cross(c4, c3) + cross(c1, c6));
  const Vec3 g6 = third * (cross(c2, c4) + cross(c5, c1));
  for (int a = 0; a < 8; ++a) {
    const Vec3 b = kHex8Xi[a] * g1 + kHex8Eta[a] * g2 + kHex8Zeta[a] * g3 +
                   kHex8Hourglass[0][a] * g4 + kHex8Hourglass[1][a] * g5 +
                   kHex8Hourglass[2][a] * g6;
    g.bx[a] = b.x;
    g.by[a] = b.y;
    g.bz[a] = b.z;
  }
  // V is homogeneous of degree 3 in the c_k (Euler): 3 V = sum_k c_k . dV/dc_k.
  g.volume = (8.0 / 3.0) *
             (dot(c1, g1) + dot(c2, g2) + dot(c3, g3) + dot(c4, g4) + dot(c5, g5) + dot(c6, g6));
  const Vec3 m[4] = {c4, c5, c6, c7};
  for (int alpha = 0; alpha < 4; ++alpha) {
    g.mx[alpha] = m[alpha].x;
    g.my[alpha] = m[alpha].y;
    g.mz[alpha] = m[alpha].z;
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
