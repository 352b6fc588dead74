// Contact of surface-1 nodes with an analytic rigid tool (tool_contact.hpp): each node as a node
// point of the interface (enforcement.cpp) against a partner whose gap, normal and velocity come
// from the tool's shape (analytic_tool.cpp) instead of a facet.
#include "abut/contact/tool_contact.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <variant>

#include "abut/contact/laws/stick_slip.hpp"
#include "abut/contact/quad.hpp"

namespace abut {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
}

void ToolContact::validate() const {
  const ContactSettings& s = settings_;
  auto refuse = [](const char* setting, const std::string& what) {
    throw ContactSetupError(setting, what + " with an analytic tool is not supported yet");
  };
  if (s.freeze) refuse("freeze", "law FREEZE");
  if (s.stick_stress) refuse("stick_stress", "sticking up to a failure stress");
  if (s.adhesion) refuse("adhesion", "adhesion");
  if (s.thermal.any()) refuse("thermal", "heat exchange");
  if (s.wear_rate1 || s.wear_rate2) refuse("wear", "wear");
  if (s.initial_region || s.moving_region) refuse("regions", "a contact region");
  if (s.initial_penetration != InitialPenetration::Offset || s.initial_offset != 0.0 ||
      s.initial_max)
    refuse("initial_offset",
           "an initial-penetration option (an offset, a maximum, or another treatment)");
  if (s.clearance) refuse("clearance", "a clearance");
  if (s.edge_tolerance != 0.0) refuse("edge_tolerance", "an edge tolerance");
  if (s.edges.selection != EdgeSelection::None) refuse("edges", "edge-to-edge contact");
  if (s.stiffness.rule != StiffnessRule::FacetPenalty)
    refuse("stiffness", "a Radioss stiffness rule (the tool has no elements)");
  if (!s.pair_scales.empty()) refuse("pair_scales", "a pair scale factor");
  if (!s.pair_frictions.empty()) refuse("pair_frictions", "a per-part-pair friction");
  if (s.gaps.mesh_fraction || s.gaps.skip_close || s.gaps.zero_at_free_edges ||
      std::isfinite(s.gaps.max_main) || s.gaps.border != GapSettings::Border::Cut)
    refuse("gaps",
           "a variable gap (a mesh-size cap, skipping initially close points, no gap at free "
           "edges, a main-side maximum or a shell border shape)");
  if (s.sense == ContactSense::Negative)
    refuse("normal_law", "a negative contact sense (choose the tool's inside instead)");
  if (std::holds_alternative<ExponentialOverclosure>(s.normal_law))
    refuse("normal_law", "the exponential pressure-overclosure law");
  const AnalyticTool& t = tool_;
  if (!(std::abs(norm(t.axis) - 1.0) < 1e-12))
    throw ContactSetupError("tool", "the tool's normal or axis must be a unit vector");
  if (t.shape != ToolShape::Plane && !(t.radius > 0.0))
    throw ContactSetupError("tool", "the tool's radius must be > 0");
  if (t.shape == ToolShape::Cylinder && !(t.length > 0.0))
    throw ContactSetupError("tool", "the cylinder's length must be > 0");
}

