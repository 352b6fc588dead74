#pragma once
// The fully integrated 8-node hexahedron for the implicit (Newton-Raphson) solver: Abaqus /
// CalculiX C3D8, trilinear, 2x2x2 Gauss points, internal force and consistent tangent stiffness,
// small strain or total Lagrangian (NLGEOM).
//
// Node order: VTK_HEXAHEDRON = Abaqus/CalculiX C3D8 (hex8.hpp: node 0 at natural coordinates
// (-1,-1,-1), 1 (1,-1,-1), 2 (1,1,-1), 3 (-1,1,-1), 4..7 the same at zeta = +1).
//
// Gauss point order: CalculiX's (gauss.f, array gauss3d2, which its C3D8 routines and *EL PRINT
// use; CalculiX User's Manual, "Eight-node brick element (C3D8)", Figure "2x2x2
// integration point scheme in hexahedral elements", doc/Int8.fig). It is the tensor-product
// order, xi fastest, then eta, then zeta. It is NOT the node order: nodes 2 and 3 go round the
// face (+,+,-), (-,+,-), points 2 and 3 do not (likewise 6 and 7):
//   point 0 (-g,-g,-g), 1 (+g,-g,-g), 2 (-g,+g,-g), 3 (+g,+g,-g),
//   point 4 (-g,-g,+g), 5 (+g,-g,+g), 6 (-g,+g,+g), 7 (+g,+g,+g),   g = 1/sqrt(3), weight 1.
// (Checked against ccx 2.20 on a single element, tests/element/test_hex8_full.cpp.)
//
// Voigt order everywhere: xx yy zz xy yz zx. Strains are ENGINEERING (shear entries 2 E_ij),
// stresses tensorial, so that stress = D strain and stress . strain = S : E. CalculiX prints
// stresses as sxx syy szz sxy sxz syz and strains as tensor components exx eyy ezz exy exz eyz:
// swap the last two entries (and halve our shear strains) to compare.
#include <concepts>

namespace abut {

// Isotropic linear elasticity as the implicit element needs it: the stress and the 6x6 tangent
// from the strain. With geometric nonlinearity the element hands it the Green-Lagrange strain E and
// reads back the second Piola-Kirchhoff stress S: the St Venant-Kirchhoff law
// S = lambda tr(E) I + 2 mu E. This is what CalculiX does for *ELASTIC with NLGEOM: it works in
// the total Lagrangian setting with the Lagrangian strain and the second Piola-Kirchhoff stress for
// elastic media and reports Cauchy ("true") stress (CalculiX User's Manual 2.17, section "Theory",
// eqs. (3) and (7); its *USER MATERIAL section on the Ciarlet model names the plain substitution
// St-Venant-Kirchhoff); a one-element ccx 2.20 NLGEOM run agrees with this element to the 7
// printed digits (Cauchy stress, Lagrangian strain, reaction forces, energy; see the tests).
// lambda = E nu / ((1 + nu)(1 - 2 nu)), mu = E / (2 (1 + nu)).
// Preconditions, not checked here (the caller validates its input): young > 0,
// -1 < poisson < 0.5.
struct IsotropicElastic {
  double young = 0.0;
  double poisson = 0.0;

  // stress = D strain (strain with engineering shears, stress tensorial, Voigt order above).
  void stress(const double strain[6], double out[6]) const;
  // D, row-major 6x6: d[6 * i + j] = d stress_i / d strain_j.
  void tangent(double d[36]) const;
  // The material-point call of the element (see Hex8MaterialPoint): stress, tangent, and the
  // stored energy density W = 1/2 stress . strain. `point` (0..7) is unused by an elastic law.
  double evaluate(int point, const double strain[6], double stress_out[6], double d[36]) const;
};

// What the element loop needs from a material point: given the Gauss point index (0..7, the order
// above; a material with history, e.g. J2 plasticity later, uses it to address its state) and the
// strain (small strain, or Green-Lagrange with NLGEOM; Voigt, engineering shears), write the
// stress (Cauchy, or second Piola-Kirchhoff with NLGEOM) and the consistent 6x6 tangent
// d stress / d strain (row-major), and return the energy density per unit reference volume.
// A material holding history does so through pointers it owns: the element takes it by const&.
// The tangent must be symmetric (hyperelastic laws, associative J2 plasticity): the element forms
// the upper triangle of K only and mirrors it.
template <class M>
concept Hex8MaterialPoint = requires(const M& m, int point, const double* strain, double* stress,
                                     double* tangent) {
  { m.evaluate(point, strain, stress, tangent) } -> std::convertible_to<double>;
};

struct Hex8FullInput {
  double X[8][3];                   // reference coordinates
  double u[8][3];                   // displacements
  bool nonlinear_geometry = false;  // NLGEOM: total Lagrangian
};

struct Hex8FullResult {
  double force[24];           // internal force, dof order node-major: (u0x,u0y,u0z,u1x,...)
  double stiffness[24 * 24];  // tangent dF/du, row-major, material + geometric (NLGEOM) part;
                              // exactly symmetric (upper triangle computed and mirrored)
  double stress[8][6];        // Cauchy stress at the Gauss points (Voigt xx yy zz xy yz zx)
  double strain[8][6];        // small strain, or Green-Lagrange with NLGEOM; engineering shears
  double energy_density[8];   // W at the Gauss points, per unit reference volume
  double strain_energy;       // integral of W over the reference volume
  double volume;              // current volume (the reference one for small strain)
  double min_jacobian;        // smallest det(dx/dxi) at the Gauss points: of the reference
                              // coordinates for small strain, of the current ones (X + u) with
                              // NLGEOM. <= 0: inverted element, the other results are meaningless.
};

// Small strain: eps = B u, f = int B^T sigma dV, K = int B^T D B dV, Cauchy stress = sigma.
// NLGEOM (total Lagrangian; Bathe, Finite Element Procedures, 1996, section 6.3.2; Belytschko,
// Liu & Moran, Nonlinear Finite Elements for Continua and Structures, 2000, section 4.9 and the
// material and geometric stiffness of section 6.4): F = I + du/dX, E = (F^T F - I)/2, S = C:E,
// f = int B_NL^T S dV0 with B_NL the linearised strain operator (delta E = B_NL delta u),
// K = int B_NL^T D B_NL dV0 + int (grad0 N_a . S grad0 N_b) I dV0, sigma = F S F^T / det F.
// No allocation; safe to call concurrently on different outputs.
void hex8_full(const Hex8FullInput& in, const IsotropicElastic& material, Hex8FullResult& out);

// The same element with any material point. Defined in src/element/hex8_full.cpp and explicitly
// instantiated there for each material (IsotropicElastic, J2StrainPoint of
// material/j2_strain_point.hpp): a new material adds one line.
template <Hex8MaterialPoint M>
void hex8_full_with(const Hex8FullInput& in, const M& material, Hex8FullResult& out);

}  // namespace abut
