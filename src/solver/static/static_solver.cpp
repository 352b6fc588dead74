// Newton-Raphson over load increments (Bathe, Finite Element Procedures, 1996, section 8.4.1;
// increment control as Abaqus/Standard and CalculiX: cut back to a quarter after a failed
// attempt, grow by half after an easy one).
#include "abut/solver/static_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <string>

#include "abut/linalg/linear_solver.hpp"
#include "abut/linalg/sparse_matrix.hpp"
#include "solver/static/dof_map.hpp"
#include "solver/static/static_elements.hpp"
#include "solver/static/step_loads.hpp"

namespace abut {

namespace {

using Clock = std::chrono::steady_clock;

// Smallest over largest pivot below which the tangent counts as singular. A floating part gives
// ~1e-16 (round-off); well-posed models, even with contact penalties 1e4 times the material
// stiffness, stay far above.
constexpr double kSingularPivotRatio = 1e-13;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// The elements' equations after the constraint expansion: for each element its list of
// equations, and for each of its 24 local dofs the (local equation, weight) terms of T.
struct ElementEquations {
  std::vector<std::int64_t> start{0};  // per element, into eqs
  std::vector<std::int32_t> eqs;
  std::vector<std::int64_t> term_start;  // per element local dof (24 per element) + 1
  struct Term {
    std::int32_t local = 0;
    double weight = 0.0;
  };
  std::vector<Term> terms;
};

ElementEquations element_equations(const detail::StaticElements& elements,
                                   const detail::DofMap& dofs) {
  ElementEquations out;
  out.term_start.push_back(0);
  std::vector<std::int32_t> local;
  for (std::size_t e = 0; e < elements.count(); ++e) {
    local.clear();
    auto local_of = [&](std::int32_t eq) {
      const auto it = std::find(local.begin(), local.end(), eq);
      if (it != local.end()) return static_cast<std::int32_t>(it - local.begin());
      local.push_back(eq);
      return static_cast<std::int32_t>(local.size() - 1);
    };
    for (int a = 0; a < 8; ++a)
      for (int k = 0; k < 3; ++k) {
        const std::size_t g = 3 * static_cast<std::size_t>(elements.nodes(e)[a]) + k;
        if (dofs.equation(g) >= 0) out.terms.push_back({local_of(dofs.equation(g)), 1.0});
        for (const auto& t : dofs.expansion(g))
          if (dofs.equation(t.dof) >= 0)
            out.terms.push_back({local_of(dofs.equation(t.dof)), t.weight});
        out.term_start.push_back(static_cast<std::int64_t>(out.terms.size()));
      }
    out.eqs.insert(out.eqs.end(), local.begin(), local.end());
    out.start.push_back(static_cast<std::int64_t>(out.eqs.size()));
  }
  return out;
}

}  // namespace

struct StaticSolver::Impl {
  const Model& model;
  StaticControls controls;
  detail::StaticElements elements;
  std::vector<double> u, reaction;
  StaticStatistics stats;
  std::unique_ptr<LinearSolver> linear;
  MatrixKind kind = MatrixKind::SymmetricPositiveDefinite;

  Impl(const Model& m, StaticControls c) : model(m), controls(c), elements(m) {
    if (!m.motions.empty() || !m.gravity.empty() || !m.pressures.empty())
      throw InputError(
          "the static solver takes its loads from the steps (*BOUNDARY, *CLOAD, *DLOAD); "
          "*BC_MOTION, *LOAD_GRAVITY and *LOAD_PRESSURE are not supported in static steps yet");
    if (m.static_steps.empty()) throw InputError("the model has no static step");
    u.assign(3 * m.mesh.nodes.size(), 0.0);
    reaction.assign(u.size(), 0.0);
  }

  // The dof of an equation, for messages.
  std::string describe_equation(const detail::DofMap& dofs, std::int64_t eq) const {
    for (std::size_t d = 0; d < dofs.dofs(); ++d)
      if (dofs.equation(d) == eq)
        return "node " + std::to_string(model.mesh.nodes.id[d / 3]) + ", direction " + "xyz"[d % 3];
    return "an unknown dof";
  }