ToolContact::ToolContact(ContactSettings settings, AnalyticTool tool,
                         const ContactSurface& surface1, std::span<const double> node_mass,
                         const ContactInput& initial, std::span<const std::int32_t> secondary_nodes)
    : settings_(std::move(settings)), tool_(tool), facets_(surface1.facets), twin_(surface1.twin) {
  validate();
  const std::size_t n = node_mass.size();
  mass_.assign(node_mass.begin(), node_mass.end());
  node_facet_start_.assign(n + 1, 0);
  for (const auto& f : facets_)
    for (int a = 0; a < 4; ++a)
      if (a < 3 || f[3] != f[2]) ++node_facet_start_[static_cast<std::size_t>(f[a]) + 1];
  for (std::size_t i = 0; i < n; ++i) node_facet_start_[i + 1] += node_facet_start_[i];
  node_facets_.resize(static_cast<std::size_t>(node_facet_start_[n]));
  std::vector<std::int32_t> fill(node_facet_start_.begin(), node_facet_start_.end() - 1);
  for (std::size_t k = 0; k < facets_.size(); ++k)
    for (int a = 0; a < 4; ++a) {
      const auto& f = facets_[k];
      if (a < 3 || f[3] != f[2])
        node_facets_[static_cast<std::size_t>(fill[static_cast<std::size_t>(f[a])]++)] =
            static_cast<std::int32_t>(k);
    }
  for (std::size_t i = 0; i < n; ++i)
    if (node_facet_start_[i + 1] > node_facet_start_[i]) nodes_.push_back(static_cast<int>(i));
  if (secondary_nodes.empty()) {
    points_ = nodes_;
  } else {
    points_.assign(secondary_nodes.begin(), secondary_nodes.end());
    for (const std::int32_t node : points_)
      if (node < 0 || static_cast<std::size_t>(node) >= n ||
          node_facet_start_[static_cast<std::size_t>(node) + 1] ==
              node_facet_start_[static_cast<std::size_t>(node)])
        throw ContactSetupError("secondary_nodes", "a secondary node is on no facet of surface 1");
  }
  const std::size_t np = points_.size();
  point_pfac_.assign(np, 0.0);
  point_gap_.assign(np, 0.0);
  point_area_.assign(np, 0.0);
  pfac_min_ = np > 0 ? kInfinity : 0.0;
  for (std::size_t p = 0; p < np; ++p) {
    const auto node = static_cast<std::size_t>(points_[p]);
    // As a node point of the interface (init_point): the stiffest facet around it, the
    // largest shell gap, a quarter of each facet's area (one side of a shell).
    for (std::int32_t k = node_facet_start_[node]; k < node_facet_start_[node + 1]; ++k) {
      const auto f = static_cast<std::size_t>(node_facets_[static_cast<std::size_t>(k)]);
      point_pfac_[p] = std::max(point_pfac_[p], surface1.penalty[f]);
      if (twin_[f] >= 0) {
        point_gap_[p] = std::max(point_gap_[p], shell_gap(settings_.gaps, surface1.thickness[f]));
        if (twin_[f] < static_cast<std::int32_t>(f)) continue;
      }
      const QuadCorners c = quad_corners(facets_[f], initial.x, initial.y, initial.z);
      point_area_[p] += 0.125 * norm(cross(c[2] - c[0], c[3] - c[1]));
    }
    point_gap_[p] = std::min(point_gap_[p], settings_.gaps.max_secondary) + settings_.gaps.padding;
    pfac_min_ = std::min(pfac_min_, point_pfac_[p]);
    pfac_max_ = std::max(pfac_max_, point_pfac_[p]);
    if (mass_[node] > 0.0)
      initial_omega2_ = std::max(initial_omega2_, point_pfac_[p] * point_area_[p] / mass_[node]);
  }
  for (auto* v : {&htx_, &hty_, &htz_, &slip_, &fx_, &fy_, &fz_, &dfx_, &dfy_, &dfz_, &energy_})
    v->assign(np, 0.0);
  hit_.assign(np, 0);
  pressure_.assign(n, 0.0);
}

double ToolContact::spring_step(double omega2) const {
  if (!(omega2 > 0.0)) return kInfinity;
  const double xi = settings_.damping;
  return 2.0 / std::sqrt(omega2) * (std::sqrt(1.0 + xi * xi) - xi);
}

double ToolContact::initial_stable_step() const {
  return spring_step(initial_omega2_ * std::max(settings_.normal_in_time.at(0.0), 1.0));
}

void ToolContact::mark_secondary_nodes_in_contact(std::span<std::uint8_t> touched) const {
  for (std::size_t p = 0; p < points_.size(); ++p)
    if (hit_[p]) touched[static_cast<std::size_t>(points_[p])] = 1;
}

