#include "abut/solver/simulation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "abut/core/parallel.hpp"
#include "abut/element/solid_block.hpp"
#include "abut/mesh/skin.hpp"
#include "abut/solver/pressure_loads.hpp"
#include "boundary_conditions.hpp"
#include "contact_set.hpp"
#include "rigid_body.hpp"

namespace abut {

namespace {

// A run whose step falls below this fraction of its initial step stops (unless *TIME dt_min is
// set).
constexpr double kStepCollapse = 1e-3;

// Where one element's force on one node sits: block and offset into its element_forces().
struct ForceSlot {
  std::int32_t block;
  std::int32_t offset;
};

struct PartInfo {
  std::int64_t part_id = 0;
  std::string title;
  bool rigid = false;
  std::size_t element_count = 0;
  double mass = 0.0;
  std::int32_t block = -1;  // deformable: index into blocks
  std::vector<std::int32_t> nodes;
  std::vector<double> node_mass;  // this part's share of each node's lumped mass
};

}  // namespace

struct Simulation::Impl {
  const Model& model;
  std::size_t n_nodes = 0;
  std::vector<double> x, y, z;             // x^n
  std::vector<double> x0, y0, z0;          // reference
  std::vector<double> vhx, vhy, vhz;       // v^{n+1/2} after kick
  std::vector<double> vx, vy, vz;          // v^n
  std::vector<double> ox, oy, oz;          // v^{n-1/2} during the kick
  std::vector<double> fx, fy, fz;          // f^n
  std::vector<double> mass, inverse_mass;  // lumped
  std::vector<std::uint8_t> node_fixed;    // *NODE bc
  std::vector<std::int32_t> rigid_body_of_node;

  std::vector<SolidBlock> blocks;
  std::vector<std::vector<std::int32_t>> block_hex_index;  // block element -> mesh hex
  std::vector<std::int32_t> slot_start;                    // CSR node -> force slots
  std::vector<ForceSlot> slots;
  std::vector<BlockStep> block_steps;

  std::unique_ptr<ContactSet> contacts;
  std::int64_t limiting_contact = -1;
  double contact_seconds = 0.0;  // wall time spent in contact (for the summary)

  std::vector<RigidBody> bodies;
  std::vector<PartInfo> parts;
  BoundaryConditions bc;
  PressureLoads pressure;  // *LOAD_PRESSURE, its forces kept apart for the external work

  double t = 0.0;
  std::int64_t n = 0;
  double dt_prev = 0.0;  // dt^{n-1/2}
  double dt_next = 0.0;  // dt^{n+1/2}
  double stable = 0.0;   // unscaled stable step at x^n
  double dt_initial = 0.0;
  std::int32_t limiting_block = -1;

  Energies energy;
  double total0 = 0.0;
  double external_work_done = 0.0;  // up to t^{n+1/2}

  std::vector<double> good_x, good_y, good_z;
  double good_t = 0.0;

  explicit Impl(const Model& m) : model(m) {}

