#include <algorithm>
#include <cmath>

#include "simulation_impl.hpp"

namespace abut {

const Model& Simulation::model() const { return impl_->model; }
std::size_t Simulation::node_count() const { return impl_->n_nodes; }
const std::vector<double>& Simulation::x() const { return impl_->x; }
const std::vector<double>& Simulation::y() const { return impl_->y; }
const std::vector<double>& Simulation::z() const { return impl_->z; }
const std::vector<double>& Simulation::vx() const { return impl_->vx; }
const std::vector<double>& Simulation::vy() const { return impl_->vy; }
const std::vector<double>& Simulation::vz() const { return impl_->vz; }
const std::vector<double>& Simulation::nodal_mass() const { return impl_->mass; }

void Simulation::element_field(void (SolidBlock::*hex_field)(std::vector<double>&) const,
                               void (SolidCellBlock::*cell_field)(std::vector<double>&) const,
                               std::vector<double>& out) const {
  const Impl& m = *impl_;
  out.assign(m.model.mesh.solid_count(), 0.0);
  std::vector<double> block_values;
  for (std::size_t b = 0; b < m.blocks.size(); ++b) {
    (m.blocks[b].*hex_field)(block_values);
    for (std::size_t e = 0; e < block_values.size(); ++e)
      out[m.block_hex_index[b][e]] = block_values[e];
  }
  for (std::size_t b = 0; b < m.cell_blocks.size(); ++b) {
    (m.cell_blocks[b].*cell_field)(block_values);
    for (std::size_t e = 0; e < block_values.size(); ++e)
      out[m.block_solid_index[b][e]] = block_values[e];
  }
}

void Simulation::von_mises_stress(std::vector<double>& out) const {
  element_field(&SolidBlock::von_mises_stress, &SolidCellBlock::von_mises_stress, out);
}
void Simulation::pressure(std::vector<double>& out) const {
  element_field(&SolidBlock::pressure, &SolidCellBlock::pressure, out);
}
std::vector<std::uint8_t> Simulation::eroded_solids() const {
  const Impl& m = *impl_;
  std::vector<std::uint8_t> out(m.model.mesh.solid_count(), 0);
  for (std::size_t b = 0; b < m.blocks.size(); ++b) {
    const auto& eroded = m.blocks[b].eroded();
    for (std::size_t e = 0; e < eroded.size(); ++e) out[m.block_hex_index[b][e]] = eroded[e];
  }
  for (std::size_t b = 0; b < m.cell_blocks.size(); ++b) {
    const auto& eroded = m.cell_blocks[b].eroded();
    for (std::size_t e = 0; e < eroded.size(); ++e) out[m.block_solid_index[b][e]] = eroded[e];
  }
  return out;
}

void Simulation::shell_field(void (ShellBlock::*field)(std::vector<double>&) const,
                             std::vector<double>& out) const {
  const Impl& m = *impl_;
  out.assign(m.model.mesh.shell_count(), 0.0);
  std::vector<double> block_values;
  for (std::size_t b = 0; b < m.shell_blocks.size(); ++b) {
    (m.shell_blocks[b].*field)(block_values);
    for (std::size_t e = 0; e < block_values.size(); ++e)
      out[m.block_shell_index[b][e]] = block_values[e];
  }
}

void Simulation::shell_von_mises_stress(std::vector<double>& out) const {
  shell_field(&ShellBlock::von_mises_stress, out);
}
void Simulation::plastic_strain_rate(std::vector<double>& out) const {
  element_field(&SolidBlock::plastic_strain_rate, &SolidCellBlock::plastic_strain_rate, out);
}
void Simulation::shell_plastic_strain_rate(std::vector<double>& out) const {
  shell_field(&ShellBlock::plastic_strain_rate, out);
}
void Simulation::shell_plastic_strain(std::vector<double>& out) const {
  shell_field(&ShellBlock::plastic_strain, out);
}
std::vector<std::uint8_t> Simulation::eroded_shells() const {
  std::vector<std::uint8_t> out(impl_->model.mesh.shell_count(), 0);
  for (std::size_t b = 0; b < impl_->shell_blocks.size(); ++b) {
    const auto& eroded = impl_->shell_blocks[b].eroded();
    for (std::size_t e = 0; e < eroded.size(); ++e) out[impl_->block_shell_index[b][e]] = eroded[e];
  }
  return out;
}

void Simulation::plastic_strain(std::vector<double>& out) const {
  element_field(&SolidBlock::plastic_strain, &SolidCellBlock::plastic_strain, out);
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
  const double total = impl_->conserved_total();
  const double scale = std::max({impl_->energy_scale, std::abs(total), std::abs(impl_->total0),
                                 std::abs(e.external_work), std::abs(e.thermal_work)});
  return scale > 0.0 ? (total - impl_->total0 - e.external_work - e.thermal_work) / scale : 0.0;
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
    if (p.shell_block >= 0) s.internal += impl_->shell_steps[p.shell_block].internal_energy;
    for (const std::int32_t b : p.cell_blocks) s.internal += impl_->cell_steps[b].internal_energy;
    out.push_back(s);
  }
  return out;
}

const std::vector<double>& Simulation::last_good_x() const { return impl_->good_x; }
const std::vector<double>& Simulation::last_good_y() const { return impl_->good_y; }
const std::vector<double>& Simulation::last_good_z() const { return impl_->good_z; }
double Simulation::last_good_time() const { return impl_->good_t; }

std::span<const double> Simulation::temperature() const {
  return impl_->heat ? impl_->heat->temperature() : std::span<const double>();
}
std::span<const double> Simulation::heat_capacity() const {
  return impl_->heat ? impl_->heat->capacity() : std::span<const double>();
}
double Simulation::temperature_time() const { return impl_->t; }
std::int64_t Simulation::thermal_steps() const { return impl_->heat_steps; }
double Simulation::thermal_stable_step() const {
  return impl_->heat ? impl_->heat->stable_step() : 0.0;
}
HeatBalance Simulation::heat_balance() const {
  return impl_->heat ? impl_->heat->balance() : HeatBalance{};
}
std::span<const double> Simulation::heat_flow() const {
  return impl_->heat ? impl_->heat->conduction_rate() : std::span<const double>();
}

}  // namespace abut