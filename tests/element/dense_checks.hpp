#pragma once
// Dense reference linear algebra for element tests: the eigenvalues of a symmetric matrix and the
// solution of a linear system, by textbook methods independent of the library's.
#include <algorithm>
#include <cmath>
#include <vector>

namespace abut::test {

// Eigenvalues of a symmetric matrix by cyclic Jacobi rotations (Golub & Van Loan, Matrix
// Computations, 4th ed., section 8.5.3).
inline std::vector<double> jacobi_eigenvalues(std::vector<double> a, int n) {
  for (int sweep = 0; sweep < 100; ++sweep) {
    double off = 0.0, diag = 0.0;
    for (int p = 0; p < n; ++p) {
      diag += a[n * p + p] * a[n * p + p];
      for (int q = p + 1; q < n; ++q) off += a[n * p + q] * a[n * p + q];
    }
    if (off <= 1e-32 * diag) break;
    for (int p = 0; p < n; ++p)
      for (int q = p + 1; q < n; ++q) {
        const double apq = a[n * p + q];
        if (apq == 0.0) continue;
        const double theta = (a[n * q + q] - a[n * p + p]) / (2.0 * apq);
        const double t =
            (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1.0 / std::sqrt(t * t + 1), s = t * c;
        for (int k = 0; k < n; ++k) {  // columns p, q
          const double akp = a[n * k + p], akq = a[n * k + q];
          a[n * k + p] = c * akp - s * akq;
          a[n * k + q] = s * akp + c * akq;
        }
        for (int k = 0; k < n; ++k) {  // rows p, q
          const double apk = a[n * p + k], aqk = a[n * q + k];
          a[n * p + k] = c * apk - s * aqk;
          a[n * q + k] = s * apk + c * aqk;
        }
      }
  }
  std::vector<double> values(n);
  for (int i = 0; i < n; ++i) values[i] = a[n * i + i];
  std::sort(values.begin(), values.end());
  return values;
}

// Solves A x = b (dense, n x n, row-major) by Gaussian elimination with partial pivoting.
inline std::vector<double> solve_dense(std::vector<double> a, std::vector<double> b) {
  const int n = static_cast<int>(b.size());
  for (int k = 0; k < n; ++k) {
    int piv = k;
    for (int i = k + 1; i < n; ++i)
      if (std::abs(a[n * i + k]) > std::abs(a[n * piv + k])) piv = i;
    for (int j = 0; j < n; ++j) std::swap(a[n * k + j], a[n * piv + j]);
    std::swap(b[k], b[piv]);
    for (int i = k + 1; i < n; ++i) {
      const double l = a[n * i + k] / a[n * k + k];
      for (int j = k; j < n; ++j) a[n * i + j] -= l * a[n * k + j];
      b[i] -= l * b[k];
    }
  }
  std::vector<double> x(n);
  for (int i = n - 1; i >= 0; --i) {
    double s = b[i];
    for (int j = i + 1; j < n; ++j) s -= a[n * i + j] * x[j];
    x[i] = s / a[n * i + i];
  }
  return x;
}

}  // namespace abut::test
