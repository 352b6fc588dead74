#include "abut/solver/simulation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "abut/core/parallel.hpp"
#include "simulation_impl.hpp"

namespace abut {

namespace {
// A run whose step falls below this fraction of its initial step stops (unless *TIME dt_min is
// set).
constexpr double kStepCollapse = 1e-3;

}  // namespace

// ---------------------------------------------------------------------------------------------

Vec3 Simulation::Impl::gravity_at(double time) const {
  Vec3 g;
  Variables v;
  v.t = time;
  v.term = model.time.end_time;
  for (const Gravity& grav : model.gravity)
    g[grav.direction] += grav.scale * model.functions.value(grav.curve, v);
  return g;
}

void Simulation::Impl::compute_forces(double dt) {
  const NodalState state{x.data(),
                         y.data(),
                         z.data(),
                         vhx.data(),
                         vhy.data(),
                         vhz.data(),
                         heat ? heat->temperature().data() : nullptr};
  stable = std::numeric_limits<double>::infinity();
  limiting_block = -1;
  limiting_shell_block = -1;
  limiting_cell_block = -1;
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    block_steps[b] = blocks[b].update(state, dt);
    if (block_steps[b].stable_step < stable) {
      stable = block_steps[b].stable_step;
      limiting_block = static_cast<std::int32_t>(b);
    }
  }
  if (!taylor_quinney.empty()) gather_plastic_heat();
  if (!shell_blocks.empty()) {
    const ShellNodalState shell_state{x.data(),   y.data(),   z.data(),   vhx.data(), vhy.data(),
                                      vhz.data(), whx.data(), why.data(), whz.data()};
    for (std::size_t b = 0; b < shell_blocks.size(); ++b) {
      shell_steps[b] = shell_blocks[b].update(shell_state, dt);
      if (shell_steps[b].stable_step < stable) {
        stable = shell_steps[b].stable_step;
        limiting_block = -1;
        limiting_shell_block = static_cast<std::int32_t>(b);
      }
    }
  }
  for (std::size_t b = 0; b < cell_blocks.size(); ++b) {
    cell_steps[b] = cell_blocks[b].update(state, dt);
    if (cell_steps[b].stable_step < stable) {
      stable = cell_steps[b].stable_step;
      limiting_block = limiting_shell_block = -1;
      limiting_cell_block = static_cast<std::int32_t>(b);
    }
  }
  report_erosion_to_contact();
  const Vec3 g = gravity_at(t);
  const std::int64_t nn = static_cast<std::int64_t>(n_nodes);
#pragma omp parallel for schedule(static) if (nn >= kParallelMinimum)
  for (std::int64_t i = 0; i < nn; ++i) {
    double sx = mass[i] * g.x, sy = mass[i] * g.y, sz = mass[i] * g.z;
    for (std::int32_t s = slot_start[i]; s < slot_start[i + 1]; ++s) {
      const double* fe = slots[s];
      sx += fe[0];
      sy += fe[1];
      sz += fe[2];
    }
    fx[i] = sx;
    fy[i] = sy;
    fz[i] = sz;
  }
  if (rotations()) {
#pragma omp parallel for schedule(static) if (nn >= kParallelMinimum)
    for (std::int64_t i = 0; i < nn; ++i) {
      double sx = 0.0, sy = 0.0, sz = 0.0;
      for (std::int32_t s = moment_slot_start[i]; s < moment_slot_start[i + 1]; ++s) {
        sx += moment_slots[s][0];
        sy += moment_slots[s][1];
        sz += moment_slots[s][2];
      }
      mx[i] = sx;
      my[i] = sy;
      mz[i] = sz;
    }
  }
  if (!pressure.empty()) pressure.add_forces(t, x, y, z, fx, fy, fz);  // follower load at x^n
  // Contact forces act at x^{n} with the latest velocities v^{n-1/2} (damping, friction).
  const auto contact_start = std::chrono::steady_clock::now();
  switch_contacts();
  // No temperatures: the contacts' conduction is advance_heat's. The balance's energy scale sets
  // the contacts' kink bound (ContactStats::kink_step).
  contacts->apply({x, y, z, vhx, vhy, vhz, t, dt, {}, energy_scale}, fx, fy, fz);
  release_at_impact();
  if (heat && contacts->thermal()) gather_contact_heat(dt);
  contact_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - contact_start).count();
  std::int64_t contact_id = -1;
  double spring_step = 0.0;
  const double contact_step = contacts->stable_step(&contact_id, &spring_step);
  limiting_contact = -1;
  limiting_kink = false;
  const double element_step = stable;
  if (contact_step < stable) {
    stable = contact_step;
    limiting_contact = contact_id;
    limiting_kink = contact_step < spring_step;
  }
  if (std::isfinite(element_step)) {
    step_sum += stable;
    element_step_sum += element_step;
    kink_step_sum += std::min(element_step, spring_step) - stable;
  }
  energy.contact = contacts->elastic_and_damping_energy();
  energy.friction = contacts->friction_energy();
  energy.contact_released = contacts->released_energy();
  energy.internal = 0.0;
  energy.hourglass = 0.0;
  energy.eroded = 0.0;
  energy.thermal_work = 0.0;
  for (const BlockStep& s : block_steps) energy.thermal_work += s.thermal_work;
  for (const auto* steps : {&block_steps, &shell_steps, &cell_steps}) {
    for (const BlockStep& s : *steps) {
      energy.internal += s.internal_energy;
      energy.hourglass += s.hourglass_energy;
      energy.eroded += s.eroded_energy;
    }
  }
}

