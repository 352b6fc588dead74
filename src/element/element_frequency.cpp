#include "abut/element/element_frequency.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "abut/element/lumped_mass.hpp"
#include "abut/element/solid_full.hpp"

namespace abut {

namespace {

// The number of eigenvalues below x of the symmetric tridiagonal matrix with diagonal d and
// off-diagonal e (e[i] couples i and i + 1): the sign changes of the Sturm sequence, in the
// LDL^T form of Golub & Van Loan, Matrix Computations, section 8.4.
std::size_t eigenvalues_below(const std::vector<double>& d, const std::vector<double>& e,
                              double x) {
  std::size_t count = 0;
  double q = 1.0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    const double coupling = i > 0 ? e[i - 1] * e[i - 1] : 0.0;
    q = d[i] - x - (i > 0 ? coupling / q : 0.0);
    if (q == 0.0) q = 1e-300;  // passes exactly through an eigenvalue: count it as below
    if (q < 0.0) ++count;
  }
  return count;
}

}  // namespace

double largest_symmetric_eigenvalue(std::vector<double>& a, std::size_t n) {
  // Householder reduction to tridiagonal form (Golub & Van Loan, algorithm 8.3.1): for each
  // column k the reflection P = I - 2 w w^T / (w^T w) that zeroes a below its subdiagonal,
  // applied as A <- P A P.
  thread_local std::vector<double> w, p, d, e;
  w.resize(n);
  p.resize(n);
  for (std::size_t k = 0; k + 2 < n; ++k) {
    double norm2 = 0.0;
    for (std::size_t i = k + 1; i < n; ++i) norm2 += a[i * n + k] * a[i * n + k];
    const double alpha = a[(k + 1) * n + k] >= 0.0 ? -std::sqrt(norm2) : std::sqrt(norm2);
    if (norm2 == 0.0) continue;
    std::fill(w.begin(), w.end(), 0.0);
    for (std::size_t i = k + 1; i < n; ++i) w[i] = a[i * n + k];
    w[k + 1] -= alpha;
    double ww = 0.0;
    for (std::size_t i = k + 1; i < n; ++i) ww += w[i] * w[i];
    if (ww == 0.0) continue;
    // p = A w * 2 / ww, K = w^T p / ww, q = p - K w; A <- A - w q^T - q w^T.
    double wp = 0.0;
    for (std::size_t i = k; i < n; ++i) {
      double sum = 0.0;
      for (std::size_t j = k + 1; j < n; ++j) sum += a[i * n + j] * w[j];
      p[i] = 2.0 * sum / ww;
      wp += w[i] * p[i];
    }
    const double half = wp / ww;
    for (std::size_t i = k; i < n; ++i) p[i] -= half * w[i];
    for (std::size_t i = k; i < n; ++i)
      for (std::size_t j = k; j < n; ++j) a[i * n + j] -= w[i] * p[j] + p[i] * w[j];
  }
  d.resize(n);
  e.resize(n > 0 ? n - 1 : 0);
  for (std::size_t i = 0; i < n; ++i) d[i] = a[i * n + i];
  for (std::size_t i = 0; i + 1 < n; ++i) e[i] = a[(i + 1) * n + i];
  // Bisection on [lo, hi] from Gershgorin's discs until the bracket stops shrinking: the top
  // of the last bracket, an upper bound to round-off.
  double lo = 0.0, hi = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double radius = (i > 0 ? std::abs(e[i - 1]) : 0.0) + (i + 1 < n ? std::abs(e[i]) : 0.0);
    lo = std::min(lo, d[i] - radius);
    hi = std::max(hi, d[i] + radius);
  }
  for (int step = 0; step < 200; ++step) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (eigenvalues_below(d, e, mid) == n ? hi : lo) = mid;
  }
  return hi;
}

double largest_element_frequency(CellType type, std::span<const double> X,
                                 std::span<const double> masses, double lambda, double mu) {
  const int nodes = topology(type).nodes;
  const auto dofs = static_cast<std::size_t>(3 * nodes);
  const IsotropicElastic material{mu * (3.0 * lambda + 2.0 * mu) / (lambda + mu),
                                  lambda / (2.0 * (lambda + mu))};
  // Scratch per thread: the set-up calls this for every element of a block, in parallel.
  thread_local SolidElementResult k;
  thread_local std::vector<double> zero, scale;
  zero.assign(dofs, 0.0);
  scale.resize(dofs);
  solid_full_with({type, quadrature(type, Integration::full), X, zero, false}, material, k);
  // A = M^-1/2 K M^-1/2, in place.
  for (std::size_t i = 0; i < dofs; ++i) scale[i] = 1.0 / std::sqrt(masses[i / 3]);
  std::vector<double>& a = k.stiffness;
  for (std::size_t i = 0; i < dofs; ++i)
    for (std::size_t j = 0; j < dofs; ++j) a[i * dofs + j] *= scale[i] * scale[j];
  return std::sqrt(largest_symmetric_eigenvalue(a, dofs));
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
