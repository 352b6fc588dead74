#pragma once
// A block of 8-node hexahedra of one part and one deformable material: one-point integration
// with Flanagan-Belytschko hourglass control and an objective stress update.
//
// Time stepping contract (central difference): at step n the solver passes coordinates x^n and
// velocities v^{n-1/2}; update() advances the stress from t^{n-1} to t^n with the velocity
// gradient of v^{n-1/2} (over dt = t^n - t^{n-1}) and computes element nodal forces from the
// stress at x^n. Forces are stored per element (24 values: node a, direction i at e*24+a*3+i)
// and are the forces acting ON the nodes (i.e. minus the internal force vector), so that the
// solver can assemble them node by node in a fixed order (bitwise identical for any thread count).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "abut/core/functions.hpp"
#include "abut/element/hex8.hpp"
#include "abut/material/material.hpp"
#include "abut/mesh/mesh.hpp"

namespace abut {

class StateArchive;

struct NodalState {
  const double* x;  // current coordinates x^n
  const double* y;
  const double* z;
  const double* vx;  // velocities v^{n-1/2}
  const double* vy;
  const double* vz;
  // Nodal temperatures at the last thermal step (issue 11); null without a temperature field.
  // Read only by blocks with a ThermalCoupling.
  const double* temperature = nullptr;
};

// Coupling of a block to the temperature field (issue 11), from its material's thermal
// properties. The element temperature is the mean of its 8 nodal temperatures.
//  - expansion alpha: the mechanical strain increment is the total one minus alpha dT I, dT the
//    change of the element temperature since its last update (hypoelastic rate form, so the
//    increments sum to alpha (T - T_initial) exactly, whatever the sub-cycling of the heat);
//  - plastic_work: record each element's plastic work of the step (for the Taylor-Quinney heat);
//  - a metal with thermal softening (MetalParams::softens) yields at its element temperature.
struct ThermalCoupling {
  double expansion = 0.0;
  bool plastic_work = false;
};

// When an element is removed (*PART erosion fields, IMPETUS): its critical step falls below
// min_step, its effective deviatoric logarithmic strain sqrt(2/3 e_dev:e_dev) exceeds
// max_geometric_strain, or its volumetric strain V/V0 - 1 exceeds max_volumetric_strain.
struct ErosionCriteria {
  double min_step = 0.0;
  double max_geometric_strain = 1e20;
  double max_volumetric_strain = 1e20;
  bool any() const {
    return min_step > 0.0 || max_geometric_strain < 1e20 || max_volumetric_strain < 1e20;
  }
};

struct BlockStep {
  double internal_energy =
      0.0;  // cumulative strain energy of the living elements (work of stresses)
  double hourglass_energy = 0.0;  // cumulative work of the hourglass forces of the living elements
  double eroded_energy = 0.0;     // internal and hourglass energy the eroded elements held
  // Energy the thermal expansion brought into the mechanics so far (elements coupled to the
  // temperature): minus the work of the stresses on the thermal strain alpha dT I;
  // internal_energy is their work on the rest of the strain.
  double thermal_work = 0.0;
  std::size_t eroded = 0;         // elements eroded so far
  double stable_step = 0.0;       // smallest element stable time step at x^n (no scale factor)
};

class SolidBlock {
 public:
  // `reference` holds the initial coordinates (needed by total-Lagrangian hyperelasticity).
  // `functions`: the curves and functions a material refers to (*MAT_METAL's flow curve).
  SolidBlock(std::int64_t part_id, const MaterialParams& material, std::vector<Hex8> hexes,
             const Nodes& reference, const FunctionTable* functions = nullptr);
  ~SolidBlock();
  SolidBlock(SolidBlock&&) noexcept;
  SolidBlock& operator=(SolidBlock&&) noexcept;

  std::int64_t part_id() const;
  const std::vector<Hex8>& hexes() const;
  std::size_t size() const;

  // Adds the lumped mass (rho * V0 / 8 to each node) of every element to nodal_mass.
  void add_lumped_mass(std::vector<double>& nodal_mass) const;
  // Stable time step at the initial configuration (no scale factor).
  double initial_stable_step(const Nodes& reference) const;

  // One step, see the contract above. dt == 0 (the first call) computes forces without
  // advancing the stress. Throws InstabilityError naming the element id source index when an
  // element inverts (volume <= 0) or produces a non-finite value.
  // With a ThermalCoupling, state.temperature must be given (else InputError).
  BlockStep update(const NodalState& state, double dt);
  const std::vector<double>& element_forces() const;

  // Per-element results at the last update (for output).
  void von_mises_stress(std::vector<double>& out) const;  // resized to size()
  void plastic_strain(std::vector<double>& out) const;    // equivalent plastic strain; 0 if elastic
  void plastic_strain_rate(std::vector<double>& out) const;  // of the last step; 0 if elastic
  void damage(std::vector<double>& out) const;  // ductile damage (*PROP_DAMAGE_JC); 0 without
  // Erosion: an element meeting a criterion at the end of a step is removed for good: no forces,
  // no stress, no step limit; its mass stays on its nodes. A metal with a damage property also
  // erodes an element whose point has failed (damage >= 1), whatever the criteria.
  void set_erosion(const ErosionCriteria& criteria);
  const std::vector<std::uint8_t>& eroded() const;  // 1 per eroded element
  void pressure(std::vector<double>& out) const;    // p = -trace(sigma)/3
  // Cauchy stress, 6 per element (xx, yy, zz, xy, yz, zx); resized to 6 * size().
  void stress(std::vector<double>& out) const;

  // Hourglass control (see solid_block.cpp): stiffness-type Flanagan-Belytschko forces with
  // stiffness hourglass_coefficient * 2 G * (b:b) / V, G the (initial) shear modulus.
  static constexpr double kDefaultHourglassCoefficient = kHex8HourglassCoefficient;
  // Artificial bulk viscosity (LS-DYNA's defaults): quadratic C0 = 1.5, linear C1 = 0.06.
  static constexpr double kDefaultBulkViscosityQuadratic = 1.5;
  static constexpr double kDefaultBulkViscosityLinear = 0.06;
  // Both >= 0; 0 and 0 switch the bulk viscosity off.
  void set_bulk_viscosity(double quadratic, double linear);
  void set_hourglass_coefficient(double coefficient);  // >= 0, else InputError
  double hourglass_coefficient() const;
  // InputError for Mooney-Rivlin with thermal expansion (not supported yet). A coupling that
  // changes nothing (no expansion, no plastic work, no softening) leaves the block uncoupled.
  void set_thermal(const ThermalCoupling& coupling);
  bool thermal() const;  // coupled: update() needs the temperatures
  // sigma : d eps_p V of each element over the last step [energy]; empty unless plastic_work.
  const std::vector<double>& plastic_work() const;
  // User element ids (one per hex) so that an InstabilityError names the element as the user
  // knows it; without them the message gives the index in the block.
  void set_element_ids(std::vector<std::int64_t> ids);
  // Saves or loads the evolving state (stresses, histories, erosion, energies) for a restart
  // (state_archive.hpp).
  void archive(StateArchive& a);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace abut
