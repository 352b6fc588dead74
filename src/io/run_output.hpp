#pragma once
// What an explicit run writes as it goes (run.cpp): the ParaView states, the time histories and
// their output times; each lists its state for restart files (StateArchive).
#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "abut/core/state_archive.hpp"
#include "abut/io/csv_history.hpp"
#include "abut/io/vtu_writer.hpp"
#include "abut/solver/simulation.hpp"
#include "contact_history.hpp"
#include "node_history.hpp"
#include "run_thermal.hpp"

namespace abut::run_output {

// Writes one ParaView state of the simulation. `failed` marks the last good state of an
// unstable run: positions from before the failing step, stresses left out. Cells are the solids
// (Mesh::solid numbering: hexahedra, then the other cells), then the shells; every cell field
// holds the solid values, then the shell values.
class StateWriter {
 public:
  StateWriter(const std::filesystem::path& dir, const Model& model)
      : dir_(dir), model_(model), series_(dir / "results.pvd") {
    std::filesystem::create_directories(dir / "states");
    const Mesh& mesh = model.mesh;
    part_id_.reserve(mesh.solid_count() + mesh.shell_count());
    for (std::size_t e = 0; e < mesh.solid_count(); ++e)
      part_id_.push_back(static_cast<double>(mesh.solid(e).part));
    for (const std::int64_t p : mesh.shell_part) part_id_.push_back(static_cast<double>(p));
    // Solids have no thickness: 0 tells them apart from shells in ParaView.
    thickness_.assign(mesh.solid_count(), 0.0);
    for (const std::int64_t p : mesh.shell_part) {
      const Part* part = model.find_part(p);  // a deck's shell parts exist; a built model's may not
      thickness_.push_back(part ? part->thickness : 0.0);
    }
  }

