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
#include "dense_checks.hpp"

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

using test::jacobi_eigenvalues;
using test::solve_dense;

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
