#pragma once
// A contact surface: quad facets with the data the contact needs per facet. Plain arrays: the
// caller builds it from its own mesh (abut's solver does so from the exterior faces of hexes and
// from shells).
//
// A shell is two facets, one per side (Radioss /INTER/TYPE25, seed 004, comment 1: "two contact
// segments with opposite normal directions"): the second lists the nodes in reverse order and
// `twin` links the pair. Both lie on the mid-surface; each side's contact surface is offset from it
// along the side's normal by the gap (gap.hpp, half the thickness by default).
#include <array>
#include <cstdint>
#include <vector>

#include "abut/contact/facet_parent.hpp"

namespace abut {

struct ContactSurface {
  // Node indices, counter-clockwise seen from outside (the right-hand normal points out of the
  // body). A triangle is a quad with its last node repeated.
  std::vector<std::array<std::int32_t, 4>> facets;
  std::vector<std::int64_t> part;  // user part id of the owning element
  std::vector<double> penalty;     // penalty stiffness pfac [stress / length]
  std::vector<double> thickness;   // owning element's size along the facet normal (shell: h)
  std::vector<std::int32_t> twin;  // shell: the facet of the other side; -1: a solid's face
  // For the Radioss stiffness rules only (stiffness_rule.hpp); may stay empty otherwise.
  std::vector<double> bulk_modulus;    // of the owning element's material
  std::vector<double> element_volume;  // of the owning element
  std::vector<double> young_modulus;   // of a shell's material (K = Stfac 0.5 E t)
  // Erosion (ContactInterface::erode): the host's index of the element the facet belongs to (-1:
  // it never erodes), and for an internal face, which joins the contact only once the element
  // on its other side has eroded (IMPETUS no_internal = 0), that element (-1: an exterior face).
  std::vector<std::int32_t> element;
  std::vector<std::int32_t> exposed_by;
  // Static contact only: the curved face each facet is a piece of (facet_parent.hpp); empty, or
  // one per facet (a plain facet has no shape).
  std::vector<FacetParent> parent;

  std::size_t size() const { return facets.size(); }
  void add(const std::array<std::int32_t, 4>& nodes, std::int64_t part_id, double pfac, double t,
           double bulk = 0.0, double volume = 0.0) {
    facets.push_back(nodes);
    part.push_back(part_id);
    penalty.push_back(pfac);
    thickness.push_back(t);
    twin.push_back(-1);
    bulk_modulus.push_back(bulk);
    element_volume.push_back(volume);
    young_modulus.push_back(0.0);
    element.push_back(-1);
    exposed_by.push_back(-1);
  }
  // Both sides of a shell of thickness h (nodes counter-clockwise about its normal), and for the
  // Radioss rules its Young's modulus.
  void add_shell(const std::array<std::int32_t, 4>& nodes, std::int64_t part_id, double pfac,
                 double h, double young = 0.0) {
    const auto first = static_cast<std::int32_t>(facets.size());
    for (const auto& n : {nodes, reversed(nodes)}) {
      add(n, part_id, pfac, h);
      young_modulus.back() = young;
    }
    twin[first] = first + 1;
    twin[first + 1] = first;
  }
  // One side of a shell only (OptiStruct MORIENT NORM / REVNORM, seed 003): a one-sided surface
  // on the mid-surface that pushes every point out to the side of its normal (`reverse`: the
  // other side), as a solid's face does, also points that come from behind within the detection
  // depth. It has no twin and so no shell gap (gap.hpp padding may add one).
  void add_shell_side(const std::array<std::int32_t, 4>& nodes, std::int64_t part_id, double pfac,
                      double h, bool reverse) {
    add(reverse ? reversed(nodes) : nodes, part_id, pfac, h);
  }
  // The nodes of a facet seen from its other side (a triangle keeps its repeated last node).
  static std::array<std::int32_t, 4> reversed(const std::array<std::int32_t, 4>& nodes) {
    return nodes[2] == nodes[3]
               ? std::array<std::int32_t, 4>{nodes[1], nodes[0], nodes[2], nodes[2]}
               : std::array<std::int32_t, 4>{nodes[3], nodes[2], nodes[1], nodes[0]};
  }
};

}  // namespace abut
