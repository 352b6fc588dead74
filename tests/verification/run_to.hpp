#pragma once
// Helpers shared by the verification problems: build a model from deck text and march it.
#include <cstddef>
#include <functional>
#include <string>

#include "abut/io/deck.hpp"
#include "abut/solver/simulation.hpp"

namespace abut::verification {

// Advances until time >= t (or the end time), calling `each` after every cycle.
inline void run_to(Simulation& sim, double t, const std::function<void(const Simulation&)>& each = {}) {
  while (!sim.finished() && sim.time() < t) {
    sim.advance();
    if (each) each(sim);
  }
}

// Index of the node nearest to the reference point (x, y, z).
inline std::size_t node_near(const Model& model, double x, double y, double z) {
  const Nodes& nodes = model.mesh.nodes;
  std::size_t best = 0;
  double best_d = 1e300;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const double d = (nodes.x[i] - x) * (nodes.x[i] - x) + (nodes.y[i] - y) * (nodes.y[i] - y) +
                     (nodes.z[i] - z) * (nodes.z[i] - z);
    if (d < best_d) {
      best_d = d;
      best = i;
    }
  }
  return best;
}

}  // namespace abut::verification
