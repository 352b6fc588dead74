// Heat conduction in the hexahedron (hex8_thermal.hpp): conservation (a uniform temperature
// makes no flow), Fourier's law exactly for linear temperature fields on a distorted element
// (the flow through the faces of a unit cube under a unit gradient is k A), the lumped capacity,
// and the stable step against the exact largest eigenvalue.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "abut/element/hex8_thermal.hpp"
#include "hex8_fixtures.hpp"

namespace abut {
namespace {

using namespace hex8_test;

void coords(const Nodes& n, double X[8][3]) {
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i) X[a][i] = n[a][i];
}

TEST(Hex8Conduction, UniformTemperatureMakesNoFlowAndKIsSymmetric) {
  double X[8][3];
  coords(kDistorted, X);
  Hex8Conduction r;
  hex8_conduction(X, 45.0, 3.6e6, r);
  for (int a = 0; a < 8; ++a) {
    double row = 0.0;
    for (int b = 0; b < 8; ++b) {
      row += r.conductance[8 * a + b];
      EXPECT_EQ(r.conductance[8 * a + b], r.conductance[8 * b + a]);
    }
    EXPECT_NEAR(row, 0.0, 1e-12 * r.conductance[9 * a]);
    EXPECT_GT(r.conductance[9 * a], 0.0);
  }
}

// T = g . x: the element's nodal flows are the consistent ones of the uniform flux -k g: their
// sum over the nodes of a face of a unit cube is the face's flow k g_n A (Fourier).
TEST(Hex8Conduction, LinearFieldGivesFouriersFlux) {
  double X[8][3];
  coords(kUnitCube, X);
  const double k = 45.0, g[3] = {100.0, -30.0, 7.0};
  Hex8Conduction r;
  hex8_conduction(X, k, 1.0, r);
  double t[8], flow[8];
  for (int a = 0; a < 8; ++a) t[a] = g[0] * X[a][0] + g[1] * X[a][1] + g[2] * X[a][2];
  for (int a = 0; a < 8; ++a) {
    flow[a] = 0.0;  // heat the element draws out of node a
    for (int b = 0; b < 8; ++b) flow[a] += r.conductance[8 * a + b] * t[b];
  }
  // Nodes on x = 1 (1, 2, 5, 6) carry the heat that leaves through that face: -k g_x per unit
  // area flows in the -x direction, i.e. the element pulls k g_x out of the hot face's nodes.
  const double face_x1 = flow[1] + flow[2] + flow[5] + flow[6];
  EXPECT_NEAR(face_x1, k * g[0], 1e-9 * k * std::abs(g[0]));
  // Each node: a quarter of the flows of its three faces, with signs.
  for (int a = 0; a < 8; ++a) {
    const double expected = 0.25 * k *
                            ((X[a][0] > 0.5 ? g[0] : -g[0]) + (X[a][1] > 0.5 ? g[1] : -g[1]) +
                             (X[a][2] > 0.5 ? g[2] : -g[2]));
    EXPECT_NEAR(flow[a], expected, 1e-9 * k * 100.0) << a;
  }
}

TEST(Hex8Conduction, LumpedCapacityAndVolume) {
  double X[8][3];
  coords(kDistorted, X);
  Hex8Conduction r;
  hex8_conduction(X, 1.0, 2.0, r);
  double total = 0.0;
  for (const double c : r.capacity) total += c;
  EXPECT_NEAR(total, 2.0 * r.volume, 1e-12 * r.volume);
  double Xu[8][3];
  coords(kUnitCube, Xu);
  hex8_conduction(Xu, 1.0, 2.0, r);
  EXPECT_NEAR(r.volume, 1.0, 1e-14);
}

// The bound 2 / lambda_e is safe (lambda_e >= the exact lambda_max of C^-1 K, here the element
// alone) and not wasteful (within a factor 2 of it on a cube).
TEST(Hex8Conduction, StableStepBoundsTheLargestEigenvalue) {
  for (const Nodes& n : {kUnitCube, kDistorted}) {
    double X[8][3];
    coords(n, X);
    Hex8Conduction r;
    hex8_conduction(X, 45.0, 3.6e6, r);
    std::vector<double> a(64);  // C^-1/2 K C^-1/2 (symmetric, same eigenvalues)
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j)
        a[8 * i + j] = r.conductance[8 * i + j] / std::sqrt(r.capacity[i] * r.capacity[j]);
    const double lambda_max = jacobi_eigenvalues(a, 8).back();
    const double exact_step = 2.0 / lambda_max;
    EXPECT_LE(r.stable_step, exact_step * (1.0 + 1e-12));
    EXPECT_GT(r.stable_step, 0.5 * exact_step);
  }
}

}  // namespace
}  // namespace abut
