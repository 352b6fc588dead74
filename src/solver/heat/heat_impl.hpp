#pragma once
// The state of the heat solver (heat.hpp), shared by the transient step (heat_solver.cpp) and the
// steady state (steady_heat.cpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "abut/contact/quad.hpp"
#include "abut/element/thermal_block.hpp"
#include "abut/solver/heat.hpp"

namespace abut {

namespace detail {

// int N_a dA over a face (bilinear quad, 2 x 2 Gauss points) at the given coordinates: the share
// of a uniform face load that goes to each of its nodes.
inline std::array<double, 4> nodal_areas(const std::array<std::int32_t, 4>& face,
                                         std::span<const double> x, std::span<const double> y,
                                         std::span<const double> z) {
  const QuadCorners c = quad_corners(face, x, y, z);
  const double g = 1.0 / std::sqrt(3.0);
  std::array<double, 4> w{};
  for (const double xi : {-g, g})
    for (const double eta : {-g, g}) {
      double jacobian = 0.0;
      quad_normal(c, xi, eta, jacobian);
      const auto n = quad_shape(xi, eta);
      for (int a = 0; a < 4; ++a) w[a] += n[a] * jacobian;
    }
  return w;
}

}  // namespace detail

struct HeatSolver::Impl {
  // scale x curve(t), or scale alone without a curve.
  double amplitude(FunctionRef curve, double scale, double time) const {
    if (!curve.valid()) return scale;
    Variables v;  // a *FUNCTION reads the time as t (a curve takes it as its abscissa)
    v.t = time;
    return scale * model.functions.value(curve, time, v);
  }

  const Model& model;
  std::optional<ThermalBlock> block;
  std::vector<double> t, t0, capacity, rate, conduction;
  std::vector<std::uint8_t> prescribed;
  std::vector<std::uint8_t> thermal;  // per node: of a thermal hex or shell
  HeatBalance balance;
  double stable = std::numeric_limits<double>::infinity();

  explicit Impl(const Model& m) : model(m) {
    const Mesh& mesh = m.mesh;
    const std::size_t n = mesh.nodes.size();
    t.assign(n, m.thermal.initial_temperature);
    capacity.assign(n, 0.0);
    rate.assign(n, 0.0);
    conduction.assign(n, 0.0);
    prescribed.assign(n, 0);
    // The thermal parts and their hexes.
    std::vector<Hex8> hexes;
    std::vector<double> k, rho_c;
    for (std::size_t h = 0; h < mesh.hex_count(); ++h) {
      const ThermalProperties* p = properties_of_part(mesh.hex_part[h]);
      if (!p) continue;
      hexes.push_back(mesh.hexes[h]);
      k.push_back(p->conductivity);
      rho_c.push_back(density_of(m.material_of_part(mesh.hex_part[h])) * p->specific_heat);
    }
    // Shells: conduction in the mid-surface through the part's thickness (shell4_thermal.hpp).
    std::vector<ThermalShell> shells;
    for (std::size_t s = 0; s < mesh.shell_count(); ++s) {
      const ThermalProperties* p = properties_of_part(mesh.shell_part[s]);
      if (!p) continue;
      const Part* part = m.find_part(mesh.shell_part[s]);
      shells.push_back({mesh.shells[s], part->thickness, p->conductivity,
                        density_of(m.material_of_part(part->id)) * p->specific_heat});
    }
    for (const InitialTemperature& i : m.thermal.initial)
      for (const std::int32_t node : i.nodes) t[static_cast<std::size_t>(node)] = i.value;
    thermal = thermal_node_flags(m);  // the nodes of `hexes` and `shells`
    if (!hexes.empty() || !shells.empty()) {
      block.emplace(std::move(hexes), std::move(k), std::move(rho_c), n, std::move(shells));
      const Nodes& x = mesh.nodes;
      block->add_capacity(x.x, x.y, x.z, capacity);
      stable = block->add_conduction(x.x, x.y, x.z, t, conduction);
    }
    auto check_nodes = [&](std::span<const std::int32_t> nodes, const SourceLocation& where) {
      for (const std::int32_t node : nodes)
        if (!thermal[static_cast<std::size_t>(node)])
          throw InputError(where, "node " + std::to_string(mesh.nodes.id[node]) +
                                      " is not in a part with thermal properties (thpid)");
    };
    for (const PrescribedTemperature& p : m.thermal.prescribed) {
      check_nodes(p.nodes, p.where);
      for (const std::int32_t node : p.nodes) {
        prescribed[static_cast<std::size_t>(node)] = 1;
        t[static_cast<std::size_t>(node)] = amplitude(p.curve, p.scale, 0.0);
      }
    }
    for (const SurfaceHeatFlux& f : m.thermal.fluxes)
      for (const auto& face : f.faces) check_nodes(face, f.where);
    for (const SurfaceConvection& c : m.thermal.convection)
      for (const auto& face : c.faces) check_nodes(face, c.where);
    t0 = t;
  }

