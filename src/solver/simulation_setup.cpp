#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>

#include "abut/element/lumped_mass.hpp"
#include "abut/element/shell4.hpp"
#include "abut/mesh/skin.hpp"
#include "simulation_impl.hpp"
#include "tie_search.hpp"

namespace abut {

// ---------------------------------------------------------------------------------------------
// Set-up

void Simulation::Impl::setup() {
  const Mesh& mesh = model.mesh;
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

  // Group elements by part, in the order parts were defined.
  std::map<std::int64_t, std::vector<std::int32_t>> hexes_of_part, shells_of_part, cells_of_part;
  for (std::size_t e = 0; e < mesh.hex_count(); ++e)
    hexes_of_part[mesh.hex_part[e]].push_back(static_cast<std::int32_t>(e));
  for (std::size_t e = mesh.hex_count(); e < mesh.solid_count(); ++e)
    cells_of_part[mesh.solid(e).part].push_back(static_cast<std::int32_t>(e));
  for (std::size_t e = 0; e < mesh.shell_count(); ++e)
    shells_of_part[mesh.shell_part[e]].push_back(static_cast<std::int32_t>(e));
  if (mesh.shell_count() > 0) rotary_inertia.assign(n_nodes, 0.0);

  for (const Part& part : model.parts) {
    const auto hex_it = hexes_of_part.find(part.id);
    const auto shell_it = shells_of_part.find(part.id);
    const auto cell_it = cells_of_part.find(part.id);
    const std::vector<std::int32_t> none;
    const auto& part_hexes = hex_it == hexes_of_part.end() ? none : hex_it->second;
    const auto& part_shells = shell_it == shells_of_part.end() ? none : shell_it->second;
    const auto& part_cells = cell_it == cells_of_part.end() ? none : cell_it->second;
    if (part_hexes.empty() && part_shells.empty() && part_cells.empty())
      continue;  // no elements: not in the run
    const MaterialParams& material = model.material_of_part(part.id);
    PartInfo info;
    info.part_id = part.id;
    info.title = part.title;
    info.rigid = is_rigid(material);
    info.element_count = part_hexes.size() + part_shells.size() + part_cells.size();

    std::vector<double> part_mass(n_nodes, 0.0);
    if (info.rigid) {
      if (part.erosion.any())
        throw InputError(part.where,
                         "part " + std::to_string(part.id) +
                             " is rigid: element erosion applies to deformable parts only");
      const double rho = density_of(material);
      for (const std::int32_t e : part_hexes) {
        const double v = hex_volume(mesh.nodes, mesh.hexes[e]);
        for (const std::int32_t node : mesh.hexes[e]) part_mass[node] += rho * v / 8.0;
      }
      for (const std::int32_t e : part_shells) {
        const Quad4& q = mesh.shells[e];
        std::array<Vec3, 4> p;
        for (int a = 0; a < 4; ++a) p[a] = mesh.nodes.position(static_cast<std::size_t>(q[a]));
        const double area = shell4_geometry(p).area;
        const int corners = is_triangle(q) ? 3 : 4;
        for (int a = 0; a < corners; ++a) part_mass[q[a]] += rho * part.thickness * area / corners;
      }
    } else {
      if (!part_hexes.empty()) {
        std::vector<Hex8> hexes;
        std::vector<std::int64_t> ids;  // messages name the user's element ids
        hexes.reserve(part_hexes.size());
        ids.reserve(part_hexes.size());
        for (const std::int32_t e : part_hexes) {
          hexes.push_back(mesh.hexes[e]);
          ids.push_back(mesh.hex_id[e]);
        }
        blocks.emplace_back(part.id, material, std::move(hexes), mesh.nodes, &model.functions);
        blocks.back().set_element_ids(std::move(ids));
        blocks.back().set_erosion(part.erosion);
        blocks.back().set_bulk_viscosity(model.bulk_viscosity.quadratic,
                                         model.bulk_viscosity.linear);
        blocks.back().add_lumped_mass(part_mass);
        check_element_step(part, blocks.back().initial_stable_step(mesh.nodes));
        block_hex_index.push_back(part_hexes);
        info.block = static_cast<std::int32_t>(blocks.size() - 1);
      }
      if (!part_shells.empty()) {
        std::vector<Quad4> shells;
        std::vector<std::int64_t> ids;
        for (const std::int32_t e : part_shells) {
          shells.push_back(mesh.shells[e]);
          ids.push_back(mesh.shell_id[e]);
        }
        const ShellSection section{part.thickness, part.shell_points, part.shell_hourglass};
        try {
          shell_blocks.emplace_back(part.id, material, section, std::move(shells), mesh.nodes,
                                    &model.functions);
        } catch (const InputError& error) {
          throw InputError(part.where, error.what());
        }
        shell_blocks.back().set_element_ids(std::move(ids));
        shell_blocks.back().set_erosion(part.erosion);
        shell_blocks.back().add_lumped_mass(part_mass, rotary_inertia);
        check_element_step(part, shell_blocks.back().initial_stable_step(mesh.nodes));
        block_shell_index.push_back(part_shells);
        info.shell_block = static_cast<std::int32_t>(shell_blocks.size() - 1);
      }
    }
    setup_cells(part, part_cells, info.rigid, info, part_mass);
    check_part_mass(part, part_mass, info.rigid);
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
                                           " of rigid part " + std::to_string(part.id) + " has " +
                                           model.sources.words("boundary_condition") +
                                           " of its own; constrain a rigid part with " +
                                           model.sources.words("rigid_motion"));
        rigid_body_of_node[node] = static_cast<std::int32_t>(bodies.size());
      }
      bodies.push_back(std::move(body));
    }
    parts.push_back(std::move(info));
  }
  // A node shared by a rigid and a deformable part moves with the rigid body; the mass the
  // deformable elements lump on it belongs to the body, and their forces act on it.
  for (RigidBody& body : bodies) {
    body.initialise(x0, y0, z0, mass);
    const Vec3& moments = body.principal_moments;
    if (!std::isfinite(moments.x + moments.y + moments.z) ||
        !(std::min({moments.x, moments.y, moments.z}) > 0.0))
      throw InputError(model.find_part(body.part_id)->where,
                       fmt::format("rigid part {} has principal moments of inertia {:.4g}, {:.4g}, "
                                   "{:.4g}; expected finite and positive: check its coordinates",
                                   body.part_id, moments.x, moments.y, moments.z));
  }

  inverse_mass.assign(n_nodes, 0.0);
  for (std::size_t i = 0; i < n_nodes; ++i)
    if (mass[i] > 0.0 && rigid_body_of_node[i] < 0) inverse_mass[i] = 1.0 / mass[i];
  if (rotations()) {
    inverse_rotary_inertia.assign(n_nodes, 0.0);
    for (std::size_t i = 0; i < n_nodes; ++i)
      if (rotary_inertia[i] > 0.0 && rigid_body_of_node[i] < 0)
        inverse_rotary_inertia[i] = 1.0 / rotary_inertia[i];
    mx.assign(n_nodes, 0.0);
    my.assign(n_nodes, 0.0);
    mz.assign(n_nodes, 0.0);
  }
  build_force_slots();
  block_steps.assign(blocks.size(), {});
  shell_steps.assign(shell_blocks.size(), {});
  cell_steps.assign(cell_blocks.size(), {});

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
    body.angular_velocity = body.angular_velocity_of(angular_momentum);
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
  if (rotations()) {  // nodes with rotations start with the angular velocity of their field
    whx = model.wx0.empty() ? std::vector<double>(n_nodes, 0.0) : model.wx0;
    why = model.wy0.empty() ? std::vector<double>(n_nodes, 0.0) : model.wy0;
    whz = model.wz0.empty() ? std::vector<double>(n_nodes, 0.0) : model.wz0;
    for (std::size_t i = 0; i < n_nodes; ++i) {
      if (rigid_body_of_node[i] < 0) continue;
      const Vec3& w = bodies[static_cast<std::size_t>(rigid_body_of_node[i])].angular_velocity;
      whx[i] = w.x, why[i] = w.y, whz[i] = w.z;
    }
  }

  std::vector<std::pair<std::int64_t, std::size_t>> body_of_part;
  for (std::size_t b = 0; b < bodies.size(); ++b) body_of_part.emplace_back(bodies[b].part_id, b);
  bc = resolve_boundary_conditions(model, rigid_body_of_node, body_of_part, rotary_inertia);
  std::vector<TiedNode> tied = find_tied_nodes(model);
  const RemovedNodes tied_nodes = tied_node_set(tied);
  ties = KinematicTies(model, std::move(tied), mass, rigid_body_of_node, node_fixed, bc, vhx, vhy,
                       vhz);

  contacts = std::make_unique<ContactSet>(model, mass, vhx, vhy, vhz, tied_nodes);
  setup_sensors();
  pressure = PressureLoads(model);

  fx.assign(n_nodes, 0.0);
  fy.assign(n_nodes, 0.0);
  fz.assign(n_nodes, 0.0);
  t = model.time.start_time;
  if (!model.thermal.properties.empty()) {
    for (std::size_t e = model.mesh.hex_count(); e < model.mesh.solid_count(); ++e) {
      const SolidRef cell = model.mesh.solid(e);
      if (is_thermal_part(model, cell.part))
        throw InputError(model.find_part(cell.part)->where,
                         "part " + std::to_string(cell.part) + ": heat conduction in " +
                             std::string(element_label(cell.type)) +
                             " elements is not supported yet (8-node hexahedra and shells "
                             "conduct heat); give its material no thermal properties (" +
                             model.sources.words("thermal_properties") + ")");
    }
    heat.emplace(model);
    if (!heat->active()) heat.reset();
    heat_planned_to = t;
  }
  check_thermal_contacts(model);  // heat.hpp
  couple_heat();
  compute_forces(0.0);
  dt_initial = std::min(model.time.step_scale * stable, model.time.max_step);
  // A step of 0 or NaN would end the run at once with "completed 0 cycles": the input (a
  // density so small that a contact spring's mass vanishes, ...) cannot be run.
  if (!(dt_initial > 0.0))
    throw InputError(limit_location(),
                     fmt::format("the initial stable time step is {:.4g} (limited by {}): it must "
                                 "be > 0; check the densities, moduli and contact stiffness",
                                 dt_initial, limit_description()));
  kick();
  check_initial_energies();
  total0 = conserved_total();
  energy_scale = std::max(energy_scale, std::abs(total0));
}

