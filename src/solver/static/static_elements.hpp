#pragma once
// The elements of the static solver: every hex of the model as a fully integrated C3D8
// (element/hex8_full.hpp), evaluated in parallel at a displacement field. Each element's internal
// force and tangent go to per-element slots; the caller adds them up in element order, so the
// result does not depend on the number of threads.
#include <cstddef>
#include <span>
#include <vector>

#include "abut/element/hex8_full.hpp"
#include "abut/solver/model.hpp"

namespace abut::detail {

class StaticElements {
 public:
  // InputError for parts the static solver cannot run (naming the part and what to change).
  explicit StaticElements(const Model& model);

  std::size_t count() const { return hexes_.size(); }
  const Hex8& nodes(std::size_t e) const { return hexes_[e]; }

  // Evaluates every element at the global displacement u (3 per node). InstabilityError when an
  // element turns inside out (naming its user id).
  void evaluate(std::span<const double> u, bool nonlinear_geometry);

  // Results of the last evaluate(), per element.
  const double* force(std::size_t e) const { return &force_[24 * e]; }
  const double* stiffness(std::size_t e) const { return &stiffness_[576 * e]; }
  std::span<const double> stress() const { return stress_; }  // 48 per element
  std::span<const double> strain() const { return strain_; }  // 48 per element
  std::span<const double> energy() const { return energy_; }

  // f += the internal forces of all elements, in element order (3 per node).
  void add_forces(std::span<double> f) const;
  // Sum of |component| over the element nodal forces (before assembly), and their count.
  double force_magnitude_sum() const;
  std::size_t force_entries() const { return force_.size(); }

 private:
  const Model& model_;
  std::vector<Hex8> hexes_;
  std::vector<std::int64_t> ids_;
  std::vector<IsotropicElastic> material_;  // per element
  std::vector<double> force_, stiffness_, stress_, strain_, energy_;
};

}  // namespace abut::detail
