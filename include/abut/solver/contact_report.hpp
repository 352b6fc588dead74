#pragma once
// What the solver reports of each *CONTACT: its penalty stiffness per part and per facet pair
// (seed 000: automatic per part, the smaller of the two in a pair) and its current statistics.
#include <cstdint>
#include <string>
#include <vector>

#include "abut/contact/describe.hpp"
#include "abut/contact/interface.hpp"

namespace abut {

struct PartPenalty {
  std::int64_t part_id = 0;
  double penalty = 0.0;    // pfac [pressure / length]
  bool automatic = false;  // computed from K, L_min and v_max (or rigid), not given
};

struct ContactReport {
  std::int64_t id = 0;
  std::string title;
  std::vector<PartPenalty> parts;
  std::vector<PairStiffness> pairs;  // after the stiffness rule and pair scaling
  // What the contact does, in the model's words (contact/describe.hpp): "surface-to-surface
  // (accuracy level 2), symmetric"; "linear penalty, positive side"; "Coulomb, mu_static = 0.3,
  // mu_dynamic = 0.2"; "facet penalty"; ...
  ContactDescription laws;
  std::size_t points = 0;           // contact points (integration points or nodes, all passes)
  std::size_t released_points = 0;  // initially deeper than delta0_max
  std::vector<std::string> warnings;  // start-up checks (solver/contact_checks.hpp)
  ContactStats stats;
};

}  // namespace abut
