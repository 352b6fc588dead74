// ContactInterface: set-up (sides, contact points, parts, passes), broad phase, the step driver.
// Enforcement is in enforcement.cpp, the scatter of forces and statistics in scatter.cpp.
#include "abut/contact/interface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "abut/contact/integration.hpp"
#include "abut/contact/quad.hpp"
#include "abut/core/parallel.hpp"

namespace abut {
namespace {

// Default delta0_max: 4% of the element thickness (seed 000).
constexpr double kDefaultInitialMaxFraction = 0.04;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

QuadCorners corners_of(const std::array<std::int32_t, 4>& nodes, const ContactInput& in) {
  QuadCorners c;
  for (int a = 0; a < 4; ++a) c[a] = {in.x[nodes[a]], in.y[nodes[a]], in.z[nodes[a]]};
  return c;
}

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

}  // namespace

ContactInterface::ContactInterface(ContactSettings settings, ContactSurface surface1,
                                   ContactSurface surface2, std::span<const double> node_mass,
                                   const ContactInput& initial,
                                   std::span<const std::int32_t> secondary_nodes)
    : settings_(std::move(settings)), mass_(node_mass.begin(), node_mass.end()) {
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
  sides_.resize(self ? 1 : 2);
  sides_[0].surface = std::move(surface1);
  if (!self) sides_[1].surface = std::move(surface2);
  build_parts();
  build_sides(initial, secondary_nodes);
  build_passes();
  initial_state(initial);
}

void ContactInterface::validate(const ContactSurface& s1, const ContactSurface& s2,
                                std::size_t coordinates) const {
  const ContactSettings& s = settings_;
  auto fail = [](const char* setting, const std::string& message) {
    throw ContactSetupError(setting, message);
  };
  if (s.accuracy_level < 1) fail("accuracy_level", "expected 1 (low), 2 (standard) or more (high)");
  if (!(s.damping >= 0.0)) fail("damping", "the fraction of critical damping must be >= 0");
  if (!(s.end_time >= s.begin_time)) fail("end_time", "the contact must not end before it begins");
  if (!(s.initial_offset >= 0.0))
    fail("initial_offset", "the initial penetration offset must be >= 0");
  if (s.initial_max && !(*s.initial_max >= 0.0)) fail("initial_max", "must be >= 0");
  if (!(s.edge_tolerance >= 0.0)) fail("edge_tolerance", "the edge tolerance must be >= 0");
  if (!(s.edge_angle > 0.0 && s.edge_angle <= 180.0))
    fail("edge_angle", "expected an angle in (0, 180] degrees");
  if (s.stick_stress && !(*s.stick_stress > 0.0))
    fail("stick_stress", "the sticking failure stress must be > 0");
  if (s.search_margin && !(*s.search_margin > 0.0))
    fail("search_margin", "the search margin must be > 0");
  if (s.detection_depth && !(*s.detection_depth > 0.0))
    fail("detection_depth", "the detection depth must be > 0");
  if (s.tangential_penalty && !(*s.tangential_penalty > 0.0))
    fail("tangential_penalty", "the tangential penalty must be > 0");
  if (s.clearance && !std::isfinite(*s.clearance))
    fail("clearance", "the clearance must be a finite length");
  if (s.adhesion && !(s.adhesion->gap > 0.0 && s.adhesion->max_stress >= 0.0 &&
                      s.adhesion->fluid_viscosity >= 0.0))
    fail("adhesion",
         "adhesion needs a gap > 0, a maximum adhesive stress >= 0 and a viscosity >= 0");
  if (s.freeze && s.stick_stress)
    fail("freeze", "a frozen contact cannot also have a sticking failure stress");
  if (const auto* c = std::get_if<Coulomb>(&s.tangential_law)) {
    if (!(c->mu_static >= 0.0) || !(c->mu_dynamic >= 0.0))
      fail("tangential_law", "the friction coefficients must be >= 0");
    if (!c->function && std::holds_alternative<std::monostate>(c->model) &&
        c->mu_dynamic > c->mu_static)
      fail("tangential_law", "the dynamic friction coefficient must not exceed the static one");
  }
  if (const auto* t = std::get_if<Tresca>(&s.tangential_law)) {
    if (!(t->shear_yield > 0.0))
      fail("tangential_law", "Tresca friction needs a shear yield stress > 0");
    if (!(t->factor_static >= 0.0 && t->factor_dynamic >= 0.0 &&
          t->factor_dynamic <= t->factor_static))
      fail("tangential_law", "Tresca friction needs shear factors with 0 <= dynamic <= static");
  }
  if (const auto* c = std::get_if<CurvePenalty>(&s.normal_law); c && !c->pressure)
    fail("normal_law", "the penalty curve is missing");
  if (s.friction_filter.kind != FrictionFilter::Kind::None && !(s.friction_filter.xfreq > 0.0))
    fail("friction_filter", "the filter coefficient must be > 0");
  if (s.friction_filter.kind == FrictionFilter::Kind::Simple && !(s.friction_filter.xfreq <= 1.0))
    fail("friction_filter", "the simple filter coefficient must be in (0, 1]");
  const StiffnessSettings& k = s.stiffness;
  if (!(k.scale > 0.0) || !(k.minimum >= 0.0) || !(k.maximum > k.minimum))
    fail("stiffness", "expected a stiffness scale > 0 and 0 <= minimum < maximum");
  for (const PairScale& ps : s.pair_scales)
    if (!(ps.scale > 0.0) || !std::isfinite(ps.scale))
      fail("pair_scales", "a penalty scale factor must be > 0");
  if (s1.size() == 0) fail("surface1", "surface 1 has no facets");
  if (s2.size() == 0) fail("surface2", "surface 2 has no facets");
  const bool radioss = is_radioss_rule(k.rule);
  int which = 1;
  for (const ContactSurface* surface : {&s1, &s2}) {
    const std::string name = "surface" + std::to_string(which++);
    const std::size_t n = surface->size();
    if (surface->part.size() != n || surface->penalty.size() != n || surface->thickness.size() != n)
      fail(name.c_str(), "part, penalty and thickness need one entry per facet");
    for (std::size_t f = 0; f < n; ++f) {
      if (!(surface->penalty[f] > 0.0) || !std::isfinite(surface->penalty[f]))
        fail(name.c_str(),
             "the penalty stiffness of part " + std::to_string(surface->part[f]) + " must be > 0");
      if (!(surface->thickness[f] > 0.0))
        fail(name.c_str(),
             "a facet of part " + std::to_string(surface->part[f]) + " has no positive thickness");
      if (radioss && (surface->bulk_modulus.size() != n || surface->element_volume.size() != n ||
                      !(surface->bulk_modulus[f] > 0.0) || !(surface->element_volume[f] > 0.0)))
        fail(
            "stiffness",
            "the Radioss stiffness rules need each facet's bulk modulus and element volume (part " +
                std::to_string(surface->part[f]) + ")");
      for (auto node : surface->facets[f])
        if (node < 0 || static_cast<std::size_t>(node) >= mass_.size() ||
            static_cast<std::size_t>(node) >= coordinates)
          fail(name.c_str(),
               "a facet refers to node index " + std::to_string(node) + " beyond the nodal arrays");
    }
  }
}

void ContactInterface::build_parts() {
  for (const Side& side : sides_)
    part_ids_.insert(part_ids_.end(), side.surface.part.begin(), side.surface.part.end());
  std::sort(part_ids_.begin(), part_ids_.end());
  part_ids_.erase(std::unique(part_ids_.begin(), part_ids_.end()), part_ids_.end());
  const std::size_t n = part_ids_.size();
  part_scale_.assign(n * n, 1.0);
  auto in = [](const std::vector<std::int64_t>& set, std::int64_t part) {
    return set.empty() || std::find(set.begin(), set.end(), part) != set.end();
  };
  for (const PairScale& ps : settings_.pair_scales) {  // in order: the last assignment wins
    const std::vector<std::int64_t>& second = ps.parts2.empty() ? ps.parts1 : ps.parts2;
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = 0; b < n; ++b) {
        const std::int64_t pa = part_ids_[a], pb = part_ids_[b];
        if ((in(ps.parts1, pa) && in(second, pb)) || (in(ps.parts1, pb) && in(second, pa)))
          part_scale_[a * n + b] = ps.scale;
      }
  }
  for (Side& side : sides_) {
    side.facet_part.resize(side.surface.size());
    for (std::size_t f = 0; f < side.surface.size(); ++f)
      side.facet_part[f] = static_cast<std::int32_t>(
          std::lower_bound(part_ids_.begin(), part_ids_.end(), side.surface.part[f]) -
          part_ids_.begin());
  }
}

