// Runs the static steps of a model and writes what a user opens afterwards:
//   results.pvd + states/state_NNNN.vtu   one state per converged increment (OutputRequests:
//                                         every n-th and each step's last; the fields asked)
//   increments.csv                        step, increment, attempts, iterations, times, residual
//   energy.csv, contact.csv               energies (and the steady heat balance with heat); per
//                                         contact forces, energy, penetration (and the heat flow
//                                         with thermal contact)
//   nodes.csv                             the followed nodes' position, displacement and force
//                                         (OutputRequests::history_nodes; node_history.hpp)
//   results.dat                           the *NODE/*EL/*CONTACT PRINT blocks (CalculiX layout)
//   summary.json                          equations, increments, iterations, solve times (and
//                                         the last state's heat balance with heat)
#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "abut/io/csv_history.hpp"
#include "abut/io/json_writer.hpp"
#include "abut/io/output_directory.hpp"
#include "abut/io/run.hpp"
#include "abut/io/vtu_writer.hpp"
#include "abut/solver/static_heat.hpp"
#include "abut/solver/static_solver.hpp"
#include "io/contact_history.hpp"
#include "io/node_history.hpp"
#include "io/static_print.hpp"
#include "io/static_thermal_output.hpp"

namespace abut {

namespace {

namespace fs = std::filesystem;

// Thrown from the increment callback to leave StaticSolver::run when a stop is requested.
struct StopRequested {};

// One ParaView state: displacement and nodal force (loads and reactions) at the nodes; per solid
// element the mean over its integration points of the stress tensor and of the von Mises stress,
// the largest equivalent plastic strain of its points, and its strain energy. With thermal
// properties also the steady temperature field of the state and the heat flowing into each node by
// conduction (static_heat.hpp).
void write_state(const fs::path& dir, PvdSeries& series, const Model& model,
                 const StaticSolver& solver, double time, const StaticHeat& heat) {
  const Mesh& mesh = model.mesh;
  const std::size_t n = mesh.nodes.size(), nh = mesh.solid_count();
  std::vector<double> x(n), y(n), z(n), part(nh), stress(6 * nh, 0.0), mises(nh, 0.0),
      plastic(nh, 0.0);
  const auto u = solver.displacement();
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = mesh.nodes.x[i] + u[3 * i];
    y[i] = mesh.nodes.y[i] + u[3 * i + 1];
    z[i] = mesh.nodes.z[i] + u[3 * i + 2];
  }
  const auto s = solver.stress();
  for (std::size_t h = 0; h < nh; ++h) {
    part[h] = static_cast<double>(mesh.solid(h).part);
    const int points = solver.integration_points(h);
    for (int p = 0; p < points; ++p) {
      const std::size_t q = solver.first_point(h) + static_cast<std::size_t>(p);
      plastic[h] = std::max(plastic[h], solver.plastic_strain()[q]);
      const double* v = &s[6 * q];
      for (int k = 0; k < 6; ++k) stress[6 * h + k] += v[k] / points;
      const double dxy = v[0] - v[1], dyz = v[1] - v[2], dzx = v[2] - v[0];
      mises[h] += std::sqrt(0.5 * (dxy * dxy + dyz * dyz + dzx * dzx) +
                            3.0 * (v[3] * v[3] + v[4] * v[4] + v[5] * v[5])) /
                  points;
    }
  }
  std::vector<double> energy(solver.element_energy().begin(), solver.element_energy().end());
  std::vector<FieldView> points{{"displacement", 3, u}, {"force", 3, solver.nodal_force()}};
  if (heat.active()) {
    points.push_back({"temperature", 1, heat.temperature()});
    points.push_back({"heat_flow", 1, heat.heat_flow()});
  }
  std::vector<FieldView> cells{{"part_id", 1, part},
                               {"stress", 6, stress},
                               {"von_mises_stress", 1, mises},
                               {"plastic_strain", 1, plastic},
                               {"strain_energy", 1, energy}};
  // The fields the input asked for (OutputRequests; part_id always).
  const auto unwanted = [&model](const FieldView& f) { return !model.output.writes(f.name); };
  std::erase_if(points, unwanted);
  std::erase_if(cells, unwanted);
  const std::string name = fmt::format("states/state_{:04d}.vtu", series.size());
  write_vtu(dir / name, {x, y, z, mesh.hexes, mesh.shells, mesh.cells}, points, cells);
  series.add(time, name);
}

// One contact.csv row per contact of the model (the explicit run's columns), summed over its
// passes; a symmetric contact's second pass acts on surface 2, so its force counts negated.
// With thermal contact, the heat flow of the state's steady temperature follows.
void write_contact_rows(CsvHistory& csv, const Model& model, const StaticSolver& solver,
                        const StaticHeat& heat, bool heat_column, double time) {
  const auto passes = solver.contacts();
  for (std::size_t i = 0; i < model.contacts.size(); ++i) {
    Vec3 force{};
    double normal = 0.0, tangential = 0.0, energy = 0.0, friction = 0.0, penetration = 0.0;
    std::int64_t active = 0;
    bool first_pass = true;
    for (std::size_t k = 0; k < passes.size(); ++k) {
      if (solver.contact_of(k) != i) continue;
      const StaticContact& c = passes[k];
      force = first_pass ? force + c.total_force() : force - c.total_force();
      first_pass = false;
      friction += c.friction_work();
      for (const StaticContactPoint& p : c.points()) {
        if (!p.active) continue;
        ++active;
        normal += p.pressure * p.area;
        tangential += norm(p.traction) * p.area;
        energy += p.energy;
        penetration = std::max(penetration, -p.gap);
      }
    }
    std::vector<CsvHistory::Value> row{
        model.contacts[i].id, force.x, force.y,  force.z,     normal,
        tangential,           energy,  friction, penetration, active};
    if (heat_column) row.emplace_back(heat.contact_heat_flow()[i]);
    csv.write_row(time, row);
  }
}

// The work dissipated so far by contact stabilization (*CONTACT_STABILIZATION).
double stabilization_work(const StaticSolver& solver) {
  double w = 0.0;
  for (const StaticContact& c : solver.contacts()) w += c.stabilization_work();
  return w;
}

// The work of the loads and reactions on the model (energy.csv's external_work): the trapezoidal
// rule over each converged increment, W += (f_prev + f) . (u - u_prev) / 2, f the nodal force
// (loads and reactions, which balance the elements' and contacts' forces). Exact where f is linear
// in u over the increment (linear elastic steps); elsewhere second order in the increment.
class ExternalWork {
 public:
  explicit ExternalWork(const StaticSolver& solver)
      : u_(solver.displacement().begin(), solver.displacement().end()),
        f_(solver.nodal_force().begin(), solver.nodal_force().end()) {}
  double add(std::span<const double> u, std::span<const double> f) {
    for (std::size_t i = 0; i < u.size(); ++i) {
      work_ += 0.5 * (f_[i] + f[i]) * (u[i] - u_[i]);
      u_[i] = u[i];
      f_[i] = f[i];
    }
    return work_;
  }

