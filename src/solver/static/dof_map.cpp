#include "solver/static/dof_map.hpp"

#include <algorithm>
#include <map>
#include <string>

#include "abut/core/error.hpp"

namespace abut::detail {

namespace {

const char* const kAxis[3] = {"x", "y", "z"};

std::string dof_name(std::size_t dof) {
  return "dof " + std::to_string(dof % 3 + 1) + " (" + kAxis[dof % 3] + ")";
}

}  // namespace

DofMap::DofMap(std::size_t nodes, std::span<const std::uint8_t> prescribed,
               std::span<const LinearConstraint> constraints)
    : equation_(3 * nodes, -1), prescribed_(prescribed.begin(), prescribed.end()) {
  const std::size_t n = 3 * nodes;
  if (prescribed_.size() != n) prescribed_.resize(n, 0);
  // Raw expansions of the dependent dofs, before substitution.
  std::vector<std::int32_t> owner(n, -1);  // constraint whose dependent dof this is
  for (std::size_t c = 0; c < constraints.size(); ++c) {
    const LinearConstraint& eq = constraints[c];
    if (eq.terms.size() < 2)
      throw InputError(eq.where, "a linear constraint needs at least two terms");
    const auto& first = eq.terms.front();
    const std::size_t d = 3 * static_cast<std::size_t>(first.node) + first.dof;
    if (first.coefficient == 0.0)
      throw InputError(eq.where,
                       "the first term of a linear constraint (its dependent dof) needs a "
                       "nonzero coefficient");
    if (prescribed_[d])
      throw InputError(eq.where,
                       "the dependent " + dof_name(d) +
                           " of this linear constraint also has a boundary condition in this "
                           "step: put another dof first or remove the condition");
    if (owner[d] >= 0)
      throw InputError(eq.where,
                       "this " + dof_name(d) +
                           " is already the dependent dof of another linear constraint (line " +
                           std::to_string(constraints[owner[d]].where.line) + ")");
    owner[d] = static_cast<std::int32_t>(c);
  }
  // Substitute dependent dofs within expansions (depth-first, cycles are an error).
  std::vector<std::map<std::int32_t, double>> resolved(constraints.size());
  std::vector<std::uint8_t> state(constraints.size(), 0);  // 0 new, 1 in progress, 2 done
  auto resolve = [&](auto&& self, std::size_t c) -> const std::map<std::int32_t, double>& {
    if (state[c] == 2) return resolved[c];
    if (state[c] == 1)
      throw InputError(constraints[c].where,
                       "the linear constraints depend on each other in a cycle through this one");
    state[c] = 1;
    const LinearConstraint& eq = constraints[c];
    const double c1 = eq.terms.front().coefficient;
    std::map<std::int32_t, double> out;
    for (std::size_t k = 1; k < eq.terms.size(); ++k) {
      const auto& t = eq.terms[k];
      const auto dof = static_cast<std::int32_t>(3 * static_cast<std::size_t>(t.node) + t.dof);
      const double w = -t.coefficient / c1;
      if (owner[dof] >= 0) {
        for (const auto& [target, weight] : self(self, owner[dof])) out[target] += w * weight;
      } else {
        out[dof] += w;
      }
    }
    state[c] = 2;
    return resolved[c] = std::move(out);
  };
  term_start_.assign(n + 1, 0);
  for (std::size_t d = 0; d < n; ++d) {
    if (owner[d] >= 0)
      for (const auto& [target, weight] : resolve(resolve, owner[d]))
        if (weight != 0.0) terms_.push_back({target, weight});
    term_start_[d + 1] = static_cast<std::int64_t>(terms_.size());
  }
  for (std::size_t d = 0; d < n; ++d)
    if (!prescribed_[d] && owner[d] < 0) equation_[d] = equations_++;
}

void DofMap::update_dependent(std::span<double> u) const {
  for (std::size_t d = 0; d < dofs(); ++d) {
    if (!dependent(d)) continue;
    double value = 0.0;
    for (const Term& t : expansion(d)) value += t.weight * u[t.dof];
    u[d] = value;
  }
}

void DofMap::reduce(std::span<const double> global, std::span<double> reduced) const {
  std::fill(reduced.begin(), reduced.end(), 0.0);
  for (std::size_t d = 0; d < dofs(); ++d) {
    if (equation_[d] >= 0) reduced[equation_[d]] += global[d];
    for (const Term& t : expansion(d))
      if (equation_[t.dof] >= 0) reduced[equation_[t.dof]] += t.weight * global[d];
  }
}

void DofMap::expand_add(std::span<const double> dq, std::span<double> u) const {
  for (std::size_t d = 0; d < dofs(); ++d)
    if (equation_[d] >= 0) u[d] += dq[equation_[d]];
  update_dependent(u);
}

}  // namespace abut::detail
