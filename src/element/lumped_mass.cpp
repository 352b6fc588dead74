#include "abut/element/lumped_mass.hpp"

#include <array>
#include <cmath>
#include <vector>

#include "abut/mesh/shape_functions.hpp"

namespace abut {
namespace {

// The collapsed Gauss product on the reference tetrahedron (volume 1/6): with u, v, w in [0, 1]
// (4-point Gauss-Legendre each), xi = u, eta = v (1 - u), zeta = w (1 - u)(1 - v), Jacobian
// (1 - u)^2 (1 - v). A polynomial of degree p in (xi, eta, zeta) is of degree p + 2 in u, which
// 4 points integrate exactly up to p = 5.
std::vector<QuadraturePoint> collapsed_tetrahedron_rule() {
  const double a = std::sqrt(3.0 / 7.0 - 2.0 / 7.0 * std::sqrt(6.0 / 5.0));
  const double b = std::sqrt(3.0 / 7.0 + 2.0 / 7.0 * std::sqrt(6.0 / 5.0));
  const double wa = (18.0 + std::sqrt(30.0)) / 36.0, wb = (18.0 - std::sqrt(30.0)) / 36.0;
  const std::array<double, 4> x = {-b, -a, a, b}, w = {wb, wa, wa, wb};
  std::vector<QuadraturePoint> rule;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) {
        const double u = 0.5 * (1.0 + x[i]), v = 0.5 * (1.0 + x[j]), s = 0.5 * (1.0 + x[k]);
        const double weight = 0.125 * w[i] * w[j] * w[k] * (1.0 - u) * (1.0 - u) * (1.0 - v);
        rule.push_back({{u, v * (1.0 - u), s * (1.0 - u) * (1.0 - v)}, weight});
      }
  return rule;
}

std::span<const QuadraturePoint> mass_rule(CellType type) {
  switch (type) {
    case CellType::tet4:
    case CellType::tet10: {
      static const std::vector<QuadraturePoint> rule = collapsed_tetrahedron_rule();
      return rule;
    }
    case CellType::hex8:    // 2 x 2 x 2: degree 3 >= 2 per direction
    case CellType::hex20:   // 3 x 3 x 3: degree 5 >= 4
    case CellType::hex27:   // 3 x 3 x 3: degree 5 >= 4
    case CellType::hex64:   // 4 x 4 x 4: degree 7 >= 6
    case CellType::wedge6:  // degree 2 on the triangle, 3 along zeta: N^2 is of degree 2 in both
      return quadrature(type, Integration::full);
  }
  return {};
}

}  // namespace

double lumped_volume_shares(CellType type, std::span<const double> X, std::span<double> shares) {
  const int nodes = topology(type).nodes;
  double n[kMaxCellNodes], dn[kMaxCellNodes][3], grad[kMaxCellNodes][3];
  double diagonal[kMaxCellNodes] = {};
  double volume = 0.0;
  for (const QuadraturePoint& q : mass_rule(type)) {
    const double dv = q.weight * shape_gradients(type, X, q.xi, n, dn, grad);
    volume += dv;
    for (int a = 0; a < nodes; ++a) diagonal[a] += n[a] * n[a] * dv;
  }
  double sum = 0.0;
  for (int a = 0; a < nodes; ++a) sum += diagonal[a];
  for (int a = 0; a < nodes; ++a) shares[static_cast<std::size_t>(a)] = volume * diagonal[a] / sum;
  return volume;
}

}  // namespace abut
