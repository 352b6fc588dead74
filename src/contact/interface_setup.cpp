// ContactInterface set-up: checks, parts and pair scales, sides and their contact points
// (integration points or nodes), passes, and the initial state of every point.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "abut/contact/integration.hpp"
#include "abut/contact/quad.hpp"
#include "abut/core/memory.hpp"
#include "abut/core/parallel.hpp"
#include "interface_impl.hpp"

namespace abut {
namespace {

// Default delta0_max: 4% of the element thickness (seed 000).
constexpr double kDefaultInitialMaxFraction = 0.04;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

double longest_edge(const QuadCorners& c) {
  double longest = 0.0;
  for (int a = 0; a < 4; ++a) longest = std::max(longest, norm(c[(a + 1) % 4] - c[a]));
  return longest;
}

// How far beyond a smooth edge, per unit distance from the facet's plane, a point may lie and
// still belong to the facet: tan(alpha_edge), the widest dead zone of a convex edge whose
// normals turn by at most alpha_edge. From 90 degrees on every crossing is accepted.
double smooth_edge_reach(double alpha_edge_degrees) {
  if (alpha_edge_degrees >= 90.0) return kInfinity;
  return std::tan(alpha_edge_degrees * std::numbers::pi / 180.0);
}

bool is_radioss_rule(StiffnessRule r) { return r != StiffnessRule::FacetPenalty; }

double shortest_edge(const QuadCorners& c) {
  double shortest = kInfinity;
  for (int a = 0; a < 4; ++a) {
    const double l = norm(c[(a + 1) % 4] - c[a]);
    if (l > 0.0) shortest = std::min(shortest, l);  // a triangle's collapsed edge does not count
  }
  return shortest;
}

// A surface built without add() may leave the shell fields empty: all its facets are solid faces.
void complete(ContactSurface& s) {
  if (s.twin.empty()) s.twin.assign(s.size(), -1);
  if (s.young_modulus.empty()) s.young_modulus.assign(s.size(), 0.0);
  if (s.element.empty()) s.element.assign(s.size(), -1);
  if (s.exposed_by.empty()) s.exposed_by.assign(s.size(), -1);
}

}  // namespace

InterfaceImpl::InterfaceImpl(ContactSettings settings, ContactSurface surface1,
                             ContactSurface surface2, std::span<const double> node_mass,
                             const ContactInput& initial,
                             std::span<const std::int32_t> secondary_nodes)
    : settings_(std::move(settings)), mass_(node_mass.begin(), node_mass.end()) {
  complete(surface1);
  complete(surface2);
  validate(surface1, surface2, initial.x.size());
  if (!secondary_nodes.empty() && settings_.discretisation != Discretisation::NodeToSurface)
    throw ContactSetupError("discretisation",
                            "secondary nodes are given, but the contact is surface-to-surface");
  const bool self = surface1.facets == surface2.facets;
  if (self && settings_.one_way)
    throw ContactSetupError("one_way",
                            "one-way contact needs two different surfaces; these two are the same "
                            "facets (self contact)");
  if (!secondary_nodes.empty() && !settings_.one_way)
    throw ContactSetupError(
        "one_way",
        "a node group is only a secondary side: node-to-surface contact of a node "
        "group is one-way");
  wear_.assign(mass_.size(), 0.0);
  pressure_.assign(mass_.size(), 0.0);
  damping_fx_.assign(mass_.size(), 0.0);
  damping_fy_.assign(mass_.size(), 0.0);
  damping_fz_.assign(mass_.size(), 0.0);
  if (settings_.gaps.skip_close) {
    x0_.assign(initial.x.begin(), initial.x.begin() + static_cast<std::ptrdiff_t>(mass_.size()));
    y0_.assign(initial.y.begin(), initial.y.begin() + static_cast<std::ptrdiff_t>(mass_.size()));
    z0_.assign(initial.z.begin(), initial.z.begin() + static_cast<std::ptrdiff_t>(mass_.size()));
  }
  sides_.resize(self ? 1 : 2);
  sides_[0].surface = std::move(surface1);
  if (!self) sides_[1].surface = std::move(surface2);
  for (Side& side : sides_)
    side.shell_facets = std::any_of(side.surface.twin.begin(), side.surface.twin.end(),
                                    [](std::int32_t twin) { return twin >= 0; });
  build_parts();
  build_sides(initial, secondary_nodes);
  build_passes();
  build_edges(initial);
  initial_state(initial);
  for (const Side& side : sides_) initial_points_.push_back(side.point_facet.size());
  // The bounds above are those of the springs at a factor 1; apply() and initial_stable_step()
  // scale them to the time's (spring_step).
  spring_factor_ = std::max(settings_.normal_in_time.at(initial.time), 1.0);
}

void InterfaceImpl::build_parts() {
  for (const Side& side : sides_)
    part_ids_.insert(part_ids_.end(), side.surface.part.begin(), side.surface.part.end());
  std::sort(part_ids_.begin(), part_ids_.end());
  part_ids_.erase(std::unique(part_ids_.begin(), part_ids_.end()), part_ids_.end());
  const std::size_t n = part_ids_.size();
  // Every local pair (a, b) that parts1 and parts2 cover (covers_pair), as a * n + b.
  auto each_covered = [&](const std::vector<std::int64_t>& parts1,
                          const std::vector<std::int64_t>& parts2, auto&& visit) {
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = 0; b < n; ++b)
        if (covers_pair(parts1, parts2, part_ids_[a], part_ids_[b])) visit(a * n + b);
  };
  part_scale_.assign(n * n, 1.0);
  for (const PairScale& ps : settings_.pair_scales)  // in order: the last assignment wins
    each_covered(ps.parts1, ps.parts2, [&](std::size_t ab) { part_scale_[ab] = ps.scale; });
  part_friction_.assign(n * n, -1);
  for (std::size_t k = 0; k < settings_.pair_frictions.size(); ++k) {
    const PairFriction& pf = settings_.pair_frictions[k];
    each_covered(pf.parts1, pf.parts2,
                 [&](std::size_t ab) { part_friction_[ab] = static_cast<std::int32_t>(k); });
  }
  for (Side& side : sides_) {
    side.facet_part.resize(side.surface.size());
    for (std::size_t f = 0; f < side.surface.size(); ++f)
      side.facet_part[f] = static_cast<std::int32_t>(
          std::lower_bound(part_ids_.begin(), part_ids_.end(), side.surface.part[f]) -
          part_ids_.begin());
  }
}