  void setup();
  void compute_forces(double dt);
  void kick();
  void drift();
  Vec3 gravity_at(double time) const;
  void apply_nodal_boundaries(double dt_avg);  // on v^{n+1/2}, from v^{n-1/2} in ox, oy, oz
  void apply_rigid_boundaries(double dt_avg);
  std::string limit_description() const;
};

// ---------------------------------------------------------------------------------------------
// Set-up

void Simulation::Impl::setup() {
  const Mesh& mesh = model.mesh;
  if (mesh.shell_count() > 0)  // until the shell element lands in the time loop
    throw InputError(SourceLocation{}, "shell elements cannot be run yet");
  n_nodes = mesh.nodes.size();
  x = mesh.nodes.x;
  y = mesh.nodes.y;
  z = mesh.nodes.z;
  x0 = x;
  y0 = y;
  z0 = z;
  node_fixed = mesh.nodes.fixed;
  mass.assign(n_nodes, 0.0);
  rigid_body_of_node.assign(n_nodes, -1);

  // Group hexes by part, in the order parts were defined.
  std::map<std::int64_t, std::vector<std::int32_t>> hexes_of_part;
  for (std::size_t e = 0; e < mesh.hex_count(); ++e)
    hexes_of_part[mesh.hex_part[e]].push_back(static_cast<std::int32_t>(e));

  for (const Part& part : model.parts) {
    auto it = hexes_of_part.find(part.id);
    if (it == hexes_of_part.end()) continue;  // a part without elements takes no part in the run
    const MaterialParams& material = model.material_of_part(part.id);
    PartInfo info;
    info.part_id = part.id;
    info.title = part.title;
    info.rigid = is_rigid(material);
    info.element_count = it->second.size();

    std::vector<double> part_mass(n_nodes, 0.0);
    if (info.rigid) {
      if (part.erosion.any())
        throw InputError(part.where,
                         "part " + std::to_string(part.id) +
                             " is rigid: element erosion applies to deformable parts only");
      const double rho = density_of(material);
      for (const std::int32_t e : it->second) {
        const double v = hex_volume(mesh.nodes, mesh.hexes[e]);
        for (const std::int32_t node : mesh.hexes[e]) part_mass[node] += rho * v / 8.0;
      }
    } else {
      std::vector<Hex8> hexes;
      hexes.reserve(it->second.size());
      for (const std::int32_t e : it->second) hexes.push_back(mesh.hexes[e]);
      blocks.emplace_back(part.id, material, std::move(hexes), mesh.nodes, &model.functions);
      blocks.back().set_erosion(part.erosion);
      blocks.back().add_lumped_mass(part_mass);
      block_hex_index.push_back(it->second);
      info.block = static_cast<std::int32_t>(blocks.size() - 1);
    }
    for (std::size_t i = 0; i < n_nodes; ++i) {
      if (part_mass[i] > 0.0) {
        info.nodes.push_back(static_cast<std::int32_t>(i));
        info.node_mass.push_back(part_mass[i]);
        mass[i] += part_mass[i];
        info.mass += part_mass[i];
      }
    }
    if (info.rigid) {
      RigidBody body;
      body.part_id = part.id;
      body.nodes = info.nodes;
      for (const std::int32_t node : info.nodes) {
        if (rigid_body_of_node[node] >= 0)
          throw InputError(
              part.where,
              "rigid parts " + std::to_string(bodies[rigid_body_of_node[node]].part_id) + " and " +
                  std::to_string(part.id) + " share nodes; give each rigid part its own nodes");
        if (node_fixed[node] != 0)
          throw InputError(part.where, "node " + std::to_string(mesh.nodes.id[node]) +
                                           " of rigid part " + std::to_string(part.id) +
                                           " has a *NODE bc; constrain a rigid "
                                           "part as a whole with *BC_MOTION (entype P)");
        rigid_body_of_node[node] = static_cast<std::int32_t>(bodies.size());
      }
      bodies.push_back(std::move(body));
    }
    parts.push_back(std::move(info));
  }
  // A node shared by a rigid and a deformable part moves with the rigid body; the mass the
  // deformable elements lump on it belongs to the body, and their forces act on it.
  for (RigidBody& body : bodies) body.initialise(x0, y0, z0, mass);

  inverse_mass.assign(n_nodes, 0.0);
  for (std::size_t i = 0; i < n_nodes; ++i)
    if (mass[i] > 0.0 && rigid_body_of_node[i] < 0) inverse_mass[i] = 1.0 / mass[i];

  // Node -> element force slots (CSR), in block and element order: the fixed summation order
  // that makes forces independent of the thread count.
  std::vector<std::int32_t> count(n_nodes + 1, 0);
  for (const SolidBlock& b : blocks)
    for (const Hex8& h : b.hexes())
      for (const std::int32_t node : h) ++count[node + 1];
  for (std::size_t i = 0; i < n_nodes; ++i) count[i + 1] += count[i];
  slot_start = count;
  slots.resize(static_cast<std::size_t>(count[n_nodes]));
  std::vector<std::int32_t> fill(slot_start.begin(), slot_start.end() - 1);
  for (std::size_t bi = 0; bi < blocks.size(); ++bi) {
    const auto& hexes = blocks[bi].hexes();
    for (std::size_t e = 0; e < hexes.size(); ++e)
      for (int a = 0; a < 8; ++a)
        slots[fill[hexes[e][a]]++] = {static_cast<std::int32_t>(bi),
                                      static_cast<std::int32_t>(e * 24 + a * 3)};
  }
  block_steps.assign(blocks.size(), {});

  // Initial velocities; rigid bodies take the momentum and angular momentum of theirs.
  vhx = model.vx0.empty() ? std::vector<double>(n_nodes, 0.0) : model.vx0;
  vhy = model.vy0.empty() ? std::vector<double>(n_nodes, 0.0) : model.vy0;
  vhz = model.vz0.empty() ? std::vector<double>(n_nodes, 0.0) : model.vz0;
  for (RigidBody& body : bodies) {
    Vec3 momentum, angular_momentum;
    for (std::size_t k = 0; k < body.nodes.size(); ++k) {
      const std::int32_t node = body.nodes[k];
      const Vec3 p = mass[node] * Vec3{vhx[node], vhy[node], vhz[node]};
      momentum += p;
      angular_momentum += cross(body.arm0[k], p);
    }
    body.velocity = momentum / body.mass;
    body.angular_velocity = inverse(body.inertia0) * angular_momentum;
    for (std::size_t k = 0; k < body.nodes.size(); ++k) {
      const std::int32_t node = body.nodes[k];
      const Vec3 v = body.velocity + cross(body.angular_velocity, body.arm0[k]);
      vhx[node] = v.x;
      vhy[node] = v.y;
      vhz[node] = v.z;
    }
  }
  vx = vhx;
  vy = vhy;
  vz = vhz;

  std::vector<std::pair<std::int64_t, std::size_t>> body_of_part;
  for (std::size_t b = 0; b < bodies.size(); ++b) body_of_part.emplace_back(bodies[b].part_id, b);
  bc = resolve_boundary_conditions(model, rigid_body_of_node, body_of_part);

  contacts = std::make_unique<ContactSet>(model, mass, vhx, vhy, vhz);
  pressure = PressureLoads(model);

  fx.assign(n_nodes, 0.0);
  fy.assign(n_nodes, 0.0);
  fz.assign(n_nodes, 0.0);
  t = model.time.start_time;
  compute_forces(0.0);
  dt_initial = std::min(model.time.step_scale * stable, model.time.max_step);
  kick();
  total0 = energy.total();
}

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
  const NodalState state{x.data(), y.data(), z.data(), vhx.data(), vhy.data(), vhz.data()};
  stable = std::numeric_limits<double>::infinity();
  limiting_block = -1;
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    block_steps[b] = blocks[b].update(state, dt);
    if (block_steps[b].stable_step < stable) {
      stable = block_steps[b].stable_step;
      limiting_block = static_cast<std::int32_t>(b);
    }
  }
  const Vec3 g = gravity_at(t);
  const std::int64_t nn = static_cast<std::int64_t>(n_nodes);
