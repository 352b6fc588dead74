#pragma once
// The state of a Simulation (simulation.hpp), shared by its set-up (simulation_setup.cpp), its
// time loop (simulation.cpp) and its results (simulation_results.cpp).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "abut/element/shell_block.hpp"
#include "abut/element/solid_block.hpp"
#include "abut/element/solid_cell_block.hpp"
#include "abut/solver/heat.hpp"
#include "abut/solver/pressure_loads.hpp"
#include "abut/solver/simulation.hpp"
#include "boundary_conditions.hpp"
#include "contact_set.hpp"
#include "rigid_body.hpp"
#include "sensors.hpp"
#include "ties.hpp"

namespace abut {

struct PartInfo {
  std::int64_t part_id = 0;
  std::string title;
  bool rigid = false;
  std::size_t element_count = 0;
  double mass = 0.0;
  std::int32_t block = -1;        // deformable solids: index into blocks
  std::vector<std::int32_t> cell_blocks;  // deformable cells: indices into cell_blocks
  std::int32_t shell_block = -1;  // deformable shells: index into shell_blocks
  std::vector<std::int32_t> nodes;
  std::vector<double> node_mass;  // this part's share of each node's lumped mass
};

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
  std::vector<BlockStep> block_steps;
  std::vector<ShellBlock> shell_blocks;
  std::vector<std::vector<std::int32_t>> block_shell_index;  // block element -> mesh shell
  std::vector<BlockStep> shell_steps;
  // Blocks of the other solid cells (tetrahedra, wedges, quadratic hexahedra), one per part and
  // cell type; each element's index in the solid numbering of Mesh::solid().
  std::vector<SolidCellBlock> cell_blocks;
  std::vector<std::vector<std::int32_t>> block_solid_index;
  std::vector<BlockStep> cell_steps;
  // Where each element's force on a node sits (CSR node -> slots, in block and element order:
  // the fixed summation order that makes forces independent of the thread count). A slot points
  // into a block's element_forces(), which never reallocates: fx, fy, fz there, and for a shell
  // the moments mx, my, mz right after (moment slots).
  std::vector<std::int32_t> slot_start, moment_slot_start;
  std::vector<const double*> slots, moment_slots;

  // Rotational degrees of freedom (nodes of shells; all empty without shells): angular
  // velocities omega^{n+1/2} (and omega^{n-1/2} during the kick), moments, rotary inertia.
  std::vector<double> whx, why, whz, owx, owy, owz, mx, my, mz;
  std::vector<double> rotary_inertia, inverse_rotary_inertia;
  bool rotations() const { return !rotary_inertia.empty(); }

  std::unique_ptr<ContactSet> contacts;
  KinematicTies ties;  // exact ties (*CONTACT_FRICTION FREEZE, tie = EXACT); empty: none
  // *SENSOR and what they switch (simulation_sensors.cpp): the sensors, the fixed directions of
  // each node released at impact (*CONTACT_RELEASE_BC; empty when no contact releases any), the
  // directions each node is held in (*NODE bc and *BC_MOTION bc_tr; same), and the log lines not
  // yet taken.
  std::unique_ptr<SensorSet> sensors;
  std::vector<std::uint8_t> released, constrained, touched;
  std::vector<std::string> messages;
  std::size_t eroded_elements = 0;           // as last reported to the contacts
  std::vector<std::uint8_t> element_eroded;  // per element, solids (Mesh::solid) then shells
  std::int64_t limiting_contact = -1;
  bool limiting_kink = false;    // the contact's kink bound (ContactStats::kink_step) sets the step
  double contact_seconds = 0.0;  // wall time spent in contact (for the summary)
  // Sums over the cycles of the stable step and of the step the elements alone would allow, and
  // of the part of the step the contacts' kink bound took beyond their springs' bound.
  double step_sum = 0.0, element_step_sum = 0.0, kink_step_sum = 0.0;

  std::vector<RigidBody> bodies;
  std::vector<PartInfo> parts;
  BoundaryConditions bc;
  PressureLoads pressure;  // *LOAD_PRESSURE, its forces kept apart for the external work

  double t = 0.0;
  std::int64_t n = 0;
  double dt_prev = 0.0;  // dt^{n-1/2}
  double dt_next = 0.0;  // dt^{n+1/2}
  // The step the kick at t^n prepares: dt^{n+1/2}, or at the end time, where that is 0, a
  // notional dt^{n-1/2} (the boundary motions are prescribed over it as over any other step).
  double kick_step() const { return dt_next > 0.0 ? dt_next : dt_prev; }
  double stable = 0.0;   // unscaled stable step at x^n
  double dt_initial = 0.0;
  std::int32_t limiting_block = -1;        // index into blocks, or
  std::int32_t limiting_shell_block = -1;  // index into shell_blocks, or
  std::int32_t limiting_cell_block = -1;   // index into cell_blocks