// Elements eroded in this update leave the contact surfaces (and expose what lay beneath).
void Simulation::Impl::report_erosion_to_contact() {
  if (contacts->empty()) return;
  std::size_t count = 0;
  for (const auto* steps : {&block_steps, &shell_steps, &cell_steps})
    for (const BlockStep& s : *steps) count += s.eroded;
  if (count == eroded_elements) return;
  eroded_elements = count;
  const std::size_t solids = model.mesh.solid_count();
  element_eroded.assign(solids + model.mesh.shell_count(), 0);
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const std::vector<std::uint8_t>& e = blocks[b].eroded();
    for (std::size_t k = 0; k < e.size(); ++k)
      if (e[k]) element_eroded[static_cast<std::size_t>(block_hex_index[b][k])] = 1;
  }
  for (std::size_t b = 0; b < shell_blocks.size(); ++b) {
    const std::vector<std::uint8_t>& e = shell_blocks[b].eroded();
    for (std::size_t k = 0; k < e.size(); ++k)
      if (e[k]) element_eroded[solids + static_cast<std::size_t>(block_shell_index[b][k])] = 1;
  }
  for (std::size_t b = 0; b < cell_blocks.size(); ++b) {
    const std::vector<std::uint8_t>& e = cell_blocks[b].eroded();
    for (std::size_t k = 0; k < e.size(); ++k)
      if (e[k]) element_eroded[static_cast<std::size_t>(block_solid_index[b][k])] = 1;
  }
  contacts->erode(element_eroded);
}

