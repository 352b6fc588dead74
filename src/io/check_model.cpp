// check_model (run.hpp): the checks of `abut check`, shared by the program, Python's abut.check
// and the deck fuzzers.
#include "abut/io/run.hpp"
#include "abut/solver/contact_report.hpp"
#include "abut/solver/simulation.hpp"
#include "abut/solver/static_solver.hpp"

namespace abut {

ModelCheck check_model(const Model& model) {
  ModelCheck out;
  if (!model.static_steps.empty()) {
    const StaticSolver solver(model);  // validates what the static solver needs
    return out;
  }
  const Simulation sim(model);
  for (const ContactReport& c : sim.contact_reports())
    out.warnings.insert(out.warnings.end(), c.warnings.begin(), c.warnings.end());
  out.initial_time_step = sim.initial_time_step();
  return out;
}

}  // namespace abut