void ContactInterface::build_sides(const ContactInput& in,
                                   std::span<const std::int32_t> secondary_nodes) {
  const ContactSettings& s = settings_;
  margin_ = kInfinity;
  smooth_reach_ = smooth_edge_reach(s.edge_angle);
  // Typical facet size of each side (median of the longest edges), for the subdivision of S2S
  // facets.
  std::vector<double> typical_size;
  for (const Side& side : sides_) {
    std::vector<double> sizes;
    for (const auto& facet : side.surface.facets)
      sizes.push_back(longest_edge(corners_of(facet, in)));
    std::nth_element(sizes.begin(), sizes.begin() + static_cast<std::ptrdiff_t>(sizes.size() / 2),
                     sizes.end());
    typical_size.push_back(sizes[sizes.size() / 2]);
  }
  for (std::size_t side_index = 0; side_index < sides_.size(); ++side_index) {
    Side& side = sides_[side_index];
    const ContactSurface& surface = side.surface;
    const std::size_t n = surface.size();
    side.sharp = sharp_edges(surface, in.x, in.y, in.z, s.edge_angle);
    side.active.assign(n, 1);
    side.depth.resize(n);
    side.facet_km.assign(n, 0.0);
    side.node_area.assign(mass_.size(), 0.0);
    for (std::size_t f = 0; f < n; ++f) {
      const QuadCorners c = corners_of(surface.facets[f], in);
      if (s.initial_region) {
        const Vec3 centre = quad_point(c, 0.0, 0.0);
        side.active[f] = s.initial_region(centre.x, centre.y, centre.z) ? 1 : 0;
      }
      side.depth[f] = s.detection_depth.value_or(0.5 * surface.thickness[f]);
      margin_ = std::min(margin_, side.depth[f]);
      if (is_radioss_rule(s.stiffness.rule))
        side.facet_km[f] = main_segment_stiffness(surface.bulk_modulus[f],
                                                  norm(cross(c[2] - c[0], c[3] - c[1])) * 0.5,
                                                  surface.element_volume[f], s.stiffness.scale);
      side.max_km = std::max(side.max_km, side.facet_km[f]);
    }
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
                 side_index == 0 ? secondary_nodes : std::span<const std::int32_t>{});
  }
  if (s.search_margin) margin_ = *s.search_margin;

  for (const Side& side : sides_)
    for (const auto& facet : side.surface.facets)
      surface_nodes_.insert(surface_nodes_.end(), facet.begin(), facet.end());
  std::sort(surface_nodes_.begin(), surface_nodes_.end());
  surface_nodes_.erase(std::unique(surface_nodes_.begin(), surface_nodes_.end()),
                       surface_nodes_.end());
}

