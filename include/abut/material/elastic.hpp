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
// On plain arrays in Sym3 order, for T = double or Lanes (lanes.hpp).
template <class T>
inline void hooke_of(const LameConstants& m, const T d[6], T out[6]) {
  const T volumetric = m.lambda * (d[0] + d[1] + d[2]);
  const double two_mu = 2.0 * m.mu;
  for (int i = 0; i < 3; ++i) out[i] = volumetric + two_mu * d[i];
  for (int i = 3; i < 6; ++i) out[i] = two_mu * d[i];
}
inline Sym3 hooke(const LameConstants& m, const Sym3& d) {
  Sym3 out;
  hooke_of(m, d.c.data(), out.c.data());
  return out;
}

}  // namespace abut
