#include "abut/element/element_frequency.hpp"

#include <cmath>
#include <vector>

#include "abut/element/lumped_mass.hpp"
#include "abut/element/solid_full.hpp"

namespace abut {

double largest_element_frequency(CellType type, std::span<const double> X,
                                 std::span<const double> masses, double lambda, double mu) {
  const int nodes = topology(type).nodes;
  const auto dofs = static_cast<std::size_t>(3 * nodes);
  const std::vector<double> zero(dofs, 0.0);
  const IsotropicElastic material{mu * (3.0 * lambda + 2.0 * mu) / (lambda + mu),
                                  lambda / (2.0 * (lambda + mu))};
  SolidElementResult k;
  solid_full_with({type, quadrature(type, Integration::full), X, zero, false}, material, k);
  // A = M^-1/2 K M^-1/2, in place.
  std::vector<double> scale(dofs);
  for (std::size_t i = 0; i < dofs; ++i) scale[i] = 1.0 / std::sqrt(masses[i / 3]);
  std::vector<double>& a = k.stiffness;
  for (std::size_t i = 0; i < dofs; ++i)
    for (std::size_t j = 0; j < dofs; ++j) a[i * dofs + j] *= scale[i] * scale[j];
  // A start with a component along every mode: alternating signs (the highest modes of a cell
  // push neighbouring nodes against each other) with an irregular magnitude.
  std::vector<double> x(dofs), y(dofs);
  double norm = 0.0;
  for (std::size_t i = 0; i < dofs; ++i) {
    x[i] = (i % 2 == 0 ? 1.0 : -1.0) * (1.0 + 0.5 * std::sin(1.7 * static_cast<double>(i) + 0.3));
    norm += x[i] * x[i];
  }
  for (double& v : x) v /= std::sqrt(norm);
  double rayleigh = 0.0, residual = 0.0;
  for (int iteration = 0; iteration < 1000; ++iteration) {
    for (std::size_t i = 0; i < dofs; ++i) {
      double sum = 0.0;
      for (std::size_t j = 0; j < dofs; ++j) sum += a[i * dofs + j] * x[j];
      y[i] = sum;
    }
    rayleigh = 0.0;
    for (std::size_t i = 0; i < dofs; ++i) rayleigh += x[i] * y[i];
    double r2 = 0.0, y2 = 0.0;
    for (std::size_t i = 0; i < dofs; ++i) {
      r2 += (y[i] - rayleigh * x[i]) * (y[i] - rayleigh * x[i]);
      y2 += y[i] * y[i];
    }
    residual = std::sqrt(r2);
    if (residual <= 1e-6 * rayleigh) break;
    const double inverse = 1.0 / std::sqrt(y2);
    for (std::size_t i = 0; i < dofs; ++i) x[i] = y[i] * inverse;
  }
  return std::sqrt(rayleigh + residual);
}

double cell_critical_step(CellType type, std::span<const double> X, double density, double lambda,
                          double mu) {
  double masses[kMaxCellNodes];
  const std::span<double> m(masses, static_cast<std::size_t>(topology(type).nodes));
  lumped_volume_shares(type, X, m);
  for (double& v : m) v *= density;
  return 2.0 / largest_element_frequency(type, X, m, lambda, mu);
}

}  // namespace abut