 private:
  std::vector<double> u_, f_;
  double work_ = 0.0;
};

// energy.csv of a static run: the elements' energy (elastic, hourglass and plastic work), the
// contact springs' energy and the friction work; with contact stabilization its work; the work of
// the loads and reactions and the balance, (energies - external work) / the largest of them so
// far (`scale`, as explicit runs do); with heat, the state's heat balance.
void write_energy_row(CsvHistory& csv, const StaticSolver& solver, const StaticHeat& heat,
                      bool stabilized, double external_work, double& scale, double time) {
  double internal = 0.0, contact = 0.0, friction = 0.0;
  for (const double e : solver.element_energy()) internal += e;
  for (const StaticContact& c : solver.contacts()) {
    contact += c.energy();
    friction += c.friction_work();
  }
  std::vector<CsvHistory::Value> row{internal, contact, friction};
  double books = internal + contact + friction;
  if (stabilized) {
    const double stabilization = stabilization_work(solver);
    row.emplace_back(stabilization);
    books += stabilization;
  }
  scale = std::max({scale, std::abs(books), std::abs(external_work)});
  row.emplace_back(external_work);
  row.emplace_back(scale > 0.0 ? (books - external_work) / scale : 0.0);
  if (heat.active()) static_thermal_output::append_energy_values(heat, row);
  csv.write_row(time, row);
}

}  // namespace

