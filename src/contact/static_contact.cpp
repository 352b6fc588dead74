#include "abut/contact/static_contact.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "abut/contact/adjust.hpp"
#include "abut/contact/integration.hpp"
#include "abut/contact/narrow_phase.hpp"
#include "abut/contact/quad.hpp"
#include "facet_weights.hpp"

namespace abut {

using namespace facet_weights;

namespace {

constexpr double kPi = 3.14159265358979323846;

Vec3 tangential(const Vec3& v, const Vec3& n) { return v - n * dot(v, n); }

// The settings a tool takes (the delegating constructor's check, before anything is made).
StaticContactSettings checked_for_tool(StaticContactSettings s) {
  const char* refused = !s.node_to_surface ? "surface-to-surface points (a tool meets nodes)"
                        : s.tied           ? "a tie"
                        : s.small_sliding  ? "small sliding"
                        : s.adhesion       ? "adhesion"
                        : s.clearance      ? "a clearance"
                        : s.initial_penetration != InitialPenetration::Force
                            ? "an initial-penetration option"
                        : !s.pair_frictions.empty()        ? "friction by part pair"
                        : !s.removed_nodes.nodes().empty() ? "removed nodes"
                                                           : nullptr;
  if (refused)
    throw std::invalid_argument(std::string("an analytic tool does not take ") + refused);
  return s;
}

}  // namespace

StaticContact::StaticContact(StaticContactSettings settings, ContactSurface secondary,
                             AnalyticTool tool, ToolPoseAt pose,
                             std::span<const std::int32_t> secondary_nodes,
                             const ContactInput& initial)
    : StaticContact(checked_for_tool(std::move(settings)), std::move(secondary), ContactSurface{},
                    secondary_nodes, initial) {
  tool_ = tool;
  tool_pose_ = std::move(pose);
  pose_ = committed_pose_ = tool_pose_ ? tool_pose_(initial.time) : ToolPose{};
}

StaticContact::StaticContact(StaticContactSettings settings, ContactSurface secondary,
                             ContactSurface main, std::span<const std::int32_t> secondary_nodes,
                             const ContactInput& initial, DependentNodes dependents,
                             NagataSmoothing smoothing)
    : settings_(settings),
      secondary_(std::move(secondary)),
      main_(std::move(main)),
      dependents_(std::move(dependents)),
      smoothing_(std::move(smoothing)) {
  for (const ContactSurface* s : {&secondary_, &main_})
    if (!s->parent.empty() && s->parent.size() != s->size())
      throw std::invalid_argument(
          "StaticContact: a surface's parent list must be empty or hold "
          "one entry per facet");
  const ContactInput reference = extended(initial);
  x0_.assign(reference.x.begin(), reference.x.end());
  y0_.assign(reference.y.begin(), reference.y.end());
  z0_.assign(reference.z.begin(), reference.z.end());
  xc_ = x0_, yc_ = y0_, zc_ = z0_;
  const std::size_t nf = main_.size();
  main_sharp_ = sharp_edges(main_, x0_, y0_, z0_, settings_.edge_angle, &main_free_);
  main_active_.assign(nf, 1);
  main_depth_.assign(nf, settings_.depth);
  main_gap_.assign(nf, 0.0);
  main_min_edge_.assign(nf, std::numeric_limits<double>::infinity());
  main_twin_.assign(nf, -1);
  if (settings_.node_to_surface) {
    std::vector<std::int32_t> nodes(secondary_nodes.begin(), secondary_nodes.end());
    if (nodes.empty())
      for (const auto& f : secondary_.facets) nodes.insert(nodes.end(), f.begin(), f.end());
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    std::erase_if(nodes, [this](std::int32_t n) { return settings_.removed_nodes.has(n); });
    point_node_ = nodes;
    point_facet_.assign(nodes.size(), -1);
    // Facets around each node (for its tributary area).
    node_facet_start_.assign(x0_.size() + 1, 0);
    for (const auto& f : secondary_.facets)
      for (int a = 0; a < 4; ++a)
        if (a < 3 || f[3] != f[2]) ++node_facet_start_[f[a] + 1];
    for (std::size_t i = 0; i + 1 < node_facet_start_.size(); ++i)
      node_facet_start_[i + 1] += node_facet_start_[i];
    node_facets_.resize(static_cast<std::size_t>(node_facet_start_.back()));
    std::vector<std::int32_t> fill(node_facet_start_.begin(), node_facet_start_.end() - 1);
    for (std::size_t f = 0; f < secondary_.size(); ++f)
      for (int a = 0; a < 4; ++a)
        if (a < 3 || secondary_.facets[f][3] != secondary_.facets[f][2])
          node_facets_[fill[secondary_.facets[f][a]]++] = static_cast<std::int32_t>(f);
  } else {
    const std::vector<FacetPoint> rule = facet_rule(settings_.accuracy_level, false, 0);
    for (std::size_t f = 0; f < secondary_.size(); ++f) {
      // Radioss Irem_i2 = 1: a facet whose nodes (its curved face's, for a facet of one; of
      // those the host's: a smoothed facet's patch has dependent mid-points) are all removed has
      // no points.
      const FacetParent* face = parent_of(secondary_, static_cast<std::int32_t>(f));
      std::vector<std::int32_t> host;
      if (face)
        for (int a = 0; a < face->count; ++a)
          if (dependents_.empty() || face->nodes[a] < dependents_.first)
            host.push_back(face->nodes[a]);
      if (settings_.removed_nodes.covers(face
                                             ? std::span<const std::int32_t>(host)
                                             : std::span<const std::int32_t>(secondary_.facets[f])))
        continue;
      for (const FacetPoint& p : rule) {
        point_facet_.push_back(static_cast<std::int32_t>(f));
        point_node_.push_back(-1);
        point_xi_.push_back(p.xi);
        point_eta_.push_back(p.eta);
        point_weight_.push_back(p.weight);
        point_cell_.push_back({p.xi0, p.xi1, p.eta0, p.eta1});
      }
    }
  }
  committed_.assign(point_facet_.size(), History{});
  trial_ = committed_;
  points_.assign(point_facet_.size(), StaticContactPoint{});
  if (settings_.tied || settings_.small_sliding) {  // pairs (and tie offsets) of the reference
    evaluate(initial);
    commit();
  }
  if (!settings_.tied &&
      (settings_.clearance || settings_.initial_penetration != InitialPenetration::Force))
    initial_gaps(initial);
}

// The initial treatment of the settings, from each point's partner in the reference
// configuration (as InterfaceImpl::initial_state does for explicit steps).
void StaticContact::initial_gaps(const ContactInput& initial) {
  if (!settings_.small_sliding) evaluate(initial);  // small sliding: evaluated just above
  const std::size_t np = points_.size();
  if (settings_.clearance) shift_.assign(np, 0.0);
  if (settings_.initial_penetration == InitialPenetration::Offset) released_.assign(np, 0);
  for (std::size_t p = 0; p < np; ++p) {
    const StaticContactPoint& point = points_[p];
    if (!point.paired) continue;
    if (settings_.clearance) {
      shift_[p] = *settings_.clearance - point.gap;
      continue;
    }
    // A cell integrated point by point: its deepest point, so that none starts loaded.
    if (!(point.least_gap < 0.0)) continue;
    const double depth = -point.least_gap;
    if (settings_.initial_penetration == InitialPenetration::Shift)
      committed_[p].initial_offset = depth;
    else if (depth > settings_.initial_max)
      released_[p] = 1;
    else
      committed_[p].initial_offset = std::min(depth, settings_.initial_offset);
  }
  trial_ = committed_;
  std::fill(points_.begin(), points_.end(), StaticContactPoint{});
  elements_.clear();
}

ContactInput StaticContact::extended(const ContactInput& host) {
  if (dependents_.empty()) return host;
  smoothing_.update(host.x, host.y, host.z, dependents_);
  dependents_.extend(host.x, host.y, host.z, ex_, ey_, ez_);
  ContactInput in = host;
  in.x = ex_, in.y = ey_, in.z = ez_;
  return in;
}

void StaticContact::evaluate(const ContactInput& host) {
  const ContactInput in = extended(host);
  const std::size_t np = point_facet_.size();
  const double search =
      std::max(settings_.search_distance, reach_at_clearance(settings_.normal)) + settings_.padding;
  const double reach = std::max(search, settings_.depth);
  // A tool: where it is now (its surface has no edges; round-off is the secondary side's).
  if (tool_) pose_ = tool_pose_ ? tool_pose_(in.time) : ToolPose{};
  const double edge_tolerance =
      0.01 * mean_edge_length(tool_ ? secondary_ : main_, in.x, in.y, in.z);
  const double touching = 1e-10 * edge_tolerance;
  // S2S points meet the other surface cell by cell (mortar.hpp), but for tied and small-sliding
  // pairs, which keep the point's partner and place on it.
  const bool by_cells = !settings_.node_to_surface && !settings_.tied && !settings_.small_sliding;
  const double facing_cos = std::cos(settings_.edge_angle * kPi / 180.0);
  // Positions, areas and normals of the points, the boxes of their cells (S2S), and the facets
  // near each (static_contact_points.cpp).
  const PointGeometry geometry = locate_points(in, by_cells);
  const std::vector<Vec3>& own_normal = geometry.own_normal;
  const std::vector<Vec3>& node_area = geometry.node_area;
  const std::vector<double>& cell_reach = geometry.cell_reach;
  const CandidateList candidates = candidate_facets(in, geometry, by_cells, reach, edge_tolerance);
  const CoverFacets cover{main_.facets, main_active_, main_twin_, in.x, in.y, in.z, main_.parent};
  const TargetFacets target{main_.facets, main_sharp_, main_active_, main_depth_,
                            main_twin_,   main_free_,  main_gap_,    main_min_edge_,
                            in.x,         in.y,        in.z};
  PartnerRules rules;
  rules.point_depth = settings_.depth;
  rules.depth_above = search;
  rules.edge_tolerance = edge_tolerance;
  rules.smooth_reach = std::tan(settings_.edge_angle * kPi / 180.0);
  const double kn_default = settings_.penalty;
  const double kt = settings_.stick_slope > 0.0 ? settings_.stick_slope : kn_default;
  // The tangential law between two parts: the last covering pair's (Radioss /FRICTION), else
  // the contact's.
  auto law_between = [this](std::int64_t a, std::int64_t b) -> const TangentialLaw& {
    const auto& pairs = settings_.pair_frictions;
    for (auto it = pairs.rbegin(); it != pairs.rend(); ++it)
      if (covers_pair(it->parts1, it->parts2, a, b)) return it->law;
    return settings_.tangential_law;
  };
  std::vector<StaticContactElement> slot(np);  // small: weights and a 3 x 3 tangent
  std::vector<std::uint8_t> active(np, 0), slipping(np, 0), stabilized(np, 0);
  // A cell's normal law point by point (mortar.hpp, CellSample). Adhesion keeps the cell's mean
  // gap: its zone's bond is a history of the cell.
  const bool pointwise = by_cells && !settings_.adhesion;
  const auto count = static_cast<std::int64_t>(np);
#pragma omp parallel for schedule(dynamic, 64)
  for (std::int64_t ip = 0; ip < count; ++ip) {
    const auto p = static_cast<std::size_t>(ip);
    // Each thread's buffers for a cell's samples (kept from point to point).
    thread_local std::vector<CellSample> samples;
    thread_local std::vector<ContactWeights> sample_weights;
    thread_local std::vector<double> sample_gaps;
    StaticContactPoint& out = points_[p];
    History& h = trial_[p];
    const History& c = committed_[p];
    h = History{};
    h.initial_offset = c.initial_offset;
    if (!released_.empty() && released_[p]) continue;
    const Vec3 x = out.position;
    std::optional<CellOverlap> cell;
    // The partner: fixed for tied pairs and small sliding once found, else searched.
    std::int32_t facet = -1;
    double xi = 0.0, eta = 0.0;
    Vec3 normal, q;
    const bool fixed = (settings_.tied || settings_.small_sliding) && c.facet >= 0;
    const std::array<std::int32_t, 4> own =
        out.node >= 0 ? std::array<std::int32_t, 4>{out.node, out.node, out.node, out.node}
                      : secondary_.facets[out.facet];
    if (tool_) {
      // The tool's closest point, within the search distance outside it and the detection depth
      // inside (infinite by default: the tool is solid).
      const ToolProjection t = project(*tool_, pose_, x);
      if (!t.found || t.gap - settings_.padding > search || t.gap < -settings_.depth) continue;
      facet = 0, normal = t.normal, q = t.closest;
    } else if (fixed) {
      facet = c.facet;
      const QuadCorners corners = quad_corners(main_.facets[facet], in.x, in.y, in.z);
      if (settings_.tied) {
        xi = c.xi, eta = c.eta;
      } else {
        const QuadProjection proj = project_onto_quad(corners, x);
        xi = proj.xi, eta = proj.eta;
      }
      double jacobian = 0.0;
      normal = quad_normal(corners, xi, eta, jacobian);
      q = quad_point(corners, xi, eta);
    } else if (!first_ && (settings_.tied || settings_.small_sliding)) {
      facet = -1;  // paired at the reference only: no partner then, none later
    } else {
      const std::span<const std::int32_t> cand =
          candidates.point_count() > 0
              ? std::span<const std::int32_t>(candidates.facets.data() + candidates.offsets[p],
                                              candidates.offsets[p + 1] - candidates.offsets[p])
              : std::span<const std::int32_t>();
      Partner partner = find_partner(target, cand, own, x, own_normal[p], rules);
      if (by_cells) {
        // The cell over the facets it faces, when its partner faces it within alpha_edge; else
        // (its point misses the other surface, or meets a wall) the nearest facet within the
        // cell's reach that faces it, as the explicit interface does (cell_cover.cpp). Without
        // either, the point acts alone with its whole area.
        auto faces = [&](const Partner& g) {
          return g.facet >= 0 && -dot(own_normal[p], g.normal) >= facing_cos;
        };
        if (!faces(partner)) {
          PartnerRules cell_rules = rules;
          cell_rules.facing = facing_cos;
          cell_rules.edge_tolerance = std::max(edge_tolerance, cell_reach[p]);
          const Partner facing = find_partner(target, cand, own, x, own_normal[p], cell_rules);
          if (faces(facing)) partner = facing;
        }
        if (faces(partner)) {
          samples.clear();
          const CellOverlap o =
              cover_cell(own, point_cell_[p], own_normal[p] * -1.0, partner.facet, cand, cover,
                         parent_of(secondary_, out.facet), pointwise ? &samples : nullptr);
          if (!(o.area > 0.0)) continue;  // the cell lies beside the other surface
          cell = o;
        }
      }
      if (partner.facet >= 0) {
        facet = partner.facet, xi = partner.xi, eta = partner.eta, normal = partner.normal;
        q = quad_point(quad_corners(main_.facets[facet], in.x, in.y, in.z), xi, eta);
      }
    }
    if (facet < 0) continue;
    // A partner on a curved face: the face's own point there (the facet's differs by its sag).
    const FacetParent* main_face = cell ? nullptr : parent_of(main_, facet);
    if (main_face) q = surface_point(main_.facets[facet], main_face, {xi, eta}, in);
    out.paired = true;
    // A node bears with its area facing the push (as the explicit interface's node points).
    if (out.node >= 0 && settings_.node_area == StaticContactSettings::NodeArea::Facing)
      out.area = settings_.weight * std::max(0.0, -dot(node_area[p], normal));
    // A cell pushes along its own normal n, from the other surface, at its mean gap over the
    // covered part, with the area of that part.
    if (cell) {
      normal = cell->normal;
      out.area = cell->area * settings_.weight;
    }
    // A cell's pressure pushes along the slope m of the facets it covers (mortar.hpp): m is the
    // gradient of the gap along n with respect to the cell's own position, so the frozen-geometry
    // tangent of the force k g m is k m (x) m, symmetric; for a point (and a flat cover) m = n.
    const Vec3 push = cell ? cell->push : normal;
    const double distance =
        (cell ? cell_mean_gap(own, *cell, cover) : dot(x - q, normal)) - settings_.padding;
    // A cell point by point: each sample's weights (+N own, -phi partner) and distance.
    const bool by_samples = cell && pointwise;
    double least = distance;
    if (by_samples) {
      sample_weights.resize(samples.size());
      sample_gaps.resize(samples.size());
      const Vec3 origin{in.x[own[0]], in.y[own[0]], in.z[own[0]]};  // round-off, cell_mean_gap
      for (std::size_t i = 0; i < samples.size(); ++i) {
        const CellSample& sample = samples[i];
        const auto k = static_cast<std::size_t>(sample.slot);
        ContactWeights& w = sample_weights[i];
        w = ContactWeights{};
        add_shape(w, own, cell->own_parent, sample.own, 1.0);
        add_shape(w, main_.facets[cell->facet[k]], cell->target_parent[k], sample.target, -1.0);
        sample_gaps[i] = dot(weighted_point(w, in, origin), normal) - settings_.padding;
        least = std::min(least, sample_gaps[i]);
      }
    }
    if (least >= 0.0) h.initial_offset = 0.0;  // separated: the initial offset has done its job
    const double shift = h.initial_offset + (shift_.empty() ? 0.0 : shift_[p]);
    const double gap = distance + shift;
    out.least_gap = least + shift;
    // A gap within round-off of the surfaces' size is a touch (d = 0, closed below): surfaces
    // placed on each other (ADJUST, a mesh generated in contact) meet at +-ulps, and would else
    // be open or closed at random.
    const double d = gap > 0.0 && gap <= touching ? 0.0 : -gap;
    out.gap = gap;
    h.facet = facet, h.xi = xi, h.eta = eta;
    // Weights of the element: +N on the point's own nodes, -phi on the partner's.
    // A cell's: the integrals of the overlap over its area (mortar.hpp).
    ContactWeights wt;
    if (cell) {
      // A facet of a curved face: the integrals of the face's own shape functions, on its nodes.
      const double inv = 1.0 / cell->area;
      const FacetParent* own_face = cell->own_parent;
      if (own_face && own_face->curved())
        for (int a = 0; a < own_face->count; ++a)
          wt.add(own_face->nodes[a], cell->own_face[a] * inv);
      else
        for (int a = 0; a < 4; ++a) wt.add(own[a], cell->own[a] * inv);
      for (int k = 0; k < cell->count; ++k) {
        const FacetParent* face = cell->target_parent[k];
        if (face && face->curved()) {
          for (int b = 0; b < face->count; ++b)
            wt.add(face->nodes[b], -cell->target_face[k][b] * inv);
          continue;
        }
        for (int b = 0; b < 4; ++b)
          wt.add(main_.facets[cell->facet[k]][b], -cell->target[k][b] * inv);
      }
    } else if (out.node >= 0) {
      wt.add(out.node, 1.0);
    } else {
      add_shape(wt, own, parent_of(secondary_, out.facet), {point_xi_[p], point_eta_[p]}, 1.0);
    }
    if (!cell && !tool_) add_shape(wt, main_.facets[facet], main_face, {xi, eta}, -1.0);
    wt = dependents_.expand(wt);  // host nodes only
    out.weights = wt;
    out.partner = facet;
    // The point's own part: its facet's, or a node's first facet's (N2S).
    std::int64_t own_part = 0;
    if (!settings_.pair_frictions.empty()) {
      std::int32_t own_facet = out.facet;
      if (out.node >= 0 && node_facet_start_[static_cast<std::size_t>(out.node)] <
                               node_facet_start_[static_cast<std::size_t>(out.node) + 1])
        own_facet = node_facets_[static_cast<std::size_t>(
            node_facet_start_[static_cast<std::size_t>(out.node)])];
      if (own_facet >= 0) own_part = secondary_.part[static_cast<std::size_t>(own_facet)];
    }
    const TangentialLaw& law =
        settings_.pair_frictions.empty()
            ? settings_.tangential_law
            : law_between(own_part, main_.part[static_cast<std::size_t>(facet)]);
    const bool frictional = settings_.stick || !std::holds_alternative<Frictionless>(law);
    // Relative motion since the last converged state.
    Vec3 motion{};
    for (int k = 0; k < wt.count; ++k) {
      const std::int32_t n = wt.nodes[k];
      motion = motion + Vec3{in.x[n] - xc_[n], in.y[n] - yc_[n], in.z[n] - zc_[n]} * wt.weights[k];
    }
    // Against a tool: relative to its material where the point meets it.
    if (tool_) motion = motion - tool_increment(*tool_, committed_pose_, pose_, q);
    // Viscous stabilization (laws/stabilization.hpp): a spring on the motion since the last
    // converged state, also for an open point within its range, which then carries it alone.
    const ContactStabilization* damper =
        settings_.stabilization ? &*settings_.stabilization : nullptr;
    const double k_damper = damper ? damper->stiffness(gap, stabilization_factor_, in.dt) : 0.0;
    auto add_damper = [&](StaticContactElement& e) {
      if (!(k_damper > 0.0)) return;
      const Vec3 held = damper->project(motion, normal);
      e.traction = e.traction - held * k_damper;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          e.tangent[3 * i + j] += k_damper * damper->projector(normal, i, j);
      h.stabilization_work = out.area * k_damper * dot(held, motion);
    };
    // An open point is damped only against a partner that faces it (within alpha_edge, as a
    // cell's cover): the nearest facet of a point beside the other surface may be a side wall,
    // found one iteration and lost the next. A node (N2S) faces it when one of its facets does.
    auto facing_partner = [&]() {
      if (cell) return true;
      if (out.node < 0) return -dot(own_normal[p], normal) >= facing_cos;
      const auto n = static_cast<std::size_t>(out.node);
      for (std::int32_t k = node_facet_start_[n]; k < node_facet_start_[n + 1]; ++k) {
        double jacobian = 0.0;
        const Vec3 facet_normal = quad_normal(
            quad_corners(secondary_.facets[node_facets_[k]], in.x, in.y, in.z), 0.0, 0.0, jacobian);
        if (-dot(facet_normal, normal) >= facing_cos) return true;
      }
      return false;
    };
    auto damper_alone = [&]() {
      if (!(k_damper > 0.0) || !facing_partner()) return;
      StaticContactElement& e = slot[p];
      e = StaticContactElement{};
      e.count = wt.count, e.nodes = wt.nodes, e.weights = wt.weights, e.area = out.area;
      e.push = normal;
      add_damper(e);
      stabilized[p] = 1;
    };
    double pressure = 0.0, kn = 0.0, energy = 0.0;
    Vec3 traction{};
    double C[3][3] = {};
    const double P[3][3] = {{1 - normal.x * normal.x, -normal.x * normal.y, -normal.x * normal.z},
                            {-normal.y * normal.x, 1 - normal.y * normal.y, -normal.y * normal.z},
                            {-normal.z * normal.x, -normal.z * normal.y, 1 - normal.z * normal.z}};
    if (settings_.tied) {
      h.offset = c.facet < 0 ? x - q : c.offset;  // formed at the reference configuration
      pressure = kn_default * d;
      kn = kn_default;
      traction = tangential(h.offset - (x - q), normal) * kt;
      energy = 0.5 * kn * d * d + 0.5 * dot(traction, traction) / kt;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) C[i][j] = kn * normal[i] * normal[j] + kt * P[i][j];
    } else {
      const double reach_open = reach_at_clearance(settings_.normal);
      const Adhesion* bond = settings_.adhesion ? &*settings_.adhesion : nullptr;
      const bool adhesive = bond && c.in_contact && c.adhered && d < 0.0 && -d <= bond->zone();
      // Open beyond the law's reach. A point exactly touching (d = 0) is closed: it has no
      // pressure yet but its spring, so that bodies that only touch are not left floating.
      auto open = [reach_open](double depth) {
        return reach_open > 0.0 ? depth < -reach_open : depth < 0.0;
      };
      NormalResponse r;
      if (by_samples) {
        // Each sample by its own gap: the cell's normal spring (StaticContactElement) over the
        // nodes of its mean weights, which hold every sample's; the cell's pressure, stiffness
        // and energy are the samples' means, for friction and output.
        StaticContactElement& e = slot[p];
        const auto n = static_cast<std::size_t>(wt.count);
        e.spring_force.assign(n, 0.0);
        e.spring_stiffness.assign(n * n, 0.0);
        double sum_a = 0.0, sum_p = 0.0, sum_k = 0.0, sum_e = 0.0;
        std::array<std::size_t, ContactWeights::kCapacity> local{};
        for (std::size_t i = 0; i < samples.size(); ++i) {
          const double g = sample_gaps[i] + shift;
          const double ds = g > 0.0 && g <= touching ? 0.0 : -g;
          if (open(ds)) continue;
          const NormalResponse ri = scaled(abut::evaluate(settings_.normal, ds, settings_.penalty),
                                           settings_.normal_in_time.at(in.time));
          const double a = samples[i].area;
          sum_a += a, sum_p += a * ri.pressure, sum_k += a * ri.stiffness, sum_e += a * ri.energy;
          const ContactWeights w = dependents_.expand(sample_weights[i]);
          for (int k = 0; k < w.count; ++k) {
            local[k] = static_cast<std::size_t>(
                std::find(wt.nodes.begin(), wt.nodes.begin() + wt.count, w.nodes[k]) -
                wt.nodes.begin());
            assert(local[k] < n);  // the mean weights hold the same faces' nodes
          }
          const double f = a * settings_.weight * ri.pressure;
          const double s = a * settings_.weight * ri.stiffness;
          for (int k = 0; k < w.count; ++k) {
            e.spring_force[local[k]] += f * w.weights[k];
            for (int l = 0; l < w.count; ++l)
              e.spring_stiffness[local[k] * n + local[l]] += s * w.weights[k] * w.weights[l];
          }
        }
        if (!(sum_a > 0.0)) {  // every sample open
          damper_alone();
          continue;
        }
        const double inv = 1.0 / cell->area;
        r = {sum_p * inv, sum_k * inv, sum_e * inv};
      } else if (adhesive) {
        h.adhered = true;
        const double slope = bond->max_stress / bond->zone();
        r = {bond->pressure(-d), slope, 0.5 * slope * d * d};
      } else {
        if (open(d)) {
          damper_alone();
          continue;
        }
        h.adhered = bond && (d > 0.0 || (c.adhered && d >= 0.0));
        r = scaled(abut::evaluate(settings_.normal, d, settings_.penalty),
                   settings_.normal_in_time.at(in.time));
      }
      pressure = r.pressure, kn = r.stiffness, energy = r.energy;
      // A cell integrated point by point carries its normal spring apart (above).
      if (!by_samples)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) C[i][j] = kn * push[i] * push[j];
      // A curved tool's push turns as the point moves over it: t = p n(x) adds -p dn/dx.
      if (tool_) {
        const std::array<double, 9> turn = normal_gradient(*tool_, pose_, x);
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) C[i][j] -= pressure * turn[3 * i + j];
      }
      const Vec3 slip = tangential(motion, normal);
      if (adhesive || frictional) out.slip = slip;
      if (adhesive) {
        // The zone's viscosity replaces friction: t = -c slip / dt; its work over the increment,
        // t . slip, counts as friction work (as in explicit steps, enforcement.cpp).
        if (in.dt > 0.0) {
          const double viscous =
              bond->viscous_factor * bond->fluid_viscosity / bond->zone() / in.dt;
          traction = slip * -viscous;
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) C[i][j] += viscous * P[i][j];
          h.slip_work = out.area * viscous * dot(slip, slip);
        }
      } else if (frictional) {
        const Vec3 t0 = c.in_contact ? tangential(c.traction, normal) : Vec3{};
        // k_t(d) and its slope (Metafor PEN_TANGENT GD, TM; laws/dependency.hpp).
        const double kt_p = kt * settings_.stick_slope_factor.factor(d, in.time);
        const double dkt = kt * settings_.stick_slope_factor.slope(d, in.time);
        const Vec3 trial = t0 - slip * kt_p;
        // Per unit area: the normal "force" is the pressure on an area of 1.
        // The sliding speed: the slip over the increment (in.dt, 0: no rate).
        const double speed = in.dt > 0.0 ? norm(slip) / in.dt : 0.0;
        const SlipState state{std::max(pressure, 0.0), 1.0, speed, in.time, x};
        const SlipLimits limits = slip_limits(law, state);
        const double hold = c.in_contact && c.sliding ? limits.slide : limits.stick;
        const double size = norm(trial);
        if (!(kt_p > 0.0)) {
          // A factor <= 0: no tangential spring (as the explicit interface).
        } else if (settings_.stick || size <= hold) {
          traction = trial;
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) C[i][j] += kt_p * P[i][j] - dkt * slip[i] * normal[j];
        } else {
          const double limit = limits.slide;
          const double slope = slide_slope(law, state);
          // d limit / d u through the sliding speed: (dL/dV) (1/dt) s^, s^ the slip's direction.
          const double slip_size = norm(slip);
          const Vec3 rate = slip_size > 0.0 && in.dt > 0.0
                                ? slip * (slide_rate_slope(law, state) / (in.dt * slip_size))
                                : Vec3{};
          const Vec3 th = trial / size;
          traction = th * limit;
          slipping[p] = 1;
          h.sliding = true;
          const double s = limit * kt_p / size;
          // (I - th th) s: the projection of the slip off the trial direction (the dk_t/dd term).
          const Vec3 s_off = slip - th * dot(th, slip);
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
              double tt = 0.0;  // ((I - th th) P)_ij
              for (int k = 0; k < 3; ++k) tt += ((i == k) - th[i] * th[k]) * P[k][j];
              C[i][j] += slope * kn * th[i] * normal[j] - th[i] * rate[j] + s * tt -
                         (limit / size) * dkt * s_off[i] * normal[j];
            }
          h.slip_work = out.area * limit * (size - limit) / kt_p;  // |t| x plastic slip
        }
        if (kt_p > 0.0) energy += 0.5 * dot(traction, traction) / kt_p;
      }
    }
    h.in_contact = true;
    h.traction = traction;
    h.total_slip = (c.in_contact ? c.total_slip : Vec3{}) + tangential(motion, normal);
    out.total_slip = h.total_slip;
    out.active = true;
    out.slipping = slipping[p] != 0;
    out.pressure = pressure;
    out.traction = traction;
    out.energy = out.area * energy;
    active[p] = 1;
    out.normal = normal;
    out.push = push;
    StaticContactElement& e = slot[p];
    e.count = wt.count;
    e.nodes = wt.nodes;
    e.weights = wt.weights;
    e.area = out.area;
    e.traction = (by_samples ? Vec3{} : out.push * pressure) + traction;
    e.push = push;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) e.tangent[3 * i + j] = C[i][j];
    add_damper(e);
  }
  elements_.clear();
  symmetric_ = true;
  for (std::size_t p = 0; p < np; ++p) {
    if (!active[p]) {
      trial_[p].facet = settings_.tied || settings_.small_sliding ? trial_[p].facet : -1;
      if (!stabilized[p]) continue;
    }
    elements_.push_back(std::move(slot[p]));
    if (slipping[p]) symmetric_ = false;
  }
  // Tied and small-sliding partners found at the first evaluation stay (also when open).
  if (settings_.tied || settings_.small_sliding)
    for (std::size_t p = 0; p < np; ++p)
      if (committed_[p].facet >= 0 && trial_[p].facet < 0) trial_[p] = committed_[p];
  xe_.assign(in.x.begin(), in.x.end());
  ye_.assign(in.y.begin(), in.y.end());
  ze_.assign(in.z.begin(), in.z.end());
}

