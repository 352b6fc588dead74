// The largest eigenvalue behind the hexahedron's stable step (include/abut/element/stable_step.hpp)
// against cyclic Jacobi (sym_tensor.hpp; Golub and Van Loan, Matrix Computations, 4th ed., §8.5),
// and its evaluation on Lanes against one matrix at a time.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "abut/core/lanes.hpp"
#include "abut/element/stable_step.hpp"
#include "abut/material/sym_tensor.hpp"

namespace abut {
namespace {

// Deterministic LCG in [-1, 1].
struct Random {
  std::uint32_t seed = 2024u;
  double operator()() {
    seed = seed * 1664525u + 1013904223u;
    return (static_cast<double>(seed >> 8) / static_cast<double>(1u << 24)) * 2.0 - 1.0;
  }
};

// Q diag(d) Q^T with Q a random rotation (Cayley transform of a random skew tensor), in the
// order xx, yy, zz, xy, yz, xz of largest_eigenvalue.
std::array<double, 6> rotated_diagonal(const double d[3], Random& random) {
  Mat3 spin{};
  const double wx = random(), wy = random(), wz = random();
  spin[7] = wx, spin[5] = -wx, spin[2] = wy, spin[6] = -wy, spin[3] = wz, spin[1] = -wz;
  const Sym3 s = rotate(cayley_rotation(spin), Sym3{{d[0], d[1], d[2], 0.0, 0.0, 0.0}});
  return {s[0], s[1], s[2], s[3], s[4], s[5]};
}

double jacobi_largest(const std::array<double, 6>& a) {
  const SymEigen eig = eigen_symmetric(Sym3{{a[0], a[1], a[2], a[3], a[4], a[5]}});
  return std::max({eig.values[0], eig.values[1], eig.values[2]});
}

// General positive semi-definite matrices: the closed form with four Newton steps agrees with
// Jacobi to the closed form's own round-off (p and det lose digits when eigenvalues nearly
// coincide): Smith's trigonometric form, cos(acos(r) / 3), has the same worst error, 8.0e-13, on
// these matrices.
TEST(LargestEigenvalue, MatchesJacobiOnRandomMatrices) {
  Random random;
  double worst = 0.0;
  for (int n = 0; n < 20000; ++n) {
    const double d[3] = {1.0 + random(), 1.0 + random(), 1.0 + random()};
    const std::array<double, 6> a = rotated_diagonal(d, random);
    const double exact = jacobi_largest(a);
    worst = std::max(worst, std::abs(largest_eigenvalue(a.data()) - exact) / exact);
  }
  EXPECT_LT(worst, 1e-12);
}

// Two equal largest eigenvalues (r = -1, where the Newton iteration meets a double root) and
// two equal smallest (r = 1) and a rank-one matrix. Near r = -1 the closed form itself is
// ill-conditioned: a rounding error delta in r moves cos(acos(r)/3) by about sqrt(delta), so the
// check there is 1e-7, from above (the step stays on the safe side), as for Smith's formula.
TEST(LargestEigenvalue, HandlesRepeatedEigenvaluesFromAbove) {
  Random random;
  const double cases[4][3] = {{2.0, 2.0, 0.5}, {2.0, 0.5, 0.5}, {3.0, 0.0, 0.0}, {1.0, 1.0, 0.0}};
  for (const auto& d : cases) {
    for (int n = 0; n < 2000; ++n) {
      const std::array<double, 6> a = rotated_diagonal(d, random);
      const double exact = jacobi_largest(a);
      const double value = largest_eigenvalue(a.data());
      EXPECT_NEAR(value, exact, 1e-7 * exact) << d[0] << " " << d[1] << " " << d[2];
      EXPECT_GE(value, exact * (1.0 - 1e-14));
    }
  }
  const double diagonal[6] = {1.0, 3.0, 2.0, 0.0, 0.0, 0.0};
  EXPECT_EQ(largest_eigenvalue(diagonal), 3.0);
}

// Four matrices in the lanes of one Lanes give, bit for bit, what each gives alone: the kernel
// may batch elements in any grouping (solid_block_kernel.cpp).
TEST(LargestEigenvalue, LanesGiveTheValuesOfOneMatrixAtATime) {
  Random random;
  for (int n = 0; n < 1000; ++n) {
    std::array<double, 6> a[kLanes];
    Lanes lanes[6];
    for (int l = 0; l < kLanes; ++l) {
      const double d[3] = {1.0 + random(), l == 1 ? 0.0 : 1.0 + random(), 1.0 + random()};
      a[l] = rotated_diagonal(d, random);
      if (l == 3) std::fill(a[l].begin() + 3, a[l].end(), 0.0);  // diagonal
      for (int c = 0; c < 6; ++c) lanes[c][l] = a[l][c];
    }
    const Lanes volume = Lanes{} + 2.0;
    const Lanes length = hex8_critical_length(lanes, volume, 1.2e11, 8.1e10);
    for (int l = 0; l < kLanes; ++l) {
      const double one = hex8_critical_length(a[l].data(), 2.0, 1.2e11, 8.1e10);
      const double lane = length[l];  // clang takes no address of a vector's element
      EXPECT_EQ(std::memcmp(&one, &lane, sizeof(double)), 0) << "lane " << l;
    }
  }
}

}  // namespace
}  // namespace abut