// v^{n+1/2} from v^{n-1/2} and f^n, then boundary motions; energies at t^n.
void Simulation::Impl::kick() {
  const double scaled = model.time.step_scale * stable;
  // NaN would compare false below and end the run as if it had reached the end time.
  if (n > 0 && !(scaled > 0.0))
    throw InstabilityError(fmt::format("the stable time step became {:.4g} (limited by {})", scaled,
                                       limit_description()));
  dt_next = std::min({scaled, model.time.max_step, model.time.end_time - t});
  // At the start it is the deck's dt_min that cannot be: no step of the run would be allowed.
  if (n == 0 && scaled < model.time.min_step)
    throw InputError(model.sources.of(SourceEntity::Time, 0, "min_step"),
                     fmt::format("the minimum time step {:.4g} is above the initial stable time "
                                 "step {:.4g} (limited by {}): the run could not take its first "
                                 "step",
                                 model.time.min_step, scaled, limit_description()));
  if (scaled < model.time.min_step)
    throw InstabilityError(fmt::format(
        "the stable time step {:.4g} fell below the minimum {:.4g} ({}; limited by {})", scaled,
        model.time.min_step, model.sources.words("min_step"), limit_description()));
  // Without dt_min a collapsing step would let the run crawl on forever (an element crushed
  // flat shortens its own step in proportion): stop it, and say what limits the step.
  if (model.time.min_step <= 0.0 && n > 0 && scaled < kStepCollapse * dt_initial)
    throw InstabilityError(fmt::format(
        "the stable time step collapsed to {:.4g}, below {} of the initial {:.4g} "
        "(limited by {}); set a minimum time step ({}) to choose this limit yourself",
        scaled, kStepCollapse, dt_initial, limit_description(), model.sources.words("min_step")));
  // At the end time (dt^{n+1/2} = 0) the kick still uses a notional step dt^{n-1/2}: nothing
  // moves with it, but v^n and the kinetic energy at t^n are then defined as at every other t^n,
  // with the boundary motions prescribed over it (kick_step()).
  const double dt_kick = kick_step();
  const double dt_avg = n == 0 ? 0.5 * dt_kick : 0.5 * (dt_prev + dt_kick);
  // The velocity at t^n is v^{n-1/2} + (dt^{n-1/2}/2) a^n: the kick's change scaled by the
  // share of [t^{n-1/2}, t^{n+1/2}] that lies before t^n (0 at t^0, 1/2 at the end time).
  const double share = dt_avg > 0.0 ? 0.5 * dt_prev / dt_avg : 0.0;

  // v^{n-1/2} moves to ox, oy, oz by swapping the arrays (no copy), and the kick writes
  // v^{n+1/2} from it into every entry of vhx, vhy, vhz.
  ox.resize(n_nodes), oy.resize(n_nodes), oz.resize(n_nodes);  // sized once
  ox.swap(vhx);
  oy.swap(vhy);
  oz.swap(vhz);
  const std::int64_t nn = static_cast<std::int64_t>(n_nodes);
#pragma omp parallel for schedule(static) if (nn >= kParallelMinimum)
  for (std::int64_t i = 0; i < nn; ++i) {
    vhx[i] = ox[i] + dt_avg * fx[i] * inverse_mass[i];
    vhy[i] = oy[i] + dt_avg * fy[i] * inverse_mass[i];
    vhz[i] = oz[i] + dt_avg * fz[i] * inverse_mass[i];
  }
  // Exact ties (ties.hpp): the facet nodes carry their tied nodes' mass and force.
  ties.kick(dt_avg, mass, ox, oy, oz, fx, fy, fz, vhx, vhy, vhz);
  if (rotations()) {
    owx.resize(n_nodes), owy.resize(n_nodes), owz.resize(n_nodes);
    owx.swap(whx);
    owy.swap(why);
    owz.swap(whz);
#pragma omp parallel for schedule(static) if (nn >= kParallelMinimum)
    for (std::int64_t i = 0; i < nn; ++i) {
      whx[i] = owx[i] + dt_avg * mx[i] * inverse_rotary_inertia[i];
      why[i] = owy[i] + dt_avg * my[i] * inverse_rotary_inertia[i];
      whz[i] = owz[i] + dt_avg * mz[i] * inverse_rotary_inertia[i];
    }
  }
  // Rigid bodies: resultant force and moment about the centre of mass (with the moments that
  // shells attached to the body put on its nodes).
  for (RigidBody& body : bodies) {
    body.previous_velocity = body.velocity;
    body.previous_angular_velocity = body.angular_velocity;
    Vec3 force, moment;
    for (const std::int32_t node : body.nodes) {
      const Vec3 f{fx[node], fy[node], fz[node]};
      force += f;
      moment += cross(Vec3{x[node], y[node], z[node]} - body.centre, f);
      if (rotations()) moment += Vec3{mx[node], my[node], mz[node]};
    }
    body.velocity += (dt_avg / body.mass) * force;
    body.angular_velocity =
        body.angular_velocity_of(body.angular_momentum(body.angular_velocity) + dt_avg * moment);
  }
  apply_rigid_boundaries(dt_avg);
  for (const RigidBody& body : bodies) {
    for (const std::int32_t node : body.nodes) {
      const Vec3 v = body.velocity +
                     cross(body.angular_velocity, Vec3{x[node], y[node], z[node]} - body.centre);
      vhx[node] = v.x;
      vhy[node] = v.y;
      vhz[node] = v.z;
      if (rotations()) {
        whx[node] = body.angular_velocity.x;
        why[node] = body.angular_velocity.y;
        whz[node] = body.angular_velocity.z;
      }
    }
  }
  apply_nodal_boundaries(dt_avg);
  ties.follow(vhx, vhy, vhz);  // tied nodes move with their facets

  // Work of the external forces over [t^{n-1/2}, t^{n+1/2}]: every force that is not internal
  // (gravity and boundary reactions) equals m dv/dt - f_internal. Central differences conserve
  // (1/2) m v^{n-1/2} . v^{n+1/2} plus the strain energy less the trapezoidal work of the forces,
  // (1/2) (F^{n-1} + F^n) . (x^n - x^{n-1}) over each step: the part of the force F^n's work that
  // lies before t^n is F^n . v^{n-1/2} dt^{n-1/2}/2, the part after it F^n . v^{n+1/2}
  // dt^{n+1/2}/2. (Reported at t^n with the kick's mid velocity instead, the work was off by
  // F^n . a^n dt^2/4: a rigid sheet set down under gravity read 35% in its first cycle.) The half
  // kick at t^0 takes the mid velocity over its half step, which the kinetic energy at t^0,
  // (1/2) m |v^0|^2 without the a^0 term, matches.
  const Vec3 g = gravity_at(t);
  double before = 0.0, after = 0.0;  // sums of the impulse F^n dt_avg times v^{n-1/2}, v^{n+1/2}
  // With exact ties, that of the tied system: a tied node's mass and force are its facet nodes'
  // (the constraint's own forces are internal to it).
  const bool tied = !ties.empty();
  for (std::size_t i = 0; i < n_nodes; ++i) {
    if (tied && ties.tied(i)) continue;
    const double m = tied ? mass[i] + ties.added_mass(i) : mass[i];
    const double gx = tied ? fx[i] + ties.added_force(i, 0) : fx[i],
                 gy = tied ? fy[i] + ties.added_force(i, 1) : fy[i],
                 gz = tied ? fz[i] + ties.added_force(i, 2) : fz[i];
    // Reaction = m (v_new - v_old)/dt_avg - f^n (f^n includes gravity, so add gravity back).
    const double rx = m * (vhx[i] - ox[i]) - dt_avg * gx + dt_avg * m * g.x;
    const double ry = m * (vhy[i] - oy[i]) - dt_avg * gy + dt_avg * m * g.y;
    const double rz = m * (vhz[i] - oz[i]) - dt_avg * gz + dt_avg * m * g.z;
    before += rx * ox[i] + ry * oy[i] + rz * oz[i];
    after += rx * vhx[i] + ry * vhy[i] + rz * vhz[i];
  }
  // f^n includes the pressure forces too: add their work back as gravity's.
  if (!pressure.empty()) {
    before += dt_avg * pressure.mid_step_power(ox, oy, oz, ox, oy, oz);
    after += dt_avg * pressure.mid_step_power(vhx, vhy, vhz, vhx, vhy, vhz);
  }
  if (rotations()) {  // reaction moments of rotational constraints, the same way
    for (std::size_t i = 0; i < n_nodes; ++i) {
      // A rigid body's nodes turn with it: the shells' moments on them act on the body.
      const double inertia = rigid_body_of_node[i] < 0 ? rotary_inertia[i] : 0.0;
      if (inertia == 0.0) continue;
      const double rx = inertia * (whx[i] - owx[i]) - dt_avg * mx[i],
                   ry = inertia * (why[i] - owy[i]) - dt_avg * my[i],
                   rz = inertia * (whz[i] - owz[i]) - dt_avg * mz[i];
      before += rx * owx[i] + ry * owy[i] + rz * owz[i];
      after += rx * whx[i] + ry * why[i] + rz * whz[i];
    }
  }
  // share = dt^{n-1/2} / (2 dt_avg): F^n dt_avg share = F^n dt^{n-1/2}/2.
  const double work = n == 0 ? 0.5 * (before + after) : share * before + (1.0 - share) * after;
  // The moving analytic tools' work up to t^n (the contact booked it at t^n, ContactStats::
  // tool_work): external work the nodal reactions above do not see.
  energy.external_work = external_work_done + share * before + contacts->tool_work();
  external_work_done += work;
  // Kinetic energy at t^n: (1/2) m |v^n|^2, a sum of squares, and a rigid body's (1/2) M |v^n|^2
  // + (1/2) omega^n . I omega^n from the velocities of its centre and rotation at t^n, exactly
  // those of a prescribed motion. The balance keeps the energy central differences conserve,
  // (1/2) m v^{n-1/2} . v^{n+1/2} (conserved_kinetic, simulation_impl.hpp), which goes negative
  // where a velocity turns within a step: a rigid body on a stiff contact, a node at the turning
  // point of its vibration (issue 28).
  // With exact ties, the kinetic energy of the tied system the run integrates: a tied node's mass
  // counts at its facet's nodes, where the kick carries it (ties.hpp; it exceeds the nodes' own
  // (1/2) m |v|^2 by the variance of the facet's velocities).
  // Where the step changes, that product changes its meaning: with v^{n-1/2} = v^n - a^n h_-/2 and
  // v^{n+1/2} = v^n + a^n h_+/2 (h_-, h_+ the steps before and after t^n) it is |v^n|^2
  // + v^n . a^n (h_+ - h_-)/2 - |a^n|^2 h_- h_+/4. What a constant step h conserves is
  // |v^n|^2 - |a^n|^2 h^2/4 (with the strain energy): the run so far conserved it with h_-, the
  // steps to come conserve it with h_+, and the same motion reads |a^n|^2 (h_+^2 - h_-^2)/4 less
  // in the second (for a linear oscillator at step h it is (1 - (omega h/2)^2) of its amplitude's
  // energy: a mode near the stability limit shows a fifth of it). So the balance keeps
  // (1/2) m (|v^n|^2 - |a^n|^2 h_-^2/4), the product at a constant step, and adds back what the
  // changes of the step so far took from it (step_change_kinetic): a step cut to the end time,
  // or one that grows when a contact lets go while the bodies ring, no longer moves the balance
  // without a change in the motion. a^n is the kick's (v^{n+1/2} - v^{n-1/2}) / dt_avg.
  const double h_before = n == 0 ? 0.0 : dt_prev, h_after = dt_kick;
  const double inverse_avg = dt_avg > 0.0 ? 1.0 / dt_avg : 0.0;
  double kinetic = 0.0, conserved = 0.0, acceleration2 = 0.0;  // sum of m |a^n|^2
  for (std::size_t i = 0; i < n_nodes; ++i) {
    vx[i] = ox[i] + share * (vhx[i] - ox[i]);
    vy[i] = oy[i] + share * (vhy[i] - oy[i]);
    vz[i] = oz[i] + share * (vhz[i] - oz[i]);
    if (tied && ties.tied(i)) continue;
    const double m = tied ? mass[i] + ties.added_mass(i) : mass[i];
    const double v2 = vx[i] * vx[i] + vy[i] * vy[i] + vz[i] * vz[i];
    if (rigid_body_of_node[i] < 0) kinetic += 0.5 * m * v2;
    const double ax = (vhx[i] - ox[i]) * inverse_avg, ay = (vhy[i] - oy[i]) * inverse_avg,
                 az = (vhz[i] - oz[i]) * inverse_avg;
    const double a2 = ax * ax + ay * ay + az * az;
    conserved += 0.5 * m * (v2 - 0.25 * a2 * h_before * h_before);
    acceleration2 += m * a2;
  }
  if (rotations()) {  // shell nodes; a rigid body's rotation is in its own energy below
    for (std::size_t i = 0; i < n_nodes; ++i) {
      if (rigid_body_of_node[i] >= 0) continue;
      const double wx = owx[i] + share * (whx[i] - owx[i]), wy = owy[i] + share * (why[i] - owy[i]),
                   wz = owz[i] + share * (whz[i] - owz[i]);
      const double w2 = wx * wx + wy * wy + wz * wz;
      kinetic += 0.5 * rotary_inertia[i] * w2;
      const double ax = (whx[i] - owx[i]) * inverse_avg, ay = (why[i] - owy[i]) * inverse_avg,
                   az = (whz[i] - owz[i]) * inverse_avg;
      const double a2 = ax * ax + ay * ay + az * az;
      conserved += 0.5 * rotary_inertia[i] * (w2 - 0.25 * a2 * h_before * h_before);
      acceleration2 += rotary_inertia[i] * a2;
    }
  }
  for (const RigidBody& body : bodies) {
    const Vec3 v = body.previous_velocity + share * (body.velocity - body.previous_velocity);
    const Vec3 w = body.previous_angular_velocity +
                   share * (body.angular_velocity - body.previous_angular_velocity);
    for (const std::int32_t node : body.nodes) {
      const Vec3 u = v + cross(w, Vec3{x[node], y[node], z[node]} - body.centre);
      vx[node] = u.x;
      vy[node] = u.y;
      vz[node] = u.z;
    }
    kinetic += body.kinetic_energy(v, w);
  }
  conserved_kinetic = conserved + step_change_kinetic;
  // Not at t^0: the half kick that starts the run makes v^{1/2} . v^{3/2} the product of a run at
  // the first step throughout, and the external work booked over that half step matches it.
  if (n > 0 && h_after != h_before)
    step_change_kinetic += 0.125 * acceleration2 * (h_after * h_after - h_before * h_before);
  energy.kinetic = kinetic;
  energy_scale = std::max({energy_scale, std::abs(conserved_total()),
                           std::abs(energy.external_work), std::abs(energy.thermal_work)});
}

