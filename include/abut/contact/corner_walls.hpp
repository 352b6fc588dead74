#pragma once
// The walls of a concave corner that a contact node presses besides its partner (issue 27).
//
// A node pressed into a concave corner (a block in the corner of two plates) penetrates both walls.
// Its partner is the closest facet alone, so its force jumped from one wall's normal to the other's
// each time the closer one changed: that force does work over a cycle (an elastic block pressed
// into the corner of two shell plates gained 58% of the work done in 20 ms). The region
// behind a concave corner is the union of the half-spaces behind its walls, so the squared distance
// out of it is the sum of the squared penetrations of the walls, d1^2 + d2^2: the penalty
// potential of the corner is the sum of each wall's, and so is its force, each along its own
// wall's normal (Wriggers, "Computational Contact Mechanics", 2nd ed., 2006, sec. 4.1 and 9.3:
// the penalty term as a sum over the active constraints; at a convex edge the gap is the distance
// to the nearest face only, which the closest partner gives).
//
// A wall is a facet that
//  - the narrow phase accepts for the point (narrow_phase.hpp) and the point penetrates,
//  - is turned from the partner and from every wall taken before by more than alpha_edge (a
//    facet of the partner's own smooth surface is not another wall: the partner speaks for it),
//  - forms a concave corner with each of them: each facet's centre (on its contact surface) lies
//    in front of the other's plane, as the floor and the wall of a room do; at a convex edge each
//    lies behind the other's.
// Of the facets of one wall the closest is taken (ties: the lower facet number); at most
// kMaxCornerWalls, taken closest first (a node in the corner of a box meets three walls).
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "abut/contact/narrow_phase.hpp"

namespace abut {

inline constexpr std::size_t kMaxCornerWalls = 2;

struct CornerWalls {
  std::array<Partner, kMaxCornerWalls> walls;
  std::size_t count = 0;
};

// `partner`: the point's partner among `candidates` (find_partner); `sharp_cos`: cos(alpha_edge).
CornerWalls find_corner_walls(const TargetFacets& target, std::span<const std::int32_t> candidates,
                              const std::array<std::int32_t, 4>& own_nodes, const Vec3& x,
                              const Vec3& normal, const PartnerRules& rules, const Partner& partner,
                              double sharp_cos);

}  // namespace abut
