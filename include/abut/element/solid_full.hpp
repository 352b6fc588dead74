#pragma once
// The isoparametric solid element of any cell type for the implicit (Newton-Raphson) solver:
// internal force and consistent tangent at the integration points of a rule (shape_functions.hpp),
// small strain or total Lagrangian (NLGEOM). The formulation, conventions (Voigt order, engineering
// shears) and material-point seam are those of the 8-node hexahedron in hex8_full.hpp, which is
// this element with CellType::hex8 and the 2x2x2 rule (tests/element/test_solid_full.cpp checks
// that they agree); what changes is only the interpolation (Abaqus/CalculiX C3D4, C3D10, C3D20,
// C3D20R, C3D6).
#include <span>
#include <vector>

#include "abut/element/hex8_full.hpp"
#include "abut/mesh/shape_functions.hpp"

namespace abut {

struct SolidElementInput {
  CellType type = CellType::hex8;
  std::span<const QuadraturePoint> points;  // the integration rule
  std::span<const double> X;                // reference coordinates, 3 per node
  std::span<const double> u;                // displacements, 3 per node
  bool nonlinear_geometry = false;          // NLGEOM: total Lagrangian
};

// Sized by the element for its cell and rule; reused from call to call without allocating.
struct SolidElementResult {
  std::vector<double> force;           // 3 per node, node-major
  std::vector<double> stiffness;       // (3 nodes)^2, row-major, exactly symmetric
  std::vector<double> stress;          // 6 per point: Cauchy (Voigt xx yy zz xy yz zx)
  std::vector<double> strain;          // 6 per point: small, or Green-Lagrange; engineering shears
  std::vector<double> energy_density;  // 1 per point, per unit reference volume
  double strain_energy = 0.0;          // integral of the energy density over the reference volume
  double volume = 0.0;                 // current volume (the reference one for small strain)
  double min_jacobian = 0.0;           // smallest det(dx/dxi) at the points (current with NLGEOM);
                                       // <= 0: an inverted element, the rest is meaningless
  // Scratch of the element (B and D B).
  std::vector<double> work;
};

// The material's evaluate() is called with the point index 0..points-1, in the rule's order.
template <Hex8MaterialPoint M>
void solid_full_with(const SolidElementInput& in, const M& material, SolidElementResult& out);

}  // namespace abut
