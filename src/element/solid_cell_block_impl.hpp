#pragma once
// The state of a SolidCellBlock (solid_cell_block.hpp), shared by its set-up
// (solid_cell_block.cpp) and its update (solid_cell_block_kernel.cpp). Internal to the element
// layer.
#include <cstdint>
#include <string>
#include <vector>

#include "abut/element/solid_cell_block.hpp"
#include "abut/material/point_law.hpp"
#include "abut/mesh/shape_functions.hpp"
#include "solid_block_impl.hpp"

namespace abut {

// The most integration points of a full rule (hex20: 3 x 3 x 3): the kernel's scratch.
inline constexpr int kMaxPoints = 64;

struct SolidCellBlock::Impl {
  std::int64_t part_id = 0;
  MaterialParams material;
  const FunctionTable* functions = nullptr;
  CellType type = CellType::tet4;
  int nodes = 0;   // per element
  int points = 0;  // integration points per element (the full rule)
  std::vector<std::int32_t> connectivity;
  std::vector<std::int64_t> element_ids;
  double density = 0.0, wave_speed = 0.0;
  double lame_lambda = 0.0, lame_mu = 0.0;  // initial moduli (mu with the viscous terms)
  double newtonian_viscosity = 0.0;
  int viscous_terms = 0;
  double bulk_viscosity_quadratic = SolidBlock::kDefaultBulkViscosityQuadratic;
  double bulk_viscosity_linear = SolidBlock::kDefaultBulkViscosityLinear;

  // The rule: weights and the natural derivatives of the shape functions at each point
  // (natural[(q * nodes + a)][r]).
  std::vector<double> weight;
  std::vector<double> natural;  // 3 per node per point
  const double (*natural_at(std::size_t q) const)[3] {
    return reinterpret_cast<const double(*)[3]>(&natural[3 * q * static_cast<std::size_t>(nodes)]);
  }

  // Per element: reference coordinates (3 per node), volume, HRZ volume shares (1 per node), each
  // point's share of the volume, the initial step and the factor of the characteristic length.
  std::vector<double> reference, reference_volume, shares, point_share;
  std::vector<double> initial_step, length_factor;

  // Per point (element-major): stress (6, Sym3 order), history (metals), viscous stresses
  // (6 per active term, rubber).
  std::vector<double> stress, viscous;
  std::vector<PointHistory> history;
  bool fails_by_damage = false;

  // Per element, as SolidBlock (block_step.hpp reads them).
  std::vector<double> forces;  // 3 * nodes per element
  std::vector<double> internal_work, hourglass_work, bulk_pressure, stable;
  std::vector<unsigned char> failure;
  ErosionCriteria erosion;
  std::vector<std::uint8_t> eroded;
  std::vector<double> element_internal, element_hourglass, geometric_strain, volume_ratio;
  double eroded_energy = 0.0;
  std::size_t eroded_count = 0;
  double internal_energy = 0.0, hourglass_energy = 0.0;

  // Average nodal pressure (set_nodal_pressure): each connectivity entry's node in a numbering
  // of the block's own nodes; per such node the sums of V/4 and of (V tr(D dt))/4 (hypoelastic
  // laws) or of V(x^n)/4 and V(X)/4 (Mooney-Rivlin) of its elements; per element its two terms.
  bool nodal_pressure = false;
  std::vector<std::int32_t> local_node;
  std::vector<double> node_weight, node_value, element_weight, element_value;

  std::size_t size() const { return initial_step.size(); }
  template <class Law>
  void average_nodal_volumes(const NodalState& s, double dt);
  std::string element_name(std::size_t e) const;
  // The coordinates of element e's nodes from x, y, z: out[3 a + i].
  void gather(std::size_t e, const double* x, const double* y, const double* z, double* out) const;
  double characteristic_length(const double* X, double volume) const;
  Sym3 mean_stress(std::size_t e) const;
  double mean_history(std::size_t e, double PointHistory::*field) const;
  // l / (Q + sqrt(Q^2 + c^2)), SolidBlock's critical_step.
  double critical_step(double length, double q_speed) const {
    const double q = q_speed + 4.0 * newtonian_viscosity / (3.0 * density * length);
    return length / (q + std::sqrt(q * q + wave_speed * wave_speed));
  }

  template <class Law>
  void element(std::size_t e, const NodalState& s, double dt, const Law& law);
  template <class Law>
  BlockStep step(const NodalState& s, double dt, const Law& law);
  void erode(BlockStep& out);
};

}  // namespace abut