void InterfaceImpl::build_sides(const ContactInput& in,
                                std::span<const std::int32_t> secondary_nodes) {
  const ContactSettings& s = settings_;
  margin_ = kInfinity;
  smooth_reach_ = smooth_edge_reach(s.edge_angle);
  sharp_cos_ = std::cos(s.edge_angle * std::numbers::pi / 180.0);
  // Typical facet size of each side (median of the longest edges), for the subdivision of S2S
  // facets.
  std::vector<double> typical_size;
  for (const Side& side : sides_) {
    std::vector<double> sizes;
    for (const auto& facet : side.surface.facets)
      sizes.push_back(longest_edge(quad_corners(facet, in.x, in.y, in.z)));
    std::nth_element(sizes.begin(), sizes.begin() + static_cast<std::ptrdiff_t>(sizes.size() / 2),
                     sizes.end());
    typical_size.push_back(sizes[sizes.size() / 2]);
  }
  for (std::size_t side_index = 0; side_index < sides_.size(); ++side_index) {
    Side& side = sides_[side_index];
    const ContactSurface& surface = side.surface;
    const std::size_t n = surface.size();
    std::vector<std::uint8_t> free_edges;
    side.sharp = sharp_edges(surface, in.x, in.y, in.z, s.edge_angle, &free_edges);
    side.off.assign(n, 0);
    side.depth.resize(n);
    side.facet_km.assign(n, 0.0);
    side.facet_gap.assign(n, 0.0);
    side.facet_min_edge.resize(n);
    side.node_area.assign(mass_.size(), 0.0);
    for (std::size_t f = 0; f < n; ++f) {
      const QuadCorners c = quad_corners(surface.facets[f], in.x, in.y, in.z);
      if (s.initial_region) {
        const Vec3 centre = quad_point(c, 0.0, 0.0);
        if (!s.initial_region(centre.x, centre.y, centre.z)) side.off[f] |= kOutsideRegion;
      }
      if (surface.exposed_by[f] >= 0) side.off[f] |= kDormant;  // until its neighbour erodes
      const bool shell = surface.twin[f] >= 0;
      side.depth[f] = s.detection_depth.value_or(0.5 * surface.thickness[f]);
      side.max_pfac = std::max(side.max_pfac, surface.penalty[f]);
      margin_ = std::min(margin_, side.depth[f]);
      if (shell)
        side.facet_gap[f] = std::min(shell_gap(s.gaps, surface.thickness[f]), s.gaps.max_main);
      side.facet_gap[f] += s.gaps.padding;
      side.max_facet_gap = std::max(side.max_facet_gap, side.facet_gap[f]);
      side.facet_min_edge[f] = shortest_edge(c);
      if (is_radioss_rule(s.stiffness.rule))
        side.facet_km[f] =
            shell ? shell_segment_stiffness(surface.young_modulus[f], surface.thickness[f],
                                            s.stiffness.scale)
                  : main_segment_stiffness(surface.bulk_modulus[f],
                                           norm(cross(c[2] - c[0], c[3] - c[1])) * 0.5,
                                           surface.element_volume[f], s.stiffness.scale);
      side.max_km = std::max(side.max_km, side.facet_km[f]);
    }
    side.active.resize(n);
    for (std::size_t f = 0; f < n; ++f) side.active[f] = side.off[f] == 0 ? 1 : 0;
    side.node_free.assign(mass_.size(), 0);
    // Node -> facets (CSR), for node normals, areas and thicknesses.
    side.node_facet_start.assign(mass_.size() + 1, 0);
    for (const auto& facet : surface.facets)
      for (int a = 0; a < 4; ++a)
        if (a == 0 || facet[a] != facet[a - 1]) ++side.node_facet_start[facet[a] + 1];
    for (std::size_t i = 0; i < mass_.size(); ++i)
      side.node_facet_start[i + 1] += side.node_facet_start[i];
    side.node_facets.assign(side.node_facet_start.back(), -1);
    std::vector<std::int32_t> fill(side.node_facet_start.begin(), side.node_facet_start.end() - 1);
    for (std::size_t f = 0; f < n; ++f)
      for (int a = 0; a < 4; ++a)
        if (a == 0 || surface.facets[f][a] != surface.facets[f][a - 1])
          side.node_facets[fill[surface.facets[f][a]]++] = static_cast<std::int32_t>(f);
    const double other_size = typical_size[sides_.size() == 1 ? 0 : 1 - side_index];
    build_points(side, in, other_size,
                 side_index == 0 ? secondary_nodes : std::span<const std::int32_t>{}, free_edges);
    side.free_edges = std::move(free_edges);
  }
  if (s.search_margin) margin_ = *s.search_margin;

  for (const Side& side : sides_)
    for (const auto& facet : side.surface.facets)
      surface_nodes_.insert(surface_nodes_.end(), facet.begin(), facet.end());
  std::sort(surface_nodes_.begin(), surface_nodes_.end());
  surface_nodes_.erase(std::unique(surface_nodes_.begin(), surface_nodes_.end()),
                       surface_nodes_.end());
}

