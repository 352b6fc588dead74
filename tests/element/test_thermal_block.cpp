// Conduction over a block of hexahedra (thermal_block.hpp): a linear temperature field carries
// Fourier's flux through the block and leaves every interior node in balance (the trilinear
// element represents it exactly), the heat capacities add up to rho c V, and the result is
// bitwise the same on 1 and 2 threads.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <vector>

#include "abut/element/hex8_thermal.hpp"
#include "abut/element/thermal_block.hpp"
#include "abut/mesh/generators.hpp"

namespace abut {
namespace {

constexpr double kK = 45.0, kRhoC = 3.6e6;  // steel: W/(m K), J/(m^3 K)

struct Box {
  Mesh mesh;
  ThermalBlock block;
  static Mesh make() {
    Mesh m;
    generate_box(m, {1, 4, 3, 2, {0, 0, 0}, {0.4, 0.3, 0.2}});
    return m;
  }
  Box()
      : mesh(make()),
        block(mesh.hexes, std::vector<double>(mesh.hex_count(), kK),
              std::vector<double>(mesh.hex_count(), kRhoC), mesh.nodes.size()) {}
};

TEST(ThermalBlock, LinearFieldCarriesFouriersFluxAndBalancesInteriorNodes) {
  Box b;
  const Nodes& n = b.mesh.nodes;
  const double gradient = 500.0;  // K/m along x
  std::vector<double> t(n.size()), rate(n.size(), 0.0);
  for (std::size_t i = 0; i < n.size(); ++i) t[i] = 20.0 + gradient * n.x[i];
  const double step = b.block.add_conduction(n.x, n.y, n.z, t, rate);
  double hot_end = 0.0, total = 0.0;
  for (std::size_t i = 0; i < n.size(); ++i) {
    total += rate[i];
    if (std::abs(n.x[i] - 0.4) < 1e-12) {
      hot_end += rate[i];
    } else if (n.x[i] > 1e-12) {
      EXPECT_NEAR(rate[i], 0.0, 1e-9 * kK * gradient * 0.06) << i;  // interior in x: balanced
    }
  }
  // The hot end loses k g A = 45 x 500 x 0.06 = 1350 W to the block.
  EXPECT_NEAR(hot_end, -kK * gradient * 0.3 * 0.2, 1e-9 * 1350.0);
  EXPECT_NEAR(total, 0.0, 1e-9 * 1350.0);
  // All elements are cubes of side 0.1: the block's step is that of one of them.
  const double cube[8][3] = {{0, 0, 0},   {0.1, 0, 0},   {0.1, 0.1, 0},   {0, 0.1, 0},
                             {0, 0, 0.1}, {0.1, 0, 0.1}, {0.1, 0.1, 0.1}, {0, 0.1, 0.1}};
  Hex8Conduction one;
  hex8_conduction(cube, kK, kRhoC, one);
  EXPECT_NEAR(step, one.stable_step, 1e-9 * one.stable_step);
}

TEST(ThermalBlock, CapacityIsRhoCV) {
  Box b;
  const Nodes& n = b.mesh.nodes;
  std::vector<double> c(n.size(), 0.0);
  b.block.add_capacity(n.x, n.y, n.z, c);
  double total = 0.0;
  for (const double v : c) total += v;
  EXPECT_NEAR(total, kRhoC * 0.4 * 0.3 * 0.2, 1e-9 * kRhoC * 0.024);
}

TEST(ThermalBlock, OneAndTwoThreadsBitwiseIdentical) {
  Box b;
  const Nodes& n = b.mesh.nodes;
  std::vector<double> t(n.size());
  for (std::size_t i = 0; i < n.size(); ++i)
    t[i] = 300.0 + 50.0 * std::sin(17.0 * n.x[i] + 5.0 * n.y[i] * n.z[i]);
  std::vector<double> one(n.size(), 0.0), two(n.size(), 0.0);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  b.block.add_conduction(n.x, n.y, n.z, t, one);
  omp_set_num_threads(2);
  b.block.add_conduction(n.x, n.y, n.z, t, two);
  omp_set_num_threads(threads);
  for (std::size_t i = 0; i < n.size(); ++i) EXPECT_EQ(one[i], two[i]) << i;
}

}  // namespace
}  // namespace abut
