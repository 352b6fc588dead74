#pragma once
// The 2 x 2 x 2 Gauss rule of the trilinear hexahedron, shared by the fully integrated elements
// (hex8_full.hpp, hex8_thermal.hpp): shape function derivatives at the points in CalculiX's order
// (tensor product, xi fastest: point p at natural coordinates g (+-1) with bit 0 of p for xi, bit 1
// for eta, bit 2 for zeta; g = 1/sqrt(3), weight 1) and the gradients with respect to the
// coordinates at a point.
#include "abut/element/hex8.hpp"

namespace abut {

struct Hex8GaussTable {
  double dn[8][8][3];  // [point][node][r]: dN_node / dxi_r
};

inline constexpr double kHex8Gauss = 0.57735026918962576451;  // 1/sqrt(3)

constexpr Hex8GaussTable make_hex8_gauss_table() {
  Hex8GaussTable t{};
  for (int p = 0; p < 8; ++p) {
    const double xi = (p & 1) ? kHex8Gauss : -kHex8Gauss;
    const double eta = (p & 2) ? kHex8Gauss : -kHex8Gauss;
    const double zeta = (p & 4) ? kHex8Gauss : -kHex8Gauss;
    for (int a = 0; a < 8; ++a) {
      const double xa = kHex8Xi[a], ea = kHex8Eta[a], za = kHex8Zeta[a];
      t.dn[p][a][0] = 0.125 * xa * (1.0 + ea * eta) * (1.0 + za * zeta);
      t.dn[p][a][1] = 0.125 * ea * (1.0 + xa * xi) * (1.0 + za * zeta);
      t.dn[p][a][2] = 0.125 * za * (1.0 + xa * xi) * (1.0 + ea * eta);
    }
  }
  return t;
}

inline constexpr Hex8GaussTable kHex8GaussTable = make_hex8_gauss_table();

// Gradients of the shape functions with respect to the coordinates X at Gauss point p:
// grad[a][i] = dN_a/dX_i = sum_r dN_a/dxi_r (J^-1)_ri, J_ir = dX_i/dxi_r. Returns det J.
double hex8_gauss_gradient(const double X[8][3], int p, double grad[8][3]);

}  // namespace abut