// The lumped mass a part gives its nodes must be finite, and a rigid part must have some: a
// density of 1e308 overflows, a rigid part without mass has no centre of mass; both would run
// on as infinities and NaN.
void Simulation::Impl::check_part_mass(const Part& part, const std::vector<double>& part_mass,
                                       bool rigid) const {
  double total = 0.0;
  for (const double m : part_mass) total += m;
  if (std::isfinite(total) && (total > 0.0 || !rigid)) return;
  const Material* material = model.find_material(part.material_id);
  const std::string density =
      material ? fmt::format("density {:.4g} of material {} at {}:{}",
                             density_of(material->params), material->id, material->where.file,
                             material->where.line)
               : std::string("its density");
  throw InputError(part.where,
                   fmt::format("part {} has {} mass {:.4g} (from {}); expected a finite, positive "
                               "mass: check the density and the element volumes",
                               part.id, rigid ? "rigid" : "lumped", total, density));
}

// Every deformable element has a finite stable step: a modulus so large that the wave speed
// overflows (E = 1e308) gives none, and the run would take one step of dt_max and end
// "completed" with infinities (issue 28). Checked on the reference mesh, before any erosion.
void Simulation::Impl::check_element_step(const Part& part, double step) const {
  if (std::isfinite(step) && step > 0.0) return;
  const Material* material = model.find_material(part.material_id);
  throw InputError(
      part.where,
      fmt::format("part {} has no finite element stable time step ({:.4g}): the wave speed of its "
                  "material{} is not finite; check the moduli and the density",
                  part.id, step,
                  material ? fmt::format(" {} at {}:{}", material->id, material->where.file,
                                         material->where.line)
                           : std::string()));
}

