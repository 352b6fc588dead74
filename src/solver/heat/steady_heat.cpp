// Steady heat conduction (heat.hpp, solve_steady): the conductance of the elements and of the
// convecting faces assembled over the free thermal nodes, the held temperatures moved to the right
// side, one direct solve. With the semi-discrete equations of heat.hpp at dT/dt = 0:
//   (K + H + G) T = Q_flux + H_amb + S,
// H the lumped convection h int N_a dA on the diagonal (as the transient step applies it), G the
// contact conductance (G_c w_a w_b for each contact point c over its element's nodes, so that it
// draws G_c (T_point - T_partner) from one side into the other), and the prescribed nodes
// eliminated: rhs_free -= (K + G)_fp T_p.
#include <string>

#include "abut/core/error.hpp"
#include "abut/linalg/linear_solver.hpp"
#include "abut/linalg/sparse_matrix.hpp"
#include "heat_impl.hpp"

namespace abut {

void HeatSolver::solve_steady(double time, std::span<const double> x, std::span<const double> y,
                              std::span<const double> z, std::span<const double> source,
                              std::span<const ThermalContactElement> contact) {
  Impl& s = *impl_;
  if (!s.block) return;
  const Model& model = s.model;
  const std::size_t n = s.t.size();
  // Held temperatures at `time`; equations for the other thermal nodes.
  for (const PrescribedTemperature& p : model.thermal.prescribed) {
    const double value = s.amplitude(p.curve, p.scale, time);
    for (const std::int32_t node : p.nodes) s.t[static_cast<std::size_t>(node)] = value;
  }
  // The heat each node draws by conduction in the field found (conduction_rate(), the flows
  // the caller reports), also when every node is held and there is nothing to solve.
  const auto conduct = [&] {
    std::fill(s.conduction.begin(), s.conduction.end(), 0.0);
    s.stable = s.block->add_conduction(x, y, z, s.t, s.conduction);
  };
  std::vector<std::int32_t> equation(n, -1);
  std::int32_t equations = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (s.thermal[i] && !s.prescribed[i]) equation[i] = equations++;  // no density needed
  if (equations == 0) return conduct();

  // Right side: -K_fp T_p (the conduction drawn by the held nodes alone), fluxes, convection to
  // the ambient, sources.
  std::vector<double> held(n, 0.0), rhs_nodes(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    if (s.prescribed[i]) held[i] = s.t[i];
  s.block->add_conduction(x, y, z, held, rhs_nodes);
  for (const SurfaceHeatFlux& f : model.thermal.fluxes) {
    const double q = s.amplitude(f.curve, f.scale, time);
    for (const auto& face : f.faces) {
      const auto w = detail::nodal_areas(face, x, y, z);
      for (int a = 0; a < 4; ++a) rhs_nodes[static_cast<std::size_t>(face[a])] += q * w[a];
    }
  }
  // Element dofs: hexes (8), shells (4), then one 1 x 1 element per convecting face node.
  std::vector<std::int64_t> start{0};
  std::vector<std::int32_t> dofs;
  for (const Hex8& h : s.block->hexes()) {
    for (const std::int32_t node : h) dofs.push_back(equation[static_cast<std::size_t>(node)]);
    start.push_back(static_cast<std::int64_t>(dofs.size()));
  }
  for (const ThermalShell& sh : s.block->shells()) {
    for (const std::int32_t node : sh.nodes)
      dofs.push_back(equation[static_cast<std::size_t>(node)]);
    start.push_back(static_cast<std::int64_t>(dofs.size()));
  }
  std::vector<double> values;
  s.block->conductance_matrices(x, y, z, values);
  bool convects = false;
  for (const SurfaceConvection& c : model.thermal.convection)
    for (const auto& face : c.faces) {
      const auto w = detail::nodal_areas(face, x, y, z);
      for (int a = 0; a < 4; ++a) {
        const auto node = static_cast<std::size_t>(face[a]);
        dofs.push_back(equation[node]);
        start.push_back(static_cast<std::int64_t>(dofs.size()));
        values.push_back(c.coefficient * w[a]);
        rhs_nodes[node] += c.coefficient * c.ambient * w[a];
        convects = convects || c.coefficient * w[a] > 0.0;
      }
    }
  // Contact points: G w_a w_b over their nodes; the held ones go to the right side.
  for (const ThermalContactElement& c : contact) {
    const ContactWeights& w = c.weights;
    double held_difference = 0.0;  // sum over the held nodes of w_b T_b
    for (int b = 0; b < w.count; ++b) {
      const auto node = static_cast<std::size_t>(w.nodes[b]);
      dofs.push_back(equation[node]);
      if (s.prescribed[node]) held_difference += w.weights[b] * s.t[node];
    }
    start.push_back(static_cast<std::int64_t>(dofs.size()));
    for (int a = 0; a < w.count; ++a) {
      for (int b = 0; b < w.count; ++b)
        values.push_back(c.conductance * w.weights[a] * w.weights[b]);
      rhs_nodes[static_cast<std::size_t>(w.nodes[a])] -=
          c.conductance * w.weights[a] * held_difference;
    }
  }
  bool holds = false;
  for (std::size_t i = 0; i < n; ++i) holds = holds || s.prescribed[i];
  if (!holds && !convects) {
    throw InputError(
        "a steady temperature field needs a held temperature or a convecting face somewhere: "
        "without one its level is undetermined");
  }
  if (!source.empty())
    for (std::size_t i = 0; i < n; ++i) rhs_nodes[i] += source[i];

  const SparseAssembly assembly(equations, start, dofs);
  std::vector<double> csr;
  assembly.assemble(values, csr);
  std::vector<double> rhs(static_cast<std::size_t>(equations));
  for (std::size_t i = 0; i < n; ++i)
    if (equation[i] >= 0) rhs[static_cast<std::size_t>(equation[i])] = rhs_nodes[i];
  const std::unique_ptr<LinearSolver> solver =
      make_linear_solver(MatrixKind::SymmetricPositiveDefinite);
  try {
    solver->factorize(assembly.pattern(), csr);
  } catch (const SingularMatrixError& e) {
    std::string where = "a node";
    for (std::size_t i = 0; i < n; ++i)
      if (equation[i] == e.equation()) where = "node " + std::to_string(model.mesh.nodes.id[i]);
    throw InputError("the steady temperature field is undetermined at " + where +
                     ": its body has no held temperature and no convecting face");
  }
  // A body held nowhere is singular to round-off only: its pivots fall to ~1e-16 of the others.
  constexpr double kSingular = 1e-13;
  if (solver->reciprocal_condition() < kSingular)
    throw InputError(
        "the steady temperature field is undetermined: a body has no held temperature and no "
        "convecting face");
  solver->solve(rhs, rhs);
  for (std::size_t i = 0; i < n; ++i)
    if (equation[i] >= 0) s.t[i] = rhs[static_cast<std::size_t>(equation[i])];
  conduct();
}

}  // namespace abut