void Simulation::Impl::apply_nodal_boundaries(double dt_avg) {
  double* v[3] = {vhx.data(), vhy.data(), vhz.data()};
  const double* vold[3] = {ox.data(), oy.data(), oz.data()};
  const double* pos[3] = {x.data(), y.data(), z.data()};
  const double* ref[3] = {x0.data(), y0.data(), z0.data()};
  for (std::size_t i = 0; i < n_nodes; ++i)
    for (int d = 0; d < 3; ++d)
      if (node_fixed[i] & held(i) & (1u << d)) v[d][i] = 0.0;
  double* w[3] = {whx.data(), why.data(), whz.data()};
  const double* wold[3] = {owx.data(), owy.data(), owz.data()};
  for (const NodalMotion& nm : bc.nodal) {
    const MotionBoundary& m = *nm.source;
    if (!motion_active(model, m, t)) continue;
    for (int d = 0; d < 3; ++d) {
      if (m.fixed_translation & (1u << d))
        for (const std::int32_t i : nm.nodes)
          if (held(static_cast<std::size_t>(i)) & (1u << d)) v[d][i] = 0.0;
      if (m.fixed_rotation & (1u << d))
        for (const std::int32_t i : nm.rotating_nodes) w[d][i] = 0.0;
    }
    for (const PrescribedMotion& p : m.motions) {
      if (!prescription_active(model, p, t)) continue;
      if (p.direction >= 3) {
        apply_nodal_rotation(p, nm.rotating_nodes, w[p.direction - 3], wold[p.direction - 3],
                             dt_avg);
        continue;
      }
      const int d = p.direction;
      Variables vars;
      vars.term = model.time.end_time;
      switch (p.kind) {
        case PrescribedMotion::Kind::Velocity: {
          vars.t = t + 0.5 * kick_step();
          const double value = p.scale * model.functions.value(p.curve, vars);
          for (const std::int32_t i : nm.nodes) v[d][i] = value;
          break;
        }
        case PrescribedMotion::Kind::Displacement: {
          vars.t = t + kick_step();
          const double target = p.scale * model.functions.value(p.curve, vars);
          for (const std::int32_t i : nm.nodes)
            v[d][i] = (target - (pos[d][i] - ref[d][i])) / kick_step();
          break;
        }
        case PrescribedMotion::Kind::Acceleration: {
          vars.t = t;
          const double a = p.scale * model.functions.value(p.curve, vars);
          for (const std::int32_t i : nm.nodes) v[d][i] = vold[d][i] + dt_avg * a;
          break;
        }
      }
    }
  }
}

