#pragma once
// Shape functions of every cell type (mesh/topology.hpp) and the integration rules of the solid
// elements that use them: the isoparametric interpolation x(xi) = sum_a N_a(xi) x_a.
//
// Shape functions (Zienkiewicz, Taylor & Zhu, The Finite Element Method: Its Basis and
// Fundamentals, 7th ed., 2013, sections 6.3-6.6; the same as CalculiX's shape8h, shape20h,
// shape4tet, shape10tet and shape6w):
//  hex8   N_a = (1 + xi xi_a)(1 + eta eta_a)(1 + zeta zeta_a) / 8
//  hex20  corners N_a = (1 + xi xi_a)(1 + eta eta_a)(1 + zeta zeta_a)(xi xi_a + eta eta_a +
//         zeta zeta_a - 2) / 8; midside node with xi_a = 0: (1 - xi^2)(1 + eta eta_a)(1 + zeta
//         zeta_a) / 4, and likewise along eta and zeta (serendipity)
//  tet4   N = L0, L1, L2, L3 with L0 = 1 - xi - eta - zeta, L1 = xi, L2 = eta, L3 = zeta
//  tet10  corners L_a (2 L_a - 1), midside node of edge (a, b) 4 L_a L_b
//  wedge6 triangle (1 - xi - eta, xi, eta) times (1 - zeta) / 2 (nodes 0-2), (1 + zeta) / 2 (3-5)
//  hex27, hex64  Lagrange: N_a = l_i(xi) l_j(eta) l_k(zeta) for the node at lattice place
//         (i, j, k), l_m the 1-D Lagrange polynomial of order p through the equispaced points
//         -1 + 2m/p (Zienkiewicz et al., section 6.3.1)
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "abut/core/face_subdivision.hpp"
#include "abut/mesh/topology.hpp"

namespace abut {

// n[a] = N_a(xi) and dn[a][r] = dN_a / dxi_r for a < topology(type).nodes.
void shape_functions(CellType type, const double xi[3], double* n, double (*dn)[3]);

struct QuadraturePoint {
  double xi[3];
  double weight;
};

// Full integration as Abaqus/CalculiX C3D8, C3D20, C3D4, C3D10, C3D6; reduced as C3D20R (and
// the one-point hexahedron of the explicit solver). Points are in the order CalculiX prints
// them (*EL PRINT), which the static printout follows.
enum class Integration { full, reduced };

// The points of `type` under `rule`; empty when the cell has no such rule (a reduced
// tetrahedron or wedge).
//  hex8   full 2x2x2 Gauss, reduced 1 point; hex20 full 3x3x3, reduced 2x2x2 (tensor products,
//         xi fastest, then eta, then zeta)
//  tet4   1 point at the centroid, weight 1/6
//  tet10  4 points at L = a, b, b, b (each corner in turn), a = (5 + 3 sqrt 5) / 20,
//         b = (5 - sqrt 5) / 20, weights 1/24 (degree 2; Zienkiewicz et al., table 6.3)
//  hex27  full 3x3x3, hex64 full 4x4x4 Gauss (no reduced rule: 2x2x2 and 3x3x3 would leave
//         spurious zero-energy modes)
//  wedge6 6 points: the triangle's 3-point rule (degree 2, at (1/6, 1/6), (2/3, 1/6), (1/6, 2/3),
//         weights 1/6) on the 2 Gauss levels zeta = -+1/sqrt 3. The 2-point rule (the triangle's
//         centroid on each level) leaves a spurious zero-energy mode, the two triangles turning
//         opposite ways about the wedge's axis (7 zero eigenvalues, measured).
std::span<const QuadraturePoint> quadrature(CellType type, Integration rule);

// At natural point xi of a cell with coordinates X (3 per node): the shape functions n, their
// natural derivatives dn and their gradients grad[a][i] = dN_a/dX_i = sum_r dN_a/dxi_r (J^-1)_ri
// with J_ir = dX_i/dxi_r; returns det J (grad is meaningless where it is 0).
double shape_gradients(CellType type, std::span<const double> X, const double xi[3], double* n,
                       double (*dn)[3], double (*grad)[3]);

// The same from the natural derivatives dn of `nodes` shape functions at a point and the cell's
// coordinates X (3 per node, contiguous): J by its columns, J^-1 by cofactors. Inline, so that a
// kernel with a fixed node count (hex8_full.cpp) keeps its unrolled loops.
inline double natural_to_spatial(int nodes, const double (*dn)[3], const double* X,
                                 double (*grad)[3]) {
  double j[3][3] = {};  // j[i][r] = dX_i / dxi_r
  for (int a = 0; a < nodes; ++a)
    for (int i = 0; i < 3; ++i)
      for (int r = 0; r < 3; ++r) j[i][r] += X[3 * a + i] * dn[a][r];
  const double det = j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1]) -
                     j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0]) +
                     j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]);
  const double inv_det = 1.0 / det;
  double inv[3][3];  // inv[r][i] = (J^-1)_ri
  inv[0][0] = (j[1][1] * j[2][2] - j[1][2] * j[2][1]) * inv_det;
  inv[0][1] = (j[0][2] * j[2][1] - j[0][1] * j[2][2]) * inv_det;
  inv[0][2] = (j[0][1] * j[1][2] - j[0][2] * j[1][1]) * inv_det;
  inv[1][0] = (j[1][2] * j[2][0] - j[1][0] * j[2][2]) * inv_det;
  inv[1][1] = (j[0][0] * j[2][2] - j[0][2] * j[2][0]) * inv_det;
  inv[1][2] = (j[0][2] * j[1][0] - j[0][0] * j[1][2]) * inv_det;
  inv[2][0] = (j[1][0] * j[2][1] - j[1][1] * j[2][0]) * inv_det;
  inv[2][1] = (j[0][1] * j[2][0] - j[0][0] * j[2][1]) * inv_det;
  inv[2][2] = (j[0][0] * j[1][1] - j[0][1] * j[1][0]) * inv_det;
  for (int a = 0; a < nodes; ++a)
    for (int i = 0; i < 3; ++i)
      grad[a][i] = dn[a][0] * inv[0][i] + dn[a][1] * inv[1][i] + dn[a][2] * inv[2][i];
  return det;
}

