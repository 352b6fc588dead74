#pragma once
// Helpers shared by the verification problems: build a model from deck text and march it.
#include <algorithm>
#include <cmath>
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

// Runs to the end and returns the largest |energy balance error| over the cycles where the
// energies in play (|total| or |external work|) exceed 1e-3 of `scale`, an expected size chosen
// beforehand: earlier the balance divides round-off by round-off.
inline double worst_energy_balance(Simulation& sim, double scale) {
  double worst = 0.0;
  run_to(sim, sim.end_time(), [&](const Simulation& s) {
    const Energies e = s.energies();
    if (std::max(std::abs(e.total()), std::abs(e.external_work)) > 1e-3 * scale)
      worst = std::max(worst, std::abs(s.energy_balance_error()));
  });
  return worst;
}

// The spans of a run during which its first contact touches (has active points): the first touch
// and the last release, each halfway between the cycles either side, and how many spans there
// were. start() before the run, record() after every cycle.
struct ContactSpans {
  double begin = -1.0, end = -1.0;
  int periods = 0;  // separate spans of contact

  bool touching() const { return previous_active_; }  // at the last cycle recorded

  void start(const Simulation& s) {
    previous_t_ = s.time();
    previous_active_ = touches(s);
  }
  void record(const Simulation& s) {
    const bool active = touches(s);
    if (active && !previous_active_ && ++periods == 1) begin = 0.5 * (previous_t_ + s.time());
    if (!active && previous_active_) end = 0.5 * (previous_t_ + s.time());
    previous_active_ = active;
    previous_t_ = s.time();
  }

 private:
  static bool touches(const Simulation& s) {
    return s.contact_reports().at(0).stats.active_points > 0;
  }
  double previous_t_ = 0.0;
  bool previous_active_ = false;
};

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