#pragma omp parallel for schedule(static) if (nn >= kParallelMinimum)
  for (std::int64_t i = 0; i < nn; ++i) {
    double sx = mass[i] * g.x, sy = mass[i] * g.y, sz = mass[i] * g.z;
    for (std::int32_t s = slot_start[i]; s < slot_start[i + 1]; ++s) {
      const double* fe = blocks[slots[s].block].element_forces().data() + slots[s].offset;
      sx += fe[0];
      sy += fe[1];
      sz += fe[2];
    }
    fx[i] = sx;
    fy[i] = sy;
    fz[i] = sz;
  }
  if (!pressure.empty()) pressure.add_forces(t, x, y, z, fx, fy, fz);  // follower load at x^n
  // Contact forces act at x^{n} with the latest velocities v^{n-1/2} (damping, friction).
  const auto contact_start = std::chrono::steady_clock::now();
  contacts->apply({x, y, z, vhx, vhy, vhz, t, dt}, fx, fy, fz);
  contact_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - contact_start).count();
  std::int64_t contact_id = -1;
  const double contact_step = contacts->stable_step(&contact_id);
  limiting_contact = -1;
  if (contact_step < stable) {
    stable = contact_step;
    limiting_contact = contact_id;
  }
  energy.contact = contacts->elastic_and_damping_energy();
  energy.friction = contacts->friction_energy();
  energy.internal = 0.0;
  energy.hourglass = 0.0;
  energy.eroded = 0.0;
  for (const BlockStep& s : block_steps) {
    energy.internal += s.internal_energy;
    energy.hourglass += s.hourglass_energy;
    energy.eroded += s.eroded_energy;
  }
}

