#include "abut/material/mooney_rivlin.hpp"

#include <cmath>

namespace abut {

Sym3 mooney_rivlin_stress(const MooneyRivlinParams& p, const Mat3& f) {
  Sym3 s;
  mooney_rivlin_stress_of(p, f.data(), s.c.data());
  return s;
}

int viscous_term_count(const MooneyRivlinParams& p) {
  int n = 0;
  for (double alpha : p.alpha) n += alpha > 0.0 ? 1 : 0;
  return n;
}

ViscousStep viscous_step(const MooneyRivlinParams& p, double dt) {
  ViscousStep s;
  for (std::size_t k = 0; k < p.alpha.size(); ++k) {
    if (!(p.alpha[k] > 0.0)) continue;
    const double decay = p.beta[k] > 0.0 ? std::exp(-dt / p.beta[k]) : 0.0;
    s.decay[s.count] = decay;
    s.gain[s.count] = 2.0 * p.alpha[k] * (1.0 - decay) / dt;
    ++s.count;
  }
  return s;
}

}  // namespace abut
