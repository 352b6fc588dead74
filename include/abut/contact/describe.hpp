#pragma once
// What a contact's settings do, in the library's own words (the law types and members of
// settings.hpp), for a host's log or report: the same text whatever input language the settings
// came from. Numbers are written with 4 significant digits.
#include <string>

#include "abut/contact/settings.hpp"

namespace abut {

struct ContactDescription {
  std::string discretisation;  // "surface-to-surface (accuracy level 2), symmetric"
  std::string normal_law;      // "linear penalty, positive side"
  std::string tangential_law;  // "Coulomb, mu_static = 0.3, mu_dynamic = 0.2"
  std::string stiffness_rule;  // "facet penalty"; "mean of both sides, scale = 2"
  std::string gap_rule;        // "shell gaps x 1"; "shell gaps x 1, at most 0.4 of the mesh size"
  std::string edge_rule;       // "none"; "sharp solid edges and shell borders (edge angle 135)"
  std::string erosion_rule;    // "eroded facets removed, free nodes kept"
};

ContactDescription describe(const ContactSettings& settings);

// One tangential law alone ("frictionless", "Tresca, m_static = 1, m_dynamic = 1, k = 100").
std::string describe(const TangentialLaw& law);

}  // namespace abut
