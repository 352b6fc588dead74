// The other walls of a concave corner that a node presses besides its partner (corner_walls.hpp):
// one frictionless penalty spring per wall, along that wall's normal, with the wall's share of the
// node's area, so that the node's potential is the sum of the walls' (conservative, and continuous
// as the closest wall changes). Writes the point's own slots only (points run in parallel).
#include <algorithm>
#include <cmath>

#include "abut/contact/quad.hpp"
#include "interface_impl.hpp"

namespace abut {

void InterfaceImpl::press_corner_walls(Pass& pass, std::size_t p, const PointFrame& f,
                                       const Partner& h, const ContactInput& in) {
  const ContactSettings& s = settings_;
  // The ordinary contact of pushing springs; a free node (no normal, no vector area) and a point
  // with an initial offset (measured against its partner alone) keep their partner only.
  if (s.sense != ContactSense::Positive || s.adhesion || f.free || pass.offset[p] != 0.0) return;
  const Side& own = sides_[pass.own];
  const Side& target = sides_[pass.target];
  const auto first = pass.candidates.offsets[p], last = pass.candidates.offsets[p + 1];
  const CornerWalls walls =
      find_corner_walls(target_facets(target, target.depth, in, bands_current_),
                        {pass.candidates.facets.data() + first, last - first}, f.nodes, f.x,
                        f.normal, partner_rules(own, p), h, sharp_cos_);
  const double m_own = mass_[f.nodes[0]];
  for (std::size_t k = 0; k < walls.count; ++k) {
    const Partner& wall = walls.walls[k];
    // The part of the node's tributary area that faces this wall (enforcement.cpp, facing_area).
    const double area = f.two_sided ? std::abs(dot(f.vector_area, wall.normal))
                                    : std::max(-dot(f.vector_area, wall.normal), 0.0);
    const double penetration = -wall.gap - pass.shift_at(p);
    if (!(area > 0.0) || !(penetration > 0.0)) continue;
    const double spring_k = spring(own, p, area, target, wall.facet);
    const NormalResponse response =
        scaled(evaluate(s.normal_law, penetration, spring_k / area), s.normal_in_time.at(in.time));
    const double k_n = response.stiffness * area;
    // Damping as for the partner: a fraction of critical, 2 xi sqrt(k m), m the reduced mass of the
    // node and the wall's nodal masses at the projection (enforcement.cpp).
    const auto& nodes = target.surface.facets[wall.facet];
    const auto shape = quad_shape(wall.xi, wall.eta);
    const double m = reduced_mass(m_own, mass_share(target, nodes, shape, area));
    const double c = 2.0 * s.damping * std::sqrt(k_n * m);
    const double v_n = dot(f.v - velocity_at(nodes, shape, in), wall.normal);  // < 0: approaching
    const double elastic = response.pressure * area;
    const double fn = std::max(elastic - c * v_n, 0.0);  // damping never pulls
    CornerPress& press = pass.corner[p * kMaxCornerWalls + k];
    press.facet = wall.facet;
    press.xi = wall.xi;
    press.eta = wall.eta;
    press.force = wall.normal * fn;
    press.normal_force = fn;
    press.area = area;
    press.energy = response.energy * area;
    press.damping = wall.normal * (fn - elastic);
    press.penetration = penetration;
    press.omega2 = m > 0.0 ? k_n / m : 0.0;
  }
}

double InterfaceImpl::scatter_corner(const Pass& pass, std::size_t p, ContactForces& out) {
  const Side& own = sides_[pass.own];
  const Side& target = sides_[pass.target];
  const std::int32_t node = own.point_node[p];
  double omega2 = 0.0;
  bool pressed = false;
  for (std::size_t k = 0; k < kMaxCornerWalls; ++k) {
    const CornerPress& press = pass.corner[p * kMaxCornerWalls + k];
    if (press.facet < 0) continue;
    pressed = true;
    const Vec3 force = press.force * pass.weight;
    const auto& nodes = target.surface.facets[press.facet];
    const auto shape = quad_shape(press.xi, press.eta);
    out.add(node, force);
    for (int a = 0; a < 4; ++a) out.add(nodes[a], force * -shape[a]);
    if (pass.own == 0) stats_.force += force;
    if (pass.target == 0) stats_.force -= force;
    stats_.normal_force += pass.weight * press.normal_force;
    stats_.elastic_energy += pass.weight * press.energy;
    add_damping(node, press.damping * pass.weight);
    for (int a = 0; a < 4; ++a) add_damping(nodes[a], press.damping * (-pass.weight * shape[a]));
    stats_.max_penetration = std::max(stats_.max_penetration, press.penetration);
    // Nodal pressure: area-weighted over each node's tributary area, as scatter() does (the
    // pressure fn / area times the area).
    const double load = pass.weight * press.normal_force;
    pressure_[node] += load / own.node_area[node];
    for (int a = 0; a < 4; ++a) pressure_[nodes[a]] += load * shape[a] / target.node_area[nodes[a]];
    omega2 += press.omega2;
  }
  if (pressed && !pass.hit[p]) ++stats_.active_points;
  return omega2;
}

}  // namespace abut
