#pragma once
// *MAT_ELASTIC as a hypoelastic law: the objective stress rate is Hooke's law applied to the
// rate of deformation D, sigma_rate = lambda tr(D) I + 2 mu D. The element rotates the stress
// with the Hughes-Winget increment (sym_tensor.hpp) before adding the increment, which makes
// the update a Jaumann-type rate that is exactly objective for rigid rotations.
#include "abut/material/material.hpp"
#include "abut/material/sym_tensor.hpp"

namespace abut {

struct LameConstants {
  double lambda = 0.0;
  double mu = 0.0;
};

// lambda = E nu / ((1 + nu)(1 - 2 nu)), mu = E / (2 (1 + nu)).
LameConstants lame_constants(const ElasticParams& p);

// Hooke's law for a strain increment (or strain): lambda tr(d) I + 2 mu d.
inline Sym3 hooke(const LameConstants& m, const Sym3& d) {
  const double volumetric = m.lambda * trace(d);
  const double two_mu = 2.0 * m.mu;
  return {{volumetric + two_mu * d[0], volumetric + two_mu * d[1], volumetric + two_mu * d[2],
           two_mu * d[3], two_mu * d[4], two_mu * d[5]}};
}

}  // namespace abut