// Bytes per contact point of one pass, rounded up from measurements: a slab of 2 x 8000 x 1
// hexahedra in S2S self contact, 256k points, 230 MB in all (about 870 bytes per point with the
// mesh and solver): the point's arrays on its side and in its pass (with the overlap slots of
// its cell, mortar.hpp) and its candidates.
constexpr double kBytesPerPoint = 1000.0;

void InterfaceImpl::require_point_memory(std::size_t planned) const {
  std::size_t made = 0;
  for (const Side& side : sides_) made += side.point_facet.size();
  const double points = static_cast<double>(made + planned);
  const double need = kBytesPerPoint * points;
  if (need <= settings_.memory_limit) return;
  throw ContactSetupError(
      "memory", "its surfaces make " + std::to_string(made + planned) +
                    " contact points, which need about " + gigabytes(need) +
                    " of memory, but only " + gigabytes(settings_.memory_limit) +
                    " are available: coarsen the surfaces, lower the accuracy level or use N2S");
}

void InterfaceImpl::build_points(Side& side, const ContactInput& in, double other_size,
                                 std::span<const std::int32_t> secondary_nodes,
                                 const std::vector<std::uint8_t>& free_edges) {
  const ContactSettings& s = settings_;
  const ContactSurface& surface = side.surface;
  std::vector<double> facet_area(surface.size(), 0.0);
  auto add_point = [&](std::int32_t f, std::int32_t node, double xi, double eta, double weight,
                       const CellBounds& cell = {}, double reach = 0.0) {
    side.point_facet.push_back(f);
    side.point_node.push_back(node);
    side.point_xi.push_back(xi);
    side.point_eta.push_back(eta);
    side.point_weight.push_back(weight);
    side.point_cell.insert(side.point_cell.end(), {cell.xi0, cell.xi1, cell.eta0, cell.eta1});
    side.point_reach.push_back(reach);
  };
  // Integration points (S2S). A facet two or more times larger than the facets it meets would
  // press its few points into single small facets of the other side with the stiffness of its
  // whole area: it is split into m x n cells about the size of the other side's facets along
  // each of its directions (a long thin facet, a slab's side, into a row of cells), each
  // integrated with the rule of the accuracy level, so both sides resolve the overlap alike.
  std::vector<FacetPoint> rules[16];
  auto cells_along = [other_size](double length) {
    return static_cast<int>(std::clamp(std::floor(length / other_size), 1.0, 32.0));
  };
  // Edges 0 and 2 run along xi, 1 and 3 along eta.
  auto cells_of = [&](const QuadCorners& c) {
    return std::array<int, 2>{cells_along(std::max(norm(c[1] - c[0]), norm(c[2] - c[3]))),
                              cells_along(std::max(norm(c[2] - c[1]), norm(c[3] - c[0])))};
  };
  // The rule of cell (i, j): sharp-edge strips only in cells on the facet's sharp edges (edge 0:
  // eta = -1, 1: xi = +1, 2: eta = +1, 3: xi = -1).
  auto rule_of = [&](std::size_t f, int i, int j,
                     const std::array<int, 2>& cells) -> const std::vector<FacetPoint>& {
    std::uint8_t sharp = side.sharp[f];
    if (j > 0) sharp &= ~1u;
    if (i < cells[0] - 1) sharp &= ~2u;
    if (j < cells[1] - 1) sharp &= ~4u;
    if (i > 0) sharp &= ~8u;
    std::vector<FacetPoint>& cell_rule = rules[sharp];
    if (cell_rule.empty()) cell_rule = facet_rule(s.accuracy_level, s.accuracy_edge, sharp);
    return cell_rule;
  };
  if (s.discretisation == Discretisation::SurfaceToSurface) {
    // Counted before they are made: a model whose points would not fit is refused.
    std::size_t planned = 0;
    for (std::size_t f = 0; f < surface.size(); ++f) {
      const auto cells = cells_of(quad_corners(surface.facets[f], in.x, in.y, in.z));
      for (int j = 0; j < cells[1]; ++j)
        for (int i = 0; i < cells[0]; ++i) planned += rule_of(f, i, j, cells).size();
    }
    require_point_memory(planned);
  }
  for (std::size_t f = 0; f < surface.size(); ++f) {
    const QuadCorners c = quad_corners(surface.facets[f], in.x, in.y, in.z);
    const std::array<int, 2> cells = cells_of(c);
    // Radioss Irem_i2 = 1: a facet whose nodes are all removed has no points (its area counts).
    const bool removed = s.removed_nodes.covers(surface.facets[f]);
    const int cells_xi = cells[0], cells_eta = cells[1];
    for (int j = 0; j < cells_eta; ++j)
      for (int i = 0; i < cells_xi; ++i) {
        const std::vector<FacetPoint>& cell_rule = rule_of(f, i, j, cells);
        const double inv_xi = 1.0 / cells_xi, inv_eta = 1.0 / cells_eta;
        for (const FacetPoint& q : cell_rule) {
          const double xi = -1.0 + (2.0 * i + 1.0 + q.xi) * inv_xi,
                       eta = -1.0 + (2.0 * j + 1.0 + q.eta) * inv_eta;
          const double weight = q.weight * inv_xi * inv_eta;
          double jacobian = 0.0;
          quad_normal(c, xi, eta, jacobian);
          const auto shape = quad_shape(xi, eta);
          // A shell's node carries the area of one side.
          if (surface.twin[f] < 0 || surface.twin[f] > static_cast<std::int32_t>(f))
            for (int a = 0; a < 4; ++a)
              side.node_area[surface.facets[f][a]] += shape[a] * weight * jacobian;
          facet_area[f] += weight * jacobian;
          if (s.discretisation == Discretisation::SurfaceToSurface) {
            const CellBounds cell{-1.0 + (2.0 * i + 1.0 + q.xi0) * inv_xi,
                                  -1.0 + (2.0 * i + 1.0 + q.xi1) * inv_xi,
                                  -1.0 + (2.0 * j + 1.0 + q.eta0) * inv_eta,
                                  -1.0 + (2.0 * j + 1.0 + q.eta1) * inv_eta};
            // Its cell's farthest corner from it.
            const Vec3 x = quad_point(c, xi, eta);
            double reach = 0.0;
            for (const double a : {cell.xi0, cell.xi1})
              for (const double b : {cell.eta0, cell.eta1})
                reach = std::max(reach, norm(quad_point(c, a, b) - x));
            if (!removed) add_point(static_cast<std::int32_t>(f), -1, xi, eta, weight, cell, reach);
          }
        }
      }
  }
  // Nodes (N2S): every node of the surface, or the given ones; a node point sits at corner 0 of
  // a facet made of its node four times (xi = eta = -1), so the shape functions are (1, 0, 0, 0).
  if (s.discretisation == Discretisation::NodeToSurface) {
    std::vector<std::int32_t> nodes(secondary_nodes.begin(), secondary_nodes.end());
    if (nodes.empty())
      for (const auto& facet : surface.facets)
        nodes.insert(nodes.end(), facet.begin(), facet.end());
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    for (const std::int32_t node : nodes) {
      if (s.removed_nodes.has(node)) continue;  // Radioss Irem_i2 = 1
      if (node < 0 || static_cast<std::size_t>(node) >= mass_.size() ||
          side.node_facet_start[node] == side.node_facet_start[node + 1])
        throw ContactSetupError("secondary_nodes", "node index " + std::to_string(node) +
                                                       " is not a node of a surface-1 facet");
      add_point(side.node_facets[side.node_facet_start[node]], node, -1.0, -1.0, 0.0);
    }
  }
  // Nodes on a free shell edge (Igap0).
  std::vector<std::uint8_t> on_free_edge(mass_.size(), 0);
  for (std::size_t f = 0; f < surface.size(); ++f)
    for (int e = 0; e < 4; ++e)
      if (free_edges[f] & (1u << e)) {
        on_free_edge[surface.facets[f][e]] = 1;
        on_free_edge[surface.facets[f][(e + 1) % 4]] = 1;
      }
  // A node takes its spring whole; an integration point its share of its facet's area.
  const std::size_t n = side.point_facet.size();
  for (std::size_t p = 0; p < n; ++p) {
    double share = 1.0;
    if (side.point_node[p] < 0) {
      double jacobian = 0.0;
      quad_normal(quad_corners(surface.facets[side.point_facet[p]], in.x, in.y, in.z),
                  side.point_xi[p], side.point_eta[p], jacobian);
      share = side.point_weight[p] * jacobian / facet_area[side.point_facet[p]];
    }
    init_point(side, p, on_free_edge, share);
  }
}