// v^{n+1/2} from v^{n-1/2} and f^n, then boundary motions; energies at t^n.
void Simulation::Impl::kick() {
  const double scaled = model.time.step_scale * stable;
  dt_next = std::min({scaled, model.time.max_step, model.time.end_time - t});
  if (scaled < model.time.min_step)
    throw InstabilityError(fmt::format(
        "the stable time step {:.4g} fell below dt_min = {:.4g} of *TIME (limited by {})", scaled,
        model.time.min_step, limit_description()));
  // Without dt_min a collapsing step would let the run crawl on forever (an element crushed
  // flat shortens its own step in proportion): stop it, and say what limits the step.
  if (model.time.min_step <= 0.0 && n > 0 && scaled < kStepCollapse * dt_initial)
    throw InstabilityError(
        fmt::format("the stable time step collapsed to {:.4g}, below {} of the initial {:.4g} "
                    "(limited by {}); set dt_min of *TIME to choose this limit yourself",
                    scaled, kStepCollapse, dt_initial, limit_description()));
  // At the end time (dt^{n+1/2} = 0) the kick still uses a notional step dt^{n-1/2}: nothing
  // moves with it, but v^n and the kinetic energy at t^n are then defined as at every other t^n.
  const double dt_kick = dt_next > 0.0 ? dt_next : dt_prev;
  const double dt_avg = n == 0 ? 0.5 * dt_kick : 0.5 * (dt_prev + dt_kick);

  ox.assign(vhx.begin(), vhx.end());  // v^{n-1/2} (same size every cycle: no allocation)
  oy.assign(vhy.begin(), vhy.end());
  oz.assign(vhz.begin(), vhz.end());
  const std::int64_t nn = static_cast<std::int64_t>(n_nodes);
#pragma omp parallel for schedule(static) if (nn >= kParallelMinimum)
  for (std::int64_t i = 0; i < nn; ++i) {
    vhx[i] += dt_avg * fx[i] * inverse_mass[i];
    vhy[i] += dt_avg * fy[i] * inverse_mass[i];
    vhz[i] += dt_avg * fz[i] * inverse_mass[i];
  }
  // Rigid bodies: resultant force and moment about the centre of mass.
  for (RigidBody& body : bodies) {
    Vec3 force, moment;
    for (const std::int32_t node : body.nodes) {
      const Vec3 f{fx[node], fy[node], fz[node]};
      force += f;
      moment += cross(Vec3{x[node], y[node], z[node]} - body.centre, f);
    }
    const Mat3 inertia = body.spatial_inertia();
    body.velocity += (dt_avg / body.mass) * force;
    body.angular_velocity = inverse(inertia) * (inertia * body.angular_velocity + dt_avg * moment);
  }
  apply_rigid_boundaries(dt_avg);
  for (const RigidBody& body : bodies) {
    for (const std::int32_t node : body.nodes) {
      const Vec3 v = body.velocity +
                     cross(body.angular_velocity, Vec3{x[node], y[node], z[node]} - body.centre);
      vhx[node] = v.x;
      vhy[node] = v.y;
      vhz[node] = v.z;
    }
  }
  apply_nodal_boundaries(dt_avg);

  // Work of the external forces over [t^{n-1/2}, t^{n+1/2}]: every force that is not internal
  // (gravity and boundary reactions) equals m dv/dt - f_internal; its work with the mid velocity.
  const Vec3 g = gravity_at(t);
  double work = 0.0;
  for (std::size_t i = 0; i < n_nodes; ++i) {
    const double mx = 0.5 * (ox[i] + vhx[i]), my = 0.5 * (oy[i] + vhy[i]),
                 mz = 0.5 * (oz[i] + vhz[i]);
    // Reaction = m (v_new - v_old)/dt_avg - f^n (f^n includes gravity, so add gravity back).
    const double rx = mass[i] * (vhx[i] - ox[i]) - dt_avg * fx[i];
    const double ry = mass[i] * (vhy[i] - oy[i]) - dt_avg * fy[i];
    const double rz = mass[i] * (vhz[i] - oz[i]) - dt_avg * fz[i];
    work += (rx + dt_avg * mass[i] * g.x) * mx + (ry + dt_avg * mass[i] * g.y) * my +
            (rz + dt_avg * mass[i] * g.z) * mz;
  }
  // f^n includes the pressure forces too: add their work back as gravity's.
  if (!pressure.empty()) work += dt_avg * pressure.mid_step_power(ox, oy, oz, vhx, vhy, vhz);
  // The velocity at t^n is v^{n-1/2} + (dt^{n-1/2}/2) a^n: the kick's change scaled by the
  // share of [t^{n-1/2}, t^{n+1/2}] that lies before t^n (0 at t^0, 1 at the end time where
  // dt^{n+1/2} = 0). The work reported at t^n takes the same share of this kick's work.
  const double share = dt_avg > 0.0 ? 0.5 * dt_prev / dt_avg : 0.0;
  energy.external_work = external_work_done + share * work;
  external_work_done += work;
  // Kinetic energy at t^n: (1/2) m v^{n-1/2} . v^{n+1/2}. With the internal energy this is the
  // quantity central differences conserve exactly for a linear system at a constant step
  // (H_n = x_n K x_n / 2 + v^{n-1/2} M v^{n+1/2} / 2, derived by summing the update), so the
  // energy history shows no O(dt^2) oscillation of the plain (1/2) m |v^n|^2. At t^0: (1/2) m
  // |v^0|^2.
  double kinetic = 0.0;
  for (std::size_t i = 0; i < n_nodes; ++i) {
    vx[i] = ox[i] + share * (vhx[i] - ox[i]);
    vy[i] = oy[i] + share * (vhy[i] - oy[i]);
    vz[i] = oz[i] + share * (vhz[i] - oz[i]);
    kinetic += n == 0 ? 0.5 * mass[i] * (ox[i] * ox[i] + oy[i] * oy[i] + oz[i] * oz[i])
                      : 0.5 * mass[i] * (ox[i] * vhx[i] + oy[i] * vhy[i] + oz[i] * vhz[i]);
  }
  energy.kinetic = kinetic;
}

