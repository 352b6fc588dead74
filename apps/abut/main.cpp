// abut: the command-line program. Thin: reads the deck, runs or describes the model; plots a
// run's output directory with the Python package (abut plot, abut run --plot).
// Exit codes (README, "Using it"):
//   0        success
//   1        output or system error (writing the results failed, disk full, out of memory;
//            plotting without Python, numpy or matplotlib)
//   2        user error: command line, deck missing or unreadable, an error in the deck (file and
//            line named), an output directory that cannot be written or is in use
//   3        the run went unstable (explicit) or a step did not converge (static)
//   128 + s  interrupted by signal s (130 SIGINT, 143 SIGTERM) after writing a final state
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <new>

#include "abut/core/error.hpp"
#include "abut/io/deck.hpp"
#include "abut/io/interrupt.hpp"
#include "abut/io/run.hpp"
#include "abut/solver/simulation.hpp"
#include "abut/solver/static_solver.hpp"
#include "command_line.hpp"
#include "plot_command.hpp"
#include "wait_policy.hpp"

namespace {

namespace fs = std::filesystem;

fs::path default_output_dir(const fs::path& deck) {
  return deck.parent_path() / (deck.stem().string() + "_out");
}

// "40 hexahedra" or "40 hexahedra, 96 C3D10": the solids of a mesh by type.
std::string solids_of(const abut::Mesh& mesh) {
  std::string s = fmt::format("{} hexahedra", mesh.hex_count());
  for (const abut::CellBlock& b : mesh.cells)
    s += fmt::format(", {} {}", b.size(), abut::element_label(b.type));
  return s;
}

// A static model: its parts, contacts and steps (no time step to report).
void print_static_info(const abut::Model& model, std::ostream& out) {
  const abut::StaticSolver solver(model);  // validates it
  out << fmt::format("deck:       {}\n", model.deck_path);
  if (!model.title.empty()) out << fmt::format("title:      {}\n", model.title);
  out << fmt::format("mesh:       {} nodes, {}\n", model.mesh.nodes.size(), solids_of(model.mesh));
  out << "parts:\n";
  for (const abut::Part& p : model.parts)
    out << fmt::format(
        "  {:>6}  {:<20} material {}, {} integration\n", p.id, p.title.empty() ? "-" : p.title,
        p.material_id,
        p.solid_integration == abut::Part::SolidIntegration::Full ? "full" : "reduced");
  out << fmt::format("contacts:   {}\n", model.contacts.size());
  for (const abut::ContactSpec& c : model.contacts)
    out << fmt::format("  {:>6}  {} ({})\n", c.id, c.title.empty() ? "-" : c.title,
                       c.discretisation == abut::Discretisation::NodeToSurface
                           ? "node to surface"
                           : "surface to surface");
  out << fmt::format("equations:  {}\n", model.equations.size());
  out << fmt::format("static steps: {}\n", model.static_steps.size());
  for (std::size_t i = 0; i < model.static_steps.size(); ++i) {
    const abut::StaticStep& st = model.static_steps[i];
    out << fmt::format(
        "  {:>6}  period {:.6g}, initial increment {:.6g}{}{}; {} prescribed dofs, {} forces, {} "
        "face pressures\n",
        i + 1, st.period, st.initial_increment, st.fixed_increments ? " (fixed)" : "",
        st.nonlinear_geometry ? ", NLGEOM" : "", st.displacements.size(), st.forces.size(),
        st.pressures.size());
  }
}

void print_info(const abut::Model& model, std::ostream& out) {
  if (!model.static_steps.empty()) return print_static_info(model, out);
  const abut::Simulation sim(model);
  out << fmt::format("deck:       {}\n", model.deck_path);
  if (!model.title.empty()) out << fmt::format("title:      {}\n", model.title);
  out << fmt::format("units:      {}\n", model.units
                                             ? std::string(abut::unit_system_name(*model.units))
                                             : std::string("not stated (*UNIT_SYSTEM)"));
  out << fmt::format("mesh:       {} nodes, {}, {} shells\n", model.mesh.nodes.size(),
                     solids_of(model.mesh), model.mesh.shell_count());
  out << fmt::format("time:       end {:.6g}, step scale {}, initial stable step {:.4g} ({})\n",
                     model.time.end_time, model.time.step_scale, sim.initial_time_step(),
                     sim.time_step_limit());
  if (!sim.temperature().empty())
    out << fmt::format(
        "heat:       {} *PROP_THERMAL, thermal stable step of the elements {:.4g} ({:.3g} x the "
        "mechanical step; the heat is sub-cycled)\n",
        model.thermal.properties.size(), sim.thermal_stable_step(),
        sim.thermal_stable_step() / sim.initial_time_step());
  out << "parts:\n";
  for (const abut::PartState& p : sim.part_states())
    out << fmt::format("  {:>6}  {:<20} {:>8} elements  mass {:.6g}{}\n", p.part_id,
                       p.title.empty() ? "-" : p.title, p.element_count, p.mass,
                       p.rigid ? "  (rigid)" : "");
  out << fmt::format("contacts:   {}\n", model.contacts.size());
  for (const abut::ContactReport& c : sim.contact_reports())
    out << fmt::format("  {:>6}  {}: {}; {}; {}; {}\n", c.id, c.title.empty() ? "-" : c.title,
                       c.laws.discretisation, c.laws.normal_law, c.laws.tangential_law,
                       c.laws.stiffness_rule);
  for (const abut::ContactReport& c : sim.contact_reports())
    for (const std::string& w : c.warnings) out << "warning: " << w << "\n";
  out << fmt::format("boundary motions: {}, gravity loads: {}\n", model.motions.size(),
                     model.gravity.size());
}

}  // namespace

