#pragma once
// The material-point update of *MAT_METAL and *MAT_JC: hypoelastic trial stress, then the radial
// return of J2 plasticity with isotropic hardening (Wilkins 1964; Simo & Hughes, "Computational
// Inelasticity", 1998, box 3.2). With q the von Mises stress of the trial deviator s_trial, the
// return solves for the plastic strain increment dp
//     q - 3 G dp = sigma_y(epsp + dp, dp / dt)
// and scales the deviator by (q - 3 G dp) / q; the pressure stays elastic. A safeguarded Newton
// iteration (bisection when a step leaves the bracket [0, q / 3G]) handles tabulated, power-law and
// rate-dependent flow stresses alike.
#include "abut/core/functions.hpp"
#include "abut/material/material.hpp"
#include "abut/material/sym_tensor.hpp"

namespace abut {

// sigma_y(epsp, epsp_rate) of a metal; the table evaluates *MAT_METAL's curve.
class FlowStress {
 public:
  FlowStress(const MetalParams& params, const FunctionTable* table) : p_(&params), table_(table) {}
  double operator()(double plastic_strain, double plastic_strain_rate) const;

 private:
  const MetalParams* p_;
  const FunctionTable* table_;
};

struct PlasticUpdate {
  Sym3 stress;
  double plastic_strain_increment = 0.0;
};

// `trial`: rotated old stress plus the elastic increment; `shear_modulus` G; `plastic_strain`:
// epsp before the step; `dt` the step (for the rate; 0: rate-independent).
PlasticUpdate radial_return(const Sym3& trial, double shear_modulus, double plastic_strain,
                            double dt, const FlowStress& flow);

}  // namespace abut
