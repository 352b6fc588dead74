#include "abut/contact/interface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "abut/contact/friction.hpp"
#include "abut/core/parallel.hpp"
#include "abut/contact/integration.hpp"
#include "abut/contact/penalty.hpp"
#include "abut/contact/quad.hpp"

namespace abut {
namespace {

// A point within this fraction of its element thickness counts as touching when sticking
// contact ties it (absorbs round-off of initially coincident surfaces).
constexpr double kTieGapFraction = 1e-6;
// Default delta0_max: 4% of the element thickness (seed 000).
constexpr double kDefaultInitialMaxFraction = 0.04;

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

Vec3 velocity_at(const std::array<std::int32_t, 4>& nodes, const std::array<double, 4>& shape,
                 const ContactInput& in) {
  Vec3 v;
  for (int a = 0; a < 4; ++a) v += Vec3{in.vx[nodes[a]], in.vy[nodes[a]], in.vz[nodes[a]]} * shape[a];
  return v;
}

// How far beyond a smooth edge, per unit distance from the facet's plane, a point may lie and
// still belong to the facet: tan(alpha_edge), the widest dead zone of a convex edge whose
// normals turn by at most alpha_edge. From 90 degrees on every crossing is accepted.
double smooth_edge_reach(double alpha_edge_degrees) {
  if (alpha_edge_degrees >= 90.0) return std::numeric_limits<double>::infinity();
  return std::tan(alpha_edge_degrees * std::numbers::pi / 180.0);
}

bool share_a_node(const std::array<std::int32_t, 4>& a, const std::array<std::int32_t, 4>& b) {
  for (auto i : a)
    for (auto j : b)
      if (i == j) return true;
  return false;
}

}  // namespace

ContactInterface::ContactInterface(ContactSettings settings, ContactSurface surface1,
                                   ContactSurface surface2, std::span<const double> node_mass,
                                   const ContactInput& initial)
    : settings_(std::move(settings)), mass_(node_mass.begin(), node_mass.end()) {
  const ContactSettings& s = settings_;
  auto fail = [&](const std::string& field, const std::string& message) {
    SourceLocation where = s.where;
    where.field = field;
    throw InputError(where, message);
  };
  if (s.accuracy_level < 1) fail("accuracy_level", "expected 1 (low), 2 (standard) or more (high)");
  if (!(s.friction >= 0.0)) fail("mu", "the friction coefficient must be >= 0");
  if (!(s.damping >= 0.0)) fail("xi", "the fraction of critical damping must be >= 0");
  if (!(s.end_time >= s.begin_time)) fail("t_end", "the deactivation time must not precede t_beg");
  if (!(s.initial_offset >= 0.0)) fail("delta0_offset", "the initial penetration offset must be >= 0");
  if (s.initial_max && !(*s.initial_max >= 0.0)) fail("delta0_max", "must be >= 0");
  if (!(s.edge_tolerance >= 0.0)) fail("delta_edge", "the edge tolerance must be >= 0");
  if (!(s.edge_angle > 0.0 && s.edge_angle <= 180.0)) fail("alpha_edge", "expected an angle in (0, 180] degrees");
  if (s.stick_stress && !(*s.stick_stress > 0.0)) fail("sigma_stick", "the sticking failure stress must be > 0");
  if (s.search_margin && !(*s.search_margin > 0.0)) fail("", "the search margin must be > 0");
  if (surface1.size() == 0) fail("enid_1", "surface 1 has no facets: the entity has no exterior faces");
  if (surface2.size() == 0) fail("enid_2", "surface 2 has no facets: the entity has no exterior faces");
  const bool self = surface1.facets == surface2.facets;
  if (self && s.one_way)
    fail("one_way", "one-way contact needs two different surfaces; these two are the same faces (self contact)");
  for (const ContactSurface* surface : {&surface1, &surface2})
    for (std::size_t f = 0; f < surface->size(); ++f) {
      if (!(surface->penalty[f] > 0.0) || !std::isfinite(surface->penalty[f]))
        fail("pfac", "the penalty stiffness of part " + std::to_string(surface->part[f]) + " must be > 0");
      if (!(surface->thickness[f] > 0.0))
        fail("", "a facet of part " + std::to_string(surface->part[f]) + " has no positive thickness");
      for (auto n : surface->facets[f])
        if (n < 0 || static_cast<std::size_t>(n) >= mass_.size() || static_cast<std::size_t>(n) >= initial.x.size())
          fail("", "a facet refers to node index " + std::to_string(n) + " beyond the nodal arrays");
    }

  wear_.assign(mass_.size(), 0.0);
  pressure_.assign(mass_.size(), 0.0);
  sides_.resize(self ? 1 : 2);
  sides_[0].surface = std::move(surface1);
  if (!self) sides_[1].surface = std::move(surface2);
  build_sides(initial);
  build_passes();
  initial_penetrations(initial);
}

void ContactInterface::build_sides(const ContactInput& in) {
  const ContactSettings& s = settings_;
  margin_ = std::numeric_limits<double>::infinity();
  smooth_reach_ = smooth_edge_reach(s.edge_angle);
  double omega2_max = 0.0;
  // Typical facet size of each side (median of the longest edges), for the subdivision below.
  std::vector<double> typical_size;
  for (const Side& side : sides_) {
    std::vector<double> sizes;
    for (const auto& facet : side.surface.facets) sizes.push_back(longest_edge(corners_of(facet, in)));
    std::nth_element(sizes.begin(), sizes.begin() + static_cast<std::ptrdiff_t>(sizes.size() / 2), sizes.end());
    typical_size.push_back(sizes[sizes.size() / 2]);
  }
  for (std::size_t side_index = 0; side_index < sides_.size(); ++side_index) {
    Side& side = sides_[side_index];
    const double other_size = typical_size[sides_.size() == 1 ? 0 : 1 - side_index];
    const ContactSurface& surface = side.surface;
    const std::size_t n = surface.size();
    side.sharp = sharp_edges(surface, in.x, in.y, in.z, s.edge_angle);
    side.active.assign(n, 1);
    side.depth.resize(n);
    side.node_area.assign(mass_.size(), 0.0);
    std::vector<FacetPoint> rules[16];
    for (std::size_t f = 0; f < n; ++f) {
      const QuadCorners c = corners_of(surface.facets[f], in);
      if (s.initial_region) {
        const Vec3 centre = quad_point(c, 0.0, 0.0);
        side.active[f] = s.initial_region(centre.x, centre.y, centre.z) ? 1 : 0;
      }
      side.depth[f] = 0.5 * surface.thickness[f];
      margin_ = std::min(margin_, side.depth[f]);
      // A facet two or more times larger than the facets it meets would press its few points into single
      // small facets of the other side with the stiffness of its whole area. It is split into
      // m x m cells about the size of the other side's facets, each integrated with the rule of
      // the accuracy level, so both sides resolve the overlap alike.
      const int cells = static_cast<int>(std::clamp(std::floor(longest_edge(c) / other_size), 1.0, 32.0));
      std::vector<FacetPoint> rule;
      for (int j = 0; j < cells; ++j) {
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
          for (const FacetPoint& q : cell_rule)
            rule.push_back({-1.0 + (2.0 * i + 1.0 + q.xi) * inv, -1.0 + (2.0 * j + 1.0 + q.eta) * inv,
                            q.weight * inv * inv});
        }
      }
      double facet_area = 0.0;
      for (const FacetPoint& q : rule) {
        side.point_facet.push_back(static_cast<std::int32_t>(f));
        side.point_xi.push_back(q.xi);
        side.point_eta.push_back(q.eta);
        side.point_weight.push_back(q.weight);
        double jacobian = 0.0;
        quad_normal(c, q.xi, q.eta, jacobian);
        const auto shape = quad_shape(q.xi, q.eta);
        for (int a = 0; a < 4; ++a) side.node_area[surface.facets[f][a]] += shape[a] * q.weight * jacobian;
        facet_area += q.weight * jacobian;
      }
      // Before contact: a facet's spring pfac*A between its lightest node and an equal mass
      // on the other side, omega^2 = 2 pfac A / m_min (a conservative bound).
      double m_min = std::numeric_limits<double>::infinity();
      for (auto node : surface.facets[f]) m_min = std::min(m_min, mass_[node]);
      if (m_min > 0.0) omega2_max = std::max(omega2_max, 2.0 * surface.penalty[f] * facet_area / m_min);
    }
  }
  if (s.search_margin) margin_ = *s.search_margin;
  initial_stable_step_ = omega2_max > 0.0 ? 2.0 / std::sqrt(omega2_max) : std::numeric_limits<double>::infinity();

