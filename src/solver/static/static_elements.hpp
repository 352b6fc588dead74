#pragma once
// The elements of the static solver: every hex of the model as a fully integrated C3D8
// (element/hex8_full.hpp) or, for parts with one-point integration, a C3D8R with hourglass
// stiffness (element/hex8_reduced.hpp); linear elastic (*ELASTIC, *MAT_ELASTIC) or J2 plastic
// (*PLASTIC, *MAT_METAL, *MAT_JC; material/j2_strain_point.hpp). Evaluated in parallel at a
// displacement field; each element's internal force and tangent go to per-element slots and the
// caller adds them up in element order, so the result does not depend on the number of threads.
// Plastic history: evaluate() computes it from the last committed state; commit() accepts it
// once the increment has converged.
#include <cstddef>
#include <span>
#include <vector>

#include "abut/element/hex8_full.hpp"
#include "abut/material/j2_strain_point.hpp"
#include "abut/solver/model.hpp"

namespace abut::detail {

class StaticElements {
 public:
  // InputError for parts the static solver cannot run (naming the part and what to change).
  explicit StaticElements(const Model& model);

  std::size_t count() const { return hexes_.size(); }
  const Hex8& nodes(std::size_t e) const { return hexes_[e]; }
  // 8 (C3D8) or 1 (C3D8R: its stress and strain fill all 8 slots below).
  int integration_points(std::size_t e) const { return reduced_[e] ? 1 : 8; }

  // Evaluates every element at the global displacement u (3 per node). InstabilityError when an
  // element turns inside out (naming its user id).
  void evaluate(std::span<const double> u, bool nonlinear_geometry);
  // The plastic history of the last evaluate() becomes the starting point of the next ones.
  void commit() { committed_ = trial_; }

  // Results of the last evaluate(), per element.
  const double* force(std::size_t e) const { return &force_[24 * e]; }
  const double* stiffness(std::size_t e) const { return &stiffness_[576 * e]; }
  std::span<const double> stress() const { return stress_; }  // 48 per element
  std::span<const double> strain() const { return strain_; }  // 48 per element
  std::span<const double> energy() const { return energy_; }
  std::span<const double> energy_density() const { return energy_density_; }  // 8 per element
  std::span<const double> volume() const { return volume_; }  // current volume per element
  // Equivalent plastic strain per Gauss point (8 per element, as stress()); 0 when elastic.
  std::span<const double> plastic_strain() const { return plastic_strain_; }

  // f += the internal forces of all elements, in element order (3 per node).
  void add_forces(std::span<double> f) const;
  // Sum of |component| over the element nodal forces (before assembly), and their count.
  double force_magnitude_sum() const;
  std::size_t force_entries() const { return force_.size(); }

 private:
  const Model& model_;
  std::vector<Hex8> hexes_;
  std::vector<std::int64_t> ids_;
  std::vector<std::uint8_t> reduced_;              // 1: C3D8R
  std::vector<IsotropicElastic> elastic_;          // per element: the elastic constants
  std::vector<const MetalParams*> plastic_;        // per element: J2 parameters, or null
  std::vector<double> hourglass_modulus_;          // per element: c_hg 2 G (C3D8R)
  std::vector<J2PointHistory> committed_, trial_;  // 8 per element
  std::vector<double> force_, stiffness_, stress_, strain_, energy_, plastic_strain_;
  std::vector<double> energy_density_, volume_;
};

}  // namespace abut::detail
