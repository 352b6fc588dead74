// Heat conduction in the hexahedron: see hex8_thermal.hpp.
#include "abut/element/hex8_thermal.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "abut/element/hex8_gauss.hpp"

namespace abut {

void hex8_conduction(const double X[8][3], double conductivity, double volumetric_capacity,
                     Hex8Conduction& out) {
  std::fill(out.conductance, out.conductance + 64, 0.0);
  out.volume = 0.0;
  for (int p = 0; p < 8; ++p) {
    double grad[8][3];
    const double dv = hex8_gauss_gradient(X, p, grad);  // Gauss weight 1
    out.volume += dv;
    for (int a = 0; a < 8; ++a)
      for (int b = a; b < 8; ++b)
        out.conductance[8 * a + b] +=
            conductivity * dv *
            (grad[a][0] * grad[b][0] + grad[a][1] * grad[b][1] + grad[a][2] * grad[b][2]);
  }
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < a; ++b) out.conductance[8 * a + b] = out.conductance[8 * b + a];
  const double c = volumetric_capacity * out.volume / 8.0;
  double lambda = 0.0;
  for (int a = 0; a < 8; ++a) {
    out.capacity[a] = c;
    double row = 0.0;
    for (int b = 0; b < 8; ++b) row += std::abs(out.conductance[8 * a + b]);
    lambda = std::max(lambda, row / c);
  }
  out.stable_step = lambda > 0.0 ? 2.0 / lambda : std::numeric_limits<double>::infinity();
}

}  // namespace abut
