// Enforcement at one contact point: its partner, the normal law with damping, the tangential
// law, ties (sticking contact, FREEZE) and adhesion. Writes the point's own result slots only, so
// points are evaluated in parallel.
#include <algorithm>
#include <cmath>
#include <limits>

#include "abut/contact/laws/stick_slip.hpp"
#include "abut/contact/quad.hpp"
#include "interface_impl.hpp"

namespace abut {
Vec3 InterfaceImpl::velocity_at(const std::array<std::int32_t, 4>& nodes,
                                const std::array<double, 4>& shape, const ContactInput& in) {
  Vec3 v;
  if (in.vx.empty()) return v;  // at construction
  for (int a = 0; a < 4; ++a)
    v += Vec3{in.vx[nodes[a]], in.vy[nodes[a]], in.vz[nodes[a]]} * shape[a];
  return v;
}

// The point's share of each node's mass: m_i * N_i * (its area / the node's area), so that the
// shares of all points add up to the nodal masses; on the other side a point may cover more than
// a node's area: never more than the node.
double InterfaceImpl::mass_share(const Side& side, const std::array<std::int32_t, 4>& nodes,
                                 const std::array<double, 4>& shape, double area) const {
  double m = 0.0;
  for (int a = 0; a < 4; ++a)
    if (side.node_area[nodes[a]] > 0.0)
      m += mass_[nodes[a]] * std::min(1.0, shape[a] * area / side.node_area[nodes[a]]);
  return m;
}

double InterfaceImpl::reduced_mass(double m1, double m2) {
  return m1 + m2 > 0.0 ? m1 * m2 / (m1 + m2) : 0.0;
}

InterfaceImpl::PointFrame InterfaceImpl::frame(const Side& side, std::size_t p,
                                               const ContactInput& in) const {
  PointFrame r;
  const std::int32_t node = side.point_node[p];
  r.nodes = side.point_nodes(p);
  r.shape = quad_shape(side.point_xi[p], side.point_eta[p]);
  r.v = velocity_at(r.nodes, r.shape, in);
  if (node < 0) {
    const std::int32_t f = side.point_facet[p];
    const QuadCorners c = quad_corners(r.nodes, in.x, in.y, in.z);
    double jacobian = 0.0;
    r.normal = quad_normal(c, side.point_xi[p], side.point_eta[p], jacobian);
    r.x = quad_point(c, side.point_xi[p], side.point_eta[p]);
    r.area = side.point_weight[p] * jacobian;
    r.active = side.active[f] != 0;
    return r;
  }
  // A node: the area-weighted normal of its active facets; inactive when it has none. A shell's
  // node counts one side of each shell and has no normal: it may touch with either side.
  r.x = {in.x[node], in.y[node], in.z[node]};
  Vec3 n;
  for (std::int32_t k = side.node_facet_start[node]; k < side.node_facet_start[node + 1]; ++k) {
    const std::int32_t f = side.node_facets[k];
    if (!side.active[f]) continue;
    r.active = true;
    const std::int32_t twin = side.surface.twin[f];
    if (twin >= 0) {
      r.two_sided = true;
      if (twin < f) continue;  // the second side of a shell already counted
    }
    const QuadCorners c = quad_corners(side.surface.facets[f], in.x, in.y, in.z);
    n += cross(c[2] - c[0], c[3] - c[1]);
  }
  const double length = norm(n);
  r.normal = length > 0.0 && !r.two_sided ? n / length : Vec3{};
  r.area = side.node_area[node];
  if (!r.active && side.node_free[node]) {  // a free point mass, touching with its whole area
    r.active = r.free = r.two_sided = true;
    r.normal = {};
  }
  r.vector_area =
      n * 0.125;  // each cross product of the diagonals is twice the facet's area vector
  return r;
}

TargetFacets InterfaceImpl::target_facets(const Side& target, std::span<const double> depth,
                                          const ContactInput& in, bool banded) const {
  return {target.surface.facets,
          target.sharp,
          target.active,
          depth,
          target.surface.twin,
          target.free_edges,
          target.facet_gap,
          target.facet_min_edge,
          in.x,
          in.y,
          in.z,
          banded ? std::span<const FacetBand>(target.bands) : std::span<const FacetBand>(),
          target.max_facet_gap};
}

PartnerRules InterfaceImpl::partner_rules(const Side& own, std::size_t p) const {
  PartnerRules rules;
  rules.depth_above = settings_.adhesion ? settings_.adhesion->zone() : 0.0;
  rules.point_gap = own.point_gap[p];
  rules.point_min_edge = own.point_min_edge[p];
  rules.mesh_fraction =
      settings_.gaps.mesh_fraction.value_or(std::numeric_limits<double>::infinity());
  // Radioss: Ishape 1 is not available with Igap 3 and is reset to 2 (seed 004, comment 4).
  rules.border =
      settings_.gaps.mesh_fraction && settings_.gaps.border == GapSettings::Border::Square
          ? GapSettings::Border::Round
          : settings_.gaps.border;
  if (!x0_.empty() && self_contact()) {  // Igap 2: where the point was at the start
    const auto nodes = own.point_nodes(p);
    const auto n = quad_shape(own.point_xi[p], own.point_eta[p]);
    for (int a = 0; a < 4; ++a)
      rules.initial_point += Vec3{x0_[nodes[a]], y0_[nodes[a]], z0_[nodes[a]]} * n[a];
    rules.x0 = x0_;
    rules.y0 = y0_;
    rules.z0 = z0_;
  }
  rules.from_behind = settings_.sense == ContactSense::Negative;
  rules.edge_tolerance = settings_.edge_tolerance;
  rules.smooth_reach = smooth_reach_;
  return rules;
}

Partner InterfaceImpl::partner_of(const Pass& pass, std::size_t p, const PointFrame& f,
                                  const ContactInput& in, std::int32_t previous) const {
  const Side& own = sides_[pass.own];
  const Side& target = sides_[pass.target];
  // The regular search: within the facets' own detection depth, among the candidates, whose boxes
  // of this step are at hand while the interface applies (not yet in initial_state).
  const TargetFacets facets = target_facets(target, target.depth, in, bands_current_);
  PartnerRules rules = partner_rules(own, p);
  const auto first = pass.candidates.offsets[p], last = pass.candidates.offsets[p + 1];
  const PartnerHint hint{previous, pass.hit_xi[p], pass.hit_eta[p]};
  const Partner h = find_partner(facets, {pass.candidates.facets.data() + first, last - first},
                                 f.nodes, f.x, f.normal, rules, hint);
  if (h.facet >= 0 || previous < 0) return h;
  // A point in contact last step that is now deeper than the other side's detection depth (its
  // facets are thinner than the point's own elements) keeps its partner or a neighbour of it, down
  // to its own detection depth: contact acts until the surfaces separate. The neighbours are the
  // facets around the partner's nodes (the broad phase may no longer list them).
  constexpr std::size_t kMaxNear = 64;
  std::array<std::int32_t, kMaxNear> near{};
  std::size_t count = 0;
  for (const std::int32_t node : target.surface.facets[previous])
    for (std::int32_t k = target.node_facet_start[node];
         k < target.node_facet_start[node + 1] && count < kMaxNear; ++k)
      if (std::find(near.begin(), near.begin() + static_cast<std::ptrdiff_t>(count),
                    target.node_facets[k]) == near.begin() + static_cast<std::ptrdiff_t>(count))
        near[count++] = target.node_facets[k];
  std::sort(near.begin(),
            near.begin() + static_cast<std::ptrdiff_t>(count));  // facet order, as the broad phase
  rules.point_depth = own.point_depth[p];  // as deep as either side's elements reach
  TargetFacets around = facets;
  around.bands = {};  // the neighbours need not be anyone's candidates
  return find_partner(around, {near.data(), count}, f.nodes, f.x, f.normal, rules, hint);
}

double InterfaceImpl::spring(const Side& own, std::size_t p, double area, const Side& target,
                             std::int32_t f) const {
  const std::size_t np = part_ids_.size();
  const std::size_t a = static_cast<std::size_t>(own.point_part[p]);
  double scale = 0.0;
  if (f >= 0) {
    scale = part_scale_[a * np + static_cast<std::size_t>(target.facet_part[f])];
  } else {  // the stiffest partner (stable-step bound)
    for (std::size_t b = 0; b < np; ++b) scale = std::max(scale, part_scale_[a * np + b]);
  }
  if (settings_.stiffness.rule == StiffnessRule::FacetPenalty) {
    const double pfac =
        std::min(own.point_pfac[p], f >= 0 ? target.surface.penalty[f] : target.max_pfac);
    return pfac * area * scale;
  }
  const double km = f >= 0 ? target.facet_km[f] : target.max_km;
  return combined_stiffness(settings_.stiffness, km, own.point_ks[p]) * own.point_share[p] * scale;
}

bool InterfaceImpl::quiet(const Pass& pass, std::size_t p) const {
  return pass.candidates.offsets[p] == pass.candidates.offsets[p + 1] && !pass.hit[p] &&
         pass.state[p] != kTied && !pass.remembers(p) && pass.released[p] == 0.0 &&
         (pass.heat_facet.empty() || pass.heat_facet[p] < 0);
}

void InterfaceImpl::evaluate_point(Pass& pass, std::size_t p, const ContactInput& in) {
  const std::int32_t last_partner = pass.hit[p] ? pass.hit_facet[p] : -1;
  pass.hit[p] = 0;
  pass.kink[p] = 0.0;
  // What the point's springs held at the end of last step: where they vanish without doing work
  // now, that energy is released (ContactStats::released_energy; scatter adds and clears it).
  const double held = last_partner >= 0 ? pass.energy[p] : 0.0;
  auto release = [&pass, p](double energy) {
    if (energy > 0.0) pass.released[p] += energy;
  };
  if (!pass.mortar_count.empty()) pass.mortar_count[p] = 0;  // spread at the point unless covered
  if (!pass.heat_facet.empty()) pass.heat_facet[p] = -1;
  if (!pass.corner.empty())  // N2S: last step's walls of a concave corner (corner_press.cpp)
    for (std::size_t k = 0; k < kMaxCornerWalls; ++k)
      pass.corner[p * kMaxCornerWalls + k].facet = -1;
  const Side& own = sides_[pass.own];
  const Side& target = sides_[pass.target];
  if (pass.state[p] == kReleased) return;
  // Most points have no candidate and no partner to keep: nothing to evaluate (the outcome of the
  // full path below when no partner is found).
  // A point without a partner forgets its friction history, initial offset and adhesive bond.
  // Written only when not yet clear: most points stay without a partner step after step, and a
  // store per field and point would cost more than the load.
  auto lose_partner = [&pass, p] {
    if (!pass.remembers(p)) return;
    pass.forget_friction(p);
    pass.offset[p] = 0.0;
    pass.adhered[p] = 0;
  };
  if (last_partner < 0 && pass.state[p] != kTied &&
      pass.candidates.offsets[p] == pass.candidates.offsets[p + 1]) {
    lose_partner();
    return;
  }
  // Many more are near a facet but clearly open (open_points.cpp): the full path would only find
  // that again.
  if (last_partner < 0 && pass.state[p] != kTied && surely_open(pass, p, in)) return;
  const PointFrame f = frame(own, p, in);
  // What the springs hold now, at the end of the step over which last step's force did its work
  // F . v_rel dt on the bodies: held less that work (to first order in the step).
  auto held_now = [&]() {
    if (last_partner < 0) return 0.0;
    const auto& nodes = target.surface.facets[last_partner];
    const Vec3 v_partner = velocity_at(nodes, quad_shape(pass.hit_xi[p], pass.hit_eta[p]), in);
    const Vec3 force{pass.fx[p], pass.fy[p], pass.fz[p]};
    return held - dot(force, f.v - v_partner) * in.dt;
  };
  if (!f.active) {  // its facet eroded or left the contact
    release(held_now());
    return;
  }
  const ContactSettings& s = settings_;
  // A node's area is the part of its tributary area that faces its partner, the projection of its
  // vector area on the partner's normal: the bottom of a block pressed on a plate, not its sides.
  const bool node_point = own.point_node[p] >= 0;
  double area = f.area;
  auto facing_area = [&](const Vec3& partner_normal) {
    if (node_point && !f.free)
      area = f.two_sided ? std::abs(dot(f.vector_area, partner_normal))
                         : std::max(-dot(f.vector_area, partner_normal), 0.0);
    return area > 0.0;
  };
  const double m_own = node_point ? mass_[f.nodes[0]] : mass_share(own, f.nodes, f.shape, area);

  // The spring to the partner point (xi, eta) of `facet`, along `normal`.
  struct Spring {
    Vec3 normal, velocity;
    double stiffness, effective_mass;
  };
  auto partner_spring = [&](std::int32_t facet, double pxi, double peta, const Vec3& normal) {
    const auto& nodes = target.surface.facets[facet];
    const auto n = quad_shape(pxi, peta);
    Spring r;
    r.normal = normal;
    r.velocity = velocity_at(nodes, n, in);
    r.stiffness = spring(own, p, area, target, facet);
    r.effective_mass = reduced_mass(m_own, mass_share(target, nodes, n, area));
    return r;
  };
  // Fraction xi of the critical damping 2 sqrt(k m) of a spring k.
  auto damping_of = [&](double k, const Spring& r) {
    return 2.0 * s.damping * std::sqrt(k * r.effective_mass);
  };
  auto record = [&](std::int32_t facet, double pxi, double peta, const Spring& r, double k,
                    const Vec3& force) {
    pass.hit[p] = 1;
    pass.hit_facet[p] = facet;
    pass.hit_xi[p] = pxi;
    pass.hit_eta[p] = peta;
    pass.fx[p] = force.x;
    pass.fy[p] = force.y;
    pass.fz[p] = force.z;
    pass.area[p] = area;
    pass.omega2[p] = r.effective_mass > 0.0 ? k / r.effective_mass : 0.0;
  };
  auto clear_history = [&] { pass.forget_friction(p); };

  // Tied contact (sticking contact of seed 000, FREEZE of OptiStruct): a spring to the fixed
  // partner point in every direction, in tension too; sticking contact fails for good when its
  // traction exceeds sigma_stick.
  auto tied = [&]() {
    // A tie holds its point to one partner point: spread at the point, with its whole area.
    if (!node_point) {
      area = f.area;
      pass.mortar_count[p] = 0;
    }
    const std::int32_t facet = pass.tie_facet[p];
    if (!target.active[facet]) return false;
    const QuadCorners corners = quad_corners(target.surface.facets[facet], in.x, in.y, in.z);
    double jacobian = 0.0;
    const Vec3 tie_normal = quad_normal(corners, pass.tie_xi[p], pass.tie_eta[p], jacobian);
    // A tie holds in every direction: a node facing away keeps its whole area.
    if (node_point && !facing_area(tie_normal)) area = f.area;
    const Spring r = partner_spring(facet, pass.tie_xi[p], pass.tie_eta[p], tie_normal);
    const Vec3 stretch =
        f.x - quad_point(corners, pass.tie_xi[p], pass.tie_eta[p]) + r.normal * pass.offset[p];
    const Vec3 v_rel = f.v - r.velocity;
    const double c = damping_of(r.stiffness, r);
    const Vec3 force = stretch * (-r.stiffness) - v_rel * c;
    if (s.stick_stress && norm(force) > *s.stick_stress * area) return false;  // fails for good
    record(facet, pass.tie_xi[p], pass.tie_eta[p], r, r.stiffness, force);
    const double fn = dot(force, r.normal);
    pass.normal_force[p] = fn;
    pass.tangential_force[p] = norm(force - r.normal * fn);
    pass.pressure[p] = fn / area;
    pass.slip_speed[p] = norm(v_rel - r.normal * dot(v_rel, r.normal));
    pass.energy[p] = 0.5 * r.stiffness * dot(stretch, stretch);
    pass.dfx[p] = -c * v_rel.x;
    pass.dfy[p] = -c * v_rel.y;
    pass.dfz[p] = -c * v_rel.z;
    pass.slip_work[p] = 0.0;
    pass.penetration[p] = std::max(-dot(stretch, r.normal), 0.0);
    record_conductance(pass, p, facet, pass.tie_xi[p], pass.tie_eta[p], std::max(fn, 0.0) / area,
                       0.0, area);
    return true;
  };

  if (pass.state[p] == kTied) {
    if (tied()) return;
    pass.state[p] = kUntied;  // the tie failed: its spring lets go
    release(held_now());
  }

  Partner h = partner_of(pass, p, f, in, last_partner);
  std::optional<double> cover;  // node_cover against h, where already known
  if (node_point) h = facing_node_partner(pass, p, f, in, h, cover);
  // An integration point acts with the part of its cell over the other surface, spread over the
  // nodes of both as the cell's overlaps give (mortar.hpp), at the mean gap over that part (the
  // mortar gap: its centroids on both surfaces, (x_own - x_other) . n less the pair's gap), so
  // that a cell straddling a border or a tilted partner acts where it touches. Only a cell that
  // faces its partner within alpha_edge (cell_cover.cpp): one turned further (a block's side wall
  // against a plate it digs into) projects edge-on, and acts at its point with its whole area.
  CellOverlap o;
  const bool facing_cell = !node_point && meet_by_cell(pass, p, f, in, h, o);
  if (h.facet < 0 || (facing_cell && !(o.area > 0.0))) {
    // beyond the detection depth or off the facets (its cell too), while it was pressed
    release(held_now());
    lose_partner();
    return;
  }
  if (!pass.corner.empty() && node_point) press_corner_walls(pass, p, f, h, in);
  Vec3 mortar_velocity;  // sum of W v over both sides' nodes: the cell's mean relative velocity
  if (facing_cell) {
    if (!(o.area > 0.0)) {
      lose_partner();
      return;
    }
    area = o.area;
    const double inv = 1.0 / o.area;
    for (int a = 0; a < 4; ++a) {
      pass.mortar_own[4 * p + a] = o.own[a] * inv;
      const std::int32_t i = f.nodes[a];
      if (!in.vx.empty()) mortar_velocity += Vec3{in.vx[i], in.vy[i], in.vz[i]} * (o.own[a] * inv);
    }
    for (int k = 0; k < o.count; ++k) {
      pass.mortar_facet[kMaxOverlaps * p + k] = o.facet[k];
      const auto& nodes = target.surface.facets[o.facet[k]];
      for (int b = 0; b < 4; ++b) {
        const double w = o.target[k][b] * inv;
        pass.mortar_target[4 * (kMaxOverlaps * p + k) + b] = w;
        if (!in.vx.empty())
          mortar_velocity -= Vec3{in.vx[nodes[b]], in.vy[nodes[b]], in.vz[nodes[b]]} * w;
      }
    }
    pass.mortar_count[p] = static_cast<std::uint8_t>(o.count);
  }
  const bool from_behind = s.sense == ContactSense::Negative;
  const bool bilateral = s.sense == ContactSense::Bilateral;
  const double gap =
      from_behind ? -h.gap : h.gap;      // opening along the direction the contact pushes
  if (gap >= 0.0) pass.offset[p] = 0.0;  // separated: the initial offset has done its job
  if (s.stick_stress && pass.state[p] == kFree &&
      gap <= kTouchingGapFraction * own.point_thickness[p]) {
    pass.state[p] = kTied;
    pass.tie_facet[p] = h.facet;
    pass.tie_xi[p] = h.xi;
    pass.tie_eta[p] = h.eta;
    if (tied()) return;
    pass.state[p] = kUntied;
  }
  const double penetration = -gap - pass.offset[p] - pass.shift_at(p);
  // Outside: no force, unless the contact is bilateral or the point is adhered and still within
  // the adhesive zone (Radioss IVIS2 = -1: the bond breaks at its border).
  bool adhesive = false, bond_broke = false;
  if (s.adhesion) {
    if (penetration > 0.0) {
      pass.adhered[p] = 1;
    } else if (pass.adhered[p] && -penetration <= s.adhesion->zone()) {
      adhesive = true;
    } else {
      bond_broke = pass.adhered[p] != 0;
      pass.adhered[p] = 0;
    }
  }
  if (!(penetration > 0.0) && !bilateral && !adhesive) {
    // Separated. The springs let go of forces that fell on the way (the friction force is bound
    // by the normal one), and last step's force did its work on the way out; an adhesive bond
    // that broke at the zone's border lets go of its whole pull.
    if (bond_broke) release(held_now());
    clear_history();
    // Open within reach of the partner: heat may still cross the gap (thermal.hpp).
    if (s.thermal.conductance &&
        (!node_point || facing_area(from_behind ? h.normal * -1.0 : h.normal)))
      record_conductance(
          pass, p, h.facet, h.xi, h.eta, 0.0,
          -penetration <= kTouchingGapFraction * own.point_thickness[p] ? 0.0 : -penetration, area);
    return;
  }

  if (node_point && !facing_area(from_behind ? h.normal * -1.0 : h.normal)) {
    release(held_now());
    clear_history();
    return;
  }
  // A node on the other surface's border presses with the part of its area over that surface.
  if (node_point && !f.free && !f.two_sided && !from_behind)
    area *= cover ? *cover : node_cover(pass, p, h, in);
  // Along the facet's normal, or radially around a shell's rounded edge.
  const Spring r = partner_spring(h.facet, h.xi, h.eta, h.normal);
  // The push on the point: a cell's along its own normal (the direction of its cover).
  const Vec3 along = facing_cell ? o.normal : r.normal;
  const Vec3 normal = from_behind ? along * -1.0 : along;
  NormalResponse response;
  if (adhesive) {
    const double slope = s.adhesion->max_stress / s.adhesion->zone();
    response = {s.adhesion->pressure(-penetration), slope, 0.5 * slope * penetration * penetration};
  } else {
    response = scaled(evaluate(s.normal_law, penetration, r.stiffness / area),
                      s.normal_in_time.at(in.time));
  }
  const double k_n = response.stiffness * area;
  const double c = damping_of(k_n, r);
  // The cell's mean relative velocity (the same weights as its force: its damping and friction
  // only dissipate), else the point's.
  const Vec3 v_rel = facing_cell ? mortar_velocity : f.v - r.velocity;
  const double v_n = dot(v_rel, normal);  // < 0 while approaching
  const double elastic = response.pressure * area;
  // Damping may reduce the push but never pulls, unless the contact holds in tension.
  double fn = elastic - c * v_n;
  if (!bilateral && !adhesive) fn = std::max(fn, 0.0);
  const Vec3 v_t = v_rel - normal * v_n;
  const double slip_speed = norm(v_t);
  // Metafor PEN_TANGENT (GD, TM): the spring of this step times g(d) f(t); the history force of
  // the steps before keeps the springs it was built with (an incremental spring). A factor <= 0
  // holds no tangential force.
  const double k_t = (s.tangential_penalty ? *s.tangential_penalty * area : r.stiffness) *
                     s.tangential_penalty_factor.factor(penetration, in.time);
  const Vec3 previous{pass.htx[p], pass.hty[p], pass.htz[p]};
  Vec3 ft, spring;  // the tangential force, and its elastic part (the history)
  double slip = 0.0, slip_work = 0.0;
  if (adhesive) {  // viscous resistance replaces friction in the adhesive zone
    ft = s.adhesion->viscous_force(v_t, area);
    slip_work = -dot(ft, v_t) * in.dt;
  } else {
    // The law of this pair of parts (Radioss /FRICTION), else the interface's.
    const std::int32_t pair =
        part_friction_[static_cast<std::size_t>(own.point_part[p]) * part_ids_.size() +
                       static_cast<std::size_t>(target.facet_part[h.facet])];
    const TangentialLaw& law = pair < 0 ? s.tangential_law : s.pair_frictions[pair].law;
    const FrictionFilter& filter = pair < 0 ? s.friction_filter : s.pair_frictions[pair].filter;
    const SlipLimits limits = slip_limits(law, {std::max(fn, 0.0), area, slip_speed, in.time, f.x});
    if (k_t > 0.0 && (limits.stick > 0.0 || limits.slide > 0.0)) {
      const StickSlipResult t =
          stick_slip(previous, pass.slip[p], {normal, v_t, in.dt, k_t, damping_of(k_t, r)}, limits);
      slip = t.slip;
      ft = t.force;
      spring = t.spring;
      slip_work = t.slip_work;
    }
    if (filter.kind != FrictionFilter::Kind::None) {  // Radioss Ifiltr
      const double a = filter.alpha(in.dt);
      const Vec3 filtered = (previous - normal * dot(previous, normal)) * (1.0 - a);
      ft = ft * a + filtered;
      spring = spring * a + filtered;
    }
  }
  pass.htx[p] = spring.x;
  pass.hty[p] = spring.y;
  pass.htz[p] = spring.z;
  pass.slip[p] = slip;
  // A cell's elastic push follows the slope of the facets it covers (mortar.hpp), so that its
  // force derives from its energy; damping stays along the normal (it only dissipates).
  Vec3 push = normal * fn;
  if (facing_cell) push += ((from_behind ? o.push * -1.0 : o.push) - normal) * elastic;
  record(h.facet, h.xi, h.eta, r, std::max(k_n, k_t), push + ft);
  pass.pair_gap[p] = h.pair_gap;
  pass.normal_force[p] = fn;
  pass.tangential_force[p] = norm(ft);
  pass.pressure[p] = fn / area;
  pass.slip_speed[p] = slip_speed;
  pass.energy[p] = response.energy * area + (k_t > 0.0 ? 0.5 * dot(spring, spring) / k_t : 0.0);
  // The damping part of the force: along the normal, and the stick spring's (an adhesive zone's
  // viscous resistance counts as friction).
  Vec3 damping = normal * (fn - elastic);
  if (!adhesive) damping += ft - spring;
  pass.dfx[p] = damping.x;
  pass.dfy[p] = damping.y;
  pass.dfz[p] = damping.z;
  pass.slip_work[p] = slip_work;
  pass.penetration[p] = penetration;
  // Separating within a step's travel at the spring's own bound: it may let go part way through
  // the next step (ContactStats::kink_step).
  if (v_n > 0.0 && !adhesive && bounds_kinks() && penetration < v_n * spring_step(pass.omega2[p]))
    pass.kink[p] = 0.125 * k_n * v_n * v_n;
  record_conductance(pass, p, h.facet, h.xi, h.eta, std::max(fn, 0.0) / area, -penetration, area);
}

}  // namespace abut