int main(int argc, char** argv) {
  abut_cli::ensure_passive_wait_policy(argv);
  if (const std::string error = abut_cli::command_error(argc, argv); !error.empty()) {
    std::cerr << "error: " << error << "\n";
    return 2;
  }
  CLI::App app{
      "abut: finite-element solver built around contact (explicit dynamics, nonlinear statics)"};
  app.set_version_flag("--version", std::string("abut ") + ABUT_VERSION);
  app.require_subcommand(1);

  std::string deck;
  std::string output;
  std::string threads_text;
  bool quiet = false;
  CLI::App* run =
      app.add_subcommand("run", "Run a deck; writes a ParaView series and time histories");
  // The deck and --threads are checked below, with plain messages, rather than by CLI11.
  run->add_option("deck", deck, "Input deck (IMPETUS keyword syntax, or Abaqus/CalculiX .inp)")
      ->required();
  run->add_option("-o,--output", output,
                  "Output directory (default: <deck stem>_out beside the deck)");
  const CLI::Option* threads_option =
      run->add_option("--threads", threads_text, "Number of threads (default: all cores)");
  run->add_flag("-q,--quiet", quiet, "No progress output");
  std::string restart_from, restart_interval_text;
  run->add_option("--restart", restart_from,
                  "Continue from a restart file (default output: the file's directory)");
  const CLI::Option* interval_option = run->add_option(
      "--restart-interval", restart_interval_text,
      "Also write restart.abr every this much model time and at the end (it is always "
      "written when the run is interrupted)");
  bool plot_after_run = false;
  run->add_flag("--plot", plot_after_run,
                "After a successful run, write the figures of its output directory (abut plot)");
  CLI::App* check =
      app.add_subcommand("check", "Parse and validate a deck; every error with file:line");
  check->add_option("deck", deck, "Input deck")->required();
  CLI::App* info =
      app.add_subcommand("info", "Model summary: parts, masses, contacts, stable time step");
  info->add_option("deck", deck, "Input deck")->required();
  std::string plot_dir, plot_to;
  CLI::App* plot = app.add_subcommand(
      "plot",
      "PNG figures of a run's energies, contact forces and velocities (Python, matplotlib)");
  plot->add_option("output_dir", plot_dir, "Output directory of a run")->required();
  plot->add_option("--to", plot_to, "Directory for the figures (default: <output dir>/plots)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version (code 0) print and succeed; every other CLI11 error is a user error.
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "error: " << e.what() << " (abut --help for the usage)\n";
    return 2;
  }
  if (*plot) return abut_cli::plot_output(plot_dir, plot_to);
  int threads = 0;
  std::string error = abut_cli::deck_error(deck);
  // Given but empty (--threads '') is a mistake too, not the default.
  if (error.empty() && threads_option->count() > 0)
    error = abut_cli::parse_threads(threads_text, threads);
  double restart_interval = 0.0;
  if (error.empty() && interval_option->count() > 0)
    error = abut_cli::parse_interval(restart_interval_text, restart_interval);
  if (!error.empty()) {
    std::cerr << "error: " << error << "\n";
    return 2;
  }

  try {
    abut::DeckResult result = abut::read_deck_with_notes(deck);
    for (const std::string& note : result.notes) std::cerr << "note: " << note << "\n";
    const abut::Model& model = result.model;
    if (*check) {
      const abut::ModelCheck checked = abut::check_model(model);
      for (const std::string& w : checked.warnings) std::cerr << "warning: " << w << "\n";
      if (!checked.initial_time_step) {  // static steps
        std::cout << fmt::format(
            "{}: OK ({} nodes, {}, {} parts, {} contacts, {} static "
            "steps)\n",
            deck, model.mesh.nodes.size(), solids_of(model.mesh), model.parts.size(),
            model.contacts.size(), model.static_steps.size());
      } else {
        std::cout << fmt::format(
            "{}: OK ({} nodes, {}, {} shells, {} parts, initial stable step {:.4g})\n", deck,
            model.mesh.nodes.size(), solids_of(model.mesh), model.mesh.shell_count(),
            model.parts.size(), *checked.initial_time_step);
      }
      return 0;
    }
    if (*info) {
      print_info(model, std::cout);
      return 0;
    }
    abut::RunOptions options;
    options.output_dir = !output.empty()         ? fs::path(output)
                         : !restart_from.empty() ? fs::path(restart_from).parent_path()
                                                 : default_output_dir(deck);
    if (options.output_dir.empty()) options.output_dir = ".";
    options.restart_from = restart_from;
    options.restart_interval = restart_interval;
    options.threads = threads;
    options.progress = !quiet;
    abut::interrupt::install();
    options.stop_requested = [] { return abut::interrupt::received() != 0; };
    const abut::RunReport report = abut::run_simulation(model, options, std::cout);
    if (report.interrupted) {
      const int signal = abut::interrupt::received();
      std::cerr << "abut: interrupted by "
                << (signal == SIGINT    ? "SIGINT"
                    : signal == SIGTERM ? "SIGTERM"
                                        : "a signal")
                << "; the final state, summary.json"
                << (model.static_steps.empty() ? " and restart.abr are" : " are") << " written\n";
      return 128 + signal;
    }
    if (!report.stable) return 3;
    return plot_after_run ? abut_cli::plot_output(options.output_dir.string(), "") : 0;
  } catch (const abut::InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  } catch (const abut::InstabilityError& e) {
    std::cerr << "error: unstable: " << e.what() << "\n";
    return 3;
  } catch (const std::bad_alloc&) {
    std::cerr << "error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
