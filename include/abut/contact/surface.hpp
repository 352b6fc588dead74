#pragma once
// A contact surface: quad facets with the data the contact needs per facet. Plain arrays: the
// caller builds it from its own mesh (abut's solver does so from the exterior faces of hexes).
#include <array>
#include <cstdint>
#include <vector>

namespace abut {

struct ContactSurface {
  // Node indices, counter-clockwise seen from outside (the right-hand normal points out of the
  // body). A triangle is a quad with its last node repeated.
  std::vector<std::array<std::int32_t, 4>> facets;
  std::vector<std::int64_t> part;  // user part id of the owning element
  std::vector<double> penalty;     // penalty stiffness pfac [stress / length]
  std::vector<double> thickness;   // owning element's size along the facet normal
  // For the Radioss stiffness rules only (stiffness_rule.hpp); may stay empty otherwise.
  std::vector<double> bulk_modulus;    // of the owning element's material
  std::vector<double> element_volume;  // of the owning element

  std::size_t size() const { return facets.size(); }
  void add(const std::array<std::int32_t, 4>& nodes, std::int64_t part_id, double pfac, double t,
           double bulk = 0.0, double volume = 0.0) {
    facets.push_back(nodes);
    part.push_back(part_id);
    penalty.push_back(pfac);
    thickness.push_back(t);
    bulk_modulus.push_back(bulk);
    element_volume.push_back(volume);
  }
};

}  // namespace abut