// RX, RY, RZ of a *BC_MOTION on shell nodes: angular velocity or acceleration.
void Simulation::Impl::apply_nodal_rotation(const PrescribedMotion& p,
                                            const std::vector<std::int32_t>& nodes, double* w,
                                            const double* w_old, double dt_avg) {
  Variables vars;
  vars.term = model.time.end_time;
  switch (p.kind) {
    case PrescribedMotion::Kind::Velocity: {
      vars.t = t + 0.5 * kick_step();
      const double value = p.scale * model.functions.value(p.curve, vars);
      for (const std::int32_t i : nodes) w[i] = value;
      break;
    }
    case PrescribedMotion::Kind::Acceleration: {
      vars.t = t;
      const double a = p.scale * model.functions.value(p.curve, vars);
      for (const std::int32_t i : nodes) w[i] = w_old[i] + dt_avg * a;
      break;
    }
    case PrescribedMotion::Kind::Displacement:
      throw InputError(p.where,
                       "prescribed rotation angles (D with RX/RY/RZ) are not supported yet; "
                       "prescribe the angular velocity (V) instead");
  }
}

void Simulation::Impl::apply_rigid_boundaries(double dt_avg) {
  for (const RigidMotion& rm : bc.rigid) {
    const MotionBoundary& m = *rm.source;
    if (!motion_active(model, m, t)) continue;
    RigidBody& body = bodies[rm.body];
    for (int d = 0; d < 3; ++d) {
      if (m.fixed_translation & (1u << d)) body.velocity[d] = 0.0;
      if (m.fixed_rotation & (1u << d)) body.angular_velocity[d] = 0.0;
    }
    for (const PrescribedMotion& p : m.motions) {
      if (!prescription_active(model, p, t)) continue;
      const int d = p.direction % 3;
      const bool rotation = p.direction >= 3;
      double& target = rotation ? body.angular_velocity[d] : body.velocity[d];
      Variables vars;
      vars.term = model.time.end_time;
      switch (p.kind) {
        case PrescribedMotion::Kind::Velocity:
          vars.t = t + 0.5 * kick_step();
          target = p.scale * model.functions.value(p.curve, vars);
          break;
        case PrescribedMotion::Kind::Displacement: {
          if (rotation)
            throw InputError(p.where,
                             "prescribed rotation angles (D with RX/RY/RZ) are not supported yet; "
                             "prescribe the angular velocity (V) instead");
          vars.t = t + kick_step();
          const double displacement = p.scale * model.functions.value(p.curve, vars);
          target = (body.centre0[d] + displacement - body.centre[d]) / kick_step();
          break;
        }
        case PrescribedMotion::Kind::Acceleration:
          vars.t = t;
          target += dt_avg * p.scale * model.functions.value(p.curve, vars);
          break;
      }
    }
  }
}

