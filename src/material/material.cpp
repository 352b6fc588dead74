#include "abut/material/material.hpp"

namespace abut {

namespace {

// K = E / (3 (1 - 2 nu)), G = E / (2 (1 + nu)).
ElasticModuli isotropic(double young, double poisson) {
  return {young / (3.0 * (1.0 - 2.0 * poisson)), young / (2.0 * (1.0 + poisson))};
}

}  // namespace

ElasticModuli initial_moduli(const MaterialParams& m) {
  if (const auto* e = std::get_if<ElasticParams>(&m)) return isotropic(e->young, e->poisson);
  if (const auto* metal = std::get_if<MetalParams>(&m))
    return isotropic(metal->young, metal->poisson);
  if (const auto* mr = std::get_if<MooneyRivlinParams>(&m)) {
    // Small-strain shear modulus of Mooney-Rivlin: mu = 2 (C1 + C2).
    return {mr->bulk, 2.0 * (mr->c1 + mr->c2)};
  }
  return {};
}

}  // namespace abut
