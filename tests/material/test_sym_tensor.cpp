// Symmetric-tensor kit: Jacobi eigen-solver and the Hughes-Winget rotation increment.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "abut/material/sym_tensor.hpp"

namespace abut {
namespace {

Mat3 rotation_z(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c, -s, 0, s, c, 0, 0, 0, 1};
}

void expect_decomposes(const Sym3& s, std::array<double, 3> expected) {
  const SymEigen e = eigen_symmetric(s);
  // Reconstruction and orthonormality.
  const Sym3 back = from_spectral(e.values, e.vectors);
  for (int c = 0; c < 6; ++c) EXPECT_NEAR(back[c], s[c], 1e-14);
  for (int k = 0; k < 3; ++k) {
    for (int l = 0; l < 3; ++l) {
      double d = 0.0;
      for (int i = 0; i < 3; ++i) d += e.vectors[3 * i + k] * e.vectors[3 * i + l];
      EXPECT_NEAR(d, k == l ? 1.0 : 0.0, 1e-14);
    }
  }
  std::array<double, 3> values = e.values;
  std::sort(values.begin(), values.end());
  std::sort(expected.begin(), expected.end());
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(values[k], expected[k], 1e-14);
}

// [[2,1,0],[1,2,0],[0,0,5]] has eigenvalues 1, 3 and 5 (2 +- 1 from the 2x2 block).
TEST(SymTensor, JacobiFindsKnownEigenvalues) {
  expect_decomposes(Sym3{{2, 2, 5, 1, 0, 0}}, {1, 3, 5});
  expect_decomposes(Sym3{{2, 2, 2, 0, 0, 0}}, {2, 2, 2});  // already diagonal, repeated
  // R diag(1, 2, 3) R^T for a rotation about a skew axis: the eigenvalues stay 1, 2, 3.
  const double c = std::cos(0.7), s = std::sin(0.7);
  const Mat3 rx{1, 0, 0, 0, c, -s, 0, s, c};
  expect_decomposes(rotate(rx, rotate(rotation_z(0.4), Sym3{{1, 2, 3, 0, 0, 0}})), {1, 2, 3});
  // Two equal eigenvalues after rotation.
  expect_decomposes(rotate(rx, rotate(rotation_z(1.1), Sym3{{4, 1, 1, 0, 0, 0}})), {4, 1, 1});
}

// The Cayley transform of the mid-step spin of a rotation by theta about z is that rotation:
// W dt/2 = tan(theta/2) skew(e_z) (Hughes and Winget 1980).
TEST(SymTensor, CayleyRotationIsOrthogonalAndExactForAConstantAxis) {
  const double theta = 0.3;
  const double w = std::tan(0.5 * theta);
  const Mat3 half_spin{0, -w, 0, w, 0, 0, 0, 0, 0};
  const Mat3 q = cayley_rotation(half_spin);
  const Mat3 r = rotation_z(theta);
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(q[i], r[i], 1e-15);
  const Mat3 general = cayley_rotation({0, -0.2, 0.5, 0.2, 0, -0.1, -0.5, 0.1, 0});
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      double d = 0.0;
      for (int k = 0; k < 3; ++k) d += general[3 * i + k] * general[3 * j + k];
      EXPECT_NEAR(d, i == j ? 1.0 : 0.0, 1e-15);
    }
  }
}

TEST(SymTensor, VonMisesOfUniaxialStressIsTheStress) {
  EXPECT_NEAR(von_mises(Sym3{{250.0, 0, 0, 0, 0, 0}}), 250.0, 1e-12);
  // Pure shear tau: sqrt(3) tau.
  EXPECT_NEAR(von_mises(Sym3{{0, 0, 0, 10.0, 0, 0}}), std::sqrt(3.0) * 10.0, 1e-12);
}

}  // namespace
}  // namespace abut
