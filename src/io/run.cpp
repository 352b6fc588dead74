#include "abut/io/run.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <optional>
#include <ostream>
#include <vector>

#include "abut/core/error.hpp"
#include "abut/core/state_archive.hpp"
#include "abut/io/csv_history.hpp"
#include "abut/io/json_writer.hpp"
#include "abut/io/output_directory.hpp"
#include "abut/io/progress.hpp"
#include "abut/io/vtu_writer.hpp"
#include "abut/solver/simulation.hpp"
#include "contact_history.hpp"
#include "restart_file.hpp"
#include "run_thermal.hpp"

namespace abut {

namespace {

namespace fs = std::filesystem;

// Writes one ParaView state of the simulation. `failed` marks the last good state of an
// unstable run: positions from before the failing step, stresses left out. Cells are the
// hexahedra, then the shells; every cell field holds the hex values, then the shell values.
class StateWriter {
 public:
  StateWriter(const fs::path& dir, const Model& model)
      : dir_(dir), model_(model), series_(dir / "results.pvd") {
    fs::create_directories(dir / "states");
    const Mesh& mesh = model.mesh;
    part_id_.reserve(mesh.hex_count() + mesh.shell_count());
    for (const std::int64_t p : mesh.hex_part) part_id_.push_back(static_cast<double>(p));
    for (const std::int64_t p : mesh.shell_part) part_id_.push_back(static_cast<double>(p));
    // Hexahedra have no thickness: 0 tells them apart from shells in ParaView.
    thickness_.assign(mesh.hex_count(), 0.0);
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
    // Eroded elements disappear from the states.
    std::span<const Hex8> hexes = model_.mesh.hexes;
    std::span<const Quad4> shells = model_.mesh.shells;
    std::vector<std::uint8_t> eroded = sim.eroded_hexes();
    const std::vector<std::uint8_t> eroded_shells = sim.eroded_shells();
    eroded.insert(eroded.end(), eroded_shells.begin(), eroded_shells.end());
    if (std::find(eroded.begin(), eroded.end(), std::uint8_t{1}) != eroded.end()) {
      const std::size_t hex_count = model_.mesh.hex_count();
      alive_hexes_.clear();
      alive_shells_.clear();
      for (std::size_t e = 0; e < eroded.size(); ++e) {
        if (eroded[e]) continue;
        if (e < hex_count)
          alive_hexes_.push_back(model_.mesh.hexes[e]);
        else
          alive_shells_.push_back(model_.mesh.shells[e - hex_count]);
      }
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
    }
    const std::string name = fmt::format("states/state_{:04d}.vtu", written_);
    const HexGridView grid{x, y, z, hexes, shells};
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
    for (const fs::directory_entry& entry : fs::directory_iterator(dir_ / "states", ignored)) {
      const std::string file = entry.path().filename().string();
      unsigned index = 0;
      if (std::sscanf(file.c_str(), "state_%u.vtu", &index) == 1 && index >= written_)
        fs::remove(entry.path(), ignored);
    }
  }

  const fs::path& pvd() const { return series_.path(); }
  std::size_t count() const { return series_.size(); }

 private:
  fs::path dir_;
  const Model& model_;
  PvdSeries series_;
  double last_time_ = 0.0;
  std::uint64_t written_ = 0;  // states written, numbering the next
  std::vector<double> displacement_, velocity_, part_id_, thickness_, von_mises_, pressure_,
      plastic_strain_, plastic_strain_rate_, shell_values_;
  std::vector<double> contact_force_, contact_pressure_, wear_;
  std::vector<Hex8> alive_hexes_;
  std::vector<Quad4> alive_shells_;
  std::vector<std::vector<double>> alive_values_;
};

class HistoryWriter {
 public:
  // With `thermal`, energy.csv gets the heat balance columns (thermal_output::energy_columns);
  // with `contact_heat`, contact.csv the heat of the thermal contacts.
  HistoryWriter(const fs::path& dir, bool with_contact, bool thermal, bool contact_heat)
      : contact_heat_(contact_heat),
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
    energy_values_ = {e.kinetic,       e.internal, e.hourglass,
                      e.contact,       e.friction, e.eroded,
                      e.external_work, e.total(),  sim.energy_balance_error()};
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
  }

