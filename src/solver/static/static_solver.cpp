// Newton-Raphson over load increments (Bathe, Finite Element Procedures, 1996, section 8.4.1;
// increment control as Abaqus/Standard and CalculiX: cut back to a quarter after a failed
// attempt, grow by half after an easy one).
#include "abut/solver/static_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "abut/contact/static_contact.hpp"
#include "abut/linalg/linear_solver.hpp"
#include "abut/linalg/sparse_matrix.hpp"
#include "abut/solver/contact_surfaces.hpp"
#include "solver/static/dof_map.hpp"
#include "solver/static/static_contacts.hpp"
#include "solver/static/static_elements.hpp"
#include "solver/static/step_loads.hpp"
#include "solver/tie_search.hpp"

namespace abut {

namespace {

using Clock = std::chrono::steady_clock;

// Smallest over largest pivot below which the tangent counts as singular. A floating part gives
// ~1e-16 (round-off); well-posed models, even with contact penalties 1e4 times the material
// stiffness, stay far above.
constexpr double kSingularPivotRatio = 1e-13;

// A Newton correction of at most this many units of round-off (kEpsilon) of the largest
// coordinate moves the nodes by nothing a double can hold.
constexpr double kRoundOffUlps = 64.0;
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// The equations of the elements (hexes, then contact elements) after the constraint expansion:
// for each element its list of equations, and for each of its local dofs the (local equation,
// weight) terms of T.
struct ElementEquations {
  std::vector<std::int64_t> start{0};  // per element, into eqs
  std::vector<std::int32_t> eqs;
  std::vector<std::int64_t> dof_start{0};   // per element, into term_start (3 per node)
  std::vector<std::int64_t> term_start{0};  // per local dof, into terms
  struct Term {
    std::int32_t local = 0;
    double weight = 0.0;
  };
  std::vector<Term> terms;

  void add(std::span<const std::int32_t> nodes, const detail::DofMap& dofs) {
    const std::size_t first = eqs.size();
    auto local_of = [&](std::int32_t eq) {
      for (std::size_t k = first; k < eqs.size(); ++k)
        if (eqs[k] == eq) return static_cast<std::int32_t>(k - first);
      eqs.push_back(eq);
      return static_cast<std::int32_t>(eqs.size() - 1 - first);
    };
    for (const std::int32_t node : nodes)
      for (int k = 0; k < 3; ++k) {
        const std::size_t g = 3 * static_cast<std::size_t>(node) + k;
        if (dofs.equation(g) >= 0) terms.push_back({local_of(dofs.equation(g)), 1.0});
        for (const auto& t : dofs.expansion(g))
          if (dofs.equation(t.dof) >= 0)
            terms.push_back({local_of(dofs.equation(t.dof)), t.weight});
        term_start.push_back(static_cast<std::int64_t>(terms.size()));
      }
    start.push_back(static_cast<std::int64_t>(eqs.size()));
    dof_start.push_back(static_cast<std::int64_t>(term_start.size() - 1));
  }
  std::size_t size() const { return start.size() - 1; }

  // out (m x m, m = equations of element e) += T^T k T for the element's local matrix k (n x n,
  // n = its local dofs).
  void transform_add(std::size_t e, const double* k, double* out) const {
    const std::int64_t m = start[e + 1] - start[e];
    const std::int64_t d0 = dof_start[e], n = dof_start[e + 1] - d0;
    for (std::int64_t i = 0; i < n; ++i)
      for (std::int64_t ti = term_start[d0 + i]; ti < term_start[d0 + i + 1]; ++ti)
        for (std::int64_t j = 0; j < n; ++j) {
          const double kij = terms[ti].weight * k[n * i + j];
          if (kij == 0.0) continue;
          for (std::int64_t tj = term_start[d0 + j]; tj < term_start[d0 + j + 1]; ++tj)
            out[terms[ti].local * m + terms[tj].local] += kij * terms[tj].weight;
        }
  }
};

}  // namespace

struct StaticSolver::Impl {
  const Model& model;
  StaticControls controls;
  detail::StaticElements elements;
  std::vector<double> u, reaction, nodal_force;
  StaticStatistics stats;
  std::vector<StaticContact> contacts;  // passes (static_contacts.hpp)
  std::vector<std::size_t> contact_of;  // per pass: its index in Model::contacts
  std::unique_ptr<LinearSolver> symmetric_solver, general_solver;
  double converged_force_sum = 0.0;  // sum of the average force q of the converged increments
  int converged_increments = 0;
  double coordinate_size = 0.0;  // the largest coordinate magnitude of the model
  bool indefinite = false;       // NLGEOM made the tangent indefinite: LU from then on
  LinearSolver* linear = nullptr;
  // The exact ties' nodes (tie_search.hpp) and the linear constraints of every step: the
  // *EQUATION cards, then u_s = sum N_a u_a of each tied node, eliminated by DofMap.
  std::vector<TiedNode> tied;
  std::vector<LinearConstraint> constraints;
  // Dofs of nodes that belong to no element, constraint or tie: no stiffness holds them, so they
  // get no equation (CalculiX leaves such nodes out of its system too); they stay where they are.
  std::vector<std::uint8_t> unattached;