  // One attempt at an increment ending at step time tau. Returns the iterations used, or -1.
  int newton(const detail::StepLoads& loads, const detail::DofMap& dofs,
             const SparseAssembly& assembly, const ElementEquations& ee, double tau,
             bool nonlinear_geometry, std::vector<double>& state, double& residual_out) {
    const std::vector<double> start = state;
    loads.prescribe(tau, state);
    dofs.update_dependent(state);
    const std::size_t n = state.size();
    const auto neq = static_cast<std::size_t>(dofs.equations());
    std::vector<double> f(n), r(neq), dq(neq), element_values, csr;
    for (int it = 0; it <= controls.max_iterations; ++it) {
      const auto t0 = Clock::now();
      try {
        elements.evaluate(state, nonlinear_geometry);
      } catch (const InstabilityError&) {
        return -1;  // an element turned inside out: cut back
      }
      std::fill(f.begin(), f.end(), 0.0);
      elements.add_forces(f);
      double force_sum = 0.0;
      std::size_t force_count = 0;
      for (std::size_t d = 0; d < n; ++d)
        if (f[d] != 0.0) force_sum += std::abs(f[d]), ++force_count;
      std::vector<double> external(n, 0.0);
      loads.add_external_forces(tau, state, nonlinear_geometry, external);
      for (std::size_t d = 0; d < n; ++d) {
        if (external[d] != 0.0) force_sum += std::abs(external[d]), ++force_count;
        f[d] -= external[d];  // residual: internal - external
      }
      dofs.reduce(f, r);
      double rmax = 0.0;
      for (const double v : r) rmax = std::max(rmax, std::abs(v));
      if (!std::isfinite(rmax)) return -1;
      const double q = force_count > 0 ? force_sum / static_cast<double>(force_count) : 0.0;
      residual_out = q > 0.0 ? rmax / q : 0.0;
      // Convergence: residual small against the average force, and (after a correction) the
      // last correction small against the displacement increment.
      double cmax = 0.0, dumax = 0.0;
      if (it > 0) {
        for (const double v : dq) cmax = std::max(cmax, std::abs(v));
        for (std::size_t d = 0; d < n; ++d) dumax = std::max(dumax, std::abs(state[d] - start[d]));
      }
      const bool tiny = rmax <= 1e-8 * q || (q == 0.0 && rmax == 0.0);
      const bool converged = tiny || (it > 0 && rmax <= controls.force_tolerance * q &&
                                      cmax <= controls.displacement_tolerance * dumax);
      if (converged) {
        for (std::size_t d = 0; d < n; ++d) reaction[d] = loads.prescribed()[d] ? f[d] : 0.0;
        stats.assembly_seconds += seconds_since(t0);
        return it;
      }
      if (it == controls.max_iterations) break;
      // Tangent: T^T K_e T of every element, assembled.
      element_values.assign(static_cast<std::size_t>(assembly.element_value_count()), 0.0);
      const auto ne = static_cast<std::int64_t>(elements.count());
#pragma omp parallel for schedule(static)
      for (std::int64_t e = 0; e < ne; ++e) {
        const std::int64_t m = ee.start[e + 1] - ee.start[e];
        double* out = &element_values[static_cast<std::size_t>(assembly.value_start(e))];
        const double* k = elements.stiffness(static_cast<std::size_t>(e));
        for (int i = 0; i < 24; ++i)
          for (std::int64_t ti = ee.term_start[24 * e + i]; ti < ee.term_start[24 * e + i + 1];
               ++ti)
            for (int j = 0; j < 24; ++j)
              for (std::int64_t tj = ee.term_start[24 * e + j]; tj < ee.term_start[24 * e + j + 1];
                   ++tj)
                out[ee.terms[ti].local * m + ee.terms[tj].local] +=
                    ee.terms[ti].weight * k[24 * i + j] * ee.terms[tj].weight;
      }
      assembly.assemble(element_values, csr);
      stats.assembly_seconds += seconds_since(t0);
      const auto t1 = Clock::now();
      if (!factorize(assembly.pattern(), csr, dofs, nonlinear_geometry)) return -1;
      for (std::size_t i = 0; i < neq; ++i) r[i] = -r[i];
      linear->solve(r, dq);
      stats.solve_seconds += seconds_since(t1);
      if (linear->reciprocal_condition() < kSingularPivotRatio) {
        // Singular to round-off: a free rigid-body motion, which the solution shows as its largest
        // component. Under NLGEOM it may be a limit point instead: cut back.
        if (nonlinear_geometry) return -1;
        std::size_t worst = 0;
        for (std::size_t i = 0; i < neq; ++i)
          if (std::abs(dq[i]) > std::abs(dq[worst])) worst = i;
        throw InputError(singular_message(dofs, static_cast<std::int64_t>(worst)));
      }
      ++stats.iterations;
      dofs.expand_add(dq, state);
    }
    return -1;
  }

  std::string singular_message(const detail::DofMap& dofs, std::int64_t eq) const {
    return "the stiffness matrix is singular at " + describe_equation(dofs, eq) +
           ": a part can move without resistance (missing boundary conditions, or a part held "
           "only by a contact that is open)";
  }

