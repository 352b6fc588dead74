#pragma once
// The state of a SolidBlock (solid_block.hpp), shared by its set-up (solid_block.cpp) and its
// kernel (solid_block_kernel.cpp). Internal to the element layer.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "abut/core/error.hpp"
#include "abut/core/lanes.hpp"
#include "abut/element/solid_block.hpp"
#include "abut/material/metal.hpp"
#include "abut/material/mooney_rivlin.hpp"
#include "abut/material/point_law.hpp"

namespace abut {

enum SolidFailure : unsigned char { kOk = 0, kInverted = 1, kNonFinite = 2 };

// The Mooney-Rivlin law of a block for one step.
struct RubberLaw {
  const MooneyRivlinParams* params;
  ViscousStep viscous;  // factors for this step (count = number of active terms)
};

// "part <id>: ", the start of a block's messages. Built with append: GCC 12 reports a false
// -Wrestrict for "literal" + std::string&&.
inline std::string input_prefix(std::int64_t part_id) {
  std::string s("part ");
  s += std::to_string(part_id);
  s += ": ";
  return s;
}

// InputError at the part unless the material suits a deformable solid: not rigid, a positive
// density, moduli in range, a flow curve for a metal (SolidBlock, SolidCellBlock).
void check_solid_material(std::int64_t part_id, const MaterialParams& material,
                          const FunctionTable* functions);

// Takes a block's erosion criteria (SolidBlock, SolidCellBlock): InputError at the part for a
// limit out of range; the per-element erosion arrays of `block`'s Impl (eroded, element_internal,
// element_hourglass, geometric_strain, volume_ratio) sized to `count` elements, or `eroded` left
// empty when nothing can erode (no criterion and no damage).
template <class Impl>
void set_block_erosion(Impl& m, const ErosionCriteria& criteria, std::size_t count) {
  if (!(criteria.min_step >= 0.0) || !(criteria.max_geometric_strain > 0.0) ||
      !(criteria.max_volumetric_strain > 0.0))
    throw InputError(input_prefix(m.part_id) +
                     "erosion limits must be > 0 (the time step limit >= 0)");
  m.erosion = criteria;
  if (!criteria.any() && !m.fails_by_damage) {
    m.eroded.clear();
    return;
  }
  m.eroded.assign(count, 0);
  m.element_internal.assign(count, 0.0);
  m.element_hourglass.assign(count, 0.0);
  m.geometric_strain.assign(count, 0.0);
  m.volume_ratio.assign(count, 1.0);
}

// Takes a block's bulk viscosity coefficients: InputError unless both are >= 0.
template <class Impl>
void set_block_bulk_viscosity(Impl& m, double quadratic, double linear) {
  if (!(quadratic >= 0.0) || !(linear >= 0.0))
    throw InputError("bulk viscosity coefficients must be >= 0");
  m.bulk_viscosity_quadratic = quadratic;
  m.bulk_viscosity_linear = linear;
}

// Effective deviatoric logarithmic strain sqrt(2/3 e_dev:e_dev) of the deformation gradient F
// (erosion's geometric strain).
double deviatoric_log_strain(const Mat3& f);

struct SolidBlock::Impl {
  std::int64_t part_id = 0;
  MaterialParams material;
  std::vector<Hex8> hexes;
  std::vector<std::int64_t> element_ids;
  double density = 0.0;
  double shear_modulus = 0.0;
  double wave_speed = 0.0;
  double hourglass_coefficient = kDefaultHourglassCoefficient;
  double bulk_viscosity_quadratic = kDefaultBulkViscosityQuadratic;
  double bulk_viscosity_linear = kDefaultBulkViscosityLinear;
  double newtonian_viscosity = 0.0;  // sum of alpha_k of the Mooney-Rivlin terms with beta_k = 0
  double lame_lambda = 0.0,
         lame_mu = 0.0;  // initial moduli for the stable step (mu with viscous terms)
  int viscous_terms = 0;

