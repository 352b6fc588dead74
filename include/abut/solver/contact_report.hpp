#pragma once
// What the solver reports of each *CONTACT: its penalty stiffness per part and per facet pair
// (seed 000: automatic per part, the smaller of the two in a pair) and its current statistics.
#include <cstdint>
#include <string>
#include <vector>

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
  // What the contact does, in the deck's words: "S2S symmetric", "N2S one-way"; "LINEAR POSITIVE";
  // "COULOMB mu_s = 0.3, mu_d = 0.2"; "PFAC" or "MEAN (Istf 2), stfac = 1".
  std::string discretisation, normal_law, tangential_law, stiffness_rule;
  // "Igap 3, scale 1, 0.4 of the mesh size"; "facets REMOVE, free nodes KEEP, exposed faces join".
  std::string gap_rule, erosion_rule, edge_rule;
  std::size_t points = 0;           // contact points (integration points or nodes, all passes)
  std::size_t released_points = 0;  // initially deeper than delta0_max
  std::vector<std::string> warnings;  // start-up checks (solver/contact_checks.hpp)
  ContactStats stats;
};

}  // namespace abut