  Impl(const Model& m, StaticControls c) : model(m), controls(c), elements(m) {
    if (!m.motions.empty() || !m.gravity.empty() || !m.pressures.empty())
      throw InputError(
          "the static solver takes its loads from Model::static_steps; the model still holds "
          "explicit motions, gravity or pressures (the deck readers turn them into step loads)");
    if (m.static_steps.empty()) throw InputError("the model has no static step");
    u.assign(3 * m.mesh.nodes.size(), 0.0);
    reaction.assign(u.size(), 0.0);
    nodal_force.assign(u.size(), 0.0);
    tied = find_tied_nodes(m);
    detail::StaticContacts set = detail::make_static_contacts(m, tied_node_set(tied));
    contacts = std::move(set.passes);
    contact_of = std::move(set.contact_of);
    constraints = m.equations;
    for (const LinearConstraint& eq : m.equations) {
      const auto& first = eq.terms.front();
      for (const TiedNode& n : tied)
        if (n.node == first.node)
          throw InputError(eq.where, "the dependent dof of this " +
                                         m.sources.words("linear_constraint") + " is on node " +
                                         std::to_string(m.mesh.nodes.id[first.node]) +
                                         ", which exact tie " + std::to_string(m.ties[n.tie].id) +
                                         " binds to its facet: put another dof first");
    }
    for (LinearConstraint& eq : tie_constraints(m, tied)) constraints.push_back(std::move(eq));
    // The elements are the mesh's solids (StaticElements refuses shells).
    std::vector<std::uint8_t> used = m.mesh.nodes_in_elements();
    for (const LinearConstraint& eq : constraints)
      for (const LinearConstraint::Term& t : eq.terms) used[static_cast<std::size_t>(t.node)] = 1;
    unattached.assign(u.size(), 0);
    for (std::size_t d = 0; d < unattached.size(); ++d) unattached[d] = !used[d / 3];
    const Nodes& x = m.mesh.nodes;
    for (std::size_t i = 0; i < x.size(); ++i)
      coordinate_size =
          std::max({coordinate_size, std::abs(x.x[i]), std::abs(x.y[i]), std::abs(x.z[i])});
  }

  // The dof of an equation, for messages.
  std::string describe_equation(const detail::DofMap& dofs, std::int64_t eq) const {
    for (std::size_t d = 0; d < dofs.dofs(); ++d)
      if (dofs.equation(d) == eq)
        return "node " + std::to_string(model.mesh.nodes.id[d / 3]) + ", direction " + "xyz"[d % 3];
    return "an unknown dof";
  }