  std::vector<double> reference_volume;  // 1 per element
  // Mooney-Rivlin only: R_k = 8 G0_k / V0 of the reference configuration for the modes k = 1..6,
  // stored per element as R[6 j + k - 1] (component j), so that F = sum_k c_k (x) R_k.
  static constexpr std::size_t kReferenceModes = 18;
  std::vector<double> reference_gradient;
  // The stress (6 per element, Sym3 order) and the generalized hourglass forces (12 per element)
  // are kept batch by batch, as the kernel reads and writes them whole (solid_block_kernel.cpp):
  // component c of element e at batched(e, c, count), in whole batches.
  static std::size_t batched(std::size_t e, int c, int count) {
    const auto lanes = static_cast<std::size_t>(kLanes);
    return ((e / lanes) * static_cast<std::size_t>(count) + static_cast<std::size_t>(c)) * lanes +
           e % lanes;
  }
  static std::size_t batched_size(std::size_t n, int count) {
    const auto lanes = static_cast<std::size_t>(kLanes);
    return (n + lanes - 1) / lanes * lanes * static_cast<std::size_t>(count);
  }
  Sym3 element_stress(std::size_t e) const {
    Sym3 s;
    for (int c = 0; c < 6; ++c) s[c] = stress[batched(e, c, 6)];
    return s;
  }
  std::vector<double> stress;         // 6 per element, batched
  std::vector<double> viscous;        // 6 per active viscous term per element
  std::vector<double> hourglass;      // generalized hourglass forces, 12 per element, batched
  std::vector<double> forces;         // 24 per element
  std::vector<double> internal_work;  // per-element increments of the last step
  // The bulk viscosity's pressure q of the last update, 1 per element: its work over a step is
  // booked with the mean of q at the step's two ends (solid_block_kernel.cpp).
  std::vector<double> bulk_pressure;
  std::vector<PointHistory> history;  // plastic strain and damage (metals)
  bool fails_by_damage = false;       // a metal with a damage property: erodes at D >= 1
  ErosionCriteria erosion;
  std::vector<std::uint8_t> eroded;
  std::vector<double> element_internal, element_hourglass;  // cumulative work per element (erosion)
  std::vector<double> geometric_strain, volume_ratio;       // erosion measures at the last update
  double eroded_energy = 0.0;
  std::size_t eroded_count = 0;
  const FunctionTable* functions = nullptr;  // flow curves of *MAT_METAL
  std::vector<double> hourglass_work;
  std::vector<double> stable;
  std::vector<unsigned char> failure;

  double internal_energy = 0.0;
  double hourglass_energy = 0.0;

  // Coupling to the temperature (issue 11; solid_block.hpp): off unless set_thermal made it on.
  ThermalCoupling coupling;
  bool coupled = false;
  bool temperature_started = false;          // element_temperature holds the last temperatures
  std::vector<double> element_temperature;   // at the last update, 1 per element (coupled)
  // The stresses' work on the thermal strain of the last step, per element (coupled), and the
  // work of the expansion on the mechanics so far, minus its sum over the living elements
  // (BlockStep::thermal_work).
  std::vector<double> element_thermal_work;
  double thermal_work = 0.0;
  std::vector<double> element_plastic_work;  // of the last step (coupling.plastic_work)

  // kThermal: the block is coupled (decided once per block and step, so that the uncoupled
  // kernel is unchanged).
  // Updates the kLanes elements first, first + 1, ... (those below the block's size) at once.
  template <class Law, bool kThermal>
  void batch(std::size_t first, const NodalState& s, double dt, const Law& law);
  void clear_eroded(std::size_t e);
  template <class Law, bool kThermal = false>
  BlockStep step(const NodalState& s, double dt, const Law& law);
  void erode(BlockStep& out);
  std::string element_name(std::size_t e) const;
  // l / (Q + sqrt(Q^2 + c^2)) with Q = q_speed (bulk viscosity) plus the Newtonian Q_eta.
  // T = double or Lanes (lanes.hpp).
  template <class T>
  T critical_step(T length, T q_speed) const {
    const T q = q_speed + 4.0 * newtonian_viscosity / (3.0 * density * length);
    return length / (q + sqrt_of(q * q + wave_speed * wave_speed));
  }
};

}  // namespace abut
