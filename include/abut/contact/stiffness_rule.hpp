#pragma once
// How the penalty spring of a contact point is chosen.
//
// FacetPenalty (default, seed 000): every facet carries a penalty pfac [stress / length] (given,
// automatic per part, or element-based, chosen by the caller); a point's spring is
// k = min(pfac_own, pfac_partner) * area.
//
// The Radioss /INTER/TYPE25 rules (seed 004, comment 2; decoded in seeds/README.md) build a
// spring [force / length] from the main segment (the partner facet) and the secondary node (the
// point's own side):
//     solid main segment    K_m = Stfac * B * S^2 / V   (S facet area, V element volume, B bulk
//                                                      modulus)
//     solid secondary node  K_s = Stfac * B * V^(1/3)
//     shell (either role)   K   = Stfac * 0.5 * E * t
//     Istf 1000: K_m   2: (K_m + K_s)/2   3: max   4: min   5: K_m K_s / (K_m + K_s)
//     K = max(Stmin, min(Stmax, K_n))   (Stmin/Stmax only for Istf 2..5)
// A node-to-surface point takes K whole; an integration point takes K times its share of its
// facet's area, so that a facet's points together carry the spring of one node.
#include <algorithm>
#include <cmath>
#include <limits>

namespace abut {

enum class StiffnessRule { FacetPenalty, Main, Mean, Maximum, Minimum, Series };

struct StiffnessSettings {
  StiffnessRule rule = StiffnessRule::FacetPenalty;
  double scale = 1.0;  // Stfac (Radioss rules)
  double minimum = 0.0;
  double maximum = std::numeric_limits<double>::infinity();
};

inline double main_segment_stiffness(double bulk_modulus, double area, double volume,
                                     double stfac) {
  return stfac * bulk_modulus * area * area / volume;
}

// Shell main segment or secondary node (either side of the shell): Stfac * 0.5 * E * t.
inline double shell_segment_stiffness(double young_modulus, double thickness, double stfac) {
  return stfac * 0.5 * young_modulus * thickness;
}

inline double secondary_node_stiffness(double bulk_modulus, double volume, double stfac) {
  return stfac * bulk_modulus * std::cbrt(volume);
}

// K of a pair from the two sides' stiffnesses under a Radioss rule.
inline double combined_stiffness(const StiffnessSettings& s, double k_main, double k_secondary) {
  double k = k_main;
  switch (s.rule) {
    case StiffnessRule::FacetPenalty:
    case StiffnessRule::Main:
      return k_main;  // Stmin/Stmax apply to Istf 2..5 only (seed 004)
    case StiffnessRule::Mean:
      k = 0.5 * (k_main + k_secondary);
      break;
    case StiffnessRule::Maximum:
      k = std::max(k_main, k_secondary);
      break;
    case StiffnessRule::Minimum:
      k = std::min(k_main, k_secondary);
      break;
    case StiffnessRule::Series:
      k = k_main * k_secondary / (k_main + k_secondary);
      break;
  }
  return std::max(s.minimum, std::min(s.maximum, k));
}

}  // namespace abut
