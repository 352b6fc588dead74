#pragma once
// A contact surface: quad facets with the data the contact needs per facet.
#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "abut/mesh/skin.hpp"

namespace abut {

struct ContactSurface {
  // Node indices, counter-clockwise seen from outside (the right-hand normal points out of the
  // body). A triangle is a quad with its last node repeated.
  std::vector<std::array<std::int32_t, 4>> facets;
  std::vector<std::int64_t> part;     // user part id of the owning element
  std::vector<double> penalty;        // penalty stiffness pfac of that part [pressure / length]
  std::vector<double> thickness;      // owning element's size along the facet normal

  std::size_t size() const { return facets.size(); }
  void add(const std::array<std::int32_t, 4>& nodes, std::int64_t part_id, double pfac, double t) {
    facets.push_back(nodes);
    part.push_back(part_id);
    penalty.push_back(pfac);
    thickness.push_back(t);
  }
};

// Contact surface of skin faces, the penalty of each facet given by its part.
ContactSurface make_contact_surface(std::span<const SkinFace> faces,
                                    const std::function<double(std::int64_t part)>& penalty_of_part);

}  // namespace abut
