// The part of an S2S point's cell that lies over the other surface, and how its force spreads
// (mortar.hpp): the cell against its partner facet and the partner's smooth neighbours.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "abut/contact/interface.hpp"
#include "abut/contact/quad.hpp"

namespace abut {

// A facet turned further than about 84 degrees from a cell's normal is a wall to it, not cover.
constexpr double kEdgeOnCos = 0.1;

// The facets a cell may cover: the broad-phase candidates of its point that face it (the partner
// first). The cell and the facets are projected along the cell's own normal, so a facet turned
// towards edge-on covers a vanishing area and none enters or leaves the cover with a jump: the
// other surface, seen from the cell, is a height field over the cell's plane. Its borders (free
// edges, the far side of a sharp edge) are where its facets end.
CellOverlap ContactInterface::cover(const Pass& pass, std::size_t p, const PointFrame& f,
                                    const Partner& h, const ContactInput& in) const {
  const Side& own = sides_[pass.own];
  const Side& target = sides_[pass.target];
  constexpr std::size_t kMaxFacets = 64;
  std::array<std::int32_t, kMaxFacets> ids{};
  std::array<QuadCorners, kMaxFacets> corners{};
  std::size_t count = 0;
  const auto& own_nodes = own.surface.facets[own.point_facet[p]];
  // As the narrow phase: never the own facet or one sharing a node with it (self contact).
  auto touches_own = [&own_nodes](const std::array<std::int32_t, 4>& nodes) {
    for (const std::int32_t i : nodes)
      if (std::find(own_nodes.begin(), own_nodes.end(), i) != own_nodes.end()) return true;
    return false;
  };
  const Vec3 n = f.normal * -1.0;  // from the other surface towards the cell
  auto add = [&](std::int32_t g) {
    if (count == kMaxFacets || !target.active[g] || target.surface.twin[g] >= 0 ||
        touches_own(target.surface.facets[g]))
      return;
    const QuadCorners c = quad_corners(target.surface.facets[g], in.x, in.y, in.z);
    // Facing away (the far side), or edge-on: a wall whose projection is a line and whose
    // slope has no bound (the side of a block standing on the cell's plate).
    if (!(dot(quad_centre_normal(c), n) >= kEdgeOnCos)) return;
    ids[count] = g;
    corners[count++] = c;
  };
  if (h.facet >= 0) add(h.facet);
  const auto first = pass.candidates.offsets[p], last = pass.candidates.offsets[p + 1];
  for (auto k = first; k < last; ++k)
    if (pass.candidates.facets[k] != h.facet) add(pass.candidates.facets[k]);
  const QuadCorners c_own = quad_corners(own_nodes, in.x, in.y, in.z);
  CellOverlap o = overlap_cell(c_own, own.cell(p), n, {ids.data(), count}, {corners.data(), count});
  o.normal = n;
  return o;
}

double ContactInterface::cell_gap(const Side& own, std::size_t p, const Side& target,
                                  const Partner& h, const CellOverlap& o,
                                  const ContactInput& in) const {
  const double inv = 1.0 / o.area;
  Vec3 centroid;  // own centroid less the other side's, over the covered part
  const auto& nodes = own.surface.facets[own.point_facet[p]];
  for (int a = 0; a < 4; ++a)
    centroid += Vec3{in.x[nodes[a]], in.y[nodes[a]], in.z[nodes[a]]} * (o.own[a] * inv);
  for (int k = 0; k < o.count; ++k) {
    const auto& other = target.surface.facets[o.facet[k]];
    for (int b = 0; b < 4; ++b)
      centroid -= Vec3{in.x[other[b]], in.y[other[b]], in.z[other[b]]} * (o.target[k][b] * inv);
  }
  return dot(centroid, o.normal) - h.pair_gap;
}

// Shells keep the point-wise rule for now: their contact surfaces lie a gap off the facets and
// round their inner edges (narrow_phase.hpp), which a plane overlap does not see (a crushed tube's
// folds lost 9% of the energy balance with it).
bool ContactInterface::meet_by_cell(const Pass& pass, std::size_t p, const PointFrame& f,
                                    const ContactInput& in, Partner& h, CellOverlap& o) const {
  const Side& own = sides_[pass.own];
  const Side& target = sides_[pass.target];
  o = CellOverlap{};
  if (own.surface.twin[own.point_facet[p]] >= 0) return false;
  auto faces = [&](const Partner& g) {
    return -dot(f.normal, g.normal) >= sharp_cos_ && target.surface.twin[g.facet] < 0;
  };
  if (h.facet >= 0 && faces(h)) {
    o = cover(pass, p, f, h, in);
    if (o.area > 0.0) h.gap = cell_gap(own, p, target, h, o, in);
    return true;
  }
  // Its projection misses the other surface, or meets a wall it does not face (the side of a
  // punch pressed into the point's plate, nearer than the punch's face): the nearest facet that
  // faces the cell within its reach, if the cell lies over it in part. Else the wall acts at the
  // point with the whole area.
  const TargetFacets facets = target_facets(target, target.depth, in, bands_current_);
  PartnerRules rules = border_rules(own, p);
  rules.facing = sharp_cos_;
  const auto first = pass.candidates.offsets[p], last = pass.candidates.offsets[p + 1];
  Partner facing = find_partner(facets, {pass.candidates.facets.data() + first, last - first},
                                f.nodes, f.x, f.normal, rules);
  if (facing.facet < 0 || !faces(facing)) return false;
  const CellOverlap covered = cover(pass, p, f, facing, in);
  if (!(covered.area > 0.0)) return false;
  o = covered;
  h = facing;
  h.gap = cell_gap(own, p, target, h, o, in);
  return true;
}

PartnerRules ContactInterface::border_rules(const Side& own, std::size_t p) const {
  PartnerRules rules = partner_rules(own, p);
  if (own.point_node[p] < 0 && !own.point_reach.empty())
    rules.edge_tolerance = std::max(rules.edge_tolerance, own.point_reach[p]);
  return rules;
}

}  // namespace abut
