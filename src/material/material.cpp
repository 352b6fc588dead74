#include "abut/material/material.hpp"

namespace abut {

ElasticModuli initial_moduli(const MaterialParams& m) {
  if (const auto* e = std::get_if<ElasticParams>(&m)) {
    return {e->young / (3.0 * (1.0 - 2.0 * e->poisson)), e->young / (2.0 * (1.0 + e->poisson))};
  }
  if (const auto* metal = std::get_if<MetalParams>(&m)) {
    return {metal->young / (3.0 * (1.0 - 2.0 * metal->poisson)), metal->young / (2.0 * (1.0 + metal->poisson))};
  }
  if (const auto* mr = std::get_if<MooneyRivlinParams>(&m)) {
    // Small-strain shear modulus of Mooney-Rivlin: mu = 2 (C1 + C2).
    return {mr->bulk, 2.0 * (mr->c1 + mr->c2)};
  }
  return {};
}

}  // namespace abut
