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

// Thermal softening factor of Johnson & Cook (1983, Proc. 7th Int. Symp. Ballistics, p. 541):
//   1 - T*^m,  T* = (T - T0) / (Tm - T0) clamped to [0, 1],
// so the flow stress is unchanged at and below T0 and vanishes at the melting temperature Tm.
// 1 when the material does not soften (m = 0).
double thermal_softening(const MetalParams& params, double temperature);
// T* = (T - T0) / (Tm - T0) clamped to [0, 1]; 0 without a melting temperature above T0.
double homologous_temperature(const MetalParams& params, double temperature);

// The flow stress at a plastic strain and rate, and its derivative along a step's increment dp
// (the strain epsp + dp at the rate dp / dt): d sigma_y / d dp = d/d epsp + (1 / dt) d/d rate.
// `has_slope` false: a curve, whose slope the caller takes by a difference.
struct FlowPoint {
  double stress = 0.0;
  double slope = 0.0;
  bool has_slope = false;
};

// sigma_y(epsp, epsp_rate) of a metal; the table evaluates *MAT_METAL's curve. The same factor
// 1 - T*^m multiplies *MAT_METAL's curve and Johnson-Cook's product (at_temperature).
class FlowStress {
 public:
  FlowStress(const MetalParams& params, const FunctionTable* table) : p_(&params), table_(table) {}
  double operator()(double plastic_strain, double plastic_strain_rate) const;
  // At epsp + dp, flowing at dp / dt (rate 0 for dt = 0); Johnson-Cook with its slope in closed
  // form.
  FlowPoint along_step(double plastic_strain, double dp, double dt) const;
  // The flow stress of the same metal at a temperature (softened when the metal softens).
  FlowStress at_temperature(double temperature) const {
    FlowStress f = *this;
    f.thermal_factor_ = thermal_softening(*p_, temperature);
    return f;
  }
  const MetalParams& params() const { return *p_; }

 private:
  const MetalParams* p_;
  const FunctionTable* table_;
  double thermal_factor_ = 1.0;
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