void InterfaceImpl::init_point(Side& side, std::size_t p,
                               const std::vector<std::uint8_t>& on_free_edge, double share) {
  const ContactSettings& s = settings_;
  const ContactSurface& surface = side.surface;
  const std::size_t n = side.point_facet.size();
  for (auto* v : {&side.point_pfac, &side.point_ks, &side.point_share, &side.point_depth,
                  &side.point_thickness, &side.point_gap})
    v->resize(n, 0.0);
  side.point_min_edge.resize(n, kInfinity);
  side.point_part.resize(n, 0);
  const bool self = sides_.size() == 1;
  const bool radioss = is_radioss_rule(s.stiffness.rule);
  const std::int32_t node = side.point_node[p];
  std::int32_t first = side.point_facet[p], last = first + 1;
  const std::int32_t* facets = nullptr;
  if (node >= 0) {  // over the facets around the node
    facets = side.node_facets.data();
    first = side.node_facet_start[node];
    last = side.node_facet_start[node + 1];
  }
  for (std::int32_t k = first; k < last; ++k) {
    const std::int32_t f = facets ? facets[k] : k;
    const bool shell = surface.twin[f] >= 0;
    side.point_pfac[p] = std::max(side.point_pfac[p], surface.penalty[f]);
    side.point_thickness[p] = std::max(side.point_thickness[p], surface.thickness[f]);
    if (shell)
      side.point_gap[p] = std::max(side.point_gap[p], shell_gap(s.gaps, surface.thickness[f]));
    if (self) side.point_min_edge[p] = std::min(side.point_min_edge[p], side.facet_min_edge[f]);
    if (radioss)
      side.point_ks[p] =
          std::max(side.point_ks[p],
                   shell ? shell_segment_stiffness(surface.young_modulus[f], surface.thickness[f],
                                                   s.stiffness.scale)
                         : secondary_node_stiffness(surface.bulk_modulus[f],
                                                    surface.element_volume[f], s.stiffness.scale));
  }
  if (node >= 0 && s.gaps.zero_at_free_edges && on_free_edge[node]) side.point_gap[p] = 0.0;
  side.point_gap[p] = std::min(side.point_gap[p], s.gaps.max_secondary);
  side.max_point_gap = std::max(side.max_point_gap, side.point_gap[p]);
  side.point_part[p] = side.facet_part[side.point_facet[p]];
  side.point_share[p] = share;
  side.point_depth[p] = s.detection_depth.value_or(0.5 * side.point_thickness[p]);
  side.max_point_depth = std::max(side.max_point_depth, side.point_depth[p]);
}

