// The part of an S2S point's cell that lies over the other surface, and how its force spreads
// (mortar.hpp): the cell against its partner facet and the other facets it faces.
#include <algorithm>

#include "abut/contact/interface.hpp"

namespace abut {

// The facets a cell may cover (mortar.hpp, cover_cell): the broad-phase candidates of its point
// that face it, the partner first. Its borders (free edges, the far side of a sharp edge) are
// where the other surface's facets end.
CellOverlap ContactInterface::cover(const Pass& pass, std::size_t p, const PointFrame& f,
                                    const Partner& h, const ContactInput& in) const {
  const Side& own = sides_[pass.own];
  const Side& target = sides_[pass.target];
  const auto first = pass.candidates.offsets[p], last = pass.candidates.offsets[p + 1];
  return cover_cell(own.surface.facets[own.point_facet[p]], own.cell(p), f.normal * -1.0, h.facet,
                    {pass.candidates.facets.data() + first, last - first},
                    cover_facets(target, in));
}

CoverFacets ContactInterface::cover_facets(const Side& target, const ContactInput& in) {
  return {target.surface.facets, target.active, target.surface.twin, in.x, in.y, in.z};
}

double ContactInterface::cell_gap(const Side& own, std::size_t p, const Side& target,
                                  const Partner& h, const CellOverlap& o,
                                  const ContactInput& in) const {
  return cell_mean_gap(own.surface.facets[own.point_facet[p]], o, cover_facets(target, in)) -
         h.pair_gap;
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