void ContactInterface::build_points(Side& side, const ContactInput& in, double other_size,
                                    std::span<const std::int32_t> secondary_nodes) {
  const ContactSettings& s = settings_;
  const ContactSurface& surface = side.surface;
  std::vector<double> facet_area(surface.size(), 0.0);
  auto add_point = [&](std::int32_t f, std::int32_t node, double xi, double eta, double weight) {
    side.point_facet.push_back(f);
    side.point_node.push_back(node);
    side.point_xi.push_back(xi);
    side.point_eta.push_back(eta);
    side.point_weight.push_back(weight);
  };
  // Integration points (S2S). A facet two or more times larger than the facets it meets would
  // press its few points into single small facets of the other side with the stiffness of its
  // whole area: it is split into m x m cells about the size of the other side's facets, each
  // integrated with the rule of the accuracy level, so both sides resolve the overlap alike.
  std::vector<FacetPoint> rules[16];
  for (std::size_t f = 0; f < surface.size(); ++f) {
    const QuadCorners c = corners_of(surface.facets[f], in);
    const int cells =
        static_cast<int>(std::clamp(std::floor(longest_edge(c) / other_size), 1.0, 32.0));
    for (int j = 0; j < cells; ++j)
      for (int i = 0; i < cells; ++i) {
        // Sharp-edge strips only in cells on the facet's sharp edges (edge 0: eta = -1,
        // 1: xi = +1, 2: eta = +1, 3: xi = -1).
        std::uint8_t sharp = side.sharp[f];
        if (j > 0) sharp &= ~1u;
        if (i < cells - 1) sharp &= ~2u;
        if (j < cells - 1) sharp &= ~4u;
        if (i > 0) sharp &= ~8u;
        std::vector<FacetPoint>& cell_rule = rules[sharp];
        if (cell_rule.empty()) cell_rule = facet_rule(s.accuracy_level, s.accuracy_edge, sharp);
        const double inv = 1.0 / cells;
        for (const FacetPoint& q : cell_rule) {
          const double xi = -1.0 + (2.0 * i + 1.0 + q.xi) * inv,
                       eta = -1.0 + (2.0 * j + 1.0 + q.eta) * inv;
          const double weight = q.weight * inv * inv;
          double jacobian = 0.0;
          quad_normal(c, xi, eta, jacobian);
          const auto shape = quad_shape(xi, eta);
          for (int a = 0; a < 4; ++a)
            side.node_area[surface.facets[f][a]] += shape[a] * weight * jacobian;
          facet_area[f] += weight * jacobian;
          if (s.discretisation == Discretisation::SurfaceToSurface)
            add_point(static_cast<std::int32_t>(f), -1, xi, eta, weight);
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
      if (node < 0 || static_cast<std::size_t>(node) >= mass_.size() ||
          side.node_facet_start[node] == side.node_facet_start[node + 1])
        throw ContactSetupError("secondary_nodes", "node index " + std::to_string(node) +
                                                       " is not a node of a surface-1 facet");
      add_point(side.node_facets[side.node_facet_start[node]], node, -1.0, -1.0, 0.0);
    }
  }
  // Per point: penalty, Radioss secondary stiffness, share of its facet, depth, thickness, part.
  const std::size_t n = side.point_facet.size();
  for (auto* v : {&side.point_pfac, &side.point_ks, &side.point_share, &side.point_depth,
                  &side.point_thickness})
    v->assign(n, 0.0);
  side.point_part.assign(n, 0);
  side.max_point_depth = 0.0;
  const bool radioss = is_radioss_rule(s.stiffness.rule);
  for (std::size_t p = 0; p < n; ++p) {
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
      side.point_pfac[p] = std::max(side.point_pfac[p], surface.penalty[f]);
      side.point_thickness[p] = std::max(side.point_thickness[p], surface.thickness[f]);
      if (radioss)
        side.point_ks[p] =
            std::max(side.point_ks[p],
                     secondary_node_stiffness(surface.bulk_modulus[f], surface.element_volume[f],
                                              s.stiffness.scale));
    }
    side.point_part[p] = side.facet_part[side.point_facet[p]];
    if (node >= 0) {
      side.point_share[p] = 1.0;
    } else {
      double jacobian = 0.0;
      quad_normal(corners_of(surface.facets[side.point_facet[p]], in), side.point_xi[p],
                  side.point_eta[p], jacobian);
      side.point_share[p] = side.point_weight[p] * jacobian / facet_area[side.point_facet[p]];
    }
    side.point_depth[p] = s.detection_depth.value_or(0.5 * side.point_thickness[p]);
    side.max_point_depth = std::max(side.max_point_depth, side.point_depth[p]);
  }
}