void StaticContact::commit() {
  for (const History& h : trial_) {
    friction_work_ += h.slip_work;
    stabilization_work_ += h.stabilization_work;
  }
  committed_ = trial_;
  committed_pose_ = pose_;
  xc_ = xe_, yc_ = ye_, zc_ = ze_;
  first_ = false;
}

void StaticContactElement::add_forces(double* f) const {
  for (int a = 0; a < count; ++a) {
    const auto ua = static_cast<std::size_t>(a);
    const Vec3 fa =
        traction * (area * weights[ua]) + (spring_force.empty() ? Vec3{} : push * spring_force[ua]);
    for (int i = 0; i < 3; ++i) f[3 * a + i] += fa[i];
  }
}

void StaticContactElement::stiffness(double* k) const {
  const int n = 3 * count;
  for (int a = 0; a < count; ++a)
    for (int b = 0; b < count; ++b) {
      const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
      const double s = area * weights[ua] * weights[ub];
      const double spring = spring_stiffness.empty()
                                ? 0.0
                                : spring_stiffness[ua * static_cast<std::size_t>(count) + ub];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          k[(3 * a + i) * n + 3 * b + j] = s * tangent[3 * i + j] + spring * push[i] * push[j];
    }
}

Vec3 StaticContact::total_force() const {
  Vec3 f{};
  for (const StaticContactPoint& p : points_)
    if (p.active) f = f + (p.push * p.pressure + p.traction) * p.area;
  return f;
}

double StaticContact::energy() const {
  double e = 0.0;
  for (const StaticContactPoint& p : points_) e += p.energy;
  return e;
}

}  // namespace abut
