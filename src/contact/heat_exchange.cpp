// Thermal contact (issue 11): heat conducted between the surfaces and friction work turned into
// heat. A point's conductance G = h A is found with its partner during enforcement (in parallel,
// its own slot); the heat goes to the nodes here, serially in point order, so that the sums do not
// depend on the thread count. Temperatures and heat are interpolated with the same shape functions
// as the forces: the point's own nodes on one side, the partner facet's nodes at the projection on
// the other, so that what one side loses the other gains.
//
// The conduction is linear in the temperatures with the geometry held, so a caller whose thermal
// step is shorter than the mechanical one evaluates it again at each of its thermal steps
// (conduct_heat, issue 29): evaluated once per mechanical step and spread over many thermal
// steps, it is forward Euler at the mechanical step, unstable beyond 2 C / G.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "abut/contact/quad.hpp"
#include "interface_impl.hpp"

namespace abut {

void InterfaceImpl::record_conductance(Pass& pass, std::size_t p, std::int32_t facet, double xi,
                                       double eta, double pressure, double gap, double area) {
  if (!settings_.thermal.conductance) return;
  const double h = conductance(*settings_.thermal.conductance, pressure, gap);
  // A negative or undefined conductance (a user function) conducts nothing: it would let heat
  // flow from cold to hot.
  if (!(h > 0.0) || !(area > 0.0)) return;
  pass.heat_facet[p] = facet;
  pass.heat_xi[p] = xi;
  pass.heat_eta[p] = eta;
  pass.heat_conductance[p] = h * area;
}

template <class Link>
void InterfaceImpl::for_each_heat_link(const Link& link) const {
  for (const Pass& pass : passes_) {
    const Side& own = sides_[pass.own];
    const Side& target = sides_[pass.target];
    for (std::size_t p = 0; p < pass.heat_facet.size(); ++p) {
      const std::int32_t facet = pass.heat_facet[p];
      if (facet < 0) continue;
      link(pass, own.point_nodes(p), quad_shape(own.point_xi[p], own.point_eta[p]),
           target.surface.facets[facet], quad_shape(pass.heat_xi[p], pass.heat_eta[p]),
           pass.weight * pass.heat_conductance[p]);
    }
  }
}

double InterfaceImpl::conduct_heat(std::span<const double> temperature, double duration,
                                   std::span<double> heat) {
  const std::size_t node_count = mass_.size();
  if (heat.size() < node_count || temperature.size() < node_count)
    throw std::invalid_argument(
        "ContactInterface::conduct_heat: temperature or heat arrays shorter than the node masses");
  double flow = 0.0;
  if (settings_.thermal.conductance)
    for_each_heat_link([&](const Pass& pass, const auto& own_nodes, const auto& n_own,
                           const auto& target_nodes, const auto& n_target, double g) {
      double t_own = 0.0, t_target = 0.0;
      for (int a = 0; a < 4; ++a) {
        t_own += n_own[a] * temperature[own_nodes[a]];
        t_target += n_target[a] * temperature[target_nodes[a]];
      }
      const double q = g * (t_own - t_target);  // from the point to its partner [power]
      for (int a = 0; a < 4; ++a) {
        heat[own_nodes[a]] -= q * n_own[a];
        heat[target_nodes[a]] += q * n_target[a];
      }
      // Surface 1 to surface 2 is positive: a pass whose points lie on surface 2 counts the
      // other way (self contact has one side and no direction).
      flow += pass.own == 0 ? q : -q;
    });
  stats_.heat_flow = flow;
  stats_.conducted_heat += flow * duration;
  return flow;
}

void InterfaceImpl::scatter_heat(const ContactInput& in, ContactForces& out) {
  const std::size_t node_count = mass_.size();
  const bool conduction = settings_.thermal.conductance.has_value();
  const bool friction = settings_.thermal.friction_heat && in.dt > 0.0;
  if (out.heat.empty() || (!conduction && !friction)) return;
  if (out.heat.size() < node_count ||
      (!out.conductance.empty() && out.conductance.size() < node_count))
    throw std::invalid_argument(
        "ContactInterface::apply: heat or conductance arrays shorter than the node masses");
  if (conduction && !out.conductance.empty())
    for_each_heat_link([&](const Pass&, const auto& own_nodes, const auto& n_own,
                           const auto& target_nodes, const auto& n_target, double g) {
      for (int a = 0; a < 4; ++a) {
        out.conductance[own_nodes[a]] += g * n_own[a];
        out.conductance[target_nodes[a]] += g * n_target[a];
      }
    });
  if (conduction && !in.temperature.empty()) conduct_heat(in.temperature, in.dt, out.heat);
  if (!friction) return;
  for (const Pass& pass : passes_) {
    const Side& own = sides_[pass.own];
    const Side& target = sides_[pass.target];
    for (std::size_t p = 0; p < pass.heat_facet.size(); ++p) {
      if (!pass.hit[p] || !(pass.slip_work[p] > 0.0)) continue;
      // The friction work of the step as heat [power], shared between the point's side and its
      // partner's (FrictionHeatSplit: to_side1 for surface 1).
      const double work = pass.weight * pass.slip_work[p];
      const FrictionHeatSplit& split = *settings_.thermal.friction_heat;
      const double to_own = pass.own == 0 ? split.side1(work) : split.side2(work);
      const double to_target = work - to_own;
      const auto own_nodes = own.point_nodes(p);
      const auto n_own = quad_shape(own.point_xi[p], own.point_eta[p]);
      const auto& target_nodes = target.surface.facets[pass.hit_facet[p]];
      const auto n_target = quad_shape(pass.hit_xi[p], pass.hit_eta[p]);
      for (int a = 0; a < 4; ++a) {
        out.heat[own_nodes[a]] += to_own / in.dt * n_own[a];
        out.heat[target_nodes[a]] += to_target / in.dt * n_target[a];
      }
      stats_.friction_heat += work;
    }
  }
}

}  // namespace abut
