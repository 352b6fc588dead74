// ContactInterface: the step driver and the broad phase; reports. Set-up is in
// interface_setup.cpp, enforcement in enforcement.cpp, the scatter of forces and statistics in
// scatter.cpp.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "abut/contact/quad.hpp"
#include "abut/core/parallel.hpp"
#include "interface_impl.hpp"

namespace abut {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

bool is_radioss_rule(StiffnessRule r) { return r != StiffnessRule::FacetPenalty; }

}  // namespace

std::size_t InterfaceImpl::point_count() const {
  std::size_t n = 0;
  for (const Pass& pass : passes_) n += pass.state.size();
  return n;
}

std::size_t InterfaceImpl::released_points() const {
  std::size_t n = 0;
  for (const Pass& pass : passes_)
    n += static_cast<std::size_t>(std::count(pass.state.begin(), pass.state.end(), kReleased));
  return n;
}

std::size_t InterfaceImpl::tied_points() const {
  std::size_t n = 0;
  for (const Pass& pass : passes_)
    n += static_cast<std::size_t>(std::count(pass.state.begin(), pass.state.end(), kTied));
  return n;
}

std::vector<ContactInterface::NodeTie> InterfaceImpl::node_ties() const {
  std::vector<NodeTie> out;
  for (const Pass& pass : passes_) {
    const Side& own = sides_[pass.own];
    const Side& target = sides_[pass.target];
    for (std::size_t p = 0; p < pass.state.size(); ++p) {
      if (pass.state[p] != kTied || own.point_node.empty() || own.point_node[p] < 0) continue;
      out.push_back({own.point_node[p], target.surface.facets[pass.tie_facet[p]],
                     quad_shape(pass.tie_xi[p], pass.tie_eta[p])});
    }
  }
  return out;
}

