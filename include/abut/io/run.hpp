#pragma once
// Runs a model to its end time and writes what a user opens afterwards:
//   results.pvd + states/state_NNNN.vtu  (ParaView series; the final state always included)
//   energy.csv, parts.csv                (time histories)
//   summary.json                         (cycles, times, speed, final energies, parts)
//   restart.abr                          (when interrupted, or at RunOptions::restart_interval)
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "abut/model/model.hpp"

namespace abut {

struct RunOptions {
  std::filesystem::path output_dir;  // created if missing
  int threads = 0;                   // 0: OpenMP default
  bool progress = true;              // progress bar / lines on stderr
  // Polled after every cycle (explicit) or increment (static): true stops the run there, with
  // a final state and summary.json written (RunReport::interrupted). Empty: never.
  std::function<bool()> stop_requested = {};
  // Called as the run advances, for a host that shows progress its own way (Python's abut.run),
  // whether or not `progress` is on: explicit runs after each cycle that completes another
  // hundredth of the run and once at its end, static runs after each converged increment; with
  // the model time, the end time and the cycles (increments) so far. Empty: never.
  std::function<void(double time, double end_time, long long cycles)> on_progress = {};
  // Restart files (issue 13; explicit runs): a run writes `restart.abr` in its output directory
  // when it is interrupted, and with restart_interval > 0 also every restart_interval of model
  // time and at its end. A run given restart_from continues from that file, bitwise identically,
  // in output_dir, whose histories and states it continues.
  double restart_interval = 0.0;
  std::filesystem::path restart_from = {};
};

struct RunReport {
  bool stable = true;        // false: the run went unstable and stopped early
  bool interrupted = false;  // stopped by RunOptions::stop_requested before its end
  std::string message;       // the instability message when !stable
  double end_time = 0.0;
  long long cycles = 0;
  double wall_seconds = 0.0;
  double ns_per_element_cycle = 0.0;
  double energy_balance_error = 0.0;
  std::filesystem::path pvd;  // results.pvd
};

// Once the model is validated, the output directory is claimed (OutputDirectory: locked, a
// previous run's files removed). Throws InputError for models the solver cannot run and output
// directories that cannot be used; an instability is reported, not thrown, after the last good
// state has been written.
// A model with static steps (Model::static_steps) runs run_static_analysis instead.
RunReport run_simulation(const Model& model, const RunOptions& options, std::ostream& log);

// What `abut check` finds without running (src/io/check_model.cpp): the solver the model needs is
// set up (the static solver for static steps, else the explicit one), which raises the
// InputErrors a run would; then the contacts' start-up warnings and, for an explicit run, its
// first stable time step.
struct ModelCheck {
  std::vector<std::string> warnings;
  std::optional<double> initial_time_step;  // explicit runs
};
ModelCheck check_model(const Model& model);

// The static steps of a model (src/io/run_static.cpp): a ParaView state per converged increment,
// increments.csv, energy.csv, contact.csv, results.dat (the *NODE/*EL/*CONTACT PRINT requests in
// CalculiX's .dat layout) and summary.json. report.cycles counts the increments; a step that does
// not converge is reported (stable = false) after the last converged state was written.
RunReport run_static_analysis(const Model& model, const RunOptions& options, std::ostream& log);

}  // namespace abut