  void write(const Simulation& sim, bool failed) {
    const std::vector<double>& x = failed ? sim.last_good_x() : sim.x();
    const std::vector<double>& y = failed ? sim.last_good_y() : sim.y();
    const std::vector<double>& z = failed ? sim.last_good_z() : sim.z();
    const double time = failed ? sim.last_good_time() : sim.time();
    if (x.empty()) return;  // failed before the first step: the initial state is on disk
    if (series_.size() > 0 && time <= last_time_) return;
    const Nodes& ref = model_.mesh.nodes;
    const std::size_t n = ref.size();
    displacement_.resize(3 * n);
    velocity_.resize(3 * n);
    for (std::size_t i = 0; i < n; ++i) {
      displacement_[3 * i] = x[i] - ref.x[i];
      displacement_[3 * i + 1] = y[i] - ref.y[i];
      displacement_[3 * i + 2] = z[i] - ref.z[i];
      velocity_[3 * i] = sim.vx()[i];
      velocity_[3 * i + 1] = sim.vy()[i];
      velocity_[3 * i + 2] = sim.vz()[i];
    }
    std::vector<FieldView> point_fields{{"displacement", 3, displacement_},
                                        {"velocity", 3, velocity_}};
    std::vector<FieldView> cell_fields{{"part_id", 1, part_id_}, {"thickness", 1, thickness_}};
    if (sim.has_contact()) {
      sim.contact_fields(contact_force_, contact_pressure_, wear_);
      point_fields.push_back({"contact_force", 3, contact_force_});
      point_fields.push_back({"contact_pressure", 1, contact_pressure_});
      point_fields.push_back({"wear", 1, wear_});
    }
    if (thermal_output::active(sim)) {
      point_fields.push_back({"temperature", 1, sim.temperature()});
      point_fields.push_back({"heat_flow", 1, sim.heat_flow()});
    }
    if (!failed) {
      sim.von_mises_stress(von_mises_);
      sim.pressure(pressure_);
      sim.plastic_strain(plastic_strain_);
      // Shells: the largest values over their through-thickness points; no pressure (plane
      // stress), written as 0 so that every cell has every field.
      sim.shell_von_mises_stress(shell_values_);
      von_mises_.insert(von_mises_.end(), shell_values_.begin(), shell_values_.end());
      pressure_.resize(pressure_.size() + model_.mesh.shell_count(), 0.0);
      sim.shell_plastic_strain(shell_values_);
      plastic_strain_.insert(plastic_strain_.end(), shell_values_.begin(), shell_values_.end());
      sim.plastic_strain_rate(plastic_strain_rate_);
      sim.shell_plastic_strain_rate(shell_values_);
      plastic_strain_rate_.insert(plastic_strain_rate_.end(), shell_values_.begin(),
                                  shell_values_.end());
      cell_fields.push_back({"von_mises_stress", 1, von_mises_});
      cell_fields.push_back({"pressure", 1, pressure_});
      cell_fields.push_back({"plastic_strain", 1, plastic_strain_});
      cell_fields.push_back({"plastic_strain_rate", 1, plastic_strain_rate_});
    }
    // The fields the input asked for (OutputRequests; part_id always).
    const auto unwanted = [this](const FieldView& f) { return !model_.output.writes(f.name); };
    std::erase_if(point_fields, unwanted);
    std::erase_if(cell_fields, unwanted);
    // Eroded elements disappear from the states.
    std::span<const Hex8> hexes = model_.mesh.hexes;
    std::span<const Quad4> shells = model_.mesh.shells;
    std::span<const CellBlock> cells = model_.mesh.cells;
    std::vector<std::uint8_t> eroded = sim.eroded_solids();
    const std::vector<std::uint8_t> eroded_shells = sim.eroded_shells();
    eroded.insert(eroded.end(), eroded_shells.begin(), eroded_shells.end());
    if (std::find(eroded.begin(), eroded.end(), std::uint8_t{1}) != eroded.end()) {
      const Mesh& mesh = model_.mesh;
      alive_hexes_.clear();
      alive_shells_.clear();
      alive_cells_.assign(mesh.cells.size(), {});
      std::size_t solid = mesh.hex_count();  // the solid numbering of the cells
      for (std::size_t b = 0; b < mesh.cells.size(); ++b) {
        const CellBlock& block = mesh.cells[b];
        alive_cells_[b].type = block.type;
        for (std::size_t c = 0; c < block.size(); ++c, ++solid) {
          if (eroded[solid]) continue;
          const auto cell = block.cell(c);
          alive_cells_[b].nodes.insert(alive_cells_[b].nodes.end(), cell.begin(), cell.end());
          alive_cells_[b].id.push_back(block.id[c]);
          alive_cells_[b].part.push_back(block.part[c]);
        }
      }
      for (std::size_t h = 0; h < mesh.hex_count(); ++h)
        if (!eroded[h]) alive_hexes_.push_back(mesh.hexes[h]);
      for (std::size_t s = 0; s < mesh.shell_count(); ++s)
        if (!eroded[mesh.solid_count() + s]) alive_shells_.push_back(mesh.shells[s]);
      alive_values_.resize(cell_fields.size());
      for (std::size_t k = 0; k < cell_fields.size(); ++k) {
        alive_values_[k].clear();
        const auto components = static_cast<std::size_t>(cell_fields[k].components);
        for (std::size_t e = 0; e < eroded.size(); ++e)
          for (std::size_t c = 0; !eroded[e] && c < components; ++c)
            alive_values_[k].push_back(cell_fields[k].values[components * e + c]);
        cell_fields[k].values = alive_values_[k];
      }
      hexes = alive_hexes_;
      shells = alive_shells_;
      cells = alive_cells_;
    }
    const std::string name = fmt::format("states/state_{:04d}.vtu", written_);
    const HexGridView grid{x, y, z, hexes, shells, cells};
    write_vtu(dir_ / name, grid, point_fields, cell_fields);
    series_.add(time, name);
    last_time_ = time;
    ++written_;
  }

  // Restart: the series so far. Loading removes the states that the interrupted run wrote after
  // its restart file (they will be written again).
  void archive(StateArchive& a) {
    a.values(series_, last_time_, written_);
    if (a.saving()) return;
    std::error_code ignored;
    for (const std::filesystem::directory_entry& entry :
         std::filesystem::directory_iterator(dir_ / "states", ignored)) {
      const std::string file = entry.path().filename().string();
      unsigned index = 0;
      if (std::sscanf(file.c_str(), "state_%u.vtu", &index) == 1 && index >= written_)
        std::filesystem::remove(entry.path(), ignored);
    }
  }

  const std::filesystem::path& pvd() const { return series_.path(); }
  std::size_t count() const { return series_.size(); }

