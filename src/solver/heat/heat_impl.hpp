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
#include "abut/core/error.hpp"
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
  // Per node: temperature, its start, heat capacity; the rates of the planned thermal step
  // [power]: all of them, the elements' conduction, the face loads.
  std::vector<double> t, t0, capacity, rate, conduction, boundary_rate;
  std::vector<std::uint8_t> prescribed;
  std::vector<std::uint8_t> thermal;  // per node: of a thermal hex or shell
  std::vector<double> load_breaks;    // abscissas of the load curves, sorted (next_load_break)
  HeatBalance balance;
  double stable = std::numeric_limits<double>::infinity();

  explicit Impl(const Model& m) : model(m) {
    const Mesh& mesh = m.mesh;
    const std::size_t n = mesh.nodes.size();
    t.assign(n, m.thermal.initial_temperature);
    capacity.assign(n, 0.0);
    rate.assign(n, 0.0);
    conduction.assign(n, 0.0);
    boundary_rate.assign(n, 0.0);
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
                                      " is not in a part with thermal properties (" +
                                      m.sources.words("thermal_properties") + ")");
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
    const auto add_breaks = [&](FunctionRef curve) {
      if (!curve.valid()) return;
      const std::span<const double> x = m.functions.breakpoints(curve);
      load_breaks.insert(load_breaks.end(), x.begin(), x.end());
    };
    for (const PrescribedTemperature& p : m.thermal.prescribed) add_breaks(p.curve);
    for (const SurfaceHeatFlux& f : m.thermal.fluxes) add_breaks(f.curve);
    std::sort(load_breaks.begin(), load_breaks.end());
    load_breaks.erase(std::unique(load_breaks.begin(), load_breaks.end()), load_breaks.end());
  }

  const ThermalProperties* properties_of_part(std::int64_t part_id) const {
    const Part* part = model.find_part(part_id);
    if (!part) return nullptr;
    const Material* mat = model.find_material(part->material_id);
    if (!mat || mat->thermal_id == 0) return nullptr;
    const ThermalProperties* p = model.thermal.find(mat->thermal_id);
    if (!p)
      throw InputError(mat->where, "material " + std::to_string(mat->id) +
                                       ": its thermal properties " +
                                       std::to_string(mat->thermal_id) + " are not defined (give " +
                                       model.sources.words("thermal_properties") + ")");
    return p;
  }

  // Sets the prescribed nodes to their temperatures at `time` and books the heat that takes in.
  void hold(double time) {
    double held = 0.0;
    for (const PrescribedTemperature& p : model.thermal.prescribed) {
      const double value = amplitude(p.curve, p.scale, time);
      for (const std::int32_t node : p.nodes) {
        const auto i = static_cast<std::size_t>(node);
        held += capacity[i] * (value - t[i]);
        t[i] = value;
      }
    }
    balance.prescribed += held;
    balance.stored += held;
  }

  void book_stored() {
    double stored = 0.0, moved = 0.0;
    for (std::size_t i = 0; i < t.size(); ++i) {
      stored += capacity[i] * (t[i] - t0[i]);
      moved += capacity[i] * std::abs(t[i] - t0[i]);
    }
    balance.stored = stored;
    balance.largest = std::max({balance.largest, moved, std::abs(balance.boundary),
                                std::abs(balance.prescribed), std::abs(balance.sources)});
  }

  // Heat into node i (capacity > 0): a held node stays held, the heat counted as taken out by
  // holding it. Returns the heat stored.
  double heat_node(std::size_t i, double heat) {
    if (prescribed[i]) {
      balance.prescribed -= heat;
      return 0.0;
    }
    t[i] += heat / capacity[i];
    return heat;
  }

  // Calls f(i) for the nodes `nodes` (empty: every node) that carry heat capacity.
  template <class F>
  void each_node(std::span<const std::int32_t> nodes, const F& f) const {
    const std::size_t count = nodes.empty() ? t.size() : nodes.size();
    for (std::size_t k = 0; k < count; ++k) {
      const auto i = nodes.empty() ? k : static_cast<std::size_t>(nodes[k]);
      if (capacity[i] > 0.0) f(i);
    }
  }

  void put_heat(std::span<const std::int32_t> nodes, std::span<const double> power, double dt) {
    double sources = 0.0, stored = 0.0;
    each_node(nodes, [&](std::size_t i) {
      const double heat = dt * power[i];
      if (heat == 0.0) return;
      sources += heat;
      stored += heat_node(i, heat);
    });
    balance.sources += sources;
    balance.stored += stored;
  }

  // The rates of the thermal step [time, time + span] at the current temperatures and
  // coordinates: conduction in the elements, the face fluxes at the middle of the span (exact
  // over a span within one segment of a tabulated curve), convection. InstabilityError when they
  // would change a node by more than a stable step can over the span.
  void plan(double time, double span, std::span<const double> x, std::span<const double> y,
            std::span<const double> z, std::span<const double> exchange) {
    if (!block) return;
    std::fill(conduction.begin(), conduction.end(), 0.0);
    stable = block->add_conduction(x, y, z, t, conduction);
    if (!exchange.empty())
      for (std::size_t i = 0; i < t.size(); ++i) conduction[i] += exchange[i];
    std::fill(boundary_rate.begin(), boundary_rate.end(), 0.0);
    // The range of the temperatures the step starts from and of the loads' ambient and held
    // temperatures: conduction changes a node by at most its row sum of |K| times that range over
    // its capacity, which a step within the stable bound keeps to about twice the range; the
    // faces' heat adds its own. A change beyond four times the range plus the faces' share can
    // only be an unstable step.
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (std::size_t i = 0; i < t.size(); ++i)
      if (capacity[i] > 0.0) {
        low = std::min(low, t[i]);
        high = std::max(high, t[i]);
      }
    const double middle = time + 0.5 * span;
    for (const SurfaceHeatFlux& f : model.thermal.fluxes) {
      const double q = amplitude(f.curve, f.scale, middle);
      for (const auto& face : f.faces) {
        const auto w = detail::nodal_areas(face, x, y, z);
        for (int a = 0; a < 4; ++a) boundary_rate[static_cast<std::size_t>(face[a])] += q * w[a];
      }
    }
    for (const SurfaceConvection& c : model.thermal.convection) {
      low = std::min(low, c.ambient);
      high = std::max(high, c.ambient);
      for (const auto& face : c.faces) {
        const auto w = detail::nodal_areas(face, x, y, z);
        for (int a = 0; a < 4; ++a) {
          const auto node = static_cast<std::size_t>(face[a]);
          boundary_rate[node] += c.coefficient * (c.ambient - t[node]) * w[a];
        }
      }
    }
    for (const PrescribedTemperature& p : model.thermal.prescribed) {
      const double value = amplitude(p.curve, p.scale, time + span);
      low = std::min(low, value);
      high = std::max(high, value);
    }
    const double range = high > low ? high - low : 0.0;
    for (std::size_t i = 0; i < t.size(); ++i) {
      rate[i] = conduction[i] + boundary_rate[i];
      if (!(capacity[i] > 0.0) || prescribed[i]) continue;
      const double change = span * rate[i] / capacity[i];
      const double bound = 4.0 * range + span * std::abs(boundary_rate[i]) / capacity[i] +
                           kChangeSlack * (range + std::abs(t[i]));
      if (!std::isfinite(change) || !(std::abs(change) <= bound))
        throw InstabilityError(unstable_message(i, time + span, change, range));
    }
    book_stored();
  }

  // The planned rates over dt on `nodes` (empty: every node).
  void flow(double dt, std::span<const std::int32_t> nodes) {
    double boundary = 0.0, stored = 0.0;
    each_node(nodes, [&](std::size_t i) {
      boundary += dt * boundary_rate[i];
      stored += heat_node(i, dt * rate[i]);
    });
    balance.boundary += boundary;
    balance.stored += stored;
  }

  void advance(double time, double dt, std::span<const double> x, std::span<const double> y,
               std::span<const double> z, std::span<const double> source) {
    if (!block) return;
    plan(time, dt, x, y, z, {});
    if (!source.empty()) put_heat({}, source, dt);
    flow(dt, {});
    hold(time + dt);
    book_stored();
  }

  // Round-off room above the bound of a stable step, relative to the temperatures.
  static constexpr double kChangeSlack = 1e-9;

  std::string unstable_message(std::size_t node, double time, double change, double range) const {
    if (!std::isfinite(change))
      return "the temperature of node " + std::to_string(model.mesh.nodes.id[node]) +
             " is no longer finite at t = " + std::to_string(time) +
             " (its loads or its conduction overflowed)";
    return "the temperature of node " + std::to_string(model.mesh.nodes.id[node]) + " changed by " +
           std::to_string(change) + " in one thermal step to t = " + std::to_string(time) +
           ", beyond what a stable step can do (four times the range " + std::to_string(range) +
           " of the temperatures plus its loads): the heat conduction went unstable";
  }
};

}  // namespace abut
