#pragma once
// The elements of the static solver: every solid of the model (Mesh::solid numbering): 8-node
// hexahedra as a fully integrated C3D8 (element/hex8_full.hpp) or, for parts with reduced
// integration, a C3D8R with hourglass stiffness (element/hex8_reduced.hpp); the other cell types
// as isoparametric elements with their full or reduced rule (element/solid_full.hpp: C3D20,
// C3D20R, C3D4, C3D10, C3D6); linear elastic (*ELASTIC, *MAT_ELASTIC) or J2 plastic
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
#include "abut/mesh/shape_functions.hpp"
#include "abut/model/model.hpp"

namespace abut::detail {

class StaticElements {
 public:
  // InputError for parts the static solver cannot run (naming the part and what to change).
  explicit StaticElements(const Model& model);

  std::size_t count() const { return types_.size(); }
  std::span<const std::int32_t> nodes(std::size_t e) const {
    return {&nodes_[node_start_[e]], node_start_[e + 1] - node_start_[e]};
  }
  // The element's integration points (8 for C3D8, 1 for C3D8R, 27 for C3D20, ...) and the index
  // of its first one in the per-point results below.
  int integration_points(std::size_t e) const {
    return static_cast<int>(point_start_[e + 1] - point_start_[e]);
  }
  std::size_t first_point(std::size_t e) const { return point_start_[e]; }

  // Evaluates every element at the global displacement u (3 per node). InstabilityError when an
  // element turns inside out (naming its user id).
  void evaluate(std::span<const double> u, bool nonlinear_geometry);
  // The plastic history of the last evaluate() becomes the starting point of the next ones.
  void commit() { committed_ = trial_; }

  // Results of the last evaluate(), per element.
  const double* force(std::size_t e) const { return &force_[3 * node_start_[e]]; }
  const double* stiffness(std::size_t e) const { return &stiffness_[stiffness_start_[e]]; }
  std::span<const double> stress() const { return stress_; }  // 6 per point
  std::span<const double> strain() const { return strain_; }  // 6 per point
  std::span<const double> energy() const { return energy_; }
  std::span<const double> energy_density() const { return energy_density_; }  // 1 per point
  std::span<const double> volume() const { return volume_; }  // current volume per element
  // Equivalent plastic strain per point (as energy_density()); 0 when elastic.
  std::span<const double> plastic_strain() const { return plastic_strain_; }

  // f += the internal forces of all elements, in element order (3 per node).
  void add_forces(std::span<double> f) const;
  // Sum of |component| over the element nodal forces (before assembly), and their count.
  double force_magnitude_sum() const;
  std::size_t force_entries() const { return force_.size(); }

 private:
  std::span<const QuadraturePoint> rule(std::size_t e) const;

  const Model& model_;
  std::vector<CellType> types_;
  std::vector<std::int32_t> nodes_;
  std::vector<std::size_t> node_start_, point_start_, stiffness_start_;  // prefix sums
  std::vector<std::int64_t> ids_;
  std::vector<std::uint8_t> reduced_;              // 1: reduced integration (C3D8R, C3D20R)
  std::vector<IsotropicElastic> elastic_;          // per element: the elastic constants
  std::vector<const MetalParams*> plastic_;        // per element: J2 parameters, or null
  std::vector<double> hourglass_modulus_;          // per element: c_hg 2 G (C3D8R)
  std::vector<J2PointHistory> committed_, trial_;  // per point
  std::vector<double> force_, stiffness_, stress_, strain_, energy_, plastic_strain_;
  std::vector<double> energy_density_, volume_;
};

}  // namespace abut::detail
