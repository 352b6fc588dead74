#include "abut/io/run.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <chrono>
#include <optional>
#include <ostream>
#include <vector>

#include "abut/core/error.hpp"
#include "abut/core/state_archive.hpp"
#include "abut/io/json_writer.hpp"
#include "abut/io/output_directory.hpp"
#include "abut/io/progress.hpp"
#include "abut/solver/simulation.hpp"
#include "contact_history.hpp"
#include "restart_file.hpp"
#include "run_output.hpp"
#include "run_thermal.hpp"

namespace abut {

namespace {

// ", 120 C3D10, 8 C3D6": the solid cells other than 8-node hexahedra, for the log.
std::string other_solids(const Mesh& mesh) {
  std::string out;
  for (const CellBlock& b : mesh.cells)
    if (b.size() > 0) out += fmt::format(", {} {}", b.size(), element_label(b.type));
  return out;
}

namespace fs = std::filesystem;
using run_output::HistoryWriter;
using run_output::Schedule;
using run_output::StateWriter;

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
  json.member("elements", static_cast<std::int64_t>(model.mesh.solid_count()));
  json.member("shells", static_cast<std::int64_t>(model.mesh.shell_count()));
  json.member("ns_per_element_cycle", report.ns_per_element_cycle);
  json.member("contact_share_of_wall_time",
              report.wall_seconds > 0 ? sim.contact_seconds() / report.wall_seconds : 0.0);
  json.member("initial_time_step", sim.initial_time_step());
  json.member("time_step_lost_to_contact", sim.contact_step_loss());
  json.member("time_step_lost_to_contact_kink", sim.contact_kink_step_loss());
  json.member("initial_time_step_limited_by", initial_limit);
  json.member("final_time_step_limited_by", sim.time_step_limit());
  const Energies e = sim.energies();
  json.key("final_energies").begin_object();
  json.member("kinetic", e.kinetic).member("internal", e.internal).member("hourglass", e.hourglass);
  json.member("contact", e.contact)
      .member("friction", e.friction)
      .member("eroded", e.eroded)
      .member("contact_released", e.contact_released)
      .member("external_work", e.external_work);
  if (thermal_output::active(sim)) json.member("thermal_work", e.thermal_work);
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
    const ContactDescription& laws = c.laws;
    json.member("discretisation", laws.discretisation).member("normal_law", laws.normal_law);
    json.member("tangential_law", laws.tangential_law);
    json.member("stiffness_rule", laws.stiffness_rule).member("gap_rule", laws.gap_rule);
    json.member("erosion", laws.erosion_rule).member("edge_contact", laws.edge_rule);
    json.member("contact_points", static_cast<std::int64_t>(c.points));
    json.member("released_points", static_cast<std::int64_t>(c.released_points));
    json.key("warnings").begin_array();
    for (const std::string& w : c.warnings) json.value(w);
    json.end_array();
    json.key("penalty_per_part").begin_array();
    for (const PartPenalty& p : c.parts) {
      json.begin_object()
          .member("part", p.part_id)
          .member("penalty", p.penalty)
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
  // A restart file holds the simulation's state, then the output's (one listing each for saving
  // and loading). A restart loads the simulation's before it claims the output directory, so that
  // a file that does not fit leaves the interrupted run's output alone.
  const auto archive_simulation = [&sim](StateArchive& a) {
    sim.archive(a);
    a.mark("output");
  };
  std::optional<StateArchive> restart;
  const SourceLocation restart_where{options.restart_from.string(), 0, "", ""};
  const auto unfit = [&](const StateArchiveError& e) {
    return InputError(restart_where,
                      std::string("the restart file does not fit this deck: ") + e.what());
  };
  if (!options.restart_from.empty()) {
    restart = restart_file::read(options.restart_from, model);
    try {
      archive_simulation(*restart);
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
      "abut: {} nodes, {} hexahedra{}, {} shells, {} parts; end time {:.4g}, initial time step "
      "{:.4g} ({})\n",
      model.mesh.nodes.size(), model.mesh.hex_count(), other_solids(model.mesh),
      model.mesh.shell_count(), model.parts.size(), t_end, sim.initial_time_step(),
      sim.time_step_limit());
  const std::string initial_limit = sim.time_step_limit();
  for (const ContactReport& c : sim.contact_reports()) {
    log << fmt::format("abut: contact {}", c.id) << (c.title.empty() ? "" : " \"" + c.title + "\"")
        << ": penalty";
    for (const PartPenalty& p : c.parts)
      log << fmt::format(" part {} = {:.4g}{}", p.part_id, p.penalty,
                         p.automatic ? " (automatic)" : "");
    log << fmt::format(", {} contact points ({}; {}; {}; {})\n", c.points, c.laws.discretisation,
                       c.laws.normal_law, c.laws.tangential_law, c.laws.stiffness_rule);
    for (const std::string& w : c.warnings) log << "warning: " << w << "\n";
  }
  if (thermal_output::active(sim)) log << thermal_output::start_line(sim);
  log << "abut: writing results to " << options.output_dir.string() << "\n" << std::flush;

  StateWriter states(options.output_dir, model);
  const bool contact_heat = contacts_exchange_heat(model);
  HistoryWriter histories(options.output_dir, model, sim.has_contact(), thermal_output::active(sim),
                          contact_heat);
  Schedule state_schedule(model.time.start_time, state_interval);
  Schedule history_schedule(model.time.start_time, history_interval);
  const double restart_interval = options.restart_interval;
  Schedule restart_schedule(model.time.start_time + restart_interval, restart_interval);
  const auto archive_output = [&](StateArchive& a) {
    a.values(states, histories, state_schedule, history_schedule);
    a.mark("end");
  };
  if (restart) {
    try {
      archive_output(*restart);
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
    archive_simulation(a);
    archive_output(a);
    restart_file::write(restart_path, model, a);
    restart_time = sim.time();
  };
  ProgressReporter progress = ProgressReporter::to_stderr(model.time.start_time, t_end);
  // RunOptions::on_progress at every hundredth of the run.
  double next_report = sim.time();
  const auto report_progress = [&](bool last) {
    if (!options.on_progress || (!last && sim.time() < next_report)) return;
    options.on_progress(sim.time(), t_end, sim.cycle());
    next_report = sim.time() + 0.01 * (t_end - model.time.start_time);
  };

  RunReport report;
  const auto wall_start = std::chrono::steady_clock::now();
  const auto log_messages = [&] {
    const std::vector<std::string> lines = sim.take_messages();
    for (const std::string& line : lines) log << line << "\n";
    if (!lines.empty()) log << std::flush;
  };
  try {
    for (;;) {
      log_messages();  // sensors and releases at impact (the set-up's at t^0 first)
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
      report_progress(false);
    }
    log_messages();
    histories.write(sim);  // the final time, unless it was just written
    states.write(sim, false);
  } catch (const InstabilityError& e) {
    report.stable = false;
    report.message = e.what();
    states.write(sim, true);
  }
  if (options.progress) progress.finish(sim.time(), sim.cycle());
  report_progress(true);
  report.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  report.end_time = sim.time();
  report.cycles = sim.cycle();
  const double element_cycles =
      static_cast<double>(model.mesh.solid_count() + model.mesh.shell_count()) *
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