void ContactInterface::build_passes() {
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
  for (Pass& pass : passes_) {
    const std::size_t n = sides_[pass.own].point_facet.size();
    for (auto* v : {&pass.state, &pass.sliding, &pass.adhered, &pass.hit}) v->assign(n, 0);
    pass.tie_facet.assign(n, -1);
    pass.hit_facet.assign(n, -1);
    for (auto* v : {&pass.offset,
                    &pass.shift,
                    &pass.htx,
                    &pass.hty,
                    &pass.htz,
                    &pass.tie_xi,
                    &pass.tie_eta,
                    &pass.hit_xi,
                    &pass.hit_eta,
                    &pass.fx,
                    &pass.fy,
                    &pass.fz,
                    &pass.area,
                    &pass.pressure,
                    &pass.slip_speed,
                    &pass.normal_force,
                    &pass.tangential_force,
                    &pass.energy,
                    &pass.damping_work,
                    &pass.slip_work,
                    &pass.penetration,
                    &pass.omega2,
                    &pass.qx,
                    &pass.qy,
                    &pass.qz})
      v->assign(n, 0.0);
  }
}

std::size_t ContactInterface::point_count() const {
  std::size_t n = 0;
  for (const Pass& pass : passes_) n += pass.state.size();
  return n;
}