void InterfaceImpl::build_passes() {
  if (sides_.size() == 1) {
    passes_.resize(1);
    passes_[0].weight = 0.5;  // both sides of a self-contact pair are in the one pass
  } else if (settings_.one_way) {
    passes_.resize(1);
    passes_[0].own = 0;
    passes_[0].target = 1;
  } else {
    passes_.resize(2);
    passes_[0].own = 0;
    passes_[0].target = 1;
    passes_[0].weight = 0.5;
    passes_[1].own = 1;
    passes_[1].target = 0;
    passes_[1].weight = 0.5;
  }
  for (Pass& pass : passes_) size_pass(pass, sides_[pass.own].point_facet.size());
}

// Per-point history and result slots for n points; points added later (free nodes) start empty.
void InterfaceImpl::size_pass(Pass& pass, std::size_t n) const {
  for (auto* v : {&pass.state, &pass.adhered, &pass.hit}) v->resize(n, 0);
  pass.hit_facet.resize(n, -1);
  const bool ties = settings_.freeze || settings_.stick_stress.has_value();
  pass.tie_facet.resize(ties ? n : 0, -1);
  pass.tie_xi.resize(ties ? n : 0, 0.0);
  pass.tie_eta.resize(ties ? n : 0, 0.0);
  pass.shift.resize(settings_.clearance ? n : 0, 0.0);
  const bool heat = settings_.thermal.any();
  pass.heat_facet.resize(heat ? n : 0, -1);
  for (auto* v : {&pass.heat_xi, &pass.heat_eta, &pass.heat_conductance}) v->resize(heat ? n : 0);
  const bool cells = settings_.discretisation == Discretisation::SurfaceToSurface;
  pass.mortar_own.resize(cells ? 4 * n : 0, 0.0);
  pass.mortar_target.resize(cells ? 4 * kMaxOverlaps * n : 0, 0.0);
  pass.mortar_facet.resize(cells ? kMaxOverlaps * n : 0, -1);
  pass.mortar_count.resize(cells ? n : 0, 0);
  for (auto* v : {&pass.offset,       &pass.htx,
                  &pass.hty,          &pass.htz,
                  &pass.slip,         &pass.hit_xi,
                  &pass.hit_eta,      &pass.fx,
                  &pass.fy,           &pass.fz,
                  &pass.dfx,          &pass.dfy,
                  &pass.dfz,          &pass.area,
                  &pass.pressure,     &pass.slip_speed,
                  &pass.normal_force, &pass.tangential_force,
                  &pass.energy,       &pass.slip_work,
                  &pass.penetration,  &pass.omega2,
                  &pass.pair_gap,     &pass.released,
                  &pass.kink,         &pass.approach_omega2})
    v->resize(n, 0.0);
  const bool nodes = settings_.discretisation == Discretisation::NodeToSurface;
  pass.corner.resize(nodes ? n * kMaxCornerWalls : 0);
}

