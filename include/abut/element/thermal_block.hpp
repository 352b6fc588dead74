#pragma once
// Heat conduction over a set of hexahedra and shells for the explicit solver: each element's
// conductance at the current coordinates (hex8_thermal.hpp, shell4_thermal.hpp), the heat it draws
// between its nodes at the current temperatures, gathered node by node in element order (so the
// sums, and the results, do not depend on the number of threads), and the smallest element stable
// step of forward Euler.
#include <cstddef>
#include <span>
#include <vector>

#include "abut/mesh/mesh.hpp"

namespace abut {

// A shell of the block: its nodes (a triangle repeats its third), thickness and properties.
struct ThermalShell {
  Quad4 nodes;
  double thickness = 0.0, conductivity = 0.0, volumetric_capacity = 0.0;
};

class ThermalBlock {
 public:
  // Per hex: conductivity k [power / (length temperature)] >= 0 and volumetric heat capacity
  // rho c [energy / (volume temperature)] > 0 (preconditions, checked by the caller); node
  // indices below node_count. Shells likewise, with a thickness > 0.
  ThermalBlock(std::vector<Hex8> hexes, std::vector<double> conductivity,
               std::vector<double> volumetric_capacity, std::size_t node_count,
               std::vector<ThermalShell> shells = {});

  std::size_t size() const { return hexes_.size() + shells_.size(); }
  const std::vector<Hex8>& hexes() const { return hexes_; }

  // capacity[n] += the lumped heat capacity rho c V / 8 of every hex at node n, at the given
  // coordinates (the reference ones: mass and heat capacity do not change as the body deforms).
  void add_capacity(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                    std::span<double> capacity) const;

  // The element conductance matrices at the given coordinates, for assembly (steady state):
  // 64 values per hex (row-major over its 8 nodes), then 16 per shell (its 4 node slots; a
  // triangle's fourth row and column are 0), in element order; and the matching node lists.
  void conductance_matrices(std::span<const double> x, std::span<const double> y,
                            std::span<const double> z, std::vector<double>& values) const;
  const std::vector<ThermalShell>& shells() const { return shells_; }

  // heat_rate[n] += the heat flowing into node n by conduction [power], -sum_e (K_e T)_n, at the
  // given coordinates and temperatures. Returns the smallest element stable step 2 / lambda_e.
  double add_conduction(std::span<const double> x, std::span<const double> y,
                        std::span<const double> z, std::span<const double> temperature,
                        std::span<double> heat_rate);

 private:
  std::vector<Hex8> hexes_;
  std::vector<double> conductivity_, capacity_;
  std::vector<ThermalShell> shells_;
  std::vector<double> element_flow_;  // 8 per hex, then 4 per shell, of the last add_conduction
  std::vector<std::int32_t> slot_start_, slots_;  // node -> its entries of element_flow_
};

}  // namespace abut
