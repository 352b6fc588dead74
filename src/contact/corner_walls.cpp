// The walls of a concave corner besides a point's partner (corner_walls.hpp).
#include "abut/contact/corner_walls.hpp"

#include <algorithm>
#include <limits>

#include "abut/contact/quad.hpp"

namespace abut {
namespace {

// Centre and unit normal of facet f, its centre moved out to its contact surface by `gap`.
struct FacetPlane {
  Vec3 centre, normal;
};
FacetPlane facet_plane(const TargetFacets& target, std::int32_t f, double gap) {
  const QuadCorners c = quad_corners(target.nodes[f], target.x, target.y, target.z);
  const Vec3 n = quad_centre_normal(c);
  return {(c[0] + c[1] + c[2] + c[3]) * 0.25 + n * gap, n};
}

// Two walls meet at a concave corner: each one's centre lies in front of the other's plane.
bool concave(const FacetPlane& a, const FacetPlane& b) {
  return dot(b.centre - a.centre, a.normal) > 0.0 && dot(a.centre - b.centre, b.normal) > 0.0;
}

}  // namespace

CornerWalls find_corner_walls(const TargetFacets& target, std::span<const std::int32_t> candidates,
                              const std::array<std::int32_t, 4>& own_nodes, const Vec3& x,
                              const Vec3& normal, const PartnerRules& rules, const Partner& partner,
                              double sharp_cos) {
  CornerWalls r;
  if (partner.facet < 0) return r;
  const FacetPlane home = facet_plane(target, partner.facet, partner.pair_gap);
  // Facets the point penetrates, turned away from the partner, closest first.
  constexpr int kMaxFound = 8;
  struct Found {
    Partner wall;
    double distance;
    FacetPlane plane;
  };
  std::array<Found, kMaxFound> found;
  int count = 0;
  for (const std::int32_t f : candidates) {
    if (f == partner.facet || !target.active[f]) continue;
    // A facet of the partner's own smooth surface is no other wall: passed over before the
    // projection (most candidates of a node on a flat surface).
    const Vec3 n =
        target.bands.empty()
            ? quad_centre_normal(quad_corners(target.nodes[f], target.x, target.y, target.z))
            : target.bands[f].normal;
    if (dot(n, home.normal) > sharp_cos) continue;
    const PairReach pair = pair_reach(target, f, rules);
    if (facet_box_distance2(target, f, x) > pair.reach * pair.reach) continue;
    const FacetVerdict v = judge_facet(target, f, pair, own_nodes, x, normal, rules);
    if (!v.accepted || !(v.partner.gap < 0.0)) continue;
    const FacetPlane plane = facet_plane(target, f, pair.gap);
    if (dot(plane.normal, home.normal) > sharp_cos || !concave(home, plane)) continue;
    // Kept in order of distance, then facet number (the candidates come in facet order).
    if (count == kMaxFound && !(v.distance < found[kMaxFound - 1].distance)) continue;
    int k = std::min(count, kMaxFound - 1);
    while (k > 0 && v.distance < found[k - 1].distance) {
      found[k] = found[k - 1];
      --k;
    }
    found[k] = {v.partner, v.distance, plane};
    count = std::min(count + 1, kMaxFound);
  }
  // Closest first, each turned from and concave with the partner and the walls taken before.
  std::array<FacetPlane, kMaxCornerWalls> taken;
  for (int i = 0; i < count && r.count < kMaxCornerWalls; ++i) {
    bool other = true;
    for (std::size_t k = 0; k < r.count && other; ++k)
      other = dot(found[i].plane.normal, taken[k].normal) <= sharp_cos &&
              concave(taken[k], found[i].plane);
    if (!other) continue;
    taken[r.count] = found[i].plane;
    r.walls[r.count++] = found[i].wall;
  }
  return r;
}

}  // namespace abut
