// The state of a Simulation for restart files (issue 13; state_archive.hpp): everything that a
// cycle carries to the next, listed once for saving and loading.
#include "abut/core/state_archive.hpp"
#include "simulation_impl.hpp"

namespace abut {

void Simulation::archive(StateArchive& a) {
  Impl& s = *impl_;
  a.mark("simulation");
  a.expect(static_cast<std::uint64_t>(s.n_nodes), "the node count");
  a.expect(static_cast<std::uint64_t>(s.blocks.size()), "the number of solid blocks");
  a.expect(static_cast<std::uint64_t>(s.shell_blocks.size()), "the number of shell blocks");
  a.expect(static_cast<std::uint64_t>(s.cell_blocks.size()), "the number of solid cell blocks");
  a.expect(static_cast<std::uint64_t>(s.bodies.size()), "the number of rigid bodies");
  // Nodes: positions, velocities (v^{n+1/2}, v^n, v^{n-1/2}), forces, masses; rotations.
  a.fixed(s.x, s.y, s.z, s.vhx, s.vhy, s.vhz, s.vx, s.vy, s.vz, s.ox, s.oy, s.oz, s.fx, s.fy, s.fz,
          s.mass, s.inverse_mass, s.whx, s.why, s.whz, s.owx, s.owy, s.owz, s.mx, s.my, s.mz,
          s.rotary_inertia, s.inverse_rotary_inertia);
  // Time, step and what limits it, energies, the last good state.
  a.values(s.t, s.n, s.dt_prev, s.dt_next, s.stable, s.dt_initial, s.limiting_block,
           s.limiting_shell_block, s.limiting_cell_block, s.limiting_contact, s.energy,
           s.conserved_kinetic, s.step_change_kinetic, s.total0, s.energy_scale,
           s.external_work_done, s.good_x, s.good_y, s.good_z, s.good_t, s.block_steps,
           s.shell_steps, s.cell_steps, s.step_sum, s.element_step_sum, s.kink_step_sum,
           s.limiting_kink);
  a.values(s.blocks, s.shell_blocks, s.cell_blocks, s.bodies);
  a.values(s.eroded_elements, s.element_eroded);  // element_eroded: filled at the first erosion
  s.contacts->archive(a);
  s.sensors->archive(a);
  a.values(s.released);
  if (!a.saving()) s.messages.clear();  // those of the set-up at t^0: the run is past them
  // Heat: the temperatures, the planned rates and how long they hold.
  a.values(s.heat, s.heat_planned_to, s.planned_contact_rate, s.heat_steps);
  a.mark("simulation end");
}

}  // namespace abut
