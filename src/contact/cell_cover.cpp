// The part of an S2S point's cell that lies over the other surface, and how its force spreads
// (mortar.hpp): the cell against its partner facet and the other facets it faces.
#include <algorithm>
#include <array>
#include <limits>

#include "interface_impl.hpp"

namespace abut {

// The facets a cell may cover (mortar.hpp, cover_cell): the broad-phase candidates of its point
// that face it, the partner first. Its borders (free edges, the far side of a sharp edge) are
// where the other surface's facets end. A shell's facet covers only where the narrow phase could
// take it as a partner (judge_facet): the point in front of it, within the pair's detection depth,
// and not within Igap 2's initial distance. In self contact a shell's other side lies in the
// cell's plane, facing it, a pair's gap deep; it is no cover.
CellOverlap InterfaceImpl::cover(const Pass& pass, std::size_t p, const PointFrame& f,
                                 const Partner& h, const ContactInput& in) const {
  const Side& own = sides_[pass.own];
  const Side& target = sides_[pass.target];
  const auto first = pass.candidates.offsets[p], last = pass.candidates.offsets[p + 1];
  std::span<const std::int32_t> candidates{pass.candidates.facets.data() + first, last - first};
  std::array<std::int32_t, kMaxCoverFacets> kept;
  if (target.shell_facets) {
    const TargetFacets facets = target_facets(target, target.depth, in, bands_current_);
    const PartnerRules rules = border_rules(own, p);
    std::size_t count = 0;
    for (const std::int32_t g : candidates) {
      if (count == kept.size()) break;
      if (g != h.facet && target.surface.twin[g] >= 0) {
        const auto& nodes = target.surface.facets[g];
        const QuadCorners c = quad_corners(nodes, in.x, in.y, in.z);
        const double front = dot(f.x - (c[0] + c[1] + c[2] + c[3]) * 0.25, quad_centre_normal(c));
        const PairReach pair = pair_reach(facets, g, rules);
        if (!(front >= 0.0) || front - pair.gap < -pair.below ||
            initially_within(rules, nodes, 2.0 * pair.gap))
          continue;
      }
      kept[count++] = g;
    }
    candidates = {kept.data(), count};
  }
  return cover_cell(own.surface.facets[own.point_facet[p]], own.cell(p), f.normal * -1.0, h.facet,
                    candidates, cover_facets(target, in));
}

CoverFacets InterfaceImpl::cover_facets(const Side& target, const ContactInput& in) {
  return {target.surface.facets, target.active, {}, in.x, in.y, in.z, {}};  // shells too (cover)
}

// The mortar gap less the pair's gap. The cell's own share of that gap, g_s, lies along its
// normal n; a shell facet's share g_t = g - g_s lies along the facet's normal m, which is
// g_t / (m . n) along n: over a facet tilted against the cell its contact surface rises further.
// (A solid's share is its padding, GapSettings::padding, taken along n.)
double InterfaceImpl::cell_gap(const Side& own, std::size_t p, const Side& target, const Partner& h,
                               const CellOverlap& o, const ContactInput& in) const {
  const CoverFacets other = cover_facets(target, in);
  const double mean = cell_mean_gap(own.surface.facets[own.point_facet[p]], o, other);
  const double g_t = std::max(h.pair_gap - own.point_gap[p], 0.0);
  if (!(g_t > 0.0)) return mean - h.pair_gap;
  double offset = 0.0;  // sum over the covered facets of A_k times the target's share along n
  for (int k = 0; k < o.count; ++k) {
    const auto g = static_cast<std::size_t>(o.facet[k]);
    const auto& w = o.target[k];
    const double part = w[0] + w[1] + w[2] + w[3];  // the shape functions sum to 1: A_k
    double along = g_t;  // a solid's padding (gap.hpp), along n as before
    if (target.surface.twin[g] >= 0) {
      const Vec3 m = quad_centre_normal(quad_corners(other.facets[g], in.x, in.y, in.z));
      along = g_t / std::max(dot(m, o.normal), kCoverMinCos);
    }
    offset += part * along;
  }
  return mean - (h.pair_gap - g_t) - offset / o.area;
}

// A shell's facets cover a cell only where the cell may reach over the shell's free border (a
// candidate facet has a free edge): there the point-wise rule counts the whole cell or none of it.
// Issue 27: a shell plate's cells straddling a shell sheet's border saw 98-102% of its footprint
// (the sheet sank -2.2% / -0.8% off F / (pfac A) in symmetric contact). Elsewhere a shell's
// contact surface rounds its inner edges, a pair's gap off the facets (narrow_phase.hpp), which
// the cover's flat overlaps do not see: a crushed tube's folds, covered, lost 5% of the energy
// balance and let the walls pass 0.33 mm into each other (22% of the wall).
bool InterfaceImpl::meet_by_cell(const Pass& pass, std::size_t p, const PointFrame& f,
                                 const ContactInput& in, Partner& h, CellOverlap& o) const {
  const Side& own = sides_[pass.own];
  const Side& target = sides_[pass.target];
  o = CellOverlap{};
  auto faces = [&](const Partner& g) { return -dot(f.normal, g.normal) >= sharp_cos_; };
  // The other surface's candidates near the cell: a solid's face, or a shell's free border.
  auto reaches_border = [&]() {
    if (!target.shell_facets) return true;
    const auto first = pass.candidates.offsets[p], last = pass.candidates.offsets[p + 1];
    for (auto k = first; k < last; ++k) {
      const auto g = static_cast<std::size_t>(pass.candidates.facets[k]);
      if (target.surface.twin[g] < 0 || target.free_edges[g] != 0) return true;
    }
    return false;
  };
  if (!reaches_border()) return false;
  if (h.facet >= 0 && faces(h)) {
    o = cover(pass, p, f, h, in);
    if (o.area > 0.0) h.gap = cell_gap(own, p, target, h, o, in);
    return true;
  }
  // Its projection misses the other surface, or meets a wall it does not face (the side of a
  // punch pressed into the point's plate, nearer than the punch's face): the nearest facet that
  // faces the cell within its reach, if the cell lies over it in part. Else the wall acts at the
  // point with the whole area.
  Partner facing = nearest_facing(pass, p, f, in, border_rules(own, p));
  if (facing.facet < 0 || !faces(facing)) return false;
  const CellOverlap covered = cover(pass, p, f, facing, in);
  if (!(covered.area > 0.0)) return false;
  o = covered;
  h = facing;
  h.gap = cell_gap(own, p, target, h, o, in);
  return true;
}

// The nearest broad-phase candidate of point p that faces it within alpha_edge and that `rules`
// accept (S2S cells: border_rules; N2S nodes: partner_rules).
Partner InterfaceImpl::nearest_facing(const Pass& pass, std::size_t p, const PointFrame& f,
                                      const ContactInput& in, PartnerRules rules) const {
  const Side& target = sides_[pass.target];
  const TargetFacets facets = target_facets(target, target.depth, in, bands_current_);
  rules.facing = sharp_cos_;
  const auto first = pass.candidates.offsets[p], last = pass.candidates.offsets[p + 1];
  return find_partner(facets, {pass.candidates.facets.data() + first, last - first}, f.nodes, f.x,
                      f.normal, rules);
}

PartnerRules InterfaceImpl::border_rules(const Side& own, std::size_t p) const {
  PartnerRules rules = partner_rules(own, p);
  if (own.point_node[p] < 0 && !own.point_reach.empty())
    rules.edge_tolerance = std::max(rules.edge_tolerance, own.point_reach[p]);
  return rules;
}

// Issue 27: in symmetric N2S on matched meshes the plane's nodes along a block's border pressed
// with their whole tributary area, half or three quarters of which lies beside the block (a block
// set down on a slope walked off). A node's area is a quarter of each of its facets (the corner
// quadrant of the facet's reference square); each quadrant is covered as an S2S cell is
// (mortar.hpp), against the partner h and the facets sharing a node with h. That ring holds every
// facet a quadrant can reach only while the quadrant is no larger than h, and the cover only
// means something where the node's facets all face h within alpha_edge and h is a solid's face:
// elsewhere (a node on an edge or in a corner, against a shell, or a coarse side pressing a fine
// one) the node keeps its whole area, as before.
double InterfaceImpl::node_cover(const Pass& pass, std::size_t p, const Partner& h,
                                 const ContactInput& in) const {
  const Side& own = sides_[pass.own];
  const Side& target = sides_[pass.target];
  if (h.facet < 0 || target.surface.twin[h.facet] >= 0) return 1.0;
  const std::int32_t node = own.point_node[p];
  constexpr std::size_t kMaxRing = 64;
  std::array<std::int32_t, kMaxRing> ring;  // the first `count` are set
  std::size_t count = 0;
  ring[count++] = h.facet;
  const auto& h_nodes = target.surface.facets[h.facet];
  for (const std::int32_t b : h_nodes)
    for (auto k = target.node_facet_start[b]; k < target.node_facet_start[b + 1]; ++k) {
      const std::int32_t g = target.node_facets[k];
      if (count < kMaxRing &&
          std::find(ring.begin(), ring.begin() + count, g) == ring.begin() + count)
        ring[count++] = g;
    }
  const QuadCorners ch = quad_corners(h_nodes, in.x, in.y, in.z);
  double h_size = std::numeric_limits<double>::infinity();
  for (int e = 0; e < 4; ++e) {
    const double length = norm(ch[(e + 1) % 4] - ch[e]);
    if (length > 0.0) h_size = std::min(h_size, length);
  }
  const CoverFacets other = cover_facets(target, in);
  double covered = 0.0, total = 0.0;
  for (auto k = own.node_facet_start[node]; k < own.node_facet_start[node + 1]; ++k) {
    const std::int32_t g = own.node_facets[k];
    if (!own.active[g]) continue;
    const auto& nodes = own.surface.facets[g];
    const QuadCorners c = quad_corners(nodes, in.x, in.y, in.z);
    const Vec3 n = quad_centre_normal(c);
    if (-dot(n, h.normal) < sharp_cos_) return 1.0;  // the node's surface turns: an edge
    const int a = static_cast<int>(std::find(nodes.begin(), nodes.end(), node) - nodes.begin());
    // The quadrant at corner a (0: xi = eta = -1, 1: xi = +1, 2: both +1, 3: eta = +1).
    const bool high_xi = a == 1 || a == 2, high_eta = a == 2 || a == 3;
    const CellBounds quadrant{high_xi ? 0.0 : -1.0, high_xi ? 1.0 : 0.0, high_eta ? 0.0 : -1.0,
                              high_eta ? 1.0 : 0.0};
    const Vec3 x00 = quad_point(c, quadrant.xi0, quadrant.eta0),
               x11 = quad_point(c, quadrant.xi1, quadrant.eta1),
               x10 = quad_point(c, quadrant.xi1, quadrant.eta0),
               x01 = quad_point(c, quadrant.xi0, quadrant.eta1);
    if (std::max(norm(x11 - x00), norm(x01 - x10)) > h_size) return 1.0;  // coarser than h
    covered += cover_cell(nodes, quadrant, n * -1.0, h.facet, {ring.data(), count}, other).area;
    total += 0.5 * norm(cross(x11 - x00, x01 - x10));
  }
  return total > 0.0 ? std::min(covered / total, 1.0) : 1.0;
}

// The node's counterpart of meet_by_cell's facing search. A node whose nearest facet is a wall
// edge-on to its surface gets from it almost no force (its area projected on the wall's normal),
// however deep it lies. Issue 27: a plate's nodes under a block's bottom edges lie nanometres
// beside or inside the block's side walls as the elastic block breathes with Poisson's ratio;
// they flickered between the wall (no push) and the bottom (half their area pressing), the
// block rang and walked off a slope it should have held. The nearest facet facing the node
// within alpha_edge, when the narrow phase accepts one and part of the node's area lies over it,
// presses instead; a node truly beside a wall (none of its area over a facing facet) keeps it.
Partner InterfaceImpl::facing_node_partner(const Pass& pass, std::size_t p, const PointFrame& f,
                                           const ContactInput& in, const Partner& h,
                                           std::optional<double>& cover) const {
  if (h.facet < 0 || f.free || f.two_sided || settings_.sense == ContactSense::Negative) return h;
  if (-dot(f.normal, h.normal) >= sharp_cos_) return h;
  const Side& own = sides_[pass.own];
  const Side& target = sides_[pass.target];
  // Only a node at the wall, not one clearly beside it: a facing facet accepts a node only on its
  // border band (kOnBorder of its size) or within delta_edge.
  if (h.gap > std::max(settings_.edge_tolerance, kOnBorder * target.facet_min_edge[h.facet]))
    return h;
  const Partner facing = nearest_facing(pass, p, f, in, partner_rules(own, p));
  if (facing.facet < 0) return h;
  const double covered = node_cover(pass, p, facing, in);
  if (!(covered > 0.0)) return h;
  cover = covered;
  return facing;
}

}  // namespace abut
