// Geometry of the one-point hexahedron against direct 2x2x2 Gauss quadrature of the trilinear
// map (exact for V and int grad N dV: the integrands are at most quadratic in each natural
// coordinate; Hughes, The Finite Element Method, 2000, §3.8).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "abut/element/hex8.hpp"
#include "element_fixtures.hpp"

namespace abut {
namespace {

struct Quadrature {
  double volume = 0.0;
  double b[8][3] = {};
};

// Direct isoparametric integration: J = dx/dxi, grad N = J^-T dN/dxi.
Quadrature gauss_2x2x2(const Hex8Coords& x) {
  Quadrature q;
  const double g = 1.0 / std::sqrt(3.0);
  for (int p = 0; p < 8; ++p) {
    const double xi = kHex8Xi[p] * g, eta = kHex8Eta[p] * g, zeta = kHex8Zeta[p] * g;
    double dn[8][3];
    for (int a = 0; a < 8; ++a) {
      dn[a][0] = 0.125 * kHex8Xi[a] * (1 + kHex8Eta[a] * eta) * (1 + kHex8Zeta[a] * zeta);
      dn[a][1] = 0.125 * kHex8Eta[a] * (1 + kHex8Xi[a] * xi) * (1 + kHex8Zeta[a] * zeta);
      dn[a][2] = 0.125 * kHex8Zeta[a] * (1 + kHex8Xi[a] * xi) * (1 + kHex8Eta[a] * eta);
    }
    double j[3][3] = {};  // j[i][r] = d x_i / d xi_r
    for (int a = 0; a < 8; ++a) {
      for (int r = 0; r < 3; ++r) {
        j[0][r] += x.x[a] * dn[a][r];
        j[1][r] += x.y[a] * dn[a][r];
        j[2][r] += x.z[a] * dn[a][r];
      }
    }
    const double det = j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1]) -
                       j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0]) +
                       j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]);
    double inv[3][3];  // inverse of j
    inv[0][0] = (j[1][1] * j[2][2] - j[1][2] * j[2][1]) / det;
    inv[0][1] = (j[0][2] * j[2][1] - j[0][1] * j[2][2]) / det;
    inv[0][2] = (j[0][1] * j[1][2] - j[0][2] * j[1][1]) / det;
    inv[1][0] = (j[1][2] * j[2][0] - j[1][0] * j[2][2]) / det;
    inv[1][1] = (j[0][0] * j[2][2] - j[0][2] * j[2][0]) / det;
    inv[1][2] = (j[0][2] * j[1][0] - j[0][0] * j[1][2]) / det;
    inv[2][0] = (j[1][0] * j[2][1] - j[1][1] * j[2][0]) / det;
    inv[2][1] = (j[0][1] * j[2][0] - j[0][0] * j[2][1]) / det;
    inv[2][2] = (j[0][0] * j[1][1] - j[0][1] * j[1][0]) / det;
    q.volume += det;
    for (int a = 0; a < 8; ++a) {
      for (int i = 0; i < 3; ++i) {  // dN/dx_i = sum_r dN/dxi_r dxi_r/dx_i
        q.b[a][i] += det * (dn[a][0] * inv[0][i] + dn[a][1] * inv[1][i] + dn[a][2] * inv[2][i]);
      }
    }
  }
  return q;
}

Hex8Coords coords(const Nodes& nodes, const Hex8& hex) {
  Hex8Coords x;
  for (int a = 0; a < 8; ++a) {
    x.x[a] = nodes.x[hex[a]];
    x.y[a] = nodes.y[hex[a]];
    x.z[a] = nodes.z[hex[a]];
  }
  return x;
}

TEST(Hex8, VolumeAndGradientMatchGaussQuadratureOnDistortedElements) {
  std::vector<Hex8> hexes;
  const Nodes single = test::distorted_hex(hexes);
  std::vector<Hex8Coords> cases{coords(single, hexes[0])};
  const Nodes grid = test::box_grid(3, 2, 2, {2.0, 1.0, 1.5}, 0.2, hexes);
  for (const Hex8& h : hexes) cases.push_back(coords(grid, h));
  for (const Hex8Coords& x : cases) {
    Hex8Gradient g;
    hex8_gradient(x, g);
    const Quadrature q = gauss_2x2x2(x);
    EXPECT_NEAR(g.volume, q.volume, 1e-13 * q.volume);
    const double scale = std::cbrt(q.volume * q.volume);
    for (int a = 0; a < 8; ++a) {
      EXPECT_NEAR(g.bx[a], q.b[a][0], 1e-13 * scale);
      EXPECT_NEAR(g.by[a], q.b[a][1], 1e-13 * scale);
      EXPECT_NEAR(g.bz[a], q.b[a][2], 1e-13 * scale);
    }
  }
}

