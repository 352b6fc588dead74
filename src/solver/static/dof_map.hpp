#pragma once
// The degrees of freedom of the static solver: three translations per node, each one of
//   free       an unknown of the linear system (an "equation"),
//   prescribed its value is given by a boundary condition of the step,
//   dependent  a linear combination of other dofs by *EQUATION (sum c_k u_k = 0, the first
//              term's dof dependent: u_1 = -sum_{k>1} (c_k / c_1) u_k, Abaqus/CalculiX).
// A dependent dof is expanded into free and prescribed dofs, so the global displacement is
//   u = T q + u_p
// with q the free unknowns, T the expansion and u_p the prescribed values (and their share in the
// dependent dofs). The element matrices transform as T^T K T and the residuals as T^T r, which is
// the master-slave elimination of linear constraints (Cook, Malkus, Plesha & Witt, Concepts and
// Applications of Finite Element Analysis, 4th ed., section 9.2).
#include <cstdint>
#include <span>
#include <vector>

#include "abut/model/model_static.hpp"

namespace abut::detail {

class DofMap {
 public:
  // `prescribed` holds one flag per global dof (3 per node, node-major). Throws InputError when a
  // constraint's dependent dof is prescribed, is the dependent dof of two constraints, has a zero
  // coefficient, or the constraints depend on each other in a cycle.
  DofMap(std::size_t nodes, std::span<const std::uint8_t> prescribed,
         std::span<const LinearConstraint> constraints);

  std::int32_t equations() const { return equations_; }
  std::size_t dofs() const { return equation_.size(); }
  // The equation of a free dof, -1 otherwise.
  std::int32_t equation(std::size_t dof) const { return equation_[dof]; }
  bool prescribed(std::size_t dof) const { return prescribed_[dof] != 0; }
  bool dependent(std::size_t dof) const { return term_start_[dof + 1] > term_start_[dof]; }
  bool any_dependent() const { return !terms_.empty(); }

  // A dependent dof's expansion: u_dof = sum weight u_target, targets free or prescribed dofs.
  struct Term {
    std::int32_t dof = 0;
    double weight = 0.0;
  };
  std::span<const Term> expansion(std::size_t dof) const {
    return {terms_.data() + term_start_[dof], terms_.data() + term_start_[dof + 1]};
  }

  // Sets every dependent dof of u (global, 3 per node) from the dofs it depends on.
  void update_dependent(std::span<double> u) const;
  // r_eq = T^T r: the residual of the equations from the global residual.
  void reduce(std::span<const double> global, std::span<double> reduced) const;
  // u += T dq: spreads a correction of the unknowns over the global dofs.
  void expand_add(std::span<const double> dq, std::span<double> u) const;

 private:
  std::vector<std::int32_t> equation_;
  std::vector<std::uint8_t> prescribed_;
  std::vector<std::int64_t> term_start_;  // dofs + 1
  std::vector<Term> terms_;
  std::int32_t equations_ = 0;
};

}  // namespace abut::detail
