// The heat balance of a steady state: see steady_heat_balance.hpp.
#include "steady_heat_balance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "solver/heat/heat_impl.hpp"  // detail::nodal_areas, the face loads' quadrature

namespace abut {

namespace {

// The flux of a *LOAD_THERMAL_SURFACE at time t [power / area], read as the heat solver reads it:
// scale x curve(t), the scale alone without a curve.
double flux_at(const Model& model, const SurfaceHeatFlux& f, double t) {
  if (!f.curve.valid()) return f.scale;
  Variables v;
  v.t = t;
  return f.scale * model.functions.value(f.curve, t, v);
}

// Adds a nodal flow to the term it belongs to: in when positive, out when negative.
void add_flow(double flow, double& in, double& out) { (flow > 0.0 ? in : out) += flow; }

}  // namespace

double SteadyHeatBalance::largest_flow() const {
  return std::max({std::abs(boundary_in), std::abs(boundary_out), std::abs(prescribed_in),
                   std::abs(prescribed_out)});
}

double SteadyHeatBalance::relative_error() const {
  const double scale = largest_flow();
  return heat_flows && scale > 0.0 ? error() / scale : 0.0;
}

SteadyHeatBalance steady_heat_balance(const Model& model, double t, std::span<const double> x,
                                      std::span<const double> y, std::span<const double> z,
                                      std::span<const double> temperature,
                                      std::span<const double> inflow) {
  const std::size_t n = temperature.size();
  SteadyHeatBalance b;
  // Heat flows when temperatures differ or a flux acts (SteadyHeatBalance::heat_flows).
  double coldest = std::numeric_limits<double>::infinity(), hottest = -coldest;
  const auto spread = [&](double value) {
    coldest = std::min(coldest, value);
    hottest = std::max(hottest, value);
  };
  bool flux = false;
  std::vector<double> face(n, 0.0);  // what the face loads bring to each node
  for (const SurfaceHeatFlux& f : model.thermal.fluxes) {
    const double q = flux_at(model, f, t);
    flux = flux || (q != 0.0 && !f.faces.empty());
    for (const auto& quad : f.faces) {
      const auto w = detail::nodal_areas(quad, x, y, z);
      for (int a = 0; a < 4; ++a) face[static_cast<std::size_t>(quad[a])] += q * w[a];
    }
  }
  for (const SurfaceConvection& c : model.thermal.convection) {
    if (!c.faces.empty()) spread(c.ambient);
    for (const auto& quad : c.faces) {
      const auto w = detail::nodal_areas(quad, x, y, z);
      for (int a = 0; a < 4; ++a) {
        const auto node = static_cast<std::size_t>(quad[a]);
        face[node] += c.coefficient * (c.ambient - temperature[node]) * w[a];
      }
    }
  }
  std::vector<std::uint8_t> held(n, 0);  // a node two conditions hold counts once
  for (const PrescribedTemperature& p : model.thermal.prescribed)
    for (const std::int32_t node : p.nodes) held[static_cast<std::size_t>(node)] = 1;
  const std::vector<std::uint8_t> thermal = thermal_node_flags(model);
  for (std::size_t a = 0; a < n; ++a)
    if (thermal[a]) spread(temperature[a]);
  constexpr double kRoundOff = 1e-9;  // of the temperatures' size: well above the solve's error
  b.heat_flows =
      flux || hottest - coldest > kRoundOff * std::max(std::abs(hottest), std::abs(coldest));
  for (std::size_t a = 0; a < n; ++a) {
    add_flow(face[a], b.boundary_in, b.boundary_out);
    // A held node's equation is not solved: its reaction is the heat that makes it balance.
    if (held[a]) add_flow(-(inflow[a] + face[a]), b.prescribed_in, b.prescribed_out);
  }
  return b;
}

}  // namespace abut
