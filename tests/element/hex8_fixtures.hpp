#pragma once
// Shared by the tests of the implicit hexahedra (C3D8, C3D8R): test elements, displacement
// fields and small dense linear algebra.
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "abut/core/mat3.hpp"
#include "abut/core/vec3.hpp"
#include "abut/element/hex8_full.hpp"

namespace abut::hex8_test {

using Nodes = std::array<std::array<double, 3>, 8>;

// A distorted element: no two faces parallel, no edge along an axis. It is also the element of
// the CalculiX reference runs below.
inline constexpr Nodes kDistorted{{{0.0, 0.0, 0.0},
                                   {2.0, 0.1, -0.1},
                                   {2.2, 1.9, 0.2},
                                   {-0.1, 1.6, 0.1},
                                   {0.2, -0.1, 1.5},
                                   {1.9, 0.2, 1.8},
                                   {2.1, 2.0, 1.7},
                                   {0.1, 1.8, 1.6}}};

// Unit cube, nodes in C3D8 / VTK order.
inline constexpr Nodes kUnitCube{
    {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};

inline Hex8FullInput make_input(const Nodes& x, const Nodes& u, bool nlgeom) {
  Hex8FullInput in{};
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i) {
      in.X[a][i] = x[a][i];
      in.u[a][i] = u[a][i];
    }
  in.nonlinear_geometry = nlgeom;
  return in;
}

// Displacements u_a = g(X_a) of a field g.
template <class Field>
Nodes field_at_nodes(const Nodes& x, Field g) {
  Nodes u{};
  for (int a = 0; a < 8; ++a) {
    const Vec3 v = g(Vec3{x[a][0], x[a][1], x[a][2]});
    u[a] = {v.x, v.y, v.z};
  }
  return u;
}

inline double max_abs(const double* v, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = std::max(m, std::abs(v[i]));
  return m;
}

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

// Symmetric 3x3 from Voigt (xx yy zz xy yz zx) and back.
inline Mat3 from_voigt(const double v[6]) {
  return Mat3{{v[0], v[3], v[5], v[3], v[1], v[4], v[5], v[4], v[2]}};
}

// A pseudo-random displacement field (deterministic LCG), amplitude `amp`.
inline Nodes random_displacements(double amp, unsigned seed) {
  Nodes u{};
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i) {
      seed = seed * 1664525u + 1013904223u;
      u[a][i] = amp * ((static_cast<double>(seed >> 8) / 16777216.0) * 2.0 - 1.0);
    }
  return u;
}

}  // namespace abut::hex8_test
