// Heat conduction over hexahedra: see thermal_block.hpp.
#include "abut/element/thermal_block.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>

#include "abut/element/hex8_thermal.hpp"
#include "abut/element/shell4_thermal.hpp"

namespace abut {

ThermalBlock::ThermalBlock(std::vector<Hex8> hexes, std::vector<double> conductivity,
                           std::vector<double> volumetric_capacity, std::size_t node_count,
                           std::vector<ThermalShell> shells)
    : hexes_(std::move(hexes)),
      conductivity_(std::move(conductivity)),
      capacity_(std::move(volumetric_capacity)),
      shells_(std::move(shells)) {
  const std::size_t shell_base = 8 * hexes_.size();
  element_flow_.assign(shell_base + 4 * shells_.size(), 0.0);
  // Node -> element entries (CSR), hexes then shells in element order; a triangle's repeated
  // node counts once.
  const auto each_entry = [&](auto&& visit) {
    for (std::size_t e = 0; e < hexes_.size(); ++e)
      for (int a = 0; a < 8; ++a) visit(hexes_[e][a], 8 * e + a);
    for (std::size_t e = 0; e < shells_.size(); ++e)
      for (int a = 0; a < (is_triangle(shells_[e].nodes) ? 3 : 4); ++a)
        visit(shells_[e].nodes[a], shell_base + 4 * e + a);
  };
  slot_start_.assign(node_count + 1, 0);
  each_entry([&](std::int32_t n, std::size_t) { ++slot_start_[static_cast<std::size_t>(n) + 1]; });
  for (std::size_t i = 0; i < node_count; ++i) slot_start_[i + 1] += slot_start_[i];
  slots_.resize(static_cast<std::size_t>(slot_start_[node_count]));
  std::vector<std::int32_t> fill(slot_start_.begin(), slot_start_.end() - 1);
  each_entry([&](std::int32_t n, std::size_t entry) {
    slots_[static_cast<std::size_t>(fill[static_cast<std::size_t>(n)]++)] =
        static_cast<std::int32_t>(entry);
  });
}

namespace {

void element_coordinates(const Hex8& h, std::span<const double> x, std::span<const double> y,
                         std::span<const double> z, double X[8][3]) {
  for (int a = 0; a < 8; ++a) {
    const auto n = static_cast<std::size_t>(h[a]);
    X[a][0] = x[n], X[a][1] = y[n], X[a][2] = z[n];
  }
}

void shell_coordinates(const Quad4& q, std::span<const double> x, std::span<const double> y,
                       std::span<const double> z, double X[4][3]) {
  for (int a = 0; a < 4; ++a) {
    const auto n = static_cast<std::size_t>(q[a]);
    X[a][0] = x[n], X[a][1] = y[n], X[a][2] = z[n];
  }
}

}  // namespace

void ThermalBlock::add_capacity(std::span<const double> x, std::span<const double> y,
                                std::span<const double> z, std::span<double> capacity) const {
  for (std::size_t e = 0; e < hexes_.size(); ++e) {
    double X[8][3];
    element_coordinates(hexes_[e], x, y, z, X);
    Hex8Conduction r;
    hex8_conduction(X, conductivity_[e], capacity_[e], r);
    for (int a = 0; a < 8; ++a) capacity[static_cast<std::size_t>(hexes_[e][a])] += r.capacity[a];
  }
  for (const ThermalShell& s : shells_) {
    double X[4][3];
    shell_coordinates(s.nodes, x, y, z, X);
    Shell4Conduction r;
    shell4_conduction(X, is_triangle(s.nodes), s.thickness, s.conductivity, s.volumetric_capacity,
                      r);
    for (int a = 0; a < (is_triangle(s.nodes) ? 3 : 4); ++a)
      capacity[static_cast<std::size_t>(s.nodes[a])] += r.capacity[a];
  }
}

void ThermalBlock::conductance_matrices(std::span<const double> x, std::span<const double> y,
                                        std::span<const double> z,
                                        std::vector<double>& values) const {
  values.assign(64 * hexes_.size() + 16 * shells_.size(), 0.0);
  const auto nh = static_cast<std::int64_t>(hexes_.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t e = 0; e < nh; ++e) {
    const auto k = static_cast<std::size_t>(e);
    double X[8][3];
    element_coordinates(hexes_[k], x, y, z, X);
    Hex8Conduction r;
    hex8_conduction(X, conductivity_[k], capacity_[k], r);
    std::copy(r.conductance, r.conductance + 64, values.begin() + 64 * e);
  }
  const std::size_t base = 64 * hexes_.size();
  for (std::size_t e = 0; e < shells_.size(); ++e) {
    const ThermalShell& s = shells_[e];
    double X[4][3];
    shell_coordinates(s.nodes, x, y, z, X);
    Shell4Conduction r;
    shell4_conduction(X, is_triangle(s.nodes), s.thickness, s.conductivity, s.volumetric_capacity,
                      r);
    std::copy(r.conductance, r.conductance + 16,
              values.begin() + static_cast<std::ptrdiff_t>(base + 16 * e));
  }
}

double ThermalBlock::add_conduction(std::span<const double> x, std::span<const double> y,
                                    std::span<const double> z, std::span<const double> temperature,
                                    std::span<double> heat_rate) {
  const auto n = static_cast<std::int64_t>(hexes_.size());
  double step = std::numeric_limits<double>::infinity();
#pragma omp parallel for schedule(static) reduction(min : step)
  for (std::int64_t e = 0; e < n; ++e) {
    const Hex8& h = hexes_[static_cast<std::size_t>(e)];
    double X[8][3], t[8];
    element_coordinates(h, x, y, z, X);
    for (int a = 0; a < 8; ++a) t[a] = temperature[static_cast<std::size_t>(h[a])];
    Hex8Conduction r;
    hex8_conduction(X, conductivity_[static_cast<std::size_t>(e)],
                    capacity_[static_cast<std::size_t>(e)], r);
    step = std::min(step, r.stable_step);
    for (int a = 0; a < 8; ++a) {
      double flow = 0.0;
      for (int b = 0; b < 8; ++b) flow -= r.conductance[8 * a + b] * t[b];
      element_flow_[static_cast<std::size_t>(8 * e + a)] = flow;
    }
  }
  const auto ns = static_cast<std::int64_t>(shells_.size());
  const std::size_t shell_base = 8 * hexes_.size();
#pragma omp parallel for schedule(static) reduction(min : step)
  for (std::int64_t e = 0; e < ns; ++e) {
    const ThermalShell& s = shells_[static_cast<std::size_t>(e)];
    double X[4][3], t[4];
    shell_coordinates(s.nodes, x, y, z, X);
    for (int a = 0; a < 4; ++a) t[a] = temperature[static_cast<std::size_t>(s.nodes[a])];
    Shell4Conduction r;
    shell4_conduction(X, is_triangle(s.nodes), s.thickness, s.conductivity, s.volumetric_capacity,
                      r);
    step = std::min(step, r.stable_step);
    for (int a = 0; a < 4; ++a) {
      double flow = 0.0;
      for (int b = 0; b < 4; ++b) flow -= r.conductance[4 * a + b] * t[b];
      element_flow_[shell_base + static_cast<std::size_t>(4 * e + a)] = flow;
    }
  }
  const auto nodes = static_cast<std::int64_t>(slot_start_.size() - 1);
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < nodes; ++i) {
    double sum = 0.0;
    for (std::int32_t k = slot_start_[static_cast<std::size_t>(i)];
         k < slot_start_[static_cast<std::size_t>(i) + 1]; ++k)
      sum += element_flow_[static_cast<std::size_t>(slots_[static_cast<std::size_t>(k)])];
    heat_rate[static_cast<std::size_t>(i)] += sum;
  }
  return step;
}

}  // namespace abut