  // One attempt at an increment ending at step time tau. Returns the iterations used, or -1.
  // `base`: the hexes' equations of this step (contact elements are added per iteration).
  int newton(const StaticStep& step, const detail::StepLoads& loads, const detail::DofMap& dofs,
             const ElementEquations& base, double tau, double dtau, bool nonlinear_geometry,
             std::vector<double>& state, double& residual_out) {
    // The step's own Newton controls (*STATIC of a .k deck) where it gives them.
    const double force_tolerance = step.force_tolerance.value_or(controls.force_tolerance);
    const double displacement_tolerance =
        step.displacement_tolerance.value_or(controls.displacement_tolerance);
    const int max_iterations = step.max_iterations.value_or(controls.max_iterations);
    // An iteration in which a contact point opened or closed does not count against the limit,
    // up to as many again: Abaqus's severe-discontinuity iterations (Analysis User's Guide 7.1.1)
    // and CalculiX, which raises its iteration limits while the contact elements change
    // (checkconvergence.c, iflagact). Points sitting at a gap of zero, as bodies that start
    // touching, open and close for some iterations before the set settles.
    int limit = max_iterations;
    std::vector<std::uint8_t> status, last_status;
    const std::vector<double> start = state;
    // Contact stabilization (laws/stabilization.hpp): the step's ramp at the increment's end,
    // times the step's period (the damping's stiffness is c T / dt).
    for (std::size_t k = 0; k < contacts.size(); ++k)
      if (const auto& stab = model.contacts[contact_of[k]].stabilization)
        contacts[k].stabilize((stab->start + (stab->end - stab->start) * tau / step.period) *
                              step.period);
    loads.prescribe(tau, state);
    dofs.update_dependent(state);
    const std::size_t n = state.size();
    const std::size_t nodes = n / 3;
    const auto neq = static_cast<std::size_t>(dofs.equations());
    std::vector<double> f(n), external(n), applied(n), r(neq), dq(neq), element_values, csr;
    std::vector<double> element_force(3 * ContactWeights::kCapacity);
    std::vector<double> x(nodes), y(nodes), z(nodes);
    for (int it = 0; it <= limit; ++it) {
      const auto t0 = Clock::now();
      try {
        elements.evaluate(state, nonlinear_geometry);
      } catch (const InstabilityError&) {
        return -1;  // an element turned inside out: cut back
      }
      std::fill(f.begin(), f.end(), 0.0);
      elements.add_forces(f);
      std::fill(external.begin(), external.end(), 0.0);
      loads.add_external_forces(tau, state, nonlinear_geometry, external);
      applied = external;
      // Contact forces, with the contact in the current configuration.
      const Nodes& reference = model.mesh.nodes;
      for (std::size_t i = 0; i < nodes; ++i) {
        x[i] = reference.x[i] + state[3 * i];
        y[i] = reference.y[i] + state[3 * i + 1];
        z[i] = reference.z[i] + state[3 * i + 2];
      }
      bool symmetric = true;
      status.clear();
      for (StaticContact& c : contacts) {
        // The increment's length: the sliding speed of rate-dependent friction is the slip over
        // it (laws/tangential.hpp). The time: the total time, which the deck's functions of t
        // read in static steps as in explicit runs (docs/deck-reference.md, *STATIC).
        c.evaluate({x, y, z, {}, {}, {}, loads.step_start() + tau, dtau, {}});
        symmetric = symmetric && c.symmetric();
        for (const StaticContactPoint& p : c.points()) status.push_back(p.active ? 1 : 0);
        for (const StaticContactElement& e : c.elements()) {
          std::fill(element_force.begin(), element_force.begin() + 3 * e.count, 0.0);
          e.add_forces(element_force.data());
          for (int a = 0; a < e.count; ++a)
            for (int k = 0; k < 3; ++k) external[3 * e.nodes[a] + k] += element_force[3 * a + k];
        }
      }
      // The average force: over the element nodal forces before assembly (Abaqus's spatially
      // averaged force, Analysis User's Guide 7.2.3), not over the assembled totals, which
      // cancel at the free nodes; plus the loads and contact forces.
      double force_sum = elements.force_magnitude_sum();
      std::size_t force_count = elements.force_entries();
      for (std::size_t d = 0; d < n; ++d) {
        if (external[d] != 0.0) force_sum += std::abs(external[d]), ++force_count;
        f[d] -= external[d];  // residual: internal - external
      }
      dofs.reduce(f, r);
      double rmax = 0.0;
      for (const double v : r) rmax = std::max(rmax, std::abs(v));
      if (!std::isfinite(rmax)) return -1;
      // The reference force: this average, but not below the mean over the increments converged
      // so far (Abaqus's time-averaged force, Analysis User's Guide 7.2.3), so that a state in
      // which every force vanishes (a body released to zero stress) converges on round-off.
      const double q_now = force_count > 0 ? force_sum / static_cast<double>(force_count) : 0.0;
      const double q_past = converged_increments > 0
                                ? converged_force_sum / static_cast<double>(converged_increments)
                                : 0.0;
      const double q = std::max(q_now, q_past);
      residual_out = q > 0.0 ? rmax / q : 0.0;
      // Convergence: residual small against the average force, and (after a correction) the
      // last correction small against the displacement increment.
      double cmax = 0.0, dumax = 0.0;
      if (it > 0) {
        for (const double v : dq) cmax = std::max(cmax, std::abs(v));
        for (std::size_t d = 0; d < n; ++d) dumax = std::max(dumax, std::abs(state[d] - start[d]));
      }
      const bool tiny = rmax <= 1e-8 * q || (q == 0.0 && rmax == 0.0);
      // A correction within the round-off of the coordinates cannot improve the state: a state
      // whose forces are all round-off (no load, bodies that only touch) ends here.
      const bool at_round_off = it > 0 && cmax <= kRoundOffUlps * kEpsilon * coordinate_size;
      const bool converged =
          tiny || at_round_off ||
          (it > 0 && rmax <= force_tolerance * q && cmax <= displacement_tolerance * dumax);
      if (converged) {
        converged_force_sum += q_now;
        ++converged_increments;
        for (std::size_t d = 0; d < n; ++d) {
          reaction[d] = loads.prescribed()[d] ? f[d] : 0.0;
          nodal_force[d] = f[d] + applied[d];  // elements less contact: loads plus reactions
        }
        stats.assembly_seconds += seconds_since(t0);
        return it;
      }
      if (it > 0 && status != last_status) limit = std::min(limit + 1, 2 * max_iterations);
      last_status.swap(status);
      if (it >= limit) break;
      // Tangent: T^T k T of every hex and contact element, assembled.
      ElementEquations ee = base;
      for (const StaticContact& c : contacts)
        for (const StaticContactElement& e : c.elements())
          ee.add(std::span<const std::int32_t>(e.nodes.data(), static_cast<std::size_t>(e.count)),
                 dofs);
      const SparseAssembly assembly(dofs.equations(), ee.start, ee.eqs);
      element_values.assign(static_cast<std::size_t>(assembly.element_value_count()), 0.0);
      const auto nh = static_cast<std::int64_t>(elements.count());
#pragma omp parallel for schedule(static)
      for (std::int64_t e = 0; e < nh; ++e)
        ee.transform_add(static_cast<std::size_t>(e),
                         elements.stiffness(static_cast<std::size_t>(e)),
                         &element_values[static_cast<std::size_t>(assembly.value_start(e))]);
      std::size_t e = elements.count();
      std::vector<double> k(9 * ContactWeights::kCapacity * ContactWeights::kCapacity);
      for (const StaticContact& c : contacts)
        for (const StaticContactElement& ce : c.elements()) {
          ce.stiffness(k.data());
          ee.transform_add(e, k.data(),
                           &element_values[static_cast<std::size_t>(
                               assembly.value_start(static_cast<std::int64_t>(e)))]);
          ++e;
        }
      assembly.assemble(element_values, csr);
      stats.assembly_seconds += seconds_since(t0);
      const auto t1 = Clock::now();
      if (!factorize(assembly.pattern(), csr, dofs, nonlinear_geometry, symmetric)) return -1;
      for (std::size_t i = 0; i < neq; ++i) r[i] = -r[i];
      linear->solve(r, dq);
      stats.solve_seconds += seconds_since(t1);
      if (linear->reciprocal_condition() < kSingularPivotRatio) {
        // Singular to round-off: a free rigid-body motion, which the solution shows as its largest
        // component. Under NLGEOM or with contact it may be a limit point or an open contact that
        // is about to close: cut back.
        if (nonlinear_geometry || !contacts.empty()) return -1;
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

  // Cholesky for a symmetric tangent (elements, frictionless or sticking contact), LU once
  // friction slips or NLGEOM makes the tangent indefinite. False when LU fails too (cut back).
  bool factorize(const SparsePattern& pattern, const std::vector<double>& csr,
                 const detail::DofMap& dofs, bool nonlinear_geometry, bool symmetric) {
    const bool use_lu = !symmetric || indefinite;
    auto& solver = use_lu ? general_solver : symmetric_solver;
    if (!solver)
      solver =
          make_linear_solver(use_lu ? MatrixKind::General : MatrixKind::SymmetricPositiveDefinite);
    linear = solver.get();
    if (stats.linear_solver.find(linear->name()) == std::string::npos)
      stats.linear_solver +=
          (stats.linear_solver.empty() ? "" : ", ") + std::string(linear->name());
    try {
      linear->factorize(pattern, csr);
    } catch (const SingularMatrixError& e) {
      if (!nonlinear_geometry && contacts.empty())
        throw InputError(singular_message(dofs, e.equation()));
      if (use_lu) return false;
      // Geometric stiffness under compression can make the tangent indefinite but regular:
      // go on with LU.
      indefinite = true;
      return factorize(pattern, csr, dofs, nonlinear_geometry, symmetric);
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
      for (const ContactChange& change : step.contact_changes) {
        if (change.contact >= model.contacts.size())
          throw InputError(change.where, "a contact change names a contact that does not exist");
        for (std::size_t pass = 0; pass < contacts.size(); ++pass) {
          if (contact_of[pass] != change.contact) continue;
          StaticContact& c = contacts[pass];
          if (const auto& o = change.overclosure) {
            NormalLaw law = LinearPenalty{};
            if (o->table.valid()) law = curve_penalty(model, o->table);
            if (o->c0) law = ExponentialOverclosure{*o->c0, *o->p0};
            c.change_normal(law, o->slope.value_or(c.settings().penalty));
          }
          if (!change.friction && !change.stick_slope) continue;
          if (c.settings().tied || c.settings().stick)
            throw InputError(
                change.where,
                "changing the friction of a tied or sticking contact is not supported");
          c.change_friction(change.friction, change.stick_slope.value_or(c.settings().stick_slope));
        }
      }
      const detail::StepLoads loads(model, step, u, history, total);
      for (const TiedNode& n : tied)
        for (int d = 0; d < 3; ++d)
          if (loads.prescribed()[3 * static_cast<std::size_t>(n.node) + d])
            throw InputError(exact_tie_place(model, model.ties[n.tie]),
                             "node " + std::to_string(model.mesh.nodes.id[n.node]) +
                                 " follows its facet by exact tie " +
                                 std::to_string(model.ties[n.tie].id) +
                                 " but has a boundary condition in direction " + "xyz"[d] +
                                 " in step " + std::to_string(s + 1) +
                                 ": prescribe the nodes of the facet it is tied to instead");
      for (const auto& [dof, force] : loads.history(step.period).forces)
        if (force != 0.0 && unattached[static_cast<std::size_t>(dof)])
          throw InputError("step " + std::to_string(s + 1) +
                           ": a concentrated force acts on node " +
                           std::to_string(model.mesh.nodes.id[static_cast<std::size_t>(dof / 3)]) +
                           ", which belongs to no element: nothing would carry it");
      std::vector<std::uint8_t> held(loads.prescribed().begin(), loads.prescribed().end());
      for (std::size_t d = 0; d < held.size(); ++d) held[d] = held[d] || unattached[d];
      const detail::DofMap dofs(model.mesh.nodes.size(), held, constraints);
      ElementEquations base;
      for (std::size_t e = 0; e < elements.count(); ++e) base.add(elements.nodes(e), dofs);
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
                                       " increments needed (" +
                                       model.sources.words("max_increments") + ")");
        for (int attempt = 1;; ++attempt) {
          std::vector<double> trial = u;
          double residual = 0.0;
          const int iterations = newton(step, loads, dofs, base, tau + dtau, dtau,
                                        nonlinear_geometry, trial, residual);
          if (iterations >= 0) {
            u = std::move(trial);
            elements.commit();
            for (StaticContact& c : contacts) c.commit();
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
std::span<const double> StaticSolver::nodal_force() const { return impl_->nodal_force; }
std::span<const double> StaticSolver::stress() const { return impl_->elements.stress(); }
std::span<const double> StaticSolver::strain() const { return impl_->elements.strain(); }
std::span<const double> StaticSolver::plastic_strain() const {
  return impl_->elements.plastic_strain();
}
int StaticSolver::integration_points(std::size_t element) const {
  return impl_->elements.integration_points(element);
}
std::size_t StaticSolver::first_point(std::size_t element) const {
  return impl_->elements.first_point(element);
}
std::span<const double> StaticSolver::element_energy() const { return impl_->elements.energy(); }
std::span<const double> StaticSolver::energy_density() const {
  return impl_->elements.energy_density();
}
std::span<const double> StaticSolver::element_volume() const { return impl_->elements.volume(); }
const StaticStatistics& StaticSolver::statistics() const { return impl_->stats; }
std::span<const StaticContact> StaticSolver::contacts() const { return impl_->contacts; }
std::size_t StaticSolver::contact_of(std::size_t pass) const { return impl_->contact_of[pass]; }

}  // namespace abut
