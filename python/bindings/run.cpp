// Python's abut.run and abut.check over the solver (abut/io/run.hpp, abut/io/deck.hpp): the
// same reading, checks and runs as the command-line program, with errors as Python exceptions.
#include "abut/io/run.hpp"

#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <sstream>
#include <string>

#include "abut/core/error.hpp"
#include "abut/io/deck.hpp"
#include "bindings.hpp"

namespace py = pybind11;

namespace abut::python {
namespace {

// abut.errors.DeckError(message, file, line, keyword, field), raised for an InputError: the
// message is what the command-line program prints after "error: ".
void raise_deck_error(const InputError& e) {
  const SourceLocation& w = e.where();
  const py::object type = py::module_::import("abut.errors").attr("DeckError");
  const py::object error = type(e.what(), w.file, w.line, w.keyword, w.field, e.message());
  PyErr_SetObject(type.ptr(), error.ptr());
}

py::dict check(const std::string& deck) {
  DeckResult result = read_deck_with_notes(deck);
  const Model& model = result.model;
  py::dict out;
  out["notes"] = result.notes;
  out["nodes"] = model.mesh.nodes.size();
  out["parts"] = model.parts.size();
  out["contacts"] = model.contacts.size();
  out["static_steps"] = model.static_steps.size();
  const ModelCheck checked = check_model(model);
  if (checked.initial_time_step) out["initial_time_step"] = *checked.initial_time_step;
  out["warnings"] = checked.warnings;
  return out;
}

// Runs the deck into `out`; `progress(time, end_time, cycles)` is called at every hundredth of an
// explicit run and every increment of a static one. The solver runs without the GIL; Ctrl-C
// (Python's signal handler, checked at most every 0.1 s of wall time) stops it as it stops the
// program: with a final state written, then KeyboardInterrupt.
py::dict run(const std::string& deck, const std::string& out, int threads,
             const py::object& progress, bool echo) {
  DeckResult result = read_deck_with_notes(deck);
  RunOptions options;
  options.output_dir = out;
  options.threads = threads;
  options.progress = echo;
  bool interrupted = false;
  auto last_check = std::chrono::steady_clock::now();
  options.stop_requested = [&] {
    const auto now = std::chrono::steady_clock::now();
    if (now - last_check < std::chrono::milliseconds(100)) return interrupted;
    last_check = now;
    const py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) interrupted = true;  // the exception stays set
    return interrupted;
  };
  py::object callback_error;
  if (!progress.is_none())
    options.on_progress = [&](double time, double end_time, long long cycles) {
      const py::gil_scoped_acquire gil;
      if (callback_error) return;
      try {
        progress(time, end_time, cycles);
      } catch (py::error_already_set& e) {
        callback_error = py::reinterpret_borrow<py::object>(e.value());
        interrupted = true;
      }
    };
  std::ostringstream log;
  RunReport report;
  {
    const py::gil_scoped_release released;
    report = run_simulation(result.model, options, log);
  }
  if (callback_error) {
    PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(callback_error.ptr())),
                    callback_error.ptr());
    throw py::error_already_set();
  }
  if (interrupted) throw py::error_already_set();  // KeyboardInterrupt from the signal check
  if (echo) py::print(log.str(), py::arg("end") = "");
  py::dict d;
  d["stable"] = report.stable;
  d["message"] = report.message;
  d["end_time"] = report.end_time;
  d["cycles"] = report.cycles;
  d["wall_seconds"] = report.wall_seconds;
  d["ns_per_element_cycle"] = report.ns_per_element_cycle;
  d["energy_balance_error"] = report.energy_balance_error;
  d["notes"] = result.notes;
  d["log"] = log.str();
  return d;
}

}  // namespace

void bind_run(py::module_& m) {
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      raise_deck_error(e);
    } catch (const InstabilityError& e) {
      const py::object type = py::module_::import("abut.errors").attr("InstabilityError");
      PyErr_SetObject(type.ptr(), py::str(e.what()).ptr());
    }
  });
  m.def("_check", &check, py::arg("deck"));
  m.def("_run", &run, py::arg("deck"), py::arg("out"), py::arg("threads") = 0,
        py::arg("progress") = py::none(), py::arg("echo") = false);
}

}  // namespace abut::python
