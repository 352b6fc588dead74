// Scatter: the forces of the evaluated points to the nodes, serially in point order (so the sums
// do not depend on the thread count), with the interface's statistics, nodal pressure and wear.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "abut/contact/quad.hpp"
#include "interface_impl.hpp"

namespace abut {
namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
}  // namespace

void InterfaceImpl::scatter(const ContactInput& in, ContactForces& out, bool near_bound) {
  const WearRateFunction* wear_rate[2] = {&settings_.wear_rate1, &settings_.wear_rate2};
  if (self_contact() && !settings_.wear_rate1) wear_rate[0] = &settings_.wear_rate2;
  // ContactStats::approach_step: the points that touch, and those near a facet (update_near_bound)
  // where their bound holds throughout.
  double omega2_max = 0.0, approach_omega2 = near_bound ? near_omega2_ : 0.0;
  double kink = 0.0;   // sum of (1/8) k v_n^2 (ContactStats::kink_step)
  double power = 0.0;  // of the contact forces on the nodes
  // Serial, in point order: the sums do not depend on the thread count.
  for (Pass& pass : passes_) {
    const Side& own = sides_[pass.own];
    const Side& target = sides_[pass.target];
    const double w = pass.weight;
    for (const std::int32_t awake : pass.awake) {  // a quiet point has no partner
      const auto p = static_cast<std::size_t>(awake);
      kink += w * pass.kink[p];
      if (pass.released[p] != 0.0) {  // springs that let go in this step (evaluate_point)
        stats_.released_energy += w * pass.released[p];
        pass.released[p] = 0.0;
      }
      // N2S: the other walls of a concave corner; the node's springs add up (stable step).
      const double corner_omega2 = pass.corner.empty() ? 0.0 : scatter_corner(pass, p, out);
      omega2_max = std::max(omega2_max, corner_omega2 + (pass.hit[p] ? pass.omega2[p] : 0.0));
      if (!pass.hit[p]) continue;
      const auto own_nodes = own.point_nodes(p);
      const auto& target_nodes = target.surface.facets[pass.hit_facet[p]];
      const auto n_own = quad_shape(own.point_xi[p], own.point_eta[p]);
      const auto n_target = quad_shape(pass.hit_xi[p], pass.hit_eta[p]);
      const Vec3 force = Vec3{pass.fx[p], pass.fy[p], pass.fz[p]} * w;
      // Action on the point's nodes, reaction on the partner facet's nodes at the projection;
      // an integration point's over its cell and the facets the cell covers (mortar.hpp).
      const int covered = pass.mortar_count.empty() ? 0 : pass.mortar_count[p];
      std::array<double, 4> spread_own = n_own;
      if (covered > 0)
        for (int a = 0; a < 4; ++a) spread_own[a] = pass.mortar_own[4 * p + a];
      const Vec3 damping = Vec3{pass.dfx[p], pass.dfy[p], pass.dfz[p]} * w;
      for (int a = 0; a < 4; ++a) {
        out.add(own_nodes[a], force * spread_own[a]);
        add_damping(own_nodes[a], damping * spread_own[a]);
      }
      // The reaction on the facets of the other surface: (facet, weights) per covered facet.
      auto each_target = [&](auto&& visit) {
        if (covered == 0) {
          visit(target_nodes, n_target.data());
          return;
        }
        for (int k = 0; k < covered; ++k) {
          const std::size_t slot = kMaxOverlaps * p + static_cast<std::size_t>(k);
          visit(target.surface.facets[pass.mortar_facet[slot]], &pass.mortar_target[4 * slot]);
        }
      };
      Vec3 v_rel;  // the velocity of the force's own side relative to the other (its power)
      for (int a = 0; a < 4 && !in.vx.empty(); ++a) {
        const std::int32_t i = own_nodes[a];
        v_rel += Vec3{in.vx[i], in.vy[i], in.vz[i]} * spread_own[a];
      }
      each_target([&](const std::array<std::int32_t, 4>& nodes, const double* weights) {
        for (int a = 0; a < 4; ++a) {
          out.add(nodes[a], force * -weights[a]);
          add_damping(nodes[a], damping * -weights[a]);
          if (!in.vx.empty())
            v_rel -= Vec3{in.vx[nodes[a]], in.vy[nodes[a]], in.vz[nodes[a]]} * weights[a];
        }
      });
      power += dot(force, v_rel);
      if (pass.own == 0) stats_.force += force;
      if (pass.target == 0) stats_.force -= force;
      stats_.normal_force += w * pass.normal_force[p];
      stats_.tangential_force += w * pass.tangential_force[p];
      stats_.elastic_energy += w * pass.energy[p];
      stats_.friction_energy += w * pass.slip_work[p];
      stats_.max_penetration = std::max(stats_.max_penetration, pass.penetration[p]);
      if (gap_pairs_ == 0 || pass.pair_gap[p] < stats_.gap_min) stats_.gap_min = pass.pair_gap[p];
      if (gap_pairs_ == 0 || pass.pair_gap[p] > stats_.gap_max) stats_.gap_max = pass.pair_gap[p];
      ++gap_pairs_;
      ++stats_.active_points;
      omega2_max = std::max(omega2_max, pass.omega2[p]);
      approach_omega2 = std::max(approach_omega2, pass.approach_omega2[p]);

      // Nodal pressure and wear: area-weighted averages over each node's tributary area.
      const double load = w * pass.area[p];
      for (int a = 0; a < 4; ++a)
        pressure_[own_nodes[a]] +=
            load * spread_own[a] * pass.pressure[p] / own.node_area[own_nodes[a]];
      each_target([&](const std::array<std::int32_t, 4>& nodes, const double* weights) {
        for (int a = 0; a < 4; ++a)
          pressure_[nodes[a]] += load * weights[a] * pass.pressure[p] / target.node_area[nodes[a]];
      });
      const WearRateFunction& own_rate = *wear_rate[self_contact() ? 0 : pass.own];
      const WearRateFunction& target_rate = *wear_rate[self_contact() ? 0 : pass.target];
      if (own_rate) {
        const double dose = load * own_rate(pass.pressure[p], pass.slip_speed[p]) * in.dt;
        for (int a = 0; a < 4; ++a)
          wear_[own_nodes[a]] += dose * spread_own[a] / own.node_area[own_nodes[a]];
      }
      if (target_rate) {
        const double dose = load * target_rate(pass.pressure[p], pass.slip_speed[p]) * in.dt;
        each_target([&](const std::array<std::int32_t, 4>& nodes, const double* weights) {
          for (int a = 0; a < 4; ++a)
            wear_[nodes[a]] += dose * weights[a] / target.node_area[nodes[a]];
        });
      }
    }
  }
  if (omega2_max > 0.0) stats_.stable_step = spring_step(omega2_max);
  // The step a kink asked for holds while the springs hold a noticeable share of the energy: a
  // step that changes under a loaded stiff spring changes its energy too (central differences
  // conserve (1/2) k x^2 + (1/2) m v^(n-1/2) v^(n+1/2) at each constant step, a quantity that
  // differs from step to step by about (1/8) m a^2 dt^2).
  double kink_step =
      kink > 0.0 && kink_scale_ > 0.0 ? std::sqrt(kKinkShare * kink_scale_ / kink) : kInfinity;
  // So it does while they load. Unloading, it grows by no more than a step dt' - dt that changes
  // the energy by kKinkShare / 20 of the energy in play: a step that grows under forces F changes
  // it at once by about F . v (dt' - dt) / 2 (the kick's impulse over the mean of the two steps),
  // first order in F, however small the spring energy is just after the touch or before the last
  // point lets go.
  if (stats_.elastic_energy > kKinkShare * kink_scale_ || stats_.elastic_energy > kink_elastic_)
    kink_step = std::min(kink_step, kink_hold_);
  else if (std::abs(power) > 0.0)
    kink_step = std::min(kink_step, kink_hold_ + 0.1 * kKinkShare * kink_scale_ / std::abs(power));
  stats_.kink_step = kink_hold_ = kink_step;
  kink_elastic_ = stats_.elastic_energy;
  if (approach_omega2 > 0.0)
    stats_.approach_step = std::min(stats_.approach_step, approach_spring_step(approach_omega2));
}

}  // namespace abut