void Simulation::Impl::drift() {
  // x^n is kept as the last good state by swapping the arrays (no copy); the drift writes x^{n+1}
  // into every entry (rigid bodies' nodes: unchanged here, placed below).
  good_x.resize(n_nodes), good_y.resize(n_nodes), good_z.resize(n_nodes);  // sized once
  good_x.swap(x);
  good_y.swap(y);
  good_z.swap(z);
  good_t = t;
  const double dt = dt_next;
  const std::int64_t nn = static_cast<std::int64_t>(n_nodes);
#pragma omp parallel for schedule(static) if (nn >= kParallelMinimum)
  for (std::int64_t i = 0; i < nn; ++i) {
    const bool rigid = rigid_body_of_node[i] >= 0;
    x[i] = rigid ? good_x[i] : good_x[i] + dt * vhx[i];
    y[i] = rigid ? good_y[i] : good_y[i] + dt * vhy[i];
    z[i] = rigid ? good_z[i] : good_z[i] + dt * vhz[i];
  }
  for (RigidBody& body : bodies) {
    body.centre += dt * body.velocity;
    body.rotation = rotation_from_vector(dt * body.angular_velocity) * body.rotation;
    for (std::size_t k = 0; k < body.nodes.size(); ++k) {
      const std::int32_t node = body.nodes[k];
      const Vec3 p = body.centre + body.rotation * body.arm0[k];
      // The nodal velocity over the step is the secant one, consistent with the motion.
      vhx[node] = (p.x - x[node]) / dt;
      vhy[node] = (p.y - y[node]) / dt;
      vhz[node] = (p.z - z[node]) / dt;
      x[node] = p.x;
      y[node] = p.y;
      z[node] = p.z;
    }
  }
  ties.place(x, y, z);  // exactly on their facets, without the drift's round-off
  t += dt;
  ++n;
  dt_prev = dt;
  compute_forces(dt);
  bool finite = true;
#pragma omp parallel for schedule(static) reduction(&& : finite) if (nn >= kParallelMinimum)
  for (std::int64_t i = 0; i < nn; ++i)
    finite = finite && std::isfinite(x[i] + y[i] + z[i] + fx[i] + fy[i] + fz[i]);
  if (!finite)
    throw InstabilityError("non-finite coordinates or forces at cycle " + std::to_string(n) +
                           ", t = " + std::to_string(t));
  advance_heat();
}