void Simulation::Impl::setup_cells(const Part& part, const std::vector<std::int32_t>& solids,
                                   bool rigid, PartInfo& info, std::vector<double>& part_mass) {
  const Mesh& mesh = model.mesh;
  const MaterialParams& material = model.material_of_part(part.id);
  for (const CellType type : kCellTypes) {
    std::vector<std::int32_t> of_type, connectivity;
    std::vector<std::int64_t> ids;
    for (const std::int32_t e : solids) {
      const SolidRef cell = mesh.solid(static_cast<std::size_t>(e));
      if (cell.type != type) continue;
      of_type.push_back(e);
      ids.push_back(cell.id);
      connectivity.insert(connectivity.end(), cell.nodes.begin(), cell.nodes.end());
    }
    if (of_type.empty()) continue;
    if (rigid) {  // the mass of the body: the HRZ shares of its cells
      const double rho = density_of(material);
      const std::size_t nodes = static_cast<std::size_t>(topology(type).nodes);
      std::vector<double> X(3 * nodes), shares(nodes);
      for (std::size_t c = 0; c < of_type.size(); ++c) {
        for (std::size_t a = 0; a < nodes; ++a) {
          const auto node = static_cast<std::size_t>(connectivity[c * nodes + a]);
          X[3 * a] = mesh.nodes.x[node], X[3 * a + 1] = mesh.nodes.y[node];
          X[3 * a + 2] = mesh.nodes.z[node];
        }
        lumped_volume_shares(type, X, shares);
        for (std::size_t a = 0; a < nodes; ++a)
          part_mass[static_cast<std::size_t>(connectivity[c * nodes + a])] += rho * shares[a];
      }
      continue;
    }
    try {
      cell_blocks.emplace_back(part.id, material, type, std::move(connectivity), mesh.nodes,
                               &model.functions);
      SolidCellBlock& block = cell_blocks.back();
      block.set_element_ids(std::move(ids));
      block.set_erosion(part.erosion);
      block.set_bulk_viscosity(model.bulk_viscosity.quadratic, model.bulk_viscosity.linear);
    } catch (const InputError& error) {
      throw InputError(part.where, error.what());
    }
    cell_blocks.back().add_lumped_mass(part_mass);
    check_element_step(part, cell_blocks.back().initial_stable_step());
    block_solid_index.push_back(std::move(of_type));
    info.cell_blocks.push_back(static_cast<std::int32_t>(cell_blocks.size() - 1));
  }
}

