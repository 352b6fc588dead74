#pragma once
// Volume of a trilinear hexahedron: det J is at most quadratic in each natural coordinate, so
// 2x2x2 Gauss quadrature integrates it exactly.
#include <cmath>
#include <vector>

#include "abut/mesh/mesh.hpp"

namespace abut {

inline double hex_volume(const Hex8& h, const std::vector<double>& x, const std::vector<double>& y,
                         const std::vector<double>& z) {
  static constexpr double xi[8] = {-1, 1, 1, -1, -1, 1, 1, -1};
  static constexpr double eta[8] = {-1, -1, 1, 1, -1, -1, 1, 1};
  static constexpr double zeta[8] = {-1, -1, -1, -1, 1, 1, 1, 1};
  const double g = 1.0 / std::sqrt(3.0);
  double volume = 0.0;
  for (int q = 0; q < 8; ++q) {
    const double r = g * xi[q], s = g * eta[q], u = g * zeta[q];
    double j[3][3] = {};
    for (int a = 0; a < 8; ++a) {
      const double dr = 0.125 * xi[a] * (1 + s * eta[a]) * (1 + u * zeta[a]);
      const double ds = 0.125 * eta[a] * (1 + r * xi[a]) * (1 + u * zeta[a]);
      const double du = 0.125 * zeta[a] * (1 + r * xi[a]) * (1 + s * eta[a]);
      const double p[3] = {x[h[a]], y[h[a]], z[h[a]]};
      for (int i = 0; i < 3; ++i) {
        j[0][i] += dr * p[i];
        j[1][i] += ds * p[i];
        j[2][i] += du * p[i];
      }
    }
    volume += j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1]) - j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0]) +
              j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]);
  }
  return volume;  // Gauss weights are 1
}

}  // namespace abut