// The heat (issues 11, 29), after every mechanical step [t - dt, t], so that the temperatures are
// always at t:
//  - the heat the mechanics made over the step (friction, plastic work) goes in at once;
//  - the conduction in the elements and through the contacts, and the face loads, flow at the
//    rates planned at the start of their thermal step (HeatSolver::plan, forward Euler), with
//    the contacts' partners and conductances of the mechanical step the plan falls in. A thermal
//    step spans several mechanical steps (the usual case: conduction is slow), or a mechanical
//    step holds several thermal steps. It lasts at most thermal_step_limit(), never crosses a
//    break of a load's curve or the end of the run, and ends early when a contact starts to conduct
//    more than it was planned with (a contact that closes conducts from that mechanical step on);
//  - the prescribed temperatures take their values at t.
void Simulation::Impl::advance_heat() {
  if (!heat) return;
  if (!heat_energy.empty()) {
    heat->put_heat({}, heat_energy, 1.0);
    std::fill(heat_energy.begin(), heat_energy.end(), 0.0);
  }
  double time = t - dt_prev;
  if (contact_heat_rate > planned_contact_rate) heat_planned_to = time;
  while (time < t) {
    // A planned step that ends within round-off of now is over.
    if (heat_planned_to - time <= 1e-12 * std::max(std::abs(time), dt_prev)) {
      const double span = std::min({thermal_step_limit(), heat->next_load_break(time) - time,
                                    std::max(model.time.end_time - time, t - time)});
      std::span<const double> exchange;
      if (contacts->thermal()) {  // also with no partner: the flow to report is then 0
        heat_exchange.assign(n_nodes, 0.0);
        contacts->conduct_heat(heat->temperature(), heat_exchange);
        exchange = heat_exchange;
      }
      heat->plan(time, span, x, y, z, exchange);
      heat_planned_to = time + span;
      planned_contact_rate = contact_heat_rate;
      ++heat_steps;
    }
    const double part = std::min(t, heat_planned_to) - time;
    heat->flow(part, {});
    if (contacts->thermal()) contacts->book_conducted_heat(part);
    time = heat_planned_to < t ? heat_planned_to : t;
  }
  for (const PrescribedTemperature& p : model.thermal.prescribed)
    if (p.curve.valid()) {
      heat->hold(t);
      break;
    }
}