std::size_t ContactInterface::released_points() const {
  std::size_t n = 0;
  for (const Pass& pass : passes_)
    n += static_cast<std::size_t>(std::count(pass.state.begin(), pass.state.end(), kReleased));
  return n;
}

std::size_t ContactInterface::tied_points() const {
  std::size_t n = 0;
  for (const Pass& pass : passes_)
    n += static_cast<std::size_t>(std::count(pass.state.begin(), pass.state.end(), kTied));
  return n;
}

bool ContactInterface::needs_rebuild(const ContactInput& in) const {
  if (builds_ == 0) return true;
  // Verlet-list rule: boxes were inflated by the margin m; while no node has moved more than
  // m/2 since the build, a point and a facet cannot have approached each other by more than m.
  double moved2 = 0.0;
  const std::size_t n = surface_nodes_.size();
#pragma omp parallel for schedule(static) \
    reduction(max                         \
              : moved2) if (n >= static_cast <std::size_t>(kParallelMinimum))
  for (std::size_t k = 0; k < n; ++k) {
    const auto i = surface_nodes_[k];
    const double dx = in.x[i] - bx_[k], dy = in.y[i] - by_[k], dz = in.z[i] - bz_[k];
    moved2 = std::max(moved2, dx * dx + dy * dy + dz * dz);
  }
  return moved2 > 0.25 * margin_ * margin_;
}

void ContactInterface::rebuild_broad_phase(const ContactInput& in) {
  const double above =
      std::max(settings_.adhesion ? settings_.adhesion->zone() : 0.0, settings_.edge_tolerance);
  for (Pass& pass : passes_) {
    const Side& own = sides_[pass.own];
    const Side& target = sides_[pass.target];
    std::vector<Box> boxes(target.surface.size());
    for (std::size_t f = 0; f < boxes.size(); ++f) {
      const QuadCorners c = corners_of(target.surface.facets[f], in);
      const double grow = std::max({target.depth[f], above}) + margin_;
      for (int k = 0; k < 3; ++k) {
        const double lo = std::min({c[0][k], c[1][k], c[2][k], c[3][k]});
        const double hi = std::max({c[0][k], c[1][k], c[2][k], c[3][k]});
        boxes[f].lo[k] = lo - grow;
        boxes[f].hi[k] = hi + grow;
      }
    }
    pass.grid.build(boxes);
    const std::size_t n = own.point_facet.size();
#pragma omp parallel for schedule(static) if (n >= static_cast <std::size_t>(kParallelMinimum))
    for (std::size_t p = 0; p < n; ++p) {
      const std::int32_t node = own.point_node[p];
      const Vec3 x = node >= 0 ? Vec3{in.x[node], in.y[node], in.z[node]}
                               : quad_point(corners_of(own.surface.facets[own.point_facet[p]], in),
                                            own.point_xi[p], own.point_eta[p]);
      pass.qx[p] = x.x;
      pass.qy[p] = x.y;
      pass.qz[p] = x.z;
    }
    pass.grid.query(pass.qx, pass.qy, pass.qz, pass.candidates);
  }
  bx_.resize(surface_nodes_.size());
  by_.resize(surface_nodes_.size());
  bz_.resize(surface_nodes_.size());
  for (std::size_t k = 0; k < surface_nodes_.size(); ++k) {
    bx_[k] = in.x[surface_nodes_[k]];
    by_[k] = in.y[surface_nodes_[k]];
    bz_[k] = in.z[surface_nodes_[k]];
  }
  ++builds_;
}

// Initial penetrations (seed 000 delta0_offset / delta0_max, Radioss Inacti), clearance
// (OptiStruct CLEARANCE: the gap found at t = 0 is replaced by the clearance) and FREEZE ties,
// from each point's partner in the initial configuration.
void ContactInterface::initial_state(const ContactInput& in) {
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
      const Partner h = partner_of(pass, p, f, in, -1);
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
        const QuadCorners c = corners_of(nodes, in);
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
  }
  if (omega2_max > 0.0) initial_stable_step_ = 2.0 / std::sqrt(omega2_max);
}

void ContactInterface::update_moving_region(const ContactInput& in) {
  if (!settings_.moving_region) return;
  for (Side& side : sides_)
    for (std::size_t f = 0; f < side.surface.size(); ++f) {
      if (!side.active[f]) continue;
      const Vec3 centre = quad_point(corners_of(side.surface.facets[f], in), 0.0, 0.0);
      if (!settings_.moving_region(centre.x, centre.y, centre.z)) side.active[f] = 0;
    }
}

