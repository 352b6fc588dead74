#pragma once
// J2 (von Mises) plasticity with isotropic hardening as a strain-driven material point for the
// implicit elements (Hex8MaterialPoint in element/hex8_full.hpp): given the total strain of a
// Gauss point, the stress and the CONSISTENT (algorithmic) tangent of the radial return.
//
// Additive split of a small strain, or of the Green-Lagrange strain with NLGEOM (then the stress
// is the second Piola-Kirchhoff stress): eps = eps_e + eps_p, sigma = De : eps_e, yield function
// q - sigma_y(epsp) with q the von Mises stress. With the plastic strain of the last converged
// increment, the return of metal.hpp (radial_return, rate-independent here) gives the stress and
// the increment dp of the equivalent plastic strain; the plastic strain grows by the deviator
// the return removed, (s_trial - s) / 2G. The Lagrangian form is the usual "small strain, large
// rotation" extension: exact for rigid rotations, meant for strains of a few percent. (CalculiX's
// *PLASTIC uses a multiplicative finite-strain law with NLGEOM, so for large plastic strains the
// two codes differ.)
//
// Consistent tangent (Simo & Taylor 1985, CMAME 48:101; de Souza Neto, Peric & Owen,
// "Computational Methods for Plasticity", 2008, eq. 7.120), with n = s_trial / |s_trial| and
// H = d sigma_y / d epsp at the new plastic strain:
//   D = De - (6 G^2 dp / q_trial) I_dev + 6 G^2 (dp / q_trial - 1 / (3 G + H)) n (x) n.
// It is symmetric, as the element requires.
#include "abut/material/material.hpp"
#include "abut/material/metal.hpp"

namespace abut {

// The history of one Gauss point: plastic strain (Voigt xx yy zz xy yz zx, engineering shears as
// the element's strains), equivalent plastic strain, plastic work per unit volume, and the
// strain, stress and energy density of the last state (for the incremental energy).
struct J2PointHistory {
  double plastic_strain[6] = {0, 0, 0, 0, 0, 0};
  double equivalent_plastic_strain = 0.0;
  double plastic_work = 0.0;
  double strain[6] = {0, 0, 0, 0, 0, 0};
  double stress[6] = {0, 0, 0, 0, 0, 0};
  double energy = 0.0;
};

// One element's material points. `committed` (the last converged increment, read) and `trial`
// (written by evaluate; the caller commits it once the increment converges) point to the
// histories of the element's Gauss points, indexed by the point number the element passes.
struct J2StrainPoint {
  double young = 0.0;
  double poisson = 0.0;
  FlowStress flow;
  const J2PointHistory* committed = nullptr;
  J2PointHistory* trial = nullptr;

  // Hex8MaterialPoint: stress and tangent (Voigt, engineering shears, row-major 6x6) from the
  // strain; returns the energy density, the work of the stress integrated by the trapezoidal
  // rule over the increments, W = W_old + (stress_old + stress) . (strain - strain_old) / 2, as
  // CalculiX integrates its internal energy (elastic energy plus dissipation, to O(increment^2)).
  double evaluate(int point, const double strain[6], double stress[6], double d[36]) const;
};

}  // namespace abut