bool InterfaceImpl::needs_rebuild(const ContactInput& in) const {
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

Vec3 InterfaceImpl::point_at(const Side& own, std::size_t p, const ContactInput& in) const {
  const std::int32_t node = own.point_node[p];
  return node >= 0
             ? Vec3{in.x[node], in.y[node], in.z[node]}
             : quad_point(quad_corners(own.surface.facets[own.point_facet[p]], in.x, in.y, in.z),
                          own.point_xi[p], own.point_eta[p]);
}

InterfaceImpl::PointPositions InterfaceImpl::point_positions(const Side& own,
                                                             const ContactInput& in) const {
  const std::size_t n = own.point_facet.size();
  PointPositions q{std::vector<double>(n), std::vector<double>(n), std::vector<double>(n)};
#pragma omp parallel for schedule(static) if (n >= static_cast <std::size_t>(kParallelMinimum))
  for (std::size_t p = 0; p < n; ++p) {
    const Vec3 x = point_at(own, p, in);
    q.x[p] = x.x;
    q.y[p] = x.y;
    q.z[p] = x.z;
  }
  return q;
}

std::vector<Box> InterfaceImpl::cell_regions(const Side& own, const ContactInput& in) const {
  const std::size_t n = own.point_facet.size();
  std::vector<Box> regions(n);
#pragma omp parallel for schedule(static) if (n >= static_cast <std::size_t>(kParallelMinimum))
  for (std::size_t p = 0; p < n; ++p) {
    Box& r = regions[p];
    if (own.point_node[p] >= 0) {
      const std::int32_t i = own.point_node[p];
      r.lo = r.hi = {in.x[i], in.y[i], in.z[i]};
      continue;
    }
    const QuadCorners c = quad_corners(own.surface.facets[own.point_facet[p]], in.x, in.y, in.z);
    const CellBounds b = own.cell(p);
    r.lo = {kInfinity, kInfinity, kInfinity};
    r.hi = {-kInfinity, -kInfinity, -kInfinity};
    for (const double xi : {b.xi0, b.xi1})
      for (const double eta : {b.eta0, b.eta1}) {
        const Vec3 x = quad_point(c, xi, eta);
        const double v[3] = {x.x, x.y, x.z};
        for (int k = 0; k < 3; ++k) {
          r.lo[k] = std::min(r.lo[k], v[k]);
          r.hi[k] = std::max(r.hi[k], v[k]);
        }
      }
  }
  return regions;
}

void InterfaceImpl::rebuild_broad_phase(const ContactInput& in) {
  const double above =
      std::max(settings_.adhesion ? settings_.adhesion->zone() : 0.0, settings_.edge_tolerance);
  for (Pass& pass : passes_) {
    const Side& own = sides_[pass.own];
    const Side& target = sides_[pass.target];
    // A solid facet's box: the facet swept along its normals through the detection depth (and
    // the zone above it), widened by the search margin and the edge tolerance, and across its
    // sharp and free edges by kOnBorder of its diagonal: a point can meet it only there
    // (narrow_phase.cpp). Beyond a smooth edge the neighbour's box covers the dead zone. Not
    // grown by the depth sideways: the long sides of a slab lie side by side, and each of their
    // points would see all of them (issue 28). A shell facet's edges are rounded: its box grows
    // by the depth every way.
    std::vector<Box> boxes(target.surface.size());
    for (std::size_t f = 0; f < boxes.size(); ++f) {
      const QuadCorners c = quad_corners(target.surface.facets[f], in.x, in.y, in.z);
      const double gaps = target.facet_gap[f] + own.max_point_gap;
      const double deep = std::max(target.depth[f], above) + margin_ + gaps;
      const bool shell = target.surface.twin[f] >= 0;
      const double aside = shell ? deep : margin_ + gaps + settings_.edge_tolerance;
      Box& box = boxes[f];
      box.lo = {kInfinity, kInfinity, kInfinity};
      box.hi = {-kInfinity, -kInfinity, -kInfinity};
      auto include = [&box](const Vec3& x) {
        const double v[3] = {x.x, x.y, x.z};
        for (int k = 0; k < 3; ++k) {
          box.lo[k] = std::min(box.lo[k], v[k]);
          box.hi[k] = std::max(box.hi[k], v[k]);
        }
      };
      // The corners, moved across the facet's sharp and free edges (edge e runs from corner e
      // to corner e + 1, as quad.cpp numbers the crossed edges).
      std::array<Vec3, 4> corners = c;
      const unsigned borders = shell ? 0u : (target.sharp[f] | target.free_edges[f]);
      const double across = kOnBorder * norm(c[2] - c[0]);
      const Vec3 centre = (c[0] + c[1] + c[2] + c[3]) * 0.25;
      for (int e = 0; e < 4; ++e) {
        if (!(borders & (1u << e))) continue;
        const Vec3& a = c[e];
        const Vec3& b = c[(e + 1) % 4];
        const Vec3 edge_middle = (a + b) * 0.5;
        Vec3 out = (edge_middle - centre) - (b - a) * (dot(edge_middle - centre, b - a) /
                                                       std::max(dot(b - a, b - a), 1e-300));
        const double length = norm(out);
        if (!(length > 0.0)) continue;
        out = out * (across / length);
        corners[e] += out;
        corners[(e + 1) % 4] += out;
      }
      const Vec3 centre_normal = quad_centre_normal(c);
      const double xi[4] = {-1.0, 1.0, 1.0, -1.0}, eta[4] = {-1.0, -1.0, 1.0, 1.0};
      for (int a = 0; a < 4; ++a) {
        double jacobian = 0.0;
        const Vec3 corner_normal = quad_normal(c, xi[a], eta[a], jacobian);
        for (const Vec3& n : {centre_normal, corner_normal}) {
          if (shell || !(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z))) continue;
          include(corners[a] + n * deep);
          include(corners[a] - n * deep);
        }
        include(corners[a]);
      }
      for (int k = 0; k < 3; ++k) {
        box.lo[k] -= aside;
        box.hi[k] += aside;
      }
    }
    pass.grid.build(boxes);
    // Facets that share a node with the point's own never touch it (narrow_phase.hpp): dropped
    // here once per build instead of at every step, so that in self contact the points on a
    // smooth surface have no candidate at all.
    const auto keep = [&own, &target](std::size_t p, std::int32_t f) {
      const auto mine = own.point_nodes(p);
      for (const std::int32_t a : target.surface.facets[f])
        for (const std::int32_t b : mine)
          if (a == b) return false;
      return true;
    };
    if (own.point_cell.empty()) {
      const PointPositions q = point_positions(own, in);
      pass.grid.query(q.x, q.y, q.z, pass.candidates, keep);
    } else {
      // An S2S point acts with the part of its cell over the other surface (cell_cover.cpp):
      // its candidates are the facets whose boxes overlap its cell's.
      pass.grid.query(cell_regions(own, in), pass.candidates, keep);
    }
  }
  rebuild_pending_ = false;
  awake_current_ = false;
  update_near_bound();
  update_near_facets();
  if (edges_) edges_->rebuild(in.x, in.y, in.z);
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

void InterfaceImpl::update_moving_region(const ContactInput& in) {
  if (!settings_.moving_region) return;
  for (Side& side : sides_)
    for (std::size_t f = 0; f < side.surface.size(); ++f) {
      if (side.off[f] & kOutsideRegion) continue;
      const Vec3 centre =
          quad_point(quad_corners(side.surface.facets[f], in.x, in.y, in.z), 0.0, 0.0);
      if (!settings_.moving_region(centre.x, centre.y, centre.z)) {
        side.off[f] |= kOutsideRegion;
        side.active[f] = 0;
      }
    }
}

// The settings, surfaces, parts and initial coordinates come from the caller; everything else
// evolves (erosion adds points and switches facets off; the region switches facets off).
// The points with a candidate facet change only at a broad-phase build: their bound before
// touching is gathered then, not at every step (scatter adds the points that touch).
void InterfaceImpl::update_near_bound() {
  near_omega2_ = 0.0;
  for (const Pass& pass : passes_)
    for (std::size_t p = 0; p + 1 < pass.candidates.offsets.size(); ++p)
      if (pass.candidates.offsets[p] != pass.candidates.offsets[p + 1])
        near_omega2_ = std::max(near_omega2_, pass.approach_omega2[p]);
}

void InterfaceImpl::archive(StateArchive& a) {
  a.mark("contact interface");
  a.expect(static_cast<std::uint64_t>(sides_.size()), "the side count of a contact");
  a.expect(static_cast<std::uint64_t>(passes_.size()), "the passes of a contact (one way or both)");
  for (Side& side : sides_)
    a.expect(static_cast<std::uint64_t>(side.surface.size()), "the facet count of a contact");
  for (const std::uint64_t points : initial_points_)
    a.expect(points, "the contact points of a side as built");
  a.expect(settings_.thermal.any(), "whether a contact exchanges heat");
  a.values(sides_, passes_, mass_, bx_, by_, bz_, wear_, pressure_, damping_fx_, damping_fy_,
           damping_fz_, margin_, initial_stable_step_, builds_, rebuild_pending_, gap_pairs_,
           edges_, kink_scale_, kink_hold_, kink_elastic_, stats_);
  if (!a.saving()) {
    awake_current_ = false;
    update_near_bound();
    update_near_facets();
  }
}

double InterfaceImpl::spring_step(double omega2) const {
  if (!(omega2 > 0.0)) return kInfinity;
  const double xi = settings_.damping;
  return 2.0 / std::sqrt(omega2) * (std::sqrt(1.0 + xi * xi) - xi);
}

double InterfaceImpl::approach_spring_step(double omega2) const {
  return spring_step(spring_factor_ * omega2);
}

void InterfaceImpl::book_damping(const ContactInput& in) {
  if (in.vx.empty()) return;
  double power = 0.0;  // of the damping forces on the nodes (< 0: they dissipate)
  for (const auto i : surface_nodes_) power += damping_power(i, in);
  stats_.damping_energy -= 0.5 * power * in.dt;
}

std::vector<PairStiffness> InterfaceImpl::pair_stiffness() const {
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

void InterfaceImpl::apply(const ContactInput& in, ContactForces& out) {
  const std::size_t node_count = mass_.size();
  for (std::size_t size : {in.x.size(), in.y.size(), in.z.size(), in.vx.size(), in.vy.size(),
                           in.vz.size(), out.fx.size(), out.fy.size(), out.fz.size()})
    if (size < node_count)
      throw std::invalid_argument(
          "ContactInterface::apply: nodal arrays shorter than the node masses");
  const double spring_energy = stats_.elastic_energy;  // of the last step
  stats_.force = {};
  stats_.normal_force = stats_.tangential_force = stats_.elastic_energy = stats_.max_penetration =
      0.0;
  stats_.active_points = 0;  // heat_flow: set by conduct_heat, which may follow on its own clock
  stats_.stable_step = stats_.kink_step = kInfinity;
  // A normal penalty that grows in time (Metafor PEN_NORMALE TM) stiffens every spring by f(t):
  // the bounds made with the springs of factor 1 (approach, near points, the initial bound) shrink
  // by sqrt(f) (approach_spring_step); touching points carry f in their own springs. f below 1
  // is not taken: those bounds stay those of factor 1.
  spring_factor_ = std::max(settings_.normal_in_time.at(in.time), 1.0);
  // Far from every facet a point cannot touch before the next broad-phase build sees it, as long
  // as no node crosses a quarter of the search margin in one step; at rest (no speed to judge
  // by) the bound before touching holds as before contact. Last step's damping forces did the
  // other half of their work over the step just taken (book_damping), and are cleared.
  double speed2 = 0.0, power = 0.0, kinetic = 0.0;
  for (auto i : surface_nodes_) {
    pressure_[i] = 0.0;
    if (!in.vx.empty()) {
      const double v2 = in.vx[i] * in.vx[i] + in.vy[i] * in.vy[i] + in.vz[i] * in.vz[i];
      speed2 = std::max(speed2, v2);
      kinetic += 0.5 * mass_[i] * v2;
      power += damping_power(i, in);
    }
    damping_fx_[i] = damping_fy_[i] = damping_fz_[i] = 0.0;
  }
  stats_.damping_energy -= 0.5 * power * in.dt;
  kink_scale_ = std::max({kink_scale_, kinetic + spring_energy, in.energy_scale});
  // Edge-to-edge springs and contacts outside their time window (points may lie anywhere when it
  // opens) keep the bound everywhere.
  const bool outside_window =
      !enabled_ || in.time < settings_.begin_time || in.time > settings_.end_time;
  stats_.approach_step = speed2 > 0.0 && !edges_ && !outside_window
                             ? std::max(initial_stable_step(), 0.25 * margin_ / std::sqrt(speed2))
                             : initial_stable_step();
  if (outside_window) {
    for (Pass& pass : passes_) {  // outside the window: no forces and no friction memory
      for (std::size_t p = 0; p < pass.hit.size(); ++p)  // the springs let go (point order)
        if (pass.hit[p]) {
          stats_.released_energy += pass.weight * pass.energy[p];
          pass.hit[p] = 0;
        }
      std::fill(pass.htx.begin(), pass.htx.end(), 0.0);
      std::fill(pass.hty.begin(), pass.hty.end(), 0.0);
      std::fill(pass.htz.begin(), pass.htz.end(), 0.0);
      std::fill(pass.slip.begin(), pass.slip.end(), 0.0);
    }
    return;
  }
  update_moving_region(in);
  if (rebuild_pending_ || needs_rebuild(in)) rebuild_broad_phase(in);
  update_bands(in);
  bands_current_ = true;
  // While the surfaces move, a point near a facet holds the step to its spring's bound only once
  // it may touch in the next step (approach_limit); at rest and with edge-to-edge springs the
  // bound holds for every point near a facet (near_omega2_). So it does while the caller's step
  // is below half that bound: the bound does not limit the caller then (its own safety factor on
  // the step taken into account), and sparing the points' look at their candidates costs at most
  // one step at the bound once the caller's other limits rise above it.
  const double near_spring_step = approach_spring_step(near_omega2_);
  const bool per_point = speed2 > 0.0 && !edges_ && in.dt >= 0.5 * near_spring_step;
  const double speed = std::sqrt(speed2);
  const bool kinks = speed2 > 0.0 && bounds_kinks();
  double near_step = kInfinity;
  // Quiet points stay so until the next build: after a build every point is evaluated once and
  // the others listed; until the next one only those are.
  for (Pass& pass : passes_) {
    const bool every = !awake_current_;
    const std::size_t n = every ? pass.state.size() : pass.awake.size();
#pragma omp parallel for schedule(dynamic, 256) \
    reduction(min                               \
              : near_step) if (n >= static_cast <std::size_t>(kParallelMinimum) / 4)
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t p = every ? k : static_cast<std::size_t>(pass.awake[k]);
      evaluate_point(pass, p, in);
      if (kinks && !pass.hit[p]) pass.kink[p] = onset_kink(pass, p, in, speed);
      if (per_point) near_step = std::min(near_step, approach_limit(pass, p, in, speed, near_step));
    }
    if (every) {
      pass.awake.clear();
      for (std::size_t p = 0; p < pass.state.size(); ++p)
        if (!quiet(pass, p)) pass.awake.push_back(static_cast<std::int32_t>(p));
    }
  }
  awake_current_ = true;
  bands_current_ = false;
  scatter(in, out, !per_point);
  stats_.approach_step = std::min(stats_.approach_step, near_step);
  if (settings_.thermal.any()) scatter_heat(in, out);
  if (edges_) {
    const EdgeContactResult e =
        edges_->apply(in.x, in.y, in.z, in.vx, in.vy, in.vz, mass_, out.fx, out.fy, out.fz,
                      damping_fx_, damping_fy_, damping_fz_);
    stats_.force += Vec3{e.force_on_first[0], e.force_on_first[1], e.force_on_first[2]};
    stats_.normal_force += e.normal_force;
    stats_.elastic_energy += e.elastic_energy;
    stats_.max_penetration = std::max(stats_.max_penetration, e.max_penetration);
    stats_.active_points += e.active_pairs;
    if (e.omega2 > 0.0) stats_.stable_step = std::min(stats_.stable_step, spring_step(e.omega2));
  }
  book_damping(in);  // this step's damping forces (points and edges), the first half of their work
}

void InterfaceImpl::mark_secondary_nodes_in_contact(std::span<std::uint8_t> touched) const {
  for (const Pass& pass : passes_) {
    if (pass.own != 0) continue;  // surface 2's points (symmetric contact) are main nodes
    const Side& side = sides_[0];
    for (std::size_t p = 0; p < pass.hit.size(); ++p)
      if (pass.hit[p])
        for (const std::int32_t n : side.point_nodes(p)) touched[static_cast<std::size_t>(n)] = 1;
  }
}

}  // namespace abut