  // False when the tangent is not positive definite under NLGEOM and LU fails too (cut back).
  bool factorize(const SparsePattern& pattern, const std::vector<double>& csr,
                 const detail::DofMap& dofs, bool nonlinear_geometry) {
    if (!linear) {
      linear = make_linear_solver(kind);
      stats.linear_solver = linear->name();
    }
    try {
      linear->factorize(pattern, csr);
    } catch (const SingularMatrixError& e) {
      if (!nonlinear_geometry) throw InputError(singular_message(dofs, e.equation()));
      if (kind == MatrixKind::General) return false;
      // Geometric stiffness under compression can make the tangent indefinite but regular:
      // go on with LU.
      kind = MatrixKind::General;
      linear = make_linear_solver(kind);
      stats.linear_solver = linear->name();
      return factorize(pattern, csr, dofs, nonlinear_geometry);
    }
    return true;
  }

  void run(const std::function<void(const StaticIncrement&)>& on_increment) {
    detail::LoadHistory history;
    double total = 0.0;
    bool nonlinear_geometry = false;
    for (std::size_t s = 0; s < model.static_steps.size(); ++s) {
      const StaticStep& step = model.static_steps[s];
      nonlinear_geometry = nonlinear_geometry || step.nonlinear_geometry;
      const detail::StepLoads loads(model, step, u, history, total);
      const detail::DofMap dofs(model.mesh.nodes.size(), loads.prescribed(), model.equations);
      const ElementEquations ee = element_equations(elements, dofs);
      const SparseAssembly assembly(dofs.equations(), ee.start, ee.eqs);
      stats.equations = std::max<std::int64_t>(stats.equations, dofs.equations());
      const double period = step.period;
      const double min_increment = step.min_increment > 0.0 ? step.min_increment : 1e-5 * period;
      const double max_increment = step.max_increment > 0.0 ? step.max_increment : period;
      double tau = 0.0;
      double dtau =
          std::min(step.initial_increment > 0.0 ? step.initial_increment : period, period);
      int increment = 0;
      while (tau < period * (1.0 - 1e-12)) {
        dtau = std::min(dtau, period - tau);
        if (++increment > step.max_increments)
          throw StaticConvergenceError("step " + std::to_string(s + 1) + ": more than " +
                                       std::to_string(step.max_increments) +
                                       " increments (INC of *STEP) needed");
        for (int attempt = 1;; ++attempt) {
          std::vector<double> trial = u;
          double residual = 0.0;
          const int iterations =
              newton(loads, dofs, assembly, ee, tau + dtau, nonlinear_geometry, trial, residual);
          if (iterations >= 0) {
            u = std::move(trial);
            tau += dtau;
            ++stats.increments;
            StaticIncrement report;
            report.step = static_cast<int>(s);
            report.increment = increment;
            report.attempts = attempt;
            report.iterations = iterations;
            report.step_time = tau;
            report.total_time = total + tau;
            report.residual = residual;
            report.step_end = tau >= period * (1.0 - 1e-12);
            if (on_increment) on_increment(report);
            if (iterations <= controls.easy_iterations && !step.fixed_increments)
              dtau = std::min(dtau * controls.growth, max_increment);
            break;
          }
          ++stats.cutbacks;
          if (step.fixed_increments || dtau <= min_increment * (1.0 + 1e-12)) {
            elements.evaluate(u, nonlinear_geometry);  // the results of the last converged state
            std::ostringstream msg;
            msg << "step " << s + 1 << " did not converge at step time " << tau + dtau
                << " (increment " << dtau << ", "
                << (step.fixed_increments ? "fixed increments (DIRECT)" : "the smallest allowed")
                << "); the last converged state is at step time " << tau;
            throw StaticConvergenceError(msg.str());
          }
          dtau = std::max(dtau * controls.cutback, min_increment);
        }
      }
      history = loads.history(period);
      total += period;
    }
  }
};

StaticSolver::StaticSolver(const Model& model, StaticControls controls)
    : impl_(std::make_unique<Impl>(model, controls)) {}
StaticSolver::~StaticSolver() = default;

void StaticSolver::run(const std::function<void(const StaticIncrement&)>& on_increment) {
  impl_->run(on_increment);
}

std::span<const double> StaticSolver::displacement() const { return impl_->u; }
std::span<const double> StaticSolver::reaction() const { return impl_->reaction; }
std::span<const double> StaticSolver::stress() const { return impl_->elements.stress(); }
std::span<const double> StaticSolver::strain() const { return impl_->elements.strain(); }
std::span<const double> StaticSolver::element_energy() const { return impl_->elements.energy(); }
const StaticStatistics& StaticSolver::statistics() const { return impl_->stats; }

}  // namespace abut