// Faces (FaceType of mesh/topology.hpp), in natural coordinates of their own: quadrilaterals on
// [-1, 1]^2 with corners (-1,-1), (1,-1), (1,1), (-1,1); triangles with area coordinates, corners
// (0,0), (1,0), (0,1); midside nodes halfway along the edges corner 0-1, 1-2, ... The shape
// functions are the 2-D members of the families above: bilinear quad4, serendipity quad8
// (corners (1 + xi xi_a)(1 + eta eta_a)(xi xi_a + eta eta_a - 1) / 4, midsides (1 - xi^2)(1 + eta
// eta_a) / 2 and likewise), linear tri3, quadratic tri6 (corners L (2L - 1), midsides 4 L_a L_b),
// and the Lagrange quad9 and quad16 (l_s(xi) l_t(eta) for the node at face_lattice place (s, t)).
void face_shape_functions(FaceType type, const double xi[2], double* n, double (*dn)[2]);

struct FacePoint {
  double xi[2];
  double weight;
};

// Rules that integrate a uniform pressure's nodal forces on a curved face exactly: on a
// quadrilateral of order p the integrand N_a (x_xi x x_eta) has degree at most 3p - 1 per
// direction (N_a p, x_xi x x_eta 2p - 1): quad4 2x2, quad8 and quad9 3x3, quad16 5x5 Gauss
// points; tri3 its centroid (weight 1/2); tri6 Dunavant's 6-point rule of degree 4 (D. A.
// Dunavant, "High degree efficient symmetrical Gaussian quadrature rules for the triangle",
// IJNME 21, 1985, table of degree 4).
std::span<const FacePoint> face_quadrature(FaceType type);

// The nodal forces of a uniform pressure p (positive pushing into the cell) on a face whose nodes
// (face order) are at x (3 per node): f_a = -p int N_a (x_xi x x_eta) dxi deta, written to f (3
// per node). The face's nodes run counter-clockwise seen from outside, so x_xi x x_eta points out.
void face_pressure_forces(FaceType type, std::span<const double> x, double p, std::span<double> f);

// The smallest det(dX/dxi) over the points of the full rule of a cell with coordinates X
// (3 per node): <= 0 for a cell whose nodes are not in the type's order (or that is folded).
double min_jacobian(CellType type, std::span<const double> X);

// A face of `type` divided into n x n facets in its natural coordinates
// (core/face_subdivision.hpp). Contact surfaces of curved faces use it (dependent_nodes.hpp of the
// contact library).
FaceSubdivision subdivide_face(FaceType type, int n);

// The volume of a cell with coordinates X (3 per node): det J integrated by the full rule, exact
// for straight-edged cells (det J then has the degree the rule integrates) and to the rule's
// order for curved ones.
double cell_volume(CellType type, std::span<const double> X);

// The area of a face whose nodes (face order) are at x (3 per node), by face_quadrature (exact
// for a flat face; to the rule's order for a curved one).
double face_area(FaceType type, std::span<const double> x);

}  // namespace abut