// Initial penetrations (seed 000 delta0_offset / delta0_max, Radioss Inacti), clearance
// (OptiStruct CLEARANCE: the gap found at t = 0 is replaced by the clearance) and FREEZE ties,
// from each point's partner in the initial configuration.
void InterfaceImpl::initial_state(const ContactInput& in) {
  rebuild_broad_phase(in);
  const ContactSettings& s = settings_;
  initial_stable_step_ = kInfinity;
  double omega2_max = 0.0;
  for (Pass& pass : passes_) {
    const Side& own = sides_[pass.own];
    const Side& target = sides_[pass.target];
    const std::size_t n = own.point_facet.size();
    std::vector<double> omega2(n, 0.0);
#pragma omp parallel for schedule(dynamic, \
                                  256) if (n >= static_cast <std::size_t>(kParallelMinimum) / 4)
    for (std::size_t p = 0; p < n; ++p) {
      const PointFrame f = frame(own, p, in);
      // Stable step bound before any contact: the point's stiffest possible spring on its lightest
      // node.
      double m_min = kInfinity;
      for (auto node : f.nodes) m_min = std::min(m_min, mass_[node]);
      const double k_bound = spring(own, p, f.area, target, -1);
      if (m_min > 0.0) omega2[p] = 2.0 * k_bound / m_min;
      if (!f.active) continue;
      Partner h = partner_of(pass, p, f, in, -1);
      std::optional<double> cover;
      if (own.point_node[p] >= 0) h = facing_node_partner(pass, p, f, in, h, cover);
      // An integration point's partner and gap as the steps find them: over its cell
      // (cell_cover.cpp).
      CellOverlap cell;
      if (own.point_node[p] < 0 && meet_by_cell(pass, p, f, in, h, cell) && !(cell.area > 0.0))
        continue;
      if (h.facet < 0) continue;
      if (s.freeze) {
        pass.state[p] = kTied;
        pass.tie_facet[p] = h.facet;
        pass.tie_xi[p] = h.xi;
        pass.tie_eta[p] = h.eta;
        pass.offset[p] = -h.gap;  // tied at its initial distance, open or closed
        continue;
      }
      const double gap = s.sense == ContactSense::Negative ? -h.gap : h.gap;
      if (s.clearance) {
        pass.shift[p] = *s.clearance - gap;
        continue;
      }
      if (!(gap < 0.0) || s.sense == ContactSense::Bilateral) continue;
      const double depth = -gap;
      switch (s.initial_penetration) {
        case InitialPenetration::Force:
          break;
        case InitialPenetration::Shift:
          pass.offset[p] = depth;
          break;
        case InitialPenetration::Offset: {
          const double allowed =
              s.initial_max.value_or(kDefaultInitialMaxFraction * own.point_thickness[p]);
          if (depth > allowed)
            pass.state[p] = kReleased;
          else
            pass.offset[p] = std::min(depth, s.initial_offset);
        }
      }
    }
    // Before contact: a facet's springs on its lightest node against an equal mass, 2 k / m_min.
    // S2S: k sums the springs of the facet's points. N2S: each corner node's spring in proportion
    // to the facet's share of the node's area, so that both discretisations bound alike (with the
    // facet penalty rule k = pfac A either way). Less would not do: the node's own element
    // stiffens it as well.
    std::vector<double> per_facet(own.surface.size(), 0.0);
    if (own.point_node.empty() || own.point_node[0] < 0) {
      for (std::size_t p = 0; p < n; ++p) per_facet[own.point_facet[p]] += omega2[p];
    } else {
      std::vector<double> node_omega2(mass_.size(), 0.0);
      for (std::size_t p = 0; p < n; ++p) node_omega2[own.point_node[p]] = omega2[p];
      for (std::size_t f = 0; f < own.surface.size(); ++f) {
        const auto& nodes = own.surface.facets[f];
        const QuadCorners c = quad_corners(nodes, in.x, in.y, in.z);
        const double area = 0.5 * norm(cross(c[2] - c[0], c[3] - c[1]));
        double m_min = kInfinity;
        for (auto node : nodes) m_min = std::min(m_min, mass_[node]);
        for (auto node : nodes)  // omega2 of a node was 2 k / m_node
          if (own.node_area[node] > 0.0)
            per_facet[f] +=
                node_omega2[node] * mass_[node] / m_min * 0.25 * area / own.node_area[node];
      }
    }
    for (double w : per_facet) omega2_max = std::max(omega2_max, w);
    // Each point may touch with its facet's bound (N2S: the largest of its node's facets).
    for (std::size_t p = 0; p < n; ++p) {
      const std::int32_t node = own.point_node.empty() ? -1 : own.point_node[p];
      if (node < 0) {
        pass.approach_omega2[p] = per_facet[own.point_facet[p]];
        continue;
      }
      double w = 0.0;
      for (std::int32_t k = own.node_facet_start[node]; k < own.node_facet_start[node + 1]; ++k)
        w = std::max(w, per_facet[own.node_facets[k]]);
      pass.approach_omega2[p] = w;
    }
  }
  initial_stable_step_ = spring_step(omega2_max);
  update_near_bound();  // the build above came before the bounds
}

}  // namespace abut
