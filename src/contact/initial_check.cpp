// Start-up check (issue 13): contact points that begin inside the other surface deeper than the
// detection depth. The regular search only looks that deep behind a facet (half the element by
// default, seed 000), so such a point is never found: no force pushes it out and the bodies stay
// interlocked without a word. Here each point the regular search misses is looked for once more,
// down to nearly the whole first element layer behind the other side's facets.
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "abut/contact/quad.hpp"
#include "interface_impl.hpp"

namespace abut {
namespace {

// How far behind a facet the deep search reaches, as a share of its element's thickness: less
// than the whole layer, so that a point on a thin part's far face is not taken for inside it.
constexpr double kLayerShare = 0.9;

}  // namespace

std::vector<DeepStart> InterfaceImpl::deep_initial_points(const ContactInput& in) const {
  // Self contact faces its own body's far side within the layer; ties, clearance and the other
  // senses have no penetration to miss.
  if (self_contact() || settings_.freeze || settings_.clearance ||
      settings_.sense != ContactSense::Positive)
    return {};
  std::map<std::pair<std::int32_t, std::int32_t>, DeepStart> by_pair;
  for (const Pass& pass : passes_) {
    const Side& own = sides_[pass.own];
    const Side& target = sides_[pass.target];
    const std::size_t facets = target.surface.size();
    std::vector<double> layer(facets);
    std::vector<Box> boxes(facets);
    for (std::size_t f = 0; f < facets; ++f) {
      const bool shell = target.surface.twin[f] >= 0;  // a shell has no layer behind its depth
      layer[f] = shell ? target.depth[f]
                       : std::max(target.depth[f], kLayerShare * target.surface.thickness[f]);
      const QuadCorners c = quad_corners(target.surface.facets[f], in.x, in.y, in.z);
      const double grow = layer[f] + target.facet_gap[f] + own.max_point_gap;
      for (int k = 0; k < 3; ++k) {
        boxes[f].lo[k] = std::min({c[0][k], c[1][k], c[2][k], c[3][k]}) - grow;
        boxes[f].hi[k] = std::max({c[0][k], c[1][k], c[2][k], c[3][k]}) + grow;
      }
    }
    BucketGrid grid;
    grid.build(boxes);
    CandidateList candidates;
    const auto apart = [&own, &target](std::size_t p, std::int32_t f) {
      for (const std::int32_t a : target.surface.facets[f])
        for (const std::int32_t b : own.point_nodes(p))
          if (a == b) return false;
      return true;
    };
    const PointPositions q = point_positions(own, in);
    grid.query(q.x, q.y, q.z, candidates, apart);
    const TargetFacets deep = target_facets(target, layer, in);
    for (std::size_t p = 0; p < own.point_facet.size(); ++p) {
      const PointFrame f = frame(own, p, in);
      if (!f.active || partner_of(pass, p, f, in, -1).facet >= 0) continue;
      const auto first = candidates.offsets[p], last = candidates.offsets[p + 1];
      const Partner h = find_partner(deep, {candidates.facets.data() + first, last - first},
                                     f.nodes, f.x, f.normal, partner_rules(own, p));
      if (h.facet < 0 || !(-h.gap > target.depth[h.facet])) continue;
      DeepStart& d = by_pair[{own.point_part[p], target.facet_part[h.facet]}];
      d.part = part_ids_[static_cast<std::size_t>(own.point_part[p])];
      d.other_part = part_ids_[static_cast<std::size_t>(target.facet_part[h.facet])];
      ++d.points;
      d.deepest = std::max(d.deepest, -h.gap);
      d.detection_depth = std::max(d.detection_depth, target.depth[h.facet]);
    }
  }
  std::vector<DeepStart> out;
  for (const auto& [pair, d] : by_pair) out.push_back(d);
  return out;
}

}  // namespace abut
