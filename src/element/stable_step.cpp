#include "abut/element/stable_step.hpp"

namespace abut {

double hex8_critical_length(const Hex8ModalGradient& g, double lambda, double mu) {
  double product[6];
  hex8_gradient_products(g, product);
  return hex8_critical_length(product, g.volume, lambda, mu);
}

Hex8ModalGradient hex8_modal_gradient_at(const Hex8& hex, const Nodes& nodes) {
  Hex8Coords x;
  for (int a = 0; a < 8; ++a) {
    const auto node = static_cast<std::size_t>(hex[a]);
    x.x[a] = nodes.x[node];
    x.y[a] = nodes.y[node];
    x.z[a] = nodes.z[node];
  }
  Hex8Modes c;
  hex8_to_modes(x.x, c.x);
  hex8_to_modes(x.y, c.y);
  hex8_to_modes(x.z, c.z);
  Hex8ModalGradient g;
  hex8_modal_gradient(c, g);
  return g;
}

}  // namespace abut