 private:
  bool contact_heat_ = false;
  static std::vector<std::string> energy_columns(bool thermal) {
    std::vector<std::string> columns{"kinetic",       "internal", "hourglass",
                                     "contact",       "friction", "eroded",
                                     "external_work", "total",    "balance_error"};
    if (thermal)
      for (std::string& c : thermal_output::energy_columns()) columns.push_back(std::move(c));
    return columns;
  }

  CsvHistory energy_;
  bool thermal_;

 public:
  void archive(StateArchive& a) { a.values(energy_, parts_, contact_, written_, last_time_); }

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

void write_summary(const fs::path& path, const Simulation& sim, const RunReport& report,
                   const Model& model, int threads, const std::string& initial_limit) {
  JsonWriter json;
  json.begin_object();
  json.member("deck", model.deck_path);
  json.member("status", report.interrupted ? "interrupted"
                        : report.stable    ? "completed"
                                           : "unstable");
  if (!report.stable) json.member("message", report.message);
  json.member("cycles", report.cycles);
  json.member("end_time", report.end_time);
  json.member("wall_seconds", report.wall_seconds);
  json.member("threads", threads);
  json.member("nodes", static_cast<std::int64_t>(model.mesh.nodes.size()));
  json.member("elements", static_cast<std::int64_t>(model.mesh.hex_count()));
  json.member("shells", static_cast<std::int64_t>(model.mesh.shell_count()));
  json.member("ns_per_element_cycle", report.ns_per_element_cycle);
  json.member("contact_share_of_wall_time",
              report.wall_seconds > 0 ? sim.contact_seconds() / report.wall_seconds : 0.0);
  json.member("initial_time_step", sim.initial_time_step());
  json.member("time_step_lost_to_contact", sim.contact_step_loss());
  json.member("initial_time_step_limited_by", initial_limit);
  json.member("final_time_step_limited_by", sim.time_step_limit());
  const Energies e = sim.energies();
  json.key("final_energies").begin_object();
  json.member("kinetic", e.kinetic).member("internal", e.internal).member("hourglass", e.hourglass);
  json.member("contact", e.contact)
      .member("friction", e.friction)
      .member("eroded", e.eroded)
      .member("external_work", e.external_work);
  json.member("total", e.total()).member("balance_error", sim.energy_balance_error());
  json.end_object();
  json.key("parts").begin_array();
  for (const PartState& p : sim.part_states()) {
    json.begin_object();
    json.member("id", p.part_id).member("title", p.title).member("rigid", p.rigid);
    json.member("elements", static_cast<std::int64_t>(p.element_count)).member("mass", p.mass);
    json.end_object();
  }
  json.end_array();
  json.key("contacts").begin_array();
  for (const ContactReport& c : sim.contact_reports()) {
    json.begin_object();
    json.member("id", c.id).member("title", c.title);
    json.member("discretisation", c.discretisation).member("normal_law", c.normal_law);
    json.member("tangential_law", c.tangential_law).member("stiffness_rule", c.stiffness_rule);
    json.member("gap_rule", c.gap_rule).member("erosion", c.erosion_rule);
    json.member("edge_contact", c.edge_rule);
    json.member("contact_points", static_cast<std::int64_t>(c.points));
    json.member("released_points", static_cast<std::int64_t>(c.released_points));
    json.key("warnings").begin_array();
    for (const std::string& w : c.warnings) json.value(w);
    json.end_array();
    json.key("penalty_per_part").begin_array();
    for (const PartPenalty& p : c.parts) {
      json.begin_object()
          .member("part", p.part_id)
          .member("pfac", p.penalty)
          .member("automatic", p.automatic);
      json.end_object();
    }
    json.end_array();
    json.key("penalty_per_pair").begin_array();
    for (const PairStiffness& p : c.pairs) {
      json.begin_object()
          .member("part1", p.part1)
          .member("part2", p.part2)
          .member("scale", p.scale);
      json.member("penalty_min", p.penalty_min).member("penalty_max", p.penalty_max);
      json.end_object();
    }
    json.end_array();
    json.member("max_penetration", c.stats.max_penetration);
    // Range of the gaps (g_s + g_m, Radioss TYPE25) of the point-facet pairs that touched.
    json.member("gap_min", c.stats.gap_min).member("gap_max", c.stats.gap_max);
    json.member("friction_energy", c.stats.friction_energy);
    json.end_object();
  }
  json.end_array();
  if (thermal_output::active(sim)) thermal_output::write_summary(json, sim, report.cycles);
  json.end_object();
  json.write_file(path);
}

}  // namespace

RunReport run_simulation(const Model& model, const RunOptions& options, std::ostream& log) {
  if (!model.static_steps.empty()) {
    if (!options.restart_from.empty() || options.restart_interval > 0.0)
      throw InputError(
          "restart files are written and read by explicit runs only; this deck has static steps");
    return run_static_analysis(model, options, log);
  }
  if (options.threads > 0) omp_set_num_threads(options.threads);
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();

  Simulation sim(model);
  // A restart loads the simulation's state before it claims the output directory, so that a file
  // that does not fit leaves the interrupted run's output alone.
  std::optional<StateArchive> restart;
  const SourceLocation restart_where{options.restart_from.string(), 0, "", ""};
  const auto unfit = [&](const StateArchiveError& e) {
    return InputError(restart_where,
                      std::string("the restart file does not fit this deck: ") + e.what());
  };
  if (!options.restart_from.empty()) {
    restart = restart_file::read(options.restart_from, model);
    try {
      sim.archive(*restart);
      restart->mark("output");
    } catch (const StateArchiveError& e) {
      throw unfit(e);
    }
  }
  const std::int64_t first_cycle = sim.cycle();
  const OutputDirectory output(options.output_dir, !restart);
  const double t_end = model.time.end_time;
  const double span = t_end - model.time.start_time;
  const double state_interval =
      model.output.state_interval > 0 ? model.output.state_interval : span / 100.0;
  const double history_interval =
      model.output.history_interval > 0 ? model.output.history_interval : span / 1000.0;
  log << fmt::format(
      "abut: {} nodes, {} hexahedra, {} shells, {} parts; end time {:.4g}, initial time step "
      "{:.4g} ({})\n",
      model.mesh.nodes.size(), model.mesh.hex_count(), model.mesh.shell_count(), model.parts.size(),
      t_end, sim.initial_time_step(), sim.time_step_limit());
  const std::string initial_limit = sim.time_step_limit();
  for (const ContactReport& c : sim.contact_reports()) {
    log << fmt::format("abut: contact {}", c.id) << (c.title.empty() ? "" : " \"" + c.title + "\"")
        << ": pfac";
    for (const PartPenalty& p : c.parts)
      log << fmt::format(" part {} = {:.4g}{}", p.part_id, p.penalty,
                         p.automatic ? " (automatic)" : "");
    log << fmt::format(", {} contact points ({}; {}; {}; {})\n", c.points, c.discretisation,
                       c.normal_law, c.tangential_law, c.stiffness_rule);
    for (const std::string& w : c.warnings) log << "warning: " << w << "\n";
  }
  if (thermal_output::active(sim)) log << thermal_output::start_line(sim);
  log << "abut: writing results to " << options.output_dir.string() << "\n" << std::flush;

  StateWriter states(options.output_dir, model);
  const bool contact_heat = contacts_exchange_heat(model);
  HistoryWriter histories(options.output_dir, sim.has_contact(), thermal_output::active(sim),
                          contact_heat);
  Schedule state_schedule(model.time.start_time, state_interval);
  Schedule history_schedule(model.time.start_time, history_interval);
  const double restart_interval = options.restart_interval;
  Schedule restart_schedule(model.time.start_time + restart_interval, restart_interval);
  if (restart) {
    try {
      restart->values(states, histories, state_schedule, history_schedule);
      restart->mark("end");
      if (!restart->exhausted()) restart->fail("the file holds more than this deck's state");
    } catch (const StateArchiveError& e) {
      throw unfit(e);
    }
    if (restart_interval > 0.0) restart_schedule.due(sim.time());  // the next one after now
    log << fmt::format("abut: continuing from {} at t = {:.6g}, cycle {}\n",
                       options.restart_from.string(), sim.time(), sim.cycle())
        << std::flush;
  }
  // Saved at the top of a cycle, after that time's output: a restart repeats nothing.
  const fs::path restart_path = options.output_dir / restart_file::kName;
  double restart_time = -1.0;
  const auto save_restart = [&] {
    StateArchive a = StateArchive::for_saving();
    sim.archive(a);
    a.mark("output");
    a.values(states, histories, state_schedule, history_schedule);
    a.mark("end");
    restart_file::write(restart_path, model, a);
    restart_time = sim.time();
  };
  ProgressReporter progress = ProgressReporter::to_stderr(model.time.start_time, t_end);

  RunReport report;
  const auto wall_start = std::chrono::steady_clock::now();
  try {
    for (;;) {
      if (history_schedule.due(sim.time())) histories.write(sim);
      if (state_schedule.due(sim.time())) states.write(sim, false);
      if (sim.finished()) {
        if (restart_interval > 0.0) save_restart();
        break;
      }
      if (options.stop_requested && options.stop_requested()) {
        report.interrupted = true;
        save_restart();
        break;
      }
      if (restart_interval > 0.0 && restart_schedule.due(sim.time())) save_restart();
      sim.advance();
      if (options.progress) progress.update(sim.time(), sim.cycle());
    }
    histories.write(sim);  // the final time, unless it was just written
    states.write(sim, false);
  } catch (const InstabilityError& e) {
    report.stable = false;
    report.message = e.what();
    states.write(sim, true);
  }
  if (options.progress) progress.finish(sim.time(), sim.cycle());
  report.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  report.end_time = sim.time();
  report.cycles = sim.cycle();
  const double element_cycles =
      static_cast<double>(model.mesh.hex_count() + model.mesh.shell_count()) *
      static_cast<double>(report.cycles - first_cycle);
  report.ns_per_element_cycle =
      element_cycles > 0 ? 1e9 * report.wall_seconds / element_cycles : 0.0;
  report.energy_balance_error = sim.energy_balance_error();
  report.pvd = states.pvd();
  write_summary(options.output_dir / "summary.json", sim, report, model, threads, initial_limit);

  if (report.interrupted) {
    log << fmt::format(
        "abut: INTERRUPTED after {} cycles at t = {:.6g} ({:.2f} s); that state is the last of "
        "the ParaView series\n",
        report.cycles, report.end_time, report.wall_seconds);
  } else if (report.stable) {
    log << fmt::format(
        "abut: completed {} cycles to t = {:.6g} in {:.2f} s ({:.1f} ns per element-cycle, {} "
        "threads)\n",
        report.cycles, report.end_time, report.wall_seconds, report.ns_per_element_cycle, threads);
    log << fmt::format("abut: energy balance error {:.3f}%\n", 100.0 * report.energy_balance_error);
    if (thermal_output::active(sim)) log << thermal_output::end_line(sim, report.cycles);
    if (sim.has_contact())
      log << fmt::format(
          "abut: contact took {:.0f}% of the wall time and shortened the time step by {:.1f}%\n",
          100.0 * sim.contact_seconds() / report.wall_seconds, 100.0 * sim.contact_step_loss());
  } else {
    log << "abut: the run went UNSTABLE and stopped: " << report.message << "\n"
        << fmt::format("abut: the last good state (t = {:.6g}) is in the ParaView series\n",
                       sim.last_good_time());
  }
  log << "abut: ParaView series: " << report.pvd.string() << " (" << states.count() << " states)\n";
  if (restart_time >= 0.0)
    log << fmt::format("abut: restart file {} (t = {:.6g}); continue with --restart {}\n",
                       restart_path.string(), restart_time, restart_path.string());
  log << std::flush;
  return report;
}

}  // namespace abut