std::vector<PairStiffness> ContactInterface::pair_stiffness() const {
  // Every rule is increasing in both sides' values, so the range over a part pair follows from
  // the ranges of the point values (own side) and the facet values (target side) of each part.
  const std::size_t np = part_ids_.size();
  const bool radioss = is_radioss_rule(settings_.stiffness.rule);
  std::vector<double> lo(np * np, kInfinity), hi(np * np, 0.0);
  for (const Pass& pass : passes_) {
    const Side& own = sides_[pass.own];
    const Side& target = sides_[pass.target];
    std::vector<double> own_lo(np, kInfinity), own_hi(np, 0.0), target_lo(np, kInfinity),
        target_hi(np, 0.0);
    for (std::size_t p = 0; p < own.point_facet.size(); ++p) {
      const double v = radioss ? own.point_ks[p] : own.point_pfac[p];
      own_lo[own.point_part[p]] = std::min(own_lo[own.point_part[p]], v);
      own_hi[own.point_part[p]] = std::max(own_hi[own.point_part[p]], v);
    }
    for (std::size_t f = 0; f < target.surface.size(); ++f) {
      const double v = radioss ? target.facet_km[f] : target.surface.penalty[f];
      target_lo[target.facet_part[f]] = std::min(target_lo[target.facet_part[f]], v);
      target_hi[target.facet_part[f]] = std::max(target_hi[target.facet_part[f]], v);
    }
    for (std::size_t a = 0; a < np; ++a)
      for (std::size_t b = 0; b < np; ++b) {
        if (own_hi[a] == 0.0 || target_hi[b] == 0.0) continue;
        const double scale = part_scale_[a * np + b];
        const double k_lo =
            scale * (radioss ? combined_stiffness(settings_.stiffness, target_lo[b], own_lo[a])
                             : std::min(own_lo[a], target_lo[b]));
        const double k_hi =
            scale * (radioss ? combined_stiffness(settings_.stiffness, target_hi[b], own_hi[a])
                             : std::min(own_hi[a], target_hi[b]));
        const std::size_t i = pass.own == 0 ? a * np + b : b * np + a;  // surface-1 part first
        lo[i] = std::min(lo[i], k_lo);
        hi[i] = std::max(hi[i], k_hi);
      }
  }
  std::vector<PairStiffness> out;
  for (std::size_t a = 0; a < np; ++a)
    for (std::size_t b = 0; b < np; ++b)
      if (hi[a * np + b] > 0.0)
        out.push_back(
            {part_ids_[a], part_ids_[b], part_scale_[a * np + b], lo[a * np + b], hi[a * np + b]});
  return out;
}

void ContactInterface::apply(const ContactInput& in, ContactForces& out) {
  const std::size_t node_count = mass_.size();
  for (std::size_t size : {in.x.size(), in.y.size(), in.z.size(), in.vx.size(), in.vy.size(),
                           in.vz.size(), out.fx.size(), out.fy.size(), out.fz.size()})
    if (size < node_count)
      throw std::invalid_argument(
          "ContactInterface::apply: nodal arrays shorter than the node masses");
  stats_.force = {};
  stats_.normal_force = stats_.tangential_force = stats_.elastic_energy = stats_.max_penetration =
      0.0;
  stats_.active_points = 0;
  stats_.stable_step = kInfinity;
  for (auto i : surface_nodes_) pressure_[i] = 0.0;
  if (in.time < settings_.begin_time || in.time > settings_.end_time) {
    for (Pass& pass : passes_) {  // outside the window: no forces and no friction memory
      std::fill(pass.htx.begin(), pass.htx.end(), 0.0);
      std::fill(pass.hty.begin(), pass.hty.end(), 0.0);
      std::fill(pass.htz.begin(), pass.htz.end(), 0.0);
    }
    return;
  }
  update_moving_region(in);
  if (needs_rebuild(in)) rebuild_broad_phase(in);
  for (Pass& pass : passes_) {
    const std::size_t n = pass.state.size();
#pragma omp parallel for schedule(dynamic, \
                                  256) if (n >= static_cast <std::size_t>(kParallelMinimum) / 4)
    for (std::size_t p = 0; p < n; ++p) evaluate_point(pass, p, in);
  }
  scatter(in, out);
}

}  // namespace abut