  Energies energy;
  // The kinetic energy that central differences conserve, (1/2) m v^{n-1/2} . v^{n+1/2} summed
  // over the nodes ((1/2) m |v^0|^2 at t^0): with the strain energy of a linear system at a
  // constant step it is conserved exactly (H_n = x_n K x_n / 2 + v^{n-1/2} M v^{n+1/2} / 2, derived
  // by summing the update), so the energy balance is kept with it and shows no O(dt^2)
  // oscillation. energy.kinetic, (1/2) m |v^n|^2, differs from it by O(dt^2) and is never
  // negative, which this product is where a velocity turns within a step.
  double conserved_kinetic = 0.0;
  // What the changes of the step so far took from that product without a change in the motion,
  // (1/8) sum m |a^n|^2 (h_+^2 - h_-^2) over the cycles before (kick()).
  double step_change_kinetic = 0.0;
  // energy.total() with the conserved kinetic energy: what the energy balance compares.
  double conserved_total() const {
    Energies e = energy;
    e.kinetic = conserved_kinetic;
    return e.total();
  }
  double total0 = 0.0;  // conserved_total() at t^0
  // The largest of |conserved total|, |total_0| and |external work| so far: the balance error's
  // scale.
  double energy_scale = 0.0;
  double external_work_done = 0.0;  // up to t^{n+1/2}

  std::vector<double> good_x, good_y, good_z;
  double good_t = 0.0;

  // Heat (heat.hpp, advance_heat): the temperatures are at t; the rates planned at the start of
  // the current thermal step hold up to heat_planned_to.
  std::optional<HeatSolver> heat;
  double heat_planned_to = 0.0;
  double planned_contact_rate = 0.0;  // contact_heat_rate the planned step was made with
  std::int64_t heat_steps = 0;
  // Heat the mechanics made over the mechanical step [energy per node] (friction, plastic work),
  // the contact's conduction at a plan's temperatures [power per node], and the largest contact
  // conductance per heat capacity of the step [1/time] (advance_heat).
  std::vector<double> heat_energy, heat_exchange;
  double contact_heat_rate = 0.0;
  // Coupling of the mechanics to the heat (simulation_coupling.cpp): the Taylor-Quinney share of
  // each block's plastic work that becomes heat (0: none).
  std::vector<double> taylor_quinney;

  explicit Impl(const Model& m) : model(m) {}

  void setup();
  void compute_forces(double dt);
  void report_erosion_to_contact();
  void setup_sensors();                        // simulation_sensors.cpp
  void switch_contacts();                      // before the contacts' apply at t^n
  void release_at_impact();                    // after it
  std::uint8_t held(std::size_t node) const {  // fixed directions not released at impact
    return released.empty() ? 0xFF : static_cast<std::uint8_t>(~released[node]);
  }
  void kick();
  void drift();
  Vec3 gravity_at(double time) const;
  void apply_nodal_boundaries(double dt_avg);  // on v^{n+1/2}, from v^{n-1/2} in ox, oy, oz
  void apply_rigid_boundaries(double dt_avg);
  void apply_nodal_rotation(const PrescribedMotion& p, const std::vector<std::int32_t>& nodes,
                            double* w, const double* w_old, double dt_avg);
  void build_force_slots();
  // The cells of each part as blocks (simulation_setup.cpp), their masses in part_mass.
  void setup_cells(const Part& part, const std::vector<std::int32_t>& solids, bool rigid,
                   PartInfo& info, std::vector<double>& part_mass);
  void advance_heat();
  double thermal_step_limit() const;
  // What is wrong with the energies at t^n, or empty: a non-finite energy, work or balance, a
  // negative kinetic energy (simulation_energy_checks.cpp).
  std::string energy_fault() const;
  // InputError when the energies at t^0 are wrong: at the *PART whose kinetic energy overflows.
  void check_initial_energies() const;
  void gather_contact_heat(double dt);
  void couple_heat();
  void gather_plastic_heat();
  std::string limit_description() const;
  // The deck line of what limits the step (the *CONTACT or the *PART), or none.
  SourceLocation limit_location() const;
  // InputError at the *PART unless its lumped mass is finite (and positive when rigid).
  void check_part_mass(const Part& part, const std::vector<double>& part_mass, bool rigid) const;
  void check_element_step(const Part& part, double step) const;
};

}  // namespace abut
