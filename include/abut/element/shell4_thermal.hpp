#pragma once
// Heat conduction in the 4-node shell (and the 3-node triangle, a Quad4 whose last node repeats
// its third): conduction in the mid-surface through the thickness h, no gradient across it (a
// thin shell's temperature is one value through the thickness). Semi-discrete as hex8_thermal.hpp:
//   K_ab = int_A k h grad_s N_a . grad_s N_b dA,   C_a = rho c h A / n (n = 4 or 3 nodes),
// with the surface gradient of the shape functions, grad_s N = G^ij dN/dxi_i g_j (g_i = dx/dxi_i,
// G_ij = g_i . g_j), which needs no local frame and holds on warped elements (e.g. Zienkiewicz,
// Taylor & Zhu, The Finite Element Method, 7th ed., 2013, for the isoparametric quadrilateral;
// 2 x 2 Gauss points). The triangle has constant gradients, grad N_i = n x (x_k - x_j) / (2A)
// for (i, j, k) cyclic. Stable step: the element's Gershgorin bound, as for the hexahedron.
#include "abut/mesh/mesh.hpp"

namespace abut {

struct Shell4Conduction {
  double conductance[16];  // K, row-major, symmetric; a triangle's fourth row and column are 0
  double capacity[4];      // C_a [energy / temperature]; a triangle's fourth is 0
  double area;
  double stable_step;  // 2 / lambda_e [time]
};

// X: node coordinates (a triangle repeats its third node as the fourth); thickness h > 0;
// conductivity k >= 0; volumetric heat capacity rho c > 0.
void shell4_conduction(const double X[4][3], bool triangle, double thickness, double conductivity,
                       double volumetric_capacity, Shell4Conduction& out);

}  // namespace abut
