// Heat conduction in shells (shell4_thermal.hpp, thermal_block.cpp): the conduction patch test
// (a linear temperature field draws no heat at interior nodes of any patch of distorted elements,
// MacNeal & Harder 1985 style patch, here for Fourier's law), capacity rho c h A, rows summing to
// zero, and Fourier's flux k h w dT / L through a strip, on quadrilaterals and triangles in a
// plane tilted in space.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "abut/element/shell4_thermal.hpp"
#include "abut/element/thermal_block.hpp"

namespace abut {
namespace {

// A patch in the plane through the origin spanned by e1, e2 (tilted in space): a 2 x 2 patch of
// distorted quadrilaterals around interior node 4, or the same split into triangles.
struct Patch {
  std::vector<double> x, y, z, u, v;  // u, v: in-plane coordinates
  std::vector<Quad4> elements;
  Patch(bool triangles) {
    const double e1[3] = {0.6, 0.8, 0.0}, e2[3] = {0.0, 0.0, 1.0};
    const double uv[9][2] = {{0, 0},   {1, 0}, {2, 0},   {0, 1}, {1.2, 0.9},
                             {2, 1.1}, {0, 2}, {0.9, 2}, {2, 2}};
    for (const auto& p : uv) {
      u.push_back(p[0]);
      v.push_back(p[1]);
      x.push_back(p[0] * e1[0] + p[1] * e2[0]);
      y.push_back(p[0] * e1[1] + p[1] * e2[1]);
      z.push_back(p[0] * e1[2] + p[1] * e2[2]);
    }
    const Quad4 quads[4] = {{0, 1, 4, 3}, {1, 2, 5, 4}, {3, 4, 7, 6}, {4, 5, 8, 7}};
    for (const Quad4& q : quads) {
      if (triangles) {
        elements.push_back({q[0], q[1], q[2], q[2]});
        elements.push_back({q[0], q[2], q[3], q[3]});
      } else {
        elements.push_back(q);
      }
    }
  }
  ThermalBlock block(double h, double k, double rho_c) const {
    std::vector<ThermalShell> shells;
    for (const Quad4& q : elements) shells.push_back({q, h, k, rho_c});
    return ThermalBlock({}, {}, {}, x.size(), shells);
  }
};

TEST(Shell4Thermal, LinearFieldDrawsNoHeatAtTheInteriorNode) {
  const double h = 0.01, k = 40.0, rho_c = 3.5e6;
  for (const bool triangles : {false, true}) {
    const Patch patch(triangles);
    ThermalBlock block = patch.block(h, k, rho_c);
    std::vector<double> t(9), rate(9, 0.0), capacity(9, 0.0);
    for (std::size_t i = 0; i < 9; ++i) t[i] = 20.0 + 30.0 * patch.u[i] - 10.0 * patch.v[i];
    block.add_conduction(patch.x, patch.y, patch.z, t, rate);
    EXPECT_NEAR(rate[4], 0.0, 1e-12 * k * h * 30.0) << triangles;
    EXPECT_NEAR(std::accumulate(rate.begin(), rate.end(), 0.0), 0.0, 1e-12 * k * h * 30.0);
    // T^T K T = int k h |grad T|^2 dA = k h (30^2 + 10^2) A, A = 4: the patch conducts the
    // field with the material's conductivity (a linear field is reproduced exactly).
    double dissipation = 0.0;
    for (std::size_t i = 0; i < 9; ++i) dissipation -= t[i] * rate[i];
    EXPECT_NEAR(dissipation, k * h * 1000.0 * 4.0, 1e-12 * k * h * 4000.0) << triangles;
    block.add_capacity(patch.x, patch.y, patch.z, capacity);
    EXPECT_NEAR(std::accumulate(capacity.begin(), capacity.end(), 0.0), rho_c * h * 4.0,
                1e-12 * rho_c * h * 4.0);
  }
}

TEST(Shell4Thermal, RowsSumToZeroAndTheStepIsBounded) {
  const double X[4][3] = {{0, 0, 0}, {1, 0, 0.1}, {1.1, 0.9, 0}, {0, 1, 0.05}};  // warped
  Shell4Conduction r;
  shell4_conduction(X, false, 0.002, 50.0, 3.6e6, r);
  for (int a = 0; a < 4; ++a) {
    double row = 0.0;
    for (int b = 0; b < 4; ++b) {
      row += r.conductance[4 * a + b];
      EXPECT_DOUBLE_EQ(r.conductance[4 * a + b], r.conductance[4 * b + a]);
    }
    EXPECT_NEAR(row, 0.0, 1e-12 * r.conductance[0]);
    EXPECT_GT(r.conductance[5 * a], 0.0);
  }
  EXPECT_GT(r.stable_step, 0.0);
  EXPECT_LT(r.stable_step, 1e300);
}

}  // namespace
}  // namespace abut
