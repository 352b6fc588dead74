#pragma once
// Narrow phase: the partner facet of one contact point among its broad-phase candidates.
//
// Each candidate is projected on (quad.hpp). The gap g of the pair (gap.hpp: the shells' offsets)
// is subtracted from the distance along the facet's normal. It is accepted when
//  - it does not share a node with the point's own facet (no contact with itself or neighbours),
//    and with Igap 2 none of its nodes lay within twice the gap of the point at the start,
//  - for one side of a shell: the point lies on that side of the mid-surface (behind it lies the
//    other side's facet),
//  - the two surfaces face each other (n_point . n_facet < 0; reversed for contact from behind;
//    skipped when the point has no normal, a bare node),
//  - the gap (x - q) . n - g lies within [-depth_below, depth_above] (depth_below: how deep a point
//    may be and still belong to this side; beyond it lies the far side),
//  - a projection beyond a sharp (or free) edge overshoots it by at most edge_tolerance or 1e-2
//    of the facet's diagonal (a node on a border stays on it while the surfaces deform a little
//    differently); beyond a smooth edge by at most |g| tan(alpha_edge) (the dead zone of a convex
//    edge; see docs/contact.md). A shell's contact surface is rounded around its inner edges (the
//    round gap of seed 004, comment 5): beyond such an edge the gap is the distance to the edge
//    less the pair's gap, along the radial direction, at any overshoot; only its free border cuts
//    off like a sharp edge (or, for a point with a gap of its own, as the border rule says:
//    GapSettings::border, Radioss Ishape). Folds that sharpen as a shell crushes then stay
//    continuous.
// The closest accepted facet (distance less the pair's gap) is the partner.
#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <span>

#include "abut/contact/gap.hpp"
#include "abut/contact/penetration_zone.hpp"
#include "abut/contact/quad.hpp"

namespace abut {

// Beyond a sharp or free edge a point still meets a facet within this fraction of the facet's
// diagonal (a node on the border of a matched mesh; narrow_phase.cpp), or the edge tolerance.
inline constexpr double kOnBorder = 1e-2;

// The facets a point may meet, with what the acceptance rules need of each.
struct TargetFacets {
  std::span<const std::array<std::int32_t, 4>> nodes;
  std::span<const std::uint8_t> sharp;       // sharp-edge bits per facet (quad.hpp edge numbering)
  std::span<const std::uint8_t> active;      // 0: the facet takes no part
  std::span<const double> depth;             // its own detection depth
  std::span<const std::int32_t> twin;        // shell: the other side's facet, else -1
  std::span<const std::uint8_t> free_edges;  // free-edge bits per facet (a shell's border)
  std::span<const double> gap;               // g_m, capped (gap.hpp)
  std::span<const double> min_edge;          // g_m_l: its shortest edge
  std::span<const double> x, y, z;           // current nodal coordinates
  // Per facet, this step's box (penetration_zone.hpp), for the facets that may be asked for; empty:
  // the boxes come from the corners.
  std::span<const FacetBand> bands = {};
  // The largest g_m of `gap` (a bound the box test uses before a pair's own gap is looked up).
  double max_gap = std::numeric_limits<double>::infinity();
};

struct PartnerRules {
  double point_depth = 0.0;  // the point's own detection depth: a pair uses the larger one
  double depth_above = 0.0;  // largest accepted gap outside the facet
  bool from_behind = false;  // the point must face the back of the facet (contact sense negative)
  // How squarely the point must face the facet: n_point . n_facet < -facing (0: any facing at
  // all; S2S points beyond the other surface's border: cos(alpha_edge), so that a cell reaches
  // only over a surface that faces its own, not over the side walls beyond that border).
  double facing = 0.0;
  double edge_tolerance = 0.0;                                      // delta_edge
  double smooth_reach = 0.0;                                        // tan(alpha_edge)
  double point_gap = 0.0;                                           // g_s, capped (gap.hpp)
  double point_min_edge = std::numeric_limits<double>::infinity();  // g_s_l
  double mesh_fraction = std::numeric_limits<double>::infinity();   // %mesh_size (Igap 3)
  GapSettings::Border border = GapSettings::Border::Cut;            // a shell's free border
  // Igap 2 (self contact): the point's initial position and the initial nodal coordinates; a
  // facet with a node that lay within twice the pair's gap of the point is skipped. Empty: off.
  Vec3 initial_point;
  std::span<const double> x0, y0, z0;
};

struct Partner {
  std::int32_t facet = -1;
  double xi = 0.0, eta = 0.0;
  double gap = 0.0;       // (x - q) . n less the pair's gap: negative = penetration
  double pair_gap = 0.0;  // the pair's gap (gap.hpp)
  Vec3 normal;  // the push direction: the facet's normal, or around a shell's edge the radial one
};

// What the rules above allow for point and facet f: the pair's gap g, the detection depth below
// the facet, and the reach: no point further than it from the facet's bounding box is accepted.
struct PairReach {
  double gap = 0.0, below = 0.0, reach = 0.0;
};
inline PairReach pair_reach(const TargetFacets& target, std::int32_t f, const PartnerRules& rules) {
  PairReach r;
  r.below = std::max(target.depth[f], rules.point_depth);
  r.gap = pair_gap(rules.point_gap, target.gap[f], rules.point_min_edge, target.min_edge[f],
                   rules.mesh_fraction);
  r.reach = std::max({r.below, rules.depth_above, rules.edge_tolerance}) + r.gap;
  // Beyond a shell's free border the point's own gap reaches up to g_s further (GapSettings).
  if (rules.border != GapSettings::Border::Cut) r.reach += std::min(rules.point_gap, r.gap);
  return r;
}

// Igap 2: whether a node of `nodes` lay within `distance` of the point at the start (false where
// the rules hold no initial coordinates).
bool initially_within(const PartnerRules& rules, const std::array<std::int32_t, 4>& nodes,
                      double distance);

// Last step's partner of a point and where the point lay on it.
struct PartnerHint {
  std::int32_t facet = -1;
  double xi = 0.0, eta = 0.0;
};

// What the rules above make of facet f for a point within the pair's reach of its box: accepted
// as a partner at `distance` (from the facet, less the pair's gap), or not.
struct FacetVerdict {
  bool accepted = false;
  Partner partner;
  double distance = 0.0;
};
FacetVerdict judge_facet(const TargetFacets& target, std::int32_t f, const PairReach& pair,
                         const std::array<std::int32_t, 4>& own_nodes, const Vec3& x,
                         const Vec3& normal, const PartnerRules& rules,
                         const PartnerHint& hint = {});

// Squared distance from x to facet f's box (this step's band when the target has bands).
double facet_box_distance2(const TargetFacets& target, std::int32_t f, const Vec3& x);

// `own_nodes`: the nodes of the point's facet (a node-to-surface point: its node four times);
// `normal`: the point's outward normal, or zero for a bare node. `candidates` in ascending facet
// order; the hint's facet, when among them, is looked at first and its projection starts at the
// hint's (xi, eta) (for speed only: the result is the same to round-off).
Partner find_partner(const TargetFacets& target, std::span<const std::int32_t> candidates,
                     const std::array<std::int32_t, 4>& own_nodes, const Vec3& x,
                     const Vec3& normal, const PartnerRules& rules, const PartnerHint& hint = {});

}  // namespace abut
