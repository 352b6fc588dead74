#include "abut/contact/narrow_phase.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "abut/contact/gap.hpp"

namespace abut {
namespace {

constexpr double kEdgeRoundOff = 1e-9;
constexpr double kFacingRoundOff = 1e-9;

bool share_a_node(const std::array<std::int32_t, 4>& a, const std::array<std::int32_t, 4>& b) {
  for (auto i : a)
    for (auto j : b)
      if (i == j) return true;
  return false;
}

}  // namespace

bool initially_within(const PartnerRules& rules, const std::array<std::int32_t, 4>& nodes,
                      double distance) {
  if (rules.x0.empty()) return false;
  for (const std::int32_t i : nodes) {
    const Vec3 d = Vec3{rules.x0[i], rules.y0[i], rules.z0[i]} - rules.initial_point;
    if (dot(d, d) < distance * distance) return true;
  }
  return false;
}

FacetVerdict judge_facet(const TargetFacets& target, std::int32_t f, const PairReach& pair,
                         const std::array<std::int32_t, 4>& own_nodes, const Vec3& x_p,
                         const Vec3& n_p, const PartnerRules& rules, const PartnerHint& hint) {
  FacetVerdict v;
  const auto& nodes = target.nodes[f];
  const double g = pair.gap;
  if (share_a_node(own_nodes, nodes)) return v;
  if (initially_within(rules, nodes, 2.0 * g)) return v;
  const bool banded = !target.bands.empty();
  const bool has_normal = n_p.x != 0.0 || n_p.y != 0.0 || n_p.z != 0.0;
  // The far side of a shell, decided before the projection where the band shows it
  // (penetration_zone.hpp); the test after the projection decides the others alike.
  const bool shell = target.twin[f] >= 0;
  if (banded && shell && surely_behind(target.bands[f], x_p)) return v;
  // The facing test below, decided before the projection where the band shows that every local
  // normal of the facet faces the same way as the point (its own surface further along, in self
  // contact): |N - n| <= sqrt(2 (1 - cos theta)) for local normals N within theta of the mean
  // normal n (penetration_zone.hpp).
  if (banded && has_normal && target.bands[f].usable) {
    const FacetBand& band = target.bands[f];
    const double tilt = band.tilt * band.tilt;
    const double spread = std::sqrt(2.0 * (1.0 - std::sqrt(1.0 - tilt))) + kFacingRoundOff;
    const double facing = dot(n_p, band.normal);
    if (rules.from_behind ? facing < -spread : facing > spread) return v;
  }
  QuadCorners c;
  for (int a = 0; a < 4; ++a) c[a] = {target.x[nodes[a]], target.y[nodes[a]], target.z[nodes[a]]};
  const QuadProjection q =
      f == hint.facet ? project_onto_quad(c, x_p, hint.xi, hint.eta) : project_onto_quad(c, x_p);
  if (shell && q.gap < 0.0) return v;  // the other side of the shell
  double gap = q.gap - g;
  Vec3 push = q.normal;
  if (has_normal) {
    const double facing = dot(n_p, q.normal);
    if (rules.from_behind ? facing <= rules.facing : facing >= -rules.facing) return v;
  }
  if (q.crossed_edges != 0) {
    const bool sharp = (q.crossed_edges & target.sharp[f]) != 0;
    const bool rounded = shell && (q.crossed_edges & target.free_edges[f]) == 0;
    // A node on the border of a matched mesh projects onto the very edge: round-off
    // (kEdgeRoundOff of the facet's size) is no overshoot.
    const double size = norm(c[2] - c[0]);
    const bool on_edge = q.overshoot <= kEdgeRoundOff * size;
    const bool free_border = shell && (q.crossed_edges & target.free_edges[f]) != 0;
    if (rounded && !on_edge) {
      gap = q.distance - g;  // around the rounded edge
      push = (x_p - q.point) / q.distance;
    } else if (free_border && rules.border != GapSettings::Border::Cut && !on_edge) {
      // Radioss Ishape (seed 004, comment 4): the point's own gap g_s reaches over the border, no
      // further; the facet's slab (half thickness g - g_s) ends square at the border.
      const double g_s = std::min(rules.point_gap, g);
      if (q.overshoot > g_s) return v;
      if (rules.border == GapSettings::Border::Round) {
        // The slab widened by a ball of radius g_s: the distance to the slab's edge, less g_s.
        const Vec3 d = x_p - q.point;
        const double rise = std::max(q.gap - (g - g_s), 0.0);  // above the slab's face
        const Vec3 across = d - q.normal * q.gap;              // in the facet's plane
        const Vec3 to_point = across + q.normal * rise;
        const double distance = norm(to_point);
        if (!(distance > 0.0)) return v;
        gap = distance - g_s;
        push = to_point / distance;
      }
    } else {
      // Beyond a sharp (or free) edge only within delta_edge, or kOnBorder of the facet's size: a
      // node on the border of a matched mesh stays on it while the two surfaces stretch and turn
      // a little differently (issue 27; with round-off only, the border nodes of two bars pressed
      // end to end dropped out and came back deeper, +99.5% energy). Beyond a smooth edge only
      // within the dead zone of a convex edge, |gap| tan(alpha_edge) wide (docs/contact.md,
      // narrow phase), the distance counted from the facet itself as the dead zone is.
      const double allowed =
          sharp ? std::max(rules.edge_tolerance, kOnBorder * size)
                : std::max(rules.edge_tolerance, std::abs(q.gap) * rules.smooth_reach);
      if (q.overshoot > allowed && !on_edge) return v;
    }
  }
  // The far side: deeper than the pair's detection depth (or, from behind, further out).
  const double inward = rules.from_behind ? gap : -gap;
  if (inward > pair.below || -inward > std::max(rules.depth_above, pair.below)) return v;
  v.accepted = true;
  v.distance = q.distance - g;
  v.partner = {f, q.xi, q.eta, gap, g, push};
  return v;
}

Partner find_partner(const TargetFacets& target, std::span<const std::int32_t> candidates,
                     const std::array<std::int32_t, 4>& own_nodes, const Vec3& x_p, const Vec3& n_p,
                     const PartnerRules& rules, const PartnerHint& hint) {
  Partner best;
  double best_distance = std::numeric_limits<double>::infinity();
  const auto consider = [&](std::int32_t f) {
    if (!target.active[f]) return;
    // The distance to the facet's bounding box bounds the distance to the facet from below:
    // skip facets that cannot be within reach or closer than the best one so far.
    const double box2 = facet_box_distance2(target, f, x_p);
    // Not nearer than the best one so far even with the largest pair gap: the test below would
    // reject it too; passed over before the pair's own gap is looked up (most candidates, once
    // last step's partner has been found again).
    const double bound = best_distance + rules.point_gap + target.max_gap;
    if (bound < 0.0 || box2 > bound * bound) return;
    const PairReach pair = pair_reach(target, f, rules);
    const double closer = best_distance + pair.gap;  // nearer than this to beat the best so far
    if (box2 > pair.reach * pair.reach || closer < 0.0 || box2 > closer * closer) return;
    const FacetVerdict v = judge_facet(target, f, pair, own_nodes, x_p, n_p, rules, hint);
    // The closest; of equally close ones the first in facet order (the candidates' order).
    if (v.accepted &&
        (v.distance < best_distance || (v.distance == best_distance && f < best.facet))) {
      best_distance = v.distance;
      best = v.partner;
    }
  };
  // The facet given first (last step's partner) makes the best distance small at once, so that
  // the box test passes over most of the others without projecting the point on them.
  const std::int32_t first = hint.facet;
  const bool listed = first >= 0 && std::binary_search(candidates.begin(), candidates.end(), first);
  if (listed) consider(first);
  for (const std::int32_t f : candidates)
    if (!listed || f != first) consider(f);
  return best;
}

double facet_box_distance2(const TargetFacets& target, std::int32_t f, const Vec3& x) {
  if (!target.bands.empty()) return box_distance2(target.bands[f].lo, target.bands[f].hi, x);
  const QuadCorners c = quad_corners(target.nodes[f], target.x, target.y, target.z);
  Vec3 lo, hi;
  for (int i = 0; i < 3; ++i) {
    lo[i] = std::min({c[0][i], c[1][i], c[2][i], c[3][i]});
    hi[i] = std::max({c[0][i], c[1][i], c[2][i], c[3][i]});
  }
  return box_distance2(lo, hi, x);
}

}  // namespace abut
