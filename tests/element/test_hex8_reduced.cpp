// The one-point hexahedron (C3D8R) of the implicit solver: rank and rigid modes, the patch test
// (for linear fields it must give the fully integrated element's forces, since both integrate a
// constant stress exactly), the hourglass stiffness of the explicit element (FB81), and the
// consistent tangent against finite differences of its own forces and energy.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "abut/element/hex8.hpp"
#include "abut/element/hex8_full.hpp"
#include "abut/element/hex8_reduced.hpp"
#include "hex8_fixtures.hpp"

namespace abut {
namespace {

using namespace hex8_test;

constexpr IsotropicElastic kSteel{210000.0, 0.3};
constexpr double kShear = 210000.0 / 2.6;
constexpr double kHourglassModulus = kHex8HourglassCoefficient * 2.0 * kShear;

std::unique_ptr<Hex8FullResult> reduced(const Hex8FullInput& in) {
  auto r = std::make_unique<Hex8FullResult>();
  hex8_reduced_with(in, kSteel, kHourglassModulus, *r);
  return r;
}

TEST(Hex8Reduced, SymmetricPositiveWithExactlySixRigidModes) {
  const auto r = reduced(make_input(kDistorted, {}, false));
  std::vector<double> k(r->stiffness, r->stiffness + 576);
  for (int m = 0; m < 24; ++m)
    for (int n = 0; n < 24; ++n) ASSERT_EQ(k[24 * m + n], k[24 * n + m]);
  const std::vector<double> values = jacobi_eigenvalues(k, 24);
  const double largest = values.back();
  for (int i = 0; i < 6; ++i) EXPECT_LT(std::abs(values[i]), 1e-10 * largest) << i;
  EXPECT_GT(values[6], 1e-6 * largest);  // the hourglass stiffness removes the 12 zero modes
}

// Linear displacement fields: the uniform strain is exact, hourglass modes stay unexcited, and
// the forces equal those of full integration (a constant stress integrates exactly either way).
TEST(Hex8Reduced, PatchTestMatchesFullIntegration) {
  const Nodes u = field_at_nodes(kDistorted, [](const Vec3& x) {
    return Vec3{1e-3 * x.x + 4e-4 * x.y - 2e-4 * x.z + 0.01, -3e-4 * x.x + 5e-4 * x.z,
                2e-4 * x.y + 7e-4 * x.z - 0.02};
  });
  for (bool nlgeom : {false, true}) {
    const Hex8FullInput in = make_input(kDistorted, u, nlgeom);
    auto full = std::make_unique<Hex8FullResult>();
    hex8_full(in, kSteel, *full);
    const auto r = reduced(in);
    const double scale = max_abs(full->force, 24);
    for (int c = 0; c < 24; ++c) EXPECT_NEAR(r->force[c], full->force[c], 1e-12 * scale) << c;
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(r->stress[0][k], full->stress[3][k], 1e-9) << k;
    EXPECT_NEAR(r->strain_energy, full->strain_energy, 1e-12 * full->strain_energy);
  }
}

// FB81 hourglass stiffness as the explicit element has it (solid_block.cpp): on a unit cube the
// mode u_x(a) = d h_1(a) has q_1 = d and stiffness k = c_hg 2 G (b:b) / V = 3 c_hg G (b:b = 3/2).
TEST(Hex8Reduced, HourglassModeStiffnessOfTheExplicitElement) {
  const double d = 1e-3;
  Nodes u{};
  for (int a = 0; a < 8; ++a) u[a][0] = d * kHex8Hourglass[0][a];
  const auto r = reduced(make_input(kUnitCube, u, false));
  const double k = 3.0 * kHex8HourglassCoefficient * kShear;
  for (int a = 0; a < 8; ++a) {
    EXPECT_NEAR(r->force[3 * a], k * d * kHex8Hourglass[0][a] / 8.0, 1e-12 * k * d) << a;
    EXPECT_EQ(r->force[3 * a + 1], 0.0);
  }
  EXPECT_NEAR(r->strain_energy, 0.5 * k * d * d, 1e-12 * k * d * d);
  for (int k6 = 0; k6 < 6; ++k6) EXPECT_NEAR(r->stress[0][k6], 0.0, 1e-9);  // mean strain 0
}

TEST(Hex8Reduced, TangentAndForceMatchFiniteDifferences) {
  for (bool nlgeom : {true, false}) {
    const Hex8FullInput in = make_input(kDistorted, random_displacements(0.2, 7), nlgeom);
    const auto r = reduced(in);
    ASSERT_GT(r->min_jacobian, 0.0);
    const double kmax = max_abs(r->stiffness, 576), fmax = max_abs(r->force, 24);
    const double h = 1e-6;
    double worst_k = 0.0, worst_f = 0.0;
    for (int n = 0; n < 24; ++n) {
      Hex8FullInput plus = in, minus = in;
      plus.u[n / 3][n % 3] += h;
      minus.u[n / 3][n % 3] -= h;
      const auto rp = reduced(plus), rm = reduced(minus);
      for (int m = 0; m < 24; ++m) {
        const double fd = (rp->force[m] - rm->force[m]) / (2 * h);
        worst_k = std::max(worst_k, std::abs(fd - r->stiffness[24 * m + n]));
      }
      const double dw = (rp->strain_energy - rm->strain_energy) / (2 * h);
      worst_f = std::max(worst_f, std::abs(dw - r->force[n]));
    }
    EXPECT_LT(worst_k, 1e-6 * kmax) << "nlgeom " << nlgeom;
    EXPECT_LT(worst_f, 1e-6 * fmax) << "nlgeom " << nlgeom;
  }
}

}  // namespace
}  // namespace abut