void Simulation::Impl::apply_nodal_boundaries(double dt_avg) {
  double* v[3] = {vhx.data(), vhy.data(), vhz.data()};
  const double* vold[3] = {ox.data(), oy.data(), oz.data()};
  const double* pos[3] = {x.data(), y.data(), z.data()};
  const double* ref[3] = {x0.data(), y0.data(), z0.data()};
  for (std::size_t i = 0; i < n_nodes; ++i)
    for (int d = 0; d < 3; ++d)
      if (node_fixed[i] & (1u << d)) v[d][i] = 0.0;
  for (const NodalMotion& nm : bc.nodal) {
    const MotionBoundary& m = *nm.source;
    if (!motion_active(model, m, t)) continue;
    for (int d = 0; d < 3; ++d)
      if (m.fixed_translation & (1u << d))
        for (const std::int32_t i : nm.nodes) v[d][i] = 0.0;
    for (const PrescribedMotion& p : m.motions) {
      if (!prescription_active(model, p, t)) continue;
      const int d = p.direction;
      Variables vars;
      vars.term = model.time.end_time;
      switch (p.kind) {
        case PrescribedMotion::Kind::Velocity: {
          vars.t = t + 0.5 * dt_next;
          const double value = p.scale * model.functions.value(p.curve, vars);
          for (const std::int32_t i : nm.nodes) v[d][i] = value;
          break;
        }
        case PrescribedMotion::Kind::Displacement: {
          if (dt_next <= 0.0) break;  // end time reached: no further motion
          vars.t = t + dt_next;
          const double target = p.scale * model.functions.value(p.curve, vars);
          for (const std::int32_t i : nm.nodes)
            v[d][i] = (target - (pos[d][i] - ref[d][i])) / dt_next;
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
          vars.t = t + 0.5 * dt_next;
          target = p.scale * model.functions.value(p.curve, vars);
          break;
        case PrescribedMotion::Kind::Displacement: {
          if (rotation)
            throw InputError(p.where,
                             "prescribed rotation angles (D with RX/RY/RZ) are not supported yet; "
                             "prescribe the angular velocity (V) instead");
          if (dt_next <= 0.0) break;
          vars.t = t + dt_next;
          const double displacement = p.scale * model.functions.value(p.curve, vars);
          target = (body.centre0[d] + displacement - body.centre[d]) / dt_next;
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
  good_x = x;
  good_y = y;
  good_z = z;
  good_t = t;
  const double dt = dt_next;
  const std::int64_t nn = static_cast<std::int64_t>(n_nodes);
#pragma omp parallel for schedule(static) if (nn >= kParallelMinimum)
  for (std::int64_t i = 0; i < nn; ++i) {
    if (rigid_body_of_node[i] >= 0) continue;
    x[i] += dt * vhx[i];
    y[i] += dt * vhy[i];
    z[i] += dt * vhz[i];
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
  t += dt;
  ++n;
  dt_prev = dt;
  compute_forces(dt);
  bool finite = true;
  for (std::size_t i = 0; i < n_nodes && finite; ++i)
    finite = std::isfinite(x[i] + y[i] + z[i] + fx[i] + fy[i] + fz[i]);
  if (!finite)
    throw InstabilityError("non-finite coordinates or forces at cycle " + std::to_string(n) +
                           ", t = " + std::to_string(t));
}

// ---------------------------------------------------------------------------------------------

Simulation::Simulation(const Model& model) : impl_(std::make_unique<Impl>(model)) {
  impl_->setup();
}
Simulation::~Simulation() = default;

void Simulation::advance() {
  impl_->drift();
  impl_->kick();
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
std::string Simulation::Impl::limit_description() const {
  if (limiting_contact >= 0) return "contact " + std::to_string(limiting_contact) + " springs";
  if (limiting_block < 0) return "dt_max of *TIME";
  return "elements of part " + std::to_string(blocks[limiting_block].part_id());
}

std::string Simulation::time_step_limit() const { return impl_->limit_description(); }
const Model& Simulation::model() const { return impl_->model; }
std::size_t Simulation::node_count() const { return impl_->n_nodes; }
const std::vector<double>& Simulation::x() const { return impl_->x; }
const std::vector<double>& Simulation::y() const { return impl_->y; }
const std::vector<double>& Simulation::z() const { return impl_->z; }
const std::vector<double>& Simulation::vx() const { return impl_->vx; }
const std::vector<double>& Simulation::vy() const { return impl_->vy; }
const std::vector<double>& Simulation::vz() const { return impl_->vz; }
const std::vector<double>& Simulation::nodal_mass() const { return impl_->mass; }

void Simulation::element_field(void (SolidBlock::*field)(std::vector<double>&) const,
                               std::vector<double>& out) const {
  out.assign(impl_->model.mesh.hex_count(), 0.0);
  std::vector<double> block_values;
  for (std::size_t b = 0; b < impl_->blocks.size(); ++b) {
    (impl_->blocks[b].*field)(block_values);
    for (std::size_t e = 0; e < block_values.size(); ++e)
      out[impl_->block_hex_index[b][e]] = block_values[e];
  }
}

void Simulation::von_mises_stress(std::vector<double>& out) const {
  element_field(&SolidBlock::von_mises_stress, out);
}
void Simulation::pressure(std::vector<double>& out) const {
  element_field(&SolidBlock::pressure, out);
}
std::vector<std::uint8_t> Simulation::eroded_hexes() const {
  std::vector<std::uint8_t> out(impl_->model.mesh.hex_count(), 0);
  for (std::size_t b = 0; b < impl_->blocks.size(); ++b) {
    const auto& eroded = impl_->blocks[b].eroded();
    for (std::size_t e = 0; e < eroded.size(); ++e) out[impl_->block_hex_index[b][e]] = eroded[e];
  }
  return out;
}

void Simulation::shell_von_mises_stress(std::vector<double>& out) const {
  out.assign(impl_->model.mesh.shell_count(), 0.0);
}
void Simulation::shell_plastic_strain(std::vector<double>& out) const {
  out.assign(impl_->model.mesh.shell_count(), 0.0);
}
std::vector<std::uint8_t> Simulation::eroded_shells() const {
  return std::vector<std::uint8_t>(impl_->model.mesh.shell_count(), 0);
}

void Simulation::plastic_strain(std::vector<double>& out) const {
  element_field(&SolidBlock::plastic_strain, out);
}

Energies Simulation::energies() const { return impl_->energy; }

const std::vector<ContactReport>& Simulation::contact_reports() const {
  return impl_->contacts->reports();
}

void Simulation::contact_fields(std::vector<double>& force, std::vector<double>& pressure,
                                std::vector<double>& wear) const {
  impl_->contacts->nodal_fields(force, pressure, wear);
}

bool Simulation::has_contact() const { return !impl_->contacts->empty(); }
double Simulation::contact_seconds() const { return impl_->contact_seconds; }

double Simulation::energy_balance_error() const {
  const Energies& e = impl_->energy;
  const double scale =
      std::max({std::abs(e.total()), std::abs(impl_->total0), std::abs(e.external_work)});
  return scale > 0.0 ? (e.total() - impl_->total0 - e.external_work) / scale : 0.0;
}

std::vector<PartState> Simulation::part_states() const {
  std::vector<PartState> out;
  for (const PartInfo& p : impl_->parts) {
    PartState s;
    s.part_id = p.part_id;
    s.title = p.title;
    s.rigid = p.rigid;
    s.element_count = p.element_count;
    s.mass = p.mass;
    Vec3 first, momentum;
    for (std::size_t k = 0; k < p.nodes.size(); ++k) {
      const std::int32_t i = p.nodes[k];
      const double m = p.node_mass[k];
      const Vec3 v{impl_->vx[i], impl_->vy[i], impl_->vz[i]};
      first += m * Vec3{impl_->x[i], impl_->y[i], impl_->z[i]};
      momentum += m * v;
      s.kinetic += 0.5 * m * dot(v, v);
    }
    s.centre_of_mass = first / p.mass;
    s.velocity = momentum / p.mass;
    if (p.block >= 0) s.internal = impl_->block_steps[p.block].internal_energy;
    out.push_back(s);
  }
  return out;
}

const std::vector<double>& Simulation::last_good_x() const { return impl_->good_x; }
const std::vector<double>& Simulation::last_good_y() const { return impl_->good_y; }
const std::vector<double>& Simulation::last_good_z() const { return impl_->good_z; }
double Simulation::last_good_time() const { return impl_->good_t; }

}  // namespace abut
