#pragma once
// Narrow phase: the partner facet of one contact point among its broad-phase candidates.
//
// Each candidate is projected on (quad.hpp). It is accepted when
//  - it does not share a node with the point's own facet (no contact with itself or neighbours),
//  - the two surfaces face each other (n_point . n_facet < 0; reversed for contact from behind;
//    skipped when the point has no normal, a bare node),
//  - the gap g = (x - q) . n lies within [-depth_below, depth_above] (depth_below: how deep a point
//    may be and still belong to this side; beyond it lies the far side),
//  - a projection beyond a sharp (or free) edge overshoots it by at most edge_tolerance; beyond a
//    smooth edge by at most |g| tan(alpha_edge) (the dead zone of a convex edge; see
//    docs/contact.md).
// The closest accepted facet is the partner.
#include <array>
#include <cstdint>
#include <span>

#include "abut/contact/quad.hpp"

namespace abut {

// The facets a point may meet, with what the acceptance rules need of each.
struct TargetFacets {
  std::span<const std::array<std::int32_t, 4>> nodes;
  std::span<const std::uint8_t> sharp;   // sharp-edge bits per facet (quad.hpp edge numbering)
  std::span<const std::uint8_t> active;  // 0: the facet takes no part
  std::span<const double> depth;         // its own detection depth
  std::span<const double> x, y, z;       // current nodal coordinates
};

struct PartnerRules {
  double point_depth = 0.0;  // the point's own detection depth: a pair uses the larger one
  double depth_above = 0.0;  // largest accepted gap outside the facet
  bool from_behind = false;  // the point must face the back of the facet (contact sense negative)
  double edge_tolerance = 0.0;  // delta_edge
  double smooth_reach = 0.0;    // tan(alpha_edge)
};

struct Partner {
  std::int32_t facet = -1;
  double xi = 0.0, eta = 0.0, gap = 0.0;
};

// `own_nodes`: the nodes of the point's facet (a node-to-surface point: its node four times);
// `normal`: the point's outward normal, or zero for a bare node.
Partner find_partner(const TargetFacets& target, std::span<const std::int32_t> candidates,
                     const std::array<std::int32_t, 4>& own_nodes, const Vec3& x,
                     const Vec3& normal, const PartnerRules& rules);

}  // namespace abut