// The longest thermal step: at most dt_max of *TIME, kThermalStepScale of the stable step of
// the conduction in the elements and through contact, and short enough for the contact's
// exchange to be accurate. A contact conductance G_a at a node of capacity C_a adds at most
// 2 G_a / C_a to the largest eigenvalue of C^-1 K (Gershgorin's theorem; the elements' bound gives
// 2 / stable_step), so 1 / (1 / stable_step + G_a / C_a) is stable. Two nodes joined by G relax
// their difference as exp(-lambda t), lambda = G (1/C_1 + 1/C_2) <= 2 max G/C: steps of
// lambda h <= kExchangeStep follow that exponential within 0.4% of the starting difference at
// every time (forward Euler's (1 - lambda h)^n against exp(-n lambda h) is furthest apart near
// n lambda h = 1, by about e^-1 lambda h / 2). Evaluated once per mechanical step and spread over
// its thermal steps, it was forward Euler at the mechanical step: two blocks exchanging through
// h = 1e6 W/m2K at a 0.1 s step flipped sign and grew 30 times per step.
double Simulation::Impl::thermal_step_limit() const {
  constexpr double kThermalStepScale = 0.9, kExchangeStep = 0.02;
  double limit = std::min(model.time.max_step,
                          kThermalStepScale / (1.0 / heat->stable_step() + contact_heat_rate));
  if (contact_heat_rate > 0.0) limit = std::min(limit, kExchangeStep / (2.0 * contact_heat_rate));
  return limit;
}

// The friction heat the contacts put into each node over the mechanical step dt, and the largest
// ratio of a node's contact conductance to its heat capacity in the step (thermal_step_limit).
void Simulation::Impl::gather_contact_heat(double dt) {
  const std::span<const double> q = contacts->heat(), g = contacts->conductance();
  const std::span<const double> capacity = heat->capacity();
  if (heat_energy.empty()) heat_energy.assign(n_nodes, 0.0);
  contact_heat_rate = 0.0;
  for (const std::int32_t node : contacts->surface_nodes()) {
    const auto i = static_cast<std::size_t>(node);
    // Setup made sure that the surfaces of thermal contacts have heat capacity.
    if ((q[i] == 0.0 && g[i] == 0.0) || !(capacity[i] > 0.0)) continue;
    heat_energy[i] += q[i] * dt;
    contact_heat_rate = std::max(contact_heat_rate, g[i] / capacity[i]);
  }
}

void Simulation::advance() {
  impl_->drift();
  impl_->kick();
  // The nodes' check (drift) does not see an energy that overflows or turns NaN on its own.
  if (const std::string fault = impl_->energy_fault(); !fault.empty())
    throw InstabilityError(fault + " at cycle " + std::to_string(impl_->n) +
                           ", t = " + std::to_string(impl_->t));
}

bool Simulation::finished() const {
  const double end = impl_->model.time.end_time;
  return impl_->t >= end * (1.0 - 1e-12) || impl_->dt_next <= 0.0;
}

double Simulation::time() const { return impl_->t; }
double Simulation::end_time() const { return impl_->model.time.end_time; }
std::int64_t Simulation::cycle() const { return impl_->n; }
double Simulation::time_step() const { return impl_->dt_next; }
double Simulation::initial_time_step() const { return impl_->dt_initial; }
double Simulation::contact_step_loss() const {
  const Impl& s = *impl_;
  return s.element_step_sum > 0.0 ? 1.0 - s.step_sum / s.element_step_sum : 0.0;
}
double Simulation::contact_kink_step_loss() const {
  const Impl& s = *impl_;
  return s.element_step_sum > 0.0 ? s.kink_step_sum / s.element_step_sum : 0.0;
}
std::string Simulation::Impl::limit_description() const {
  if (limiting_contact >= 0)
    return "contact " + std::to_string(limiting_contact) +
           (limiting_kink ? " springs touching or letting go together" : " springs");
  if (limiting_shell_block >= 0)
    return "shells of part " + std::to_string(shell_blocks[limiting_shell_block].part_id());
  if (limiting_cell_block >= 0)
    return std::string(element_label(cell_blocks[limiting_cell_block].type())) +
           " elements of part " + std::to_string(cell_blocks[limiting_cell_block].part_id());
  if (limiting_block < 0) return model.sources.words("max_step");
  return "elements of part " + std::to_string(blocks[limiting_block].part_id());
}

SourceLocation Simulation::Impl::limit_location() const {
  if (limiting_contact >= 0) {
    for (const ContactSpec& c : model.contacts)
      if (c.id == limiting_contact) return c.where;
  }
  std::int64_t part = -1;
  if (limiting_shell_block >= 0) part = shell_blocks[limiting_shell_block].part_id();
  if (limiting_block >= 0) part = blocks[limiting_block].part_id();
  if (limiting_cell_block >= 0) part = cell_blocks[limiting_cell_block].part_id();
  if (const Part* p = model.find_part(part)) return p->where;
  return {};
}

std::string Simulation::time_step_limit() const { return impl_->limit_description(); }

}  // namespace abut