void ToolContact::apply(const ContactInput& in, const ToolPose& pose, ContactForces& out) {
  const ContactSettings& s = settings_;
  const std::size_t np = points_.size();
  auto position = [&in](std::size_t i) { return Vec3{in.x[i], in.y[i], in.z[i]}; };
  auto velocity = [&in](std::size_t i) {
    return in.vx.empty() ? Vec3{} : Vec3{in.vx[i], in.vy[i], in.vz[i]};
  };
  // Last step's forces over the tool's motion since (the mean of the forces at both ends: the
  // first half now, the second below), and the second half of last step's damping work with the
  // relative velocity of the step just taken (the interface's book_damping).
  double tool_work = 0.0, damping_power = 0.0;
  for (std::size_t p = 0; p < np; ++p) {
    if (!hit_[p]) continue;
    const auto i = static_cast<std::size_t>(points_[p]);
    const Vec3 x = position(i);
    if (posed_)
      tool_work += dot(Vec3{fx_[p], fy_[p], fz_[p]}, tool_increment(tool_, last_pose_, pose, x));
    damping_power +=
        dot(Vec3{dfx_[p], dfy_[p], dfz_[p]}, velocity(i) - tool_velocity(tool_, pose, x));
  }
  stats_.damping_energy -= 0.5 * damping_power * in.dt;
  const ToolPose from = last_pose_;
  const bool moved = posed_;
  last_pose_ = pose;
  posed_ = true;
  stats_.force = {};
  stats_.normal_force = stats_.tangential_force = stats_.elastic_energy = stats_.max_penetration =
      0.0;
  stats_.active_points = 0;
  stats_.stable_step = kInfinity;
  const double spring_factor = std::max(s.normal_in_time.at(in.time), 1.0);
  stats_.approach_step = spring_step(initial_omega2_ * spring_factor);
  for (const std::int32_t i : nodes_) pressure_[static_cast<std::size_t>(i)] = 0.0;
  const bool outside_window = !enabled_ || in.time < s.begin_time || in.time > s.end_time;
  const bool bilateral = s.sense == ContactSense::Bilateral;
  const double depth = s.detection_depth.value_or(kInfinity);
  double omega2_max = 0.0;
  bool gaps_seen = false;
  for (std::size_t p = 0; p < np; ++p) {
    const double held = hit_[p] ? energy_[p] : 0.0;
    const Vec3 last_force{fx_[p], fy_[p], fz_[p]};
    const bool was_hit = hit_[p] != 0;
    hit_[p] = 0;
    fx_[p] = fy_[p] = fz_[p] = dfx_[p] = dfy_[p] = dfz_[p] = energy_[p] = 0.0;
    auto forget = [&] { htx_[p] = hty_[p] = htz_[p] = slip_[p] = 0.0; };
    // Springs that let go while pressed release what they held, less last force's work on the
    // way (as the interface's held_now).
    const auto i = static_cast<std::size_t>(points_[p]);
    const Vec3 x = position(i);
    auto release = [&] {
      if (!was_hit) return;
      const Vec3 v_rel = velocity(i) - tool_velocity(tool_, pose, x);
      const double e = held - dot(last_force, v_rel) * in.dt;
      if (e > 0.0) stats_.released_energy += e;
    };
    if (outside_window) {
      if (was_hit) stats_.released_energy += held;
      forget();
      continue;
    }
    const ToolProjection h = project(tool_, pose, x);
    const double gap = h.gap - point_gap_[p];
    if (!h.found || gap < -depth) {  // beyond the detection depth or off the tool
      release();
      forget();
      continue;
    }
    const double penetration = -gap;
    if (!(penetration > 0.0) && !bilateral) {  // separated: the forces fell to zero on the way
      forget();
      continue;
    }
    // The node's area facing the tool: its vector area (a quarter of each facet's) projected on
    // the tool's normal; a shell's node touches with either side.
    Vec3 vector_area;
    bool two_sided = false;
    for (std::int32_t k = node_facet_start_[i]; k < node_facet_start_[i + 1]; ++k) {
      const auto f = static_cast<std::size_t>(node_facets_[static_cast<std::size_t>(k)]);
      if (twin_[f] >= 0) {
        two_sided = true;
        if (twin_[f] < static_cast<std::int32_t>(f)) continue;
      }
      const QuadCorners c = quad_corners(facets_[f], in.x, in.y, in.z);
      vector_area += cross(c[2] - c[0], c[3] - c[1]) * 0.125;
    }
    const double area = two_sided ? std::abs(dot(vector_area, h.normal))
                                  : std::max(-dot(vector_area, h.normal), 0.0);
    if (!(area > 0.0)) {
      release();
      forget();
      continue;
    }
    const Vec3& normal = h.normal;
    const double k = point_pfac_[p] * area;
    const NormalResponse response =
        scaled(evaluate(s.normal_law, penetration, point_pfac_[p]), s.normal_in_time.at(in.time));
    const double k_n = response.stiffness * area;
    const double m = mass_[i];  // the tool's mass is infinite: the reduced mass is the node's
    auto damping_of = [&](double spring) { return 2.0 * s.damping * std::sqrt(spring * m); };
    const double c = damping_of(k_n);
    const Vec3 v_rel = velocity(i) - tool_velocity(tool_, pose, x);
    const double v_n = dot(v_rel, normal);
    const double elastic = response.pressure * area;
    double fn = elastic - c * v_n;
    if (!bilateral) fn = std::max(fn, 0.0);
    const Vec3 v_t = v_rel - normal * v_n;
    const double slip_speed = norm(v_t);
    const double k_t = (s.tangential_penalty ? *s.tangential_penalty * area : k) *
                       s.tangential_penalty_factor.factor(penetration, in.time);
    const Vec3 previous{htx_[p], hty_[p], htz_[p]};
    Vec3 ft, spring;
    double slip = 0.0, slip_work = 0.0;
    const SlipLimits limits =
        slip_limits(s.tangential_law, {std::max(fn, 0.0), area, slip_speed, in.time, x});
    if (k_t > 0.0 && (limits.stick > 0.0 || limits.slide > 0.0)) {
      const StickSlipResult t =
          stick_slip(previous, slip_[p], {normal, v_t, in.dt, k_t, damping_of(k_t)}, limits);
      slip = t.slip;
      ft = t.force;
      spring = t.spring;
      slip_work = t.slip_work;
    }
    if (s.friction_filter.kind != FrictionFilter::Kind::None) {  // Radioss Ifiltr
      const double a = s.friction_filter.alpha(in.dt);
      const Vec3 filtered = (previous - normal * dot(previous, normal)) * (1.0 - a);
      ft = ft * a + filtered;
      spring = spring * a + filtered;
    }
    htx_[p] = spring.x;
    hty_[p] = spring.y;
    htz_[p] = spring.z;
    slip_[p] = slip;
    const Vec3 force = normal * fn + ft;
    const Vec3 damping = normal * (fn - elastic) + ft - spring;
    hit_[p] = 1;
    fx_[p] = force.x;
    fy_[p] = force.y;
    fz_[p] = force.z;
    dfx_[p] = damping.x;
    dfy_[p] = damping.y;
    dfz_[p] = damping.z;
    energy_[p] = response.energy * area + (k_t > 0.0 ? 0.5 * dot(spring, spring) / k_t : 0.0);
    out.add(points_[p], force);
    pressure_[i] += fn / point_area_[p];  // over the tributary area, as the interface
    stats_.force += force;
    stats_.normal_force += fn;
    stats_.tangential_force += norm(ft);
    stats_.elastic_energy += energy_[p];
    stats_.friction_energy += slip_work;
    stats_.max_penetration = std::max(stats_.max_penetration, penetration);
    if (!gaps_seen || point_gap_[p] < stats_.gap_min) stats_.gap_min = point_gap_[p];
    if (!gaps_seen || point_gap_[p] > stats_.gap_max) stats_.gap_max = point_gap_[p];
    gaps_seen = true;
    ++stats_.active_points;
    if (m > 0.0) omega2_max = std::max(omega2_max, std::max(k_n, k_t) / m);
  }
  // This step's forces over the tool's motion since the last apply: the second half of the mean.
  for (std::size_t p = 0; p < np && moved; ++p)
    if (hit_[p])
      tool_work +=
          dot(Vec3{fx_[p], fy_[p], fz_[p]},
              tool_increment(tool_, from, pose, position(static_cast<std::size_t>(points_[p]))));
  stats_.tool_work += 0.5 * tool_work;
  // This step's damping forces with the velocity of the step before (the first half).
  damping_power = 0.0;
  for (std::size_t p = 0; p < np; ++p)
    if (hit_[p]) {
      const auto i = static_cast<std::size_t>(points_[p]);
      damping_power += dot(Vec3{dfx_[p], dfy_[p], dfz_[p]},
                           velocity(i) - tool_velocity(tool_, pose, position(i)));
    }
  stats_.damping_energy -= 0.5 * damping_power * in.dt;
  if (omega2_max > 0.0) stats_.stable_step = spring_step(omega2_max);
}

void ToolContact::archive(StateArchive& a) {
  a.fixed(htx_, hty_, htz_, slip_, fx_, fy_, fz_, dfx_, dfy_, dfz_, energy_, hit_, pressure_);
  a.values(last_pose_, posed_, stats_);
}

}  // namespace abut
