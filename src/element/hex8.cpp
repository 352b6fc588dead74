#include "abut/element/hex8.hpp"

#include <algorithm>
#include <cmath>

#include "abut/core/vec3.hpp"
#include "abut/mesh/mesh.hpp"  // kHexFaces

namespace abut {

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
  double largest = 0.0;  // squared norm of the diagonal cross product (one sqrt at the end)
  for (const auto& f : kHexFaces) {
    const Vec3 d1{x.x[f[2]] - x.x[f[0]], x.y[f[2]] - x.y[f[0]], x.z[f[2]] - x.z[f[0]]};
    const Vec3 d2{x.x[f[3]] - x.x[f[1]], x.y[f[3]] - x.y[f[1]], x.z[f[3]] - x.z[f[1]]};
    const Vec3 n = cross(d1, d2);
    largest = std::max(largest, dot(n, n));
  }
  return volume / (0.5 * std::sqrt(largest));
}

}  // namespace abut