RunReport run_static_analysis(const Model& model, const RunOptions& options, std::ostream& log) {
  if (options.threads > 0) omp_set_num_threads(options.threads);
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  const fs::path& dir = options.output_dir;
  StaticSolver solver(model);
  StaticHeat heat(model);  // input errors before the output directory is touched
  const OutputDirectory output(dir);
  fs::create_directories(dir / "states");
  log << fmt::format("abut: {} nodes, {} solid elements, {} parts, {} contacts; {} static steps\n",
                     model.mesh.nodes.size(), model.mesh.solid_count(), model.parts.size(),
                     model.contacts.size(), model.static_steps.size());
  log << "abut: writing results to " << dir.string() << "\n" << std::flush;
  if (heat.active())
    log << "abut: steady heat conduction at every state (temperature in the states)\n";
  const bool contact_heat = contacts_exchange_heat(model);
  PvdSeries series(dir / "results.pvd");
  // The reference state has no contact evaluated yet: a body that only contact would hold at a
  // temperature has no steady one there and shows its initial temperature.
  try {
    heat.solve(solver, 0.0);
  } catch (const InputError& e) {
    log << "abut: the first state keeps the initial temperature (" << e.what() << ")\n";
  }
  write_state(dir, series, model, solver, 0.0, heat);
  NodeHistory nodes(dir, model, NodeHistory::Run::Static);
  nodes.write(0.0, solver.displacement(), solver.nodal_force());
  CsvHistory increments(dir / "increments.csv",
                        {"step", "increment", "attempts", "iterations", "step_time", "residual"});
  std::vector<std::string> energy_columns{"internal", "contact", "friction"};
  const bool stabilized = std::any_of(model.contacts.begin(), model.contacts.end(),
                                      [](const ContactSpec& c) { return c.stabilization; });
  if (stabilized) energy_columns.emplace_back("stabilization");
  energy_columns.insert(energy_columns.end(), {"external_work", "balance_error"});
  if (heat.active())
    for (std::string& c : static_thermal_output::energy_columns())
      energy_columns.push_back(std::move(c));
  CsvHistory energy(dir / "energy.csv", energy_columns);
  ExternalWork external_work(solver);
  double energy_scale = 0.0;
  std::optional<CsvHistory> contact;
  if (!model.contacts.empty()) {
    std::vector<std::string> columns = contact_history_columns();
    if (contact_heat) columns.emplace_back("heat_flow");
    contact.emplace(dir / "contact.csv", columns);
  }
  std::ofstream printed(dir / "results.dat");
  RunReport report;
  const auto start = std::chrono::steady_clock::now();
  double last_time = 0.0;
  double end_time = 0.0;  // the steps' periods follow one another
  for (const StaticStep& step : model.static_steps) end_time += step.period;
  std::size_t increments_done = 0;
  try {
    solver.run([&](const StaticIncrement& inc) {
      increments.write_row(
          inc.total_time,
          {static_cast<std::int64_t>(inc.step + 1), static_cast<std::int64_t>(inc.increment),
           static_cast<std::int64_t>(inc.attempts), static_cast<std::int64_t>(inc.iterations),
           inc.step_time, inc.residual});
      heat.solve(solver, inc.total_time);
      // Every n-th increment of a step (the input's output frequency), and each step's last.
      if (inc.step_end || inc.increment % model.output.state_frequency == 0)
        write_state(dir, series, model, solver, inc.total_time, heat);
      const double work = external_work.add(solver.displacement(), solver.nodal_force());
      write_energy_row(energy, solver, heat, stabilized, work, energy_scale, inc.total_time);
      nodes.write(inc.total_time, solver.displacement(), solver.nodal_force());
      if (contact) write_contact_rows(*contact, model, solver, heat, contact_heat, inc.total_time);
      print_static_results(printed, model, model.static_steps[inc.step], solver, inc);
      printed.flush();
      last_time = inc.total_time;
      if (options.progress)
        log << fmt::format(
            "abut: step {} increment {} (t = {:.6g}): {} iterations{}\n", inc.step + 1,
            inc.increment, inc.total_time, inc.iterations,
            inc.attempts > 1 ? fmt::format(", {} cut-backs", inc.attempts - 1) : std::string());
      if (options.on_progress)
        options.on_progress(inc.total_time, end_time, static_cast<long long>(++increments_done));
      if (options.stop_requested && options.stop_requested()) throw StopRequested{};
    });
  } catch (const StopRequested&) {
    report.interrupted = true;
  } catch (const InstabilityError& e) {
    report.stable = false;
    report.message = e.what();
  }
  report.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  report.end_time = last_time;
  report.pvd = series.path();
  const StaticStatistics& st = solver.statistics();
  report.cycles = st.increments;
  JsonWriter json;
  json.begin_object();
  json.member("deck", model.deck_path);
  json.member("procedure", "static");
  json.member("status", report.interrupted ? "interrupted"
                        : report.stable    ? "completed"
                                           : "did not converge");
  if (!report.stable) json.member("message", report.message);
  json.member("end_time", report.end_time).member("wall_seconds", report.wall_seconds);
  json.member("threads", threads);
  json.member("nodes", static_cast<std::int64_t>(model.mesh.nodes.size()));
  json.member("elements", static_cast<std::int64_t>(model.mesh.solid_count()));
  json.member("equations", st.equations).member("increments", st.increments);
  json.member("iterations", st.iterations).member("cutbacks", st.cutbacks);
  json.member("assembly_seconds", st.assembly_seconds).member("solve_seconds", st.solve_seconds);
  json.member("linear_solver", st.linear_solver);
  if (heat.active()) static_thermal_output::write_summary(json, heat);
  json.end_object();
  json.write_file(dir / "summary.json");
  if (report.interrupted) {
    log << fmt::format(
        "abut: INTERRUPTED after {} increments at t = {:.6g} ({:.2f} s); that state is the last "
        "of the ParaView series\n",
        st.increments, last_time, report.wall_seconds);
  } else if (report.stable) {
    log << fmt::format(
        "abut: completed {} steps in {} increments, {} iterations ({:.2f} per increment), "
        "{:.2f} s ({:.2f} s solving {} equations with {})\n",
        model.static_steps.size(), st.increments, st.iterations,
        st.increments > 0 ? static_cast<double>(st.iterations) / static_cast<double>(st.increments)
                          : 0.0,
        report.wall_seconds, st.solve_seconds, st.equations, st.linear_solver);
  } else {
    log << "abut: the static analysis stopped: " << report.message << "\n"
        << fmt::format("abut: the last converged state (t = {:.6g}) is in the ParaView series\n",
                       last_time);
  }
  if (stabilized) {
    // Abaqus's check of its stabilization: the work it dissipated beside the elements' energy.
    double internal = 0.0;
    for (const double e : solver.element_energy()) internal += e;
    const double work = stabilization_work(solver);
    log << fmt::format(
        "abut: contact stabilization dissipated {:.4g} ({:.3g}% of the elements' energy {:.4g}; "
        "a body that loads move across a gap dissipates their work there)\n",
        work, internal > 0.0 ? 100.0 * work / internal : 0.0, internal);
  }
  if (heat.active()) log << static_thermal_output::end_line(heat);
  log << "abut: ParaView series: " << report.pvd.string() << " (" << series.size()
      << " states); printed results: " << (dir / "results.dat").string() << "\n"
      << std::flush;
  return report;
}

}  // namespace abut