  for (const Side& side : sides_)
    for (const auto& facet : side.surface.facets) surface_nodes_.insert(surface_nodes_.end(), facet.begin(), facet.end());
  std::sort(surface_nodes_.begin(), surface_nodes_.end());
  surface_nodes_.erase(std::unique(surface_nodes_.begin(), surface_nodes_.end()), surface_nodes_.end());
}

void ContactInterface::build_passes() {
  if (sides_.size() == 1) {
    passes_.resize(1);
    passes_[0] = Pass{};
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
    pass.state.assign(n, kFree);
    for (auto* v : {&pass.offset, &pass.htx, &pass.hty, &pass.htz, &pass.tie_xi, &pass.tie_eta})
      v->assign(n, 0.0);
    pass.tie_facet.assign(n, -1);
    pass.hit.assign(n, 0);
    pass.hit_facet.assign(n, -1);
    for (auto* v : {&pass.hit_xi, &pass.hit_eta, &pass.fx, &pass.fy, &pass.fz, &pass.area, &pass.pressure,
                    &pass.slip_speed, &pass.normal_force, &pass.tangential_force, &pass.energy,
                    &pass.damping_work, &pass.slip_work, &pass.penetration, &pass.omega2, &pass.qx,
                    &pass.qy, &pass.qz})
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
  for (const Pass& pass : passes_) n += static_cast<std::size_t>(std::count(pass.state.begin(), pass.state.end(), kReleased));
  return n;
}

bool ContactInterface::needs_rebuild(const ContactInput& in) const {
  if (builds_ == 0) return true;
  // Verlet-list rule: boxes were inflated by the margin m; while no node has moved more than
  // m/2 since the build, a point and a facet cannot have approached each other by more than m.
  double moved2 = 0.0;
  const std::size_t n = surface_nodes_.size();
#pragma omp parallel for schedule(static) reduction(max : moved2) if (n >= static_cast<std::size_t>(kParallelMinimum))
  for (std::size_t k = 0; k < n; ++k) {
    const auto i = surface_nodes_[k];
    const double dx = in.x[i] - bx_[k], dy = in.y[i] - by_[k], dz = in.z[i] - bz_[k];
    moved2 = std::max(moved2, dx * dx + dy * dy + dz * dz);
  }
  return moved2 > 0.25 * margin_ * margin_;
}

void ContactInterface::rebuild_broad_phase(const ContactInput& in) {
  for (Pass& pass : passes_) {
    const Side& own = sides_[pass.own];
    const Side& target = sides_[pass.target];
    std::vector<Box> boxes(target.surface.size());
    for (std::size_t f = 0; f < boxes.size(); ++f) {
      const QuadCorners c = corners_of(target.surface.facets[f], in);
      const double grow = std::max(target.depth[f], settings_.edge_tolerance) + margin_;
      for (int k = 0; k < 3; ++k) {
        const double lo = std::min({c[0][k], c[1][k], c[2][k], c[3][k]});
        const double hi = std::max({c[0][k], c[1][k], c[2][k], c[3][k]});
        boxes[f].lo[k] = lo - grow;
        boxes[f].hi[k] = hi + grow;
      }
    }
    pass.grid.build(boxes);
    const std::size_t n = own.point_facet.size();
#pragma omp parallel for schedule(static) if (n >= static_cast<std::size_t>(kParallelMinimum))
    for (std::size_t p = 0; p < n; ++p) {
      const Vec3 x = quad_point(corners_of(own.surface.facets[own.point_facet[p]], in), own.point_xi[p],
                                own.point_eta[p]);
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

ContactInterface::Hit ContactInterface::closest_facet(const Pass& pass, std::size_t p, const Vec3& x_p,
                                                      const Vec3& n_p, const ContactInput& in) const {
  const Side& own = sides_[pass.own];
  const Side& target = sides_[pass.target];
  const auto& own_nodes = own.surface.facets[own.point_facet[p]];
  const double edge_tolerance = settings_.edge_tolerance;
  Hit best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t k = pass.candidates.offsets[p]; k < pass.candidates.offsets[p + 1]; ++k) {
    const std::int32_t f = pass.candidates.facets[k];
    if (!target.active[f]) continue;
    const auto& nodes = target.surface.facets[f];
    // A point never contacts its own facet nor a facet sharing a node with it (self contact).
    if (share_a_node(own_nodes, nodes)) continue;
    const QuadCorners c = corners_of(nodes, in);
    // The distance to the facet's bounding box bounds the distance to the facet from below:
    // skip facets that cannot be within reach or closer than the best one so far.
    const double reach = std::max(target.depth[f], edge_tolerance);
    double box_distance2 = 0.0;
    for (int i = 0; i < 3; ++i) {
      const double lo = std::min({c[0][i], c[1][i], c[2][i], c[3][i]});
      const double hi = std::max({c[0][i], c[1][i], c[2][i], c[3][i]});
      const double out = std::max({lo - x_p[i], x_p[i] - hi, 0.0});
      box_distance2 += out * out;
    }
    if (box_distance2 > reach * reach || box_distance2 > best_distance * best_distance) continue;
    const QuadProjection q = project_onto_quad(c, x_p);
    if (dot(n_p, q.normal) >= 0.0) continue;  // the surfaces must face each other
    // Beyond a sharp (or free) edge only within delta_edge. Beyond a smooth edge the
    // neighbouring facet is normally closer and wins, but not when the neighbour itself is
    // rejected (the point lies beyond the surface's border, next to a sharp edge of the
    // neighbour): so a smooth edge is passed only within the dead zone of a convex edge, the
    // wedge between the two facets' normals, whose width at distance |gap| is at most
    // |gap| tan(alpha_edge) since the normals turn by at most alpha_edge there.
    if (q.crossed_edges != 0) {
      const bool sharp = (q.crossed_edges & target.sharp[f]) != 0;
      const double allowed = sharp ? edge_tolerance : std::max(edge_tolerance, std::abs(q.gap) * smooth_reach_);
      if (q.overshoot > allowed) continue;
    }
    if (q.gap < -target.depth[f]) continue;  // deeper than half the element: the far side
    if (q.distance < best_distance) {
      best_distance = q.distance;
      best = {f, q.xi, q.eta, q.gap};
    }
  }
  return best;
}

void ContactInterface::initial_penetrations(const ContactInput& in) {
  rebuild_broad_phase(in);
  for (Pass& pass : passes_) {
    const Side& own = sides_[pass.own];
    const std::size_t n = own.point_facet.size();
#pragma omp parallel for schedule(dynamic, 256) if (n >= static_cast<std::size_t>(kParallelMinimum) / 4)
    for (std::size_t p = 0; p < n; ++p) {
      const std::int32_t f = own.point_facet[p];
      if (!own.active[f]) continue;
      double jacobian = 0.0;
      const QuadCorners c = corners_of(own.surface.facets[f], in);
      const Vec3 x_p = quad_point(c, own.point_xi[p], own.point_eta[p]);
      const Vec3 n_p = quad_normal(c, own.point_xi[p], own.point_eta[p], jacobian);
      const Hit h = closest_facet(pass, p, x_p, n_p, in);
      if (h.facet < 0 || !(h.gap < 0.0)) continue;
      const double depth = -h.gap;
      const double allowed = settings_.initial_max.value_or(kDefaultInitialMaxFraction * own.surface.thickness[f]);
      if (depth > allowed)
        pass.state[p] = kReleased;
      else
        pass.offset[p] = std::min(depth, settings_.initial_offset);
    }
  }
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

void ContactInterface::evaluate_point(Pass& pass, std::size_t p, const ContactInput& in) {
  pass.hit[p] = 0;
  const Side& own = sides_[pass.own];
  const Side& target = sides_[pass.target];
  const std::int32_t f_own = own.point_facet[p];
  if (pass.state[p] == kReleased || !own.active[f_own]) return;

  const auto& own_nodes = own.surface.facets[f_own];
  const QuadCorners c_own = corners_of(own_nodes, in);
  const double xi = own.point_xi[p], eta = own.point_eta[p];
  const auto shape = quad_shape(xi, eta);
  double jacobian = 0.0;
  const Vec3 n_p = quad_normal(c_own, xi, eta, jacobian);
  const Vec3 x_p = quad_point(c_own, xi, eta);
  const Vec3 v_p = velocity_at(own_nodes, shape, in);
  const double area = own.point_weight[p] * jacobian;
  // The point's share of each node's mass: m_i * N_i * (its area / the node's area), so that
  // the shares of all points add up to the nodal masses.
  auto mass_share = [&](const Side& side, const std::array<std::int32_t, 4>& nodes,
                        const std::array<double, 4>& n) {
    double m = 0.0;
    // On the other side a point may cover more than a node's area: never more than the node.
    for (int a = 0; a < 4; ++a)
      if (side.node_area[nodes[a]] > 0.0)
        m += mass_[nodes[a]] * std::min(1.0, n[a] * area / side.node_area[nodes[a]]);
    return m;
  };
  const double m_own = mass_share(own, own_nodes, shape);

  struct Partner {
    Vec3 point, normal, velocity;
    double stiffness, effective_mass, damping;
  };
  auto partner = [&](std::int32_t f, double pxi, double peta) {
    const auto& nodes = target.surface.facets[f];
    const QuadCorners c = corners_of(nodes, in);
    const auto n = quad_shape(pxi, peta);
    Partner r;
    double jac = 0.0;
    r.point = quad_point(c, pxi, peta);
    r.normal = quad_normal(c, pxi, peta, jac);
    r.velocity = velocity_at(nodes, n, in);
    r.stiffness = pair_penalty(own.surface.penalty[f_own], target.surface.penalty[f]) * area;
    const double m_target = mass_share(target, nodes, n);
    r.effective_mass = m_own + m_target > 0.0 ? m_own * m_target / (m_own + m_target) : 0.0;
    // Fraction xi of the critical damping 2 sqrt(k m) of the point's spring.
    r.damping = 2.0 * settings_.damping * std::sqrt(r.stiffness * r.effective_mass);
    return r;
  };
  auto record = [&](std::int32_t f, double pxi, double peta, const Partner& r, const Vec3& force) {
    pass.hit[p] = 1;
    pass.hit_facet[p] = f;
    pass.hit_xi[p] = pxi;
    pass.hit_eta[p] = peta;
    pass.fx[p] = force.x;
    pass.fy[p] = force.y;
    pass.fz[p] = force.z;
    pass.area[p] = area;
    pass.omega2[p] = r.effective_mass > 0.0 ? r.stiffness / r.effective_mass : 0.0;
  };
  auto clear_history = [&] { pass.htx[p] = pass.hty[p] = pass.htz[p] = 0.0; };

  // Sticking contact: a spring to the fixed partner point, in every direction, in tension too,
  // until its traction exceeds sigma_stick.
  auto tied = [&]() {
    const std::int32_t f = pass.tie_facet[p];
    if (!target.active[f]) return false;
    const Partner r = partner(f, pass.tie_xi[p], pass.tie_eta[p]);
    const Vec3 stretch = x_p - r.point + r.normal * pass.offset[p];
    const Vec3 v_rel = v_p - r.velocity;
    const Vec3 force = stretch * (-r.stiffness) - v_rel * r.damping;
    if (norm(force) > *settings_.stick_stress * area) return false;  // fails for good
    record(f, pass.tie_xi[p], pass.tie_eta[p], r, force);
    const double fn = dot(force, r.normal);
    pass.normal_force[p] = fn;
    pass.tangential_force[p] = norm(force - r.normal * fn);
    pass.pressure[p] = fn / area;
    pass.slip_speed[p] = norm(v_rel - r.normal * dot(v_rel, r.normal));
    pass.energy[p] = 0.5 * r.stiffness * dot(stretch, stretch);
    pass.damping_work[p] = r.damping * dot(v_rel, v_rel) * in.dt;
    pass.slip_work[p] = 0.0;
    pass.penetration[p] = std::max(-dot(stretch, r.normal), 0.0);
    return true;
  };

  if (pass.state[p] == kTied) {
    if (tied()) return;
    pass.state[p] = kUntied;
  }

  const Hit h = closest_facet(pass, p, x_p, n_p, in);
  if (h.facet < 0) {
    clear_history();
    pass.offset[p] = 0.0;
    return;
  }
  if (h.gap >= 0.0) pass.offset[p] = 0.0;  // separated: the initial offset has done its job
  if (settings_.stick_stress && pass.state[p] == kFree &&
      h.gap <= kTieGapFraction * own.surface.thickness[f_own]) {
    pass.state[p] = kTied;
    pass.tie_facet[p] = h.facet;
    pass.tie_xi[p] = h.xi;
    pass.tie_eta[p] = h.eta;
    if (tied()) return;
    pass.state[p] = kUntied;
  }
  const double penetration = -h.gap - pass.offset[p];
  if (!(penetration > 0.0)) {
    clear_history();
    return;
  }

  const Partner r = partner(h.facet, h.xi, h.eta);
  const Vec3 v_rel = v_p - r.velocity;
  const double v_n = dot(v_rel, r.normal);  // < 0 while approaching
  const double elastic = r.stiffness * penetration;
  // Damping may reduce the push but never pulls: contact carries no tension.
  const double fn = std::max(elastic - r.damping * v_n, 0.0);
  const Vec3 v_t = v_rel - r.normal * v_n;
  const double slip_speed = norm(v_t);
  double mu = settings_.friction;
  if (settings_.friction_function)
    mu = settings_.friction_function(fn / area, slip_speed, in.time, x_p.x, x_p.y, x_p.z);
  Vec3 ft;
  double slip_work = 0.0;
  if (mu > 0.0) {
    const auto t = CoulombFriction{r.stiffness}.evaluate({pass.htx[p], pass.hty[p], pass.htz[p]}, r.normal,
                                                         v_t, in.dt, mu * fn);
    ft = t.force;
    slip_work = t.slip_work;
  }
  pass.htx[p] = ft.x;
  pass.hty[p] = ft.y;
  pass.htz[p] = ft.z;
  record(h.facet, h.xi, h.eta, r, r.normal * fn + ft);
  pass.normal_force[p] = fn;
  pass.tangential_force[p] = norm(ft);
  pass.pressure[p] = fn / area;
  pass.slip_speed[p] = slip_speed;
  pass.energy[p] = 0.5 * r.stiffness * penetration * penetration + 0.5 * dot(ft, ft) / r.stiffness;
  pass.damping_work[p] = (fn - elastic) * (-v_n) * in.dt;
  pass.slip_work[p] = slip_work;
  pass.penetration[p] = penetration;
}

void ContactInterface::apply(const ContactInput& in, ContactForces& out) {
  const std::size_t node_count = mass_.size();
  for (std::size_t size : {in.x.size(), in.y.size(), in.z.size(), in.vx.size(), in.vy.size(), in.vz.size(),
                           out.fx.size(), out.fy.size(), out.fz.size()})
    if (size < node_count)
      throw std::invalid_argument("ContactInterface::apply: nodal arrays shorter than the node masses");
  stats_.force = {};
  stats_.normal_force = stats_.tangential_force = stats_.elastic_energy = stats_.max_penetration = 0.0;
  stats_.active_points = 0;
  stats_.stable_step = std::numeric_limits<double>::infinity();
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
#pragma omp parallel for schedule(dynamic, 256) if (n >= static_cast<std::size_t>(kParallelMinimum) / 4)
    for (std::size_t p = 0; p < n; ++p) evaluate_point(pass, p, in);
  }
  scatter(in, out);
}

void ContactInterface::scatter(const ContactInput& in, ContactForces& out) {
  const WearRateFunction* wear_rate[2] = {&settings_.wear_rate1, &settings_.wear_rate2};
  if (self_contact() && !settings_.wear_rate1) wear_rate[0] = &settings_.wear_rate2;
  double omega2_max = 0.0;
  // Serial, in point order: the sums do not depend on the thread count.
  for (const Pass& pass : passes_) {
    const Side& own = sides_[pass.own];
    const Side& target = sides_[pass.target];
    const double w = pass.weight;
    for (std::size_t p = 0; p < pass.hit.size(); ++p) {
      if (!pass.hit[p]) continue;
      const auto& own_nodes = own.surface.facets[own.point_facet[p]];
      const auto& target_nodes = target.surface.facets[pass.hit_facet[p]];
      const auto n_own = quad_shape(own.point_xi[p], own.point_eta[p]);
      const auto n_target = quad_shape(pass.hit_xi[p], pass.hit_eta[p]);
      const Vec3 force = Vec3{pass.fx[p], pass.fy[p], pass.fz[p]} * w;
      // Action on the point's nodes, reaction on the partner facet's nodes at the projection.
      for (int a = 0; a < 4; ++a) {
        out.fx[own_nodes[a]] += force.x * n_own[a];
        out.fy[own_nodes[a]] += force.y * n_own[a];
        out.fz[own_nodes[a]] += force.z * n_own[a];
      }
      for (int a = 0; a < 4; ++a) {
        out.fx[target_nodes[a]] -= force.x * n_target[a];
        out.fy[target_nodes[a]] -= force.y * n_target[a];
        out.fz[target_nodes[a]] -= force.z * n_target[a];
      }
      if (pass.own == 0) stats_.force += force;
      if (pass.target == 0) stats_.force -= force;
      stats_.normal_force += w * pass.normal_force[p];
      stats_.tangential_force += w * pass.tangential_force[p];
      stats_.elastic_energy += w * pass.energy[p];
      stats_.damping_energy += w * pass.damping_work[p];
      stats_.friction_energy += w * pass.slip_work[p];
      stats_.max_penetration = std::max(stats_.max_penetration, pass.penetration[p]);
      ++stats_.active_points;
      omega2_max = std::max(omega2_max, pass.omega2[p]);

      // Nodal pressure and wear: area-weighted averages over each node's tributary area.
      const double load = w * pass.area[p];
      for (int a = 0; a < 4; ++a) {
        pressure_[own_nodes[a]] += load * n_own[a] * pass.pressure[p] / own.node_area[own_nodes[a]];
        pressure_[target_nodes[a]] += load * n_target[a] * pass.pressure[p] / target.node_area[target_nodes[a]];
      }
      const WearRateFunction& own_rate = *wear_rate[self_contact() ? 0 : pass.own];
      const WearRateFunction& target_rate = *wear_rate[self_contact() ? 0 : pass.target];
      if (own_rate) {
        const double dose = load * own_rate(pass.pressure[p], pass.slip_speed[p]) * in.dt;
        for (int a = 0; a < 4; ++a) wear_[own_nodes[a]] += dose * n_own[a] / own.node_area[own_nodes[a]];
      }
      if (target_rate) {
        const double dose = load * target_rate(pass.pressure[p], pass.slip_speed[p]) * in.dt;
        for (int a = 0; a < 4; ++a)
          wear_[target_nodes[a]] += dose * n_target[a] / target.node_area[target_nodes[a]];
      }
    }
  }
  if (omega2_max > 0.0) stats_.stable_step = 2.0 / std::sqrt(omega2_max);
}

}  // namespace abut