 private:
  std::filesystem::path dir_;
  const Model& model_;
  PvdSeries series_;
  double last_time_ = 0.0;
  std::uint64_t written_ = 0;  // states written, numbering the next
  std::vector<double> displacement_, velocity_, part_id_, thickness_, von_mises_, pressure_,
      plastic_strain_, plastic_strain_rate_, shell_values_;
  std::vector<double> contact_force_, contact_pressure_, wear_;
  std::vector<Hex8> alive_hexes_;
  std::vector<Quad4> alive_shells_;
  std::vector<CellBlock> alive_cells_;
  std::vector<std::vector<double>> alive_values_;
};

class HistoryWriter {
 public:
  // With `thermal`, energy.csv gets the heat balance columns (thermal_output::energy_columns);
  // with `contact_heat`, contact.csv the heat of the thermal contacts.
  HistoryWriter(const std::filesystem::path& dir, const Model& model, bool with_contact,
                bool thermal, bool contact_heat)
      : nodes_(dir, model, NodeHistory::Run::Explicit),
        contact_heat_(contact_heat),
        energy_(dir / "energy.csv", energy_columns(thermal)),
        thermal_(thermal),
        parts_(dir / "parts.csv",
               {"part", "mass", "x", "y", "z", "vx", "vy", "vz", "kinetic", "internal"}) {
    std::vector<std::string> columns = contact_history_columns();
    // Thermal contact: the heat flowing from surface 1 to surface 2 now, conducted so far and
    // made by friction so far.
    if (contact_heat_)
      columns.insert(columns.end(), {"heat_flow", "conducted_heat", "friction_heat"});
    if (with_contact) contact_.emplace(dir / "contact.csv", columns);
  }

  void write(const Simulation& sim) {
    if (written_ && sim.time() <= last_time_) return;
    written_ = true;
    last_time_ = sim.time();
    const Energies e = sim.energies();
    energy_values_ = {
        e.kinetic, e.internal,         e.hourglass,     e.contact, e.friction,
        e.eroded,  e.contact_released, e.external_work, e.total(), sim.energy_balance_error()};
    if (thermal_) thermal_output::append_energy_values(sim, energy_values_);
    energy_.write_row(sim.time(), energy_values_);
    for (const PartState& p : sim.part_states())
      parts_.write_row(
          sim.time(),
          {static_cast<std::int64_t>(p.part_id), p.mass, p.centre_of_mass.x, p.centre_of_mass.y,
           p.centre_of_mass.z, p.velocity.x, p.velocity.y, p.velocity.z, p.kinetic, p.internal});
    if (contact_) {
      for (const ContactReport& c : sim.contact_reports()) {
        const ContactStats& st = c.stats;
        std::vector<CsvHistory::Value> row{static_cast<std::int64_t>(c.id),
                                           st.force.x,
                                           st.force.y,
                                           st.force.z,
                                           st.normal_force,
                                           st.tangential_force,
                                           st.elastic_energy + st.damping_energy,
                                           st.friction_energy,
                                           st.max_penetration,
                                           static_cast<std::int64_t>(st.active_points)};
        if (contact_heat_)
          row.insert(row.end(), {st.heat_flow, st.conducted_heat, st.friction_heat});
        contact_->write_row(sim.time(), row);
      }
    }
    nodes_.write(sim);
  }

 private:
  NodeHistory nodes_;
  bool contact_heat_ = false;
  static std::vector<std::string> energy_columns(bool thermal) {
    std::vector<std::string> columns{
        "kinetic", "internal",         "hourglass",     "contact", "friction",
        "eroded",  "contact_released", "external_work", "total",   "balance_error"};
    if (thermal)
      for (std::string& c : thermal_output::energy_columns()) columns.push_back(std::move(c));
    return columns;
  }

  CsvHistory energy_;
  bool thermal_;

 public:
  void archive(StateArchive& a) {
    a.values(energy_, parts_, contact_, nodes_, written_, last_time_);
  }

 private:
  std::vector<CsvHistory::Value> energy_values_;
  CsvHistory parts_;
  std::optional<CsvHistory> contact_;
  bool written_ = false;
  double last_time_ = 0.0;
};

// Output times t_start + k * interval; due() is true once the simulation has reached the next.
class Schedule {
 public:
  Schedule(double start, double interval) : next_(start), interval_(interval) {}
  bool due(double t) {
    if (t < next_ - 1e-9 * interval_) return false;
    while (next_ <= t + 1e-9 * interval_) next_ += interval_;
    return true;
  }
  void archive(StateArchive& a) { a.value(next_); }

 private:
  double next_, interval_;
};

}  // namespace abut::run_output