  const ThermalProperties* properties_of_part(std::int64_t part_id) const {
    const Part* part = model.find_part(part_id);
    if (!part) return nullptr;
    const Material* mat = model.find_material(part->material_id);
    if (!mat || mat->thermal_id == 0) return nullptr;
    const ThermalProperties* p = model.thermal.find(mat->thermal_id);
    if (!p)
      throw InputError(mat->where, "thpid " + std::to_string(mat->thermal_id) + " of material " +
                                       std::to_string(mat->id) + " has no *PROP_THERMAL");
    return p;
  }

  void advance(double time, double dt, std::span<const double> x, std::span<const double> y,
               std::span<const double> z, std::span<const double> source) {
    if (!block) return;
    std::fill(conduction.begin(), conduction.end(), 0.0);
    stable = block->add_conduction(x, y, z, t, conduction);
    rate = conduction;
    double boundary = 0.0;
    for (const SurfaceHeatFlux& f : model.thermal.fluxes) {
      const double q = amplitude(f.curve, f.scale, time);
      for (const auto& face : f.faces) {
        const auto w = detail::nodal_areas(face, x, y, z);
        for (int a = 0; a < 4; ++a) {
          rate[static_cast<std::size_t>(face[a])] += q * w[a];
          boundary += q * w[a];
        }
      }
    }
    for (const SurfaceConvection& c : model.thermal.convection)
      for (const auto& face : c.faces) {
        const auto w = detail::nodal_areas(face, x, y, z);
        for (int a = 0; a < 4; ++a) {
          const auto node = static_cast<std::size_t>(face[a]);
          const double q = c.coefficient * (c.ambient - t[node]) * w[a];
          rate[node] += q;
          boundary += q;
        }
      }
    double sources = 0.0;
    if (!source.empty())
      for (std::size_t i = 0; i < rate.size(); ++i)
        if (capacity[i] > 0.0) {
          rate[i] += source[i];
          sources += source[i];
        }
    for (std::size_t i = 0; i < t.size(); ++i)
      if (capacity[i] > 0.0 && !prescribed[i]) t[i] += dt * rate[i] / capacity[i];
    double held = 0.0;
    for (const PrescribedTemperature& p : model.thermal.prescribed) {
      const double value = amplitude(p.curve, p.scale, time + dt);
      for (const std::int32_t node : p.nodes) {
        const auto i = static_cast<std::size_t>(node);
        held += capacity[i] * (value - t[i]) - dt * rate[i];
        t[i] = value;
        rate[i] = 0.0;  // counted once, even if two conditions hold the node
      }
    }
    balance.boundary += dt * boundary;
    balance.sources += dt * sources;
    balance.prescribed += held;
    double stored = 0.0;
    for (std::size_t i = 0; i < t.size(); ++i) stored += capacity[i] * (t[i] - t0[i]);
    balance.stored = stored;
  }
};

}  // namespace abut