// Node -> element force slots (CSR) in block and element order: hexes, shells, other cells.
void Simulation::Impl::build_force_slots() {
  std::vector<std::int32_t> count(n_nodes + 1, 0), moment_count(n_nodes + 1, 0);
  for (const SolidBlock& b : blocks)
    for (const Hex8& h : b.hexes())
      for (const std::int32_t node : h) ++count[node + 1];
  for (const ShellBlock& b : shell_blocks) {
    for (const Quad4& q : b.shells()) {
      for (const std::int32_t node : q) {
        ++count[node + 1];
        ++moment_count[node + 1];
      }
    }
  }
  for (const SolidCellBlock& b : cell_blocks)
    for (std::size_t e = 0; e < b.size(); ++e)
      for (const std::int32_t node : b.element(e)) ++count[node + 1];
  for (std::size_t i = 0; i < n_nodes; ++i) {
    count[i + 1] += count[i];
    moment_count[i + 1] += moment_count[i];
  }
  slot_start = count;
  moment_slot_start = moment_count;
  slots.resize(static_cast<std::size_t>(count[n_nodes]));
  moment_slots.resize(static_cast<std::size_t>(moment_count[n_nodes]));
  std::vector<std::int32_t> fill(slot_start.begin(), slot_start.end() - 1);
  std::vector<std::int32_t> moment_fill(moment_slot_start.begin(), moment_slot_start.end() - 1);
  for (const SolidBlock& b : blocks) {
    const double* forces = b.element_forces().data();
    for (std::size_t e = 0; e < b.hexes().size(); ++e)
      for (std::size_t a = 0; a < 8; ++a) slots[fill[b.hexes()[e][a]]++] = forces + 24 * e + 3 * a;
  }
  for (const ShellBlock& b : shell_blocks) {
    const double* forces = b.element_forces().data();
    for (std::size_t e = 0; e < b.shells().size(); ++e) {
      for (std::size_t a = 0; a < 4; ++a) {
        const std::int32_t node = b.shells()[e][a];
        slots[fill[node]++] = forces + 24 * e + 6 * a;
        moment_slots[moment_fill[node]++] = forces + 24 * e + 6 * a + 3;
      }
    }
  }
  for (const SolidCellBlock& b : cell_blocks) {
    const double* forces = b.element_forces().data();
    const auto nodes = static_cast<std::size_t>(b.nodes_per_element());
    for (std::size_t e = 0; e < b.size(); ++e)
      for (std::size_t a = 0; a < nodes; ++a)
        slots[fill[b.element(e)[a]]++] = forces + 3 * (nodes * e + a);
  }
}

Simulation::Simulation(const Model& model) : impl_(std::make_unique<Impl>(model)) {
  impl_->setup();
}
Simulation::~Simulation() = default;

}  // namespace abut