// FB81: sum_a x_a (x) b_a = V I (exactness for linear fields), and the gamma vectors are
// orthogonal to constant and linear fields.
TEST(Hex8, MeanGradientIsExactForLinearFieldsAndGammaIsOrthogonalToThem) {
  std::vector<Hex8> hexes;
  const Nodes nodes = test::distorted_hex(hexes);
  const Hex8Coords x = coords(nodes, hexes[0]);
  Hex8Gradient g;
  hex8_gradient(x, g);
  const double* xs[3] = {x.x, x.y, x.z};
  const double* bs[3] = {g.bx, g.by, g.bz};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      double sum = 0.0;
      for (int a = 0; a < 8; ++a) sum += xs[i][a] * bs[j][a];
      EXPECT_NEAR(sum, i == j ? g.volume : 0.0, 1e-14);
    }
  }
  double gamma[4][8];
  hex8_hourglass_shape(g, gamma);
  for (int alpha = 0; alpha < 4; ++alpha) {
    double constant = 0.0, with_h = 0.0;
    for (int a = 0; a < 8; ++a) {
      constant += gamma[alpha][a];
      with_h += gamma[alpha][a] * kHex8Hourglass[alpha][a];
    }
    EXPECT_NEAR(constant, 0.0, 1e-15);
    EXPECT_GT(with_h, 0.5);  // the mode itself is not filtered out
    for (int i = 0; i < 3; ++i) {
      double linear = 0.0;
      for (int a = 0; a < 8; ++a) linear += gamma[alpha][a] * xs[i][a];
      EXPECT_NEAR(linear, 0.0, 1e-15);
    }
  }
}

// The nodal values of phi_k (the tables kHex8Xi, ..., kHex8Hourglass) are the unit mode k, and
// from_modes inverts to_modes.
TEST(Hex8, WalshTransformsMapTheBaseFunctionsToUnitModesAndBack) {
  const std::array<double, 8> phi[8] = {
      {1, 1, 1, 1, 1, 1, 1, 1}, kHex8Xi,           kHex8Eta,          kHex8Zeta,
      kHex8Hourglass[0],        kHex8Hourglass[1], kHex8Hourglass[2], kHex8Hourglass[3]};
  for (int k = 0; k < 8; ++k) {
    double modes[8], back[8];
    hex8_to_modes(phi[k].data(), modes);
    for (int l = 0; l < 8; ++l) EXPECT_EQ(modes[l], l == k ? 1.0 : 0.0) << k << " " << l;
    hex8_from_modes(modes, back);
    for (int a = 0; a < 8; ++a) EXPECT_EQ(back[a], phi[k][a]);
  }
  const double u[8] = {0.3, -1.7, 2.5, 0.01, -0.4, 1.1, 7.0, -3.3};
  double modes[8], back[8];
  hex8_to_modes(u, modes);
  hex8_from_modes(modes, back);
  for (int a = 0; a < 8; ++a) EXPECT_NEAR(back[a], u[a], 1e-15 * 8.0);
}

// The modal identities the element relies on, checked with b_a from Gauss quadrature:
// sum_a u_a (x) b_a = 8 sum_k u_k (x) G_k and sum_a b_a . b_a = 8 sum_k G_k . G_k.
TEST(Hex8, ModalGradientGivesTheNodalSumsOfTheQuadratureGradient) {
  std::vector<Hex8> hexes;
  const Nodes nodes = test::distorted_hex(hexes);
  const Hex8Coords x = coords(nodes, hexes[0]);
  const Quadrature q = gauss_2x2x2(x);
  Hex8Modes c;
  hex8_to_modes(x.x, c.x);
  hex8_to_modes(x.y, c.y);
  hex8_to_modes(x.z, c.z);
  Hex8ModalGradient g;
  hex8_modal_gradient(c, g);
  EXPECT_NEAR(g.volume, q.volume, 1e-13 * q.volume);
  // A non-linear nodal field u.
  const double u[3][8] = {{0.3, -1.7, 2.5, 0.01, -0.4, 1.1, 7.0, -3.3},
                          {1.0, 2.0, -0.5, 0.25, 3.0, -2.0, 0.7, 0.9},
                          {-0.6, 0.8, 1.9, -2.2, 0.05, 0.4, -1.0, 2.6}};
  double um[3][8];
  for (int i = 0; i < 3; ++i) hex8_to_modes(u[i], um[i]);
  const double* gs[3] = {g.gx, g.gy, g.gz};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      double nodal = 0.0, modal = 0.0;
      for (int a = 0; a < 8; ++a) nodal += u[i][a] * q.b[a][j];
      for (int k = 0; k < 8; ++k) modal += 8.0 * um[i][k] * gs[j][k];
      EXPECT_NEAR(modal, nodal, 1e-13 * 10.0) << i << " " << j;
    }
  }
  double bb_nodal = 0.0, bb_modal = 0.0;
  for (int a = 0; a < 8; ++a) {
    bb_nodal += q.b[a][0] * q.b[a][0] + q.b[a][1] * q.b[a][1] + q.b[a][2] * q.b[a][2];
  }
  for (int k = 0; k < 8; ++k) {
    bb_modal += 8.0 * (g.gx[k] * g.gx[k] + g.gy[k] * g.gy[k] + g.gz[k] * g.gz[k]);
  }
  EXPECT_NEAR(bb_modal, bb_nodal, 1e-13 * bb_nodal);
  EXPECT_EQ(g.gx[0], 0.0);  // translation and the xi eta zeta mode do not change V
  EXPECT_EQ(g.gx[7], 0.0);
}

// For a brick a x b x c the largest face is b*c (a <= b <= c), so L = V / (b c) = a.
TEST(Hex8, CharacteristicLengthOfABrickIsItsShortestEdge) {
  std::vector<Hex8> hexes;
  const Nodes brick = test::box_grid(1, 1, 1, {0.5, 2.0, 3.0}, 0.0, hexes);
  const Hex8Coords x = coords(brick, hexes[0]);
  Hex8Gradient g;
  hex8_gradient(x, g);
  EXPECT_NEAR(g.volume, 3.0, 1e-14);
  EXPECT_NEAR(hex8_characteristic_length(x, g.volume), 0.5, 1e-14);
}

}  // namespace
}  // namespace abut
