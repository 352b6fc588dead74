// Heat conduction over hexahedra: see thermal_block.hpp.
#include "abut/element/thermal_block.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>

#include "abut/element/hex8_thermal.hpp"

namespace abut {

ThermalBlock::ThermalBlock(std::vector<Hex8> hexes, std::vector<double> conductivity,
                           std::vector<double> volumetric_capacity, std::size_t node_count)
    : hexes_(std::move(hexes)),
      conductivity_(std::move(conductivity)),
      capacity_(std::move(volumetric_capacity)) {
  element_flow_.assign(8 * hexes_.size(), 0.0);
  // Node -> element entries (CSR), in element order.
  slot_start_.assign(node_count + 1, 0);
  for (const Hex8& h : hexes_)
    for (const std::int32_t n : h) ++slot_start_[static_cast<std::size_t>(n) + 1];
  for (std::size_t i = 0; i < node_count; ++i) slot_start_[i + 1] += slot_start_[i];
  slots_.resize(static_cast<std::size_t>(slot_start_[node_count]));
  std::vector<std::int32_t> fill(slot_start_.begin(), slot_start_.end() - 1);
  for (std::size_t e = 0; e < hexes_.size(); ++e)
    for (int a = 0; a < 8; ++a)
      slots_[static_cast<std::size_t>(fill[hexes_[e][a]]++)] = static_cast<std::int32_t>(8 * e + a);
}

namespace {

void element_coordinates(const Hex8& h, std::span<const double> x, std::span<const double> y,
                         std::span<const double> z, double X[8][3]) {
  for (int a = 0; a < 8; ++a) {
    const auto n = static_cast<std::size_t>(h[a]);
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
