#pragma once
// Explicit central-difference time integration of a Model: lumped mass, deformable hex blocks,
// rigid parts, boundary motions, gravity, energy bookkeeping.
//
// Cycle n (Belytschko, Liu & Moran, "Nonlinear Finite Elements for Continua and Structures",
// 2000, box 6.1): forces f^n at x^n; kick v^{n+1/2} = v^{n-1/2} + dt^n a^n with
// dt^n = (dt^{n-1/2} + dt^{n+1/2})/2; boundary motions on v^{n+1/2}; drift x^{n+1} = x^n +
// dt^{n+1/2} v^{n+1/2}. After construction and after every advance() the state at t^n is
// complete (positions, forces, the velocity v^n = (v^{n-1/2}+v^{n+1/2})/2, energies at t^n).
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "abut/core/vec3.hpp"
#include "abut/element/shell_block.hpp"
#include "abut/element/solid_block.hpp"
#include "abut/element/solid_cell_block.hpp"
#include "abut/model/model.hpp"
#include "abut/solver/contact_report.hpp"
#include "abut/solver/heat.hpp"

namespace abut {

class StateArchive;

struct Energies {
  double kinetic = 0.0;
  double internal = 0.0;
  double hourglass = 0.0;
  double contact = 0.0;
  double friction = 0.0;
  double eroded = 0.0;  // internal and hourglass energy the eroded elements held
  // Contact spring energy that vanished without doing work (ContactStats::released_energy).
  double contact_released = 0.0;
  double external_work = 0.0;
  // Work the thermal expansion did on the mechanics (BlockStep::thermal_work): an input, like the
  // external work; the balance is total - total_0 - external_work - thermal_work.
  double thermal_work = 0.0;
  // total = kinetic + internal + hourglass + contact + friction + eroded + contact_released
  double total() const {
    return kinetic + internal + hourglass + contact + friction + eroded + contact_released;
  }
};

struct PartState {
  std::int64_t part_id = 0;
  std::string title;
  bool rigid = false;
  std::size_t element_count = 0;
  double mass = 0.0;
  Vec3 centre_of_mass;
  Vec3 velocity;  // of the centre of mass
  double kinetic = 0.0;
  double internal = 0.0;
};

class Simulation {
 public:
  explicit Simulation(const Model& model);
  Simulation(Model&&) =
      delete;  // the simulation keeps a reference to its model: it must outlive it
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  // Advances one cycle to t^{n+1}. Throws InstabilityError when the run goes unstable; the
  // last complete state is then still available through last_good_*().
  void advance();
  bool finished() const;

  double time() const;
  double end_time() const;
  std::int64_t cycle() const;
  double time_step() const;          // dt^{n+1/2} that the next advance() uses
  double initial_time_step() const;  // scaled stable step at t = 0
  // How much the contact springs shortened the stable step over the cycles so far:
  // 1 - sum(dt) / sum(dt of the elements alone); 0 when contact never limited it.
  double contact_step_loss() const;
  // The part of it that the contacts' kink bound took beyond their springs' stable step
  // (ContactStats::kink_step: points touching or letting go together).
  double contact_kink_step_loss() const;
  std::string time_step_limit() const;  // what limits the step now (e.g. "part 2 element 17")

  const Model& model() const;
  std::size_t node_count() const;
  // Nodal state at t^n (structure of arrays).
  const std::vector<double>& x() const;
  const std::vector<double>& y() const;
  const std::vector<double>& z() const;
  const std::vector<double>& vx() const;  // v^n
  const std::vector<double>& vy() const;
  const std::vector<double>& vz() const;
  const std::vector<double>& nodal_mass() const;

  // Per-solid results in the solid numbering of Mesh::solid() (the hexahedra, then the other
  // cells; rigid solids: 0); a cell of several points gives the mean over its points.
  void von_mises_stress(std::vector<double>& out) const;
  void pressure(std::vector<double>& out) const;
  void plastic_strain(std::vector<double>& out) const;       // equivalent plastic strain
  void plastic_strain_rate(std::vector<double>& out) const;  // of the last step
  std::vector<std::uint8_t> eroded_solids() const;           // 1 per eroded solid
  // Per-shell results in Model mesh order (rigid shells: 0): the largest von Mises stress and
  // plastic strain over the element's through-thickness points.
  void shell_von_mises_stress(std::vector<double>& out) const;
  void shell_plastic_strain(std::vector<double>& out) const;
  void shell_plastic_strain_rate(std::vector<double>& out) const;
  std::vector<std::uint8_t> eroded_shells() const;  // 1 per eroded shell (mesh order)

  Energies energies() const;
  // Relative energy balance error: (total - total_0 - external_work) / the largest of |total|,
  // |total_0| and |W| so far in the run (not at this instant only: a balance whose energies pass
  // near zero would otherwise divide a small error by a smaller number).
  double energy_balance_error() const;
  std::vector<PartState> part_states() const;

  // Contact: per interface penalties and statistics; nodal fields summed over interfaces
  // (force interleaved x, y, z; pressure; accumulated wear).
  bool has_contact() const;
  double contact_seconds() const;                             // wall time spent in contact so far
  const std::vector<ContactReport>& contact_reports() const;  // valid until the next advance()
  void contact_fields(std::vector<double>& force, std::vector<double>& pressure,
                      std::vector<double>& wear) const;

  // Heat (heat.hpp): the nodal temperatures (empty without thermal properties), the time they
  // are at (time(): they advance with every mechanical step, at rates of the elements' conduction
  // planned once per thermal step), the thermal steps taken, the current thermal stable step and
  // the heat balance.
  std::span<const double> temperature() const;
  std::span<const double> heat_capacity() const;  // lumped, per node [energy / temperature]
  double temperature_time() const;
  std::int64_t thermal_steps() const;
  double thermal_stable_step() const;
  HeatBalance heat_balance() const;
  // Heat flowing into each node by conduction in the elements, as planned at the last thermal
  // step [power] (empty without thermal properties).
  std::span<const double> heat_flow() const;

  // Log lines of what happened since the last call (a sensor triggered, boundary conditions
  // released at impact), in the order they happened; the caller prints them.
  std::vector<std::string> take_messages();
  // The time the *SENSOR with this id triggered (infinity while it has not).
  double sensor_trigger_time(std::int64_t id) const;

  // Restart (issue 13): saves the complete state at t^n to `a`, or loads it into a simulation
  // built from the same model (StateArchiveError when it does not fit). Continuing from a loaded
  // state is bitwise identical to the run that saved it. The wall time spent in contact is not
  // part of the state.
  void archive(StateArchive& a);

  // The state saved before the step that failed (positions and velocities), for output.
  const std::vector<double>& last_good_x() const;
  const std::vector<double>& last_good_y() const;
  const std::vector<double>& last_good_z() const;
  double last_good_time() const;

 private:
  void element_field(void (SolidBlock::*hex_field)(std::vector<double>&) const,
                     void (SolidCellBlock::*cell_field)(std::vector<double>&) const,
                     std::vector<double>& out) const;
  void shell_field(void (ShellBlock::*field)(std::vector<double>&) const,
                   std::vector<double>& out) const;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace abut
