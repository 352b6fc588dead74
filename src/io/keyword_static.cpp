// *STATIC and *PART_SOLID (abut's own keywords): the static procedure of a .k deck. What the
// boundary conditions and loads become in the steps is decided once the deck is read
// (deck_finalize_static.cpp).
#include <algorithm>

#include "deck_reader.hpp"

namespace abut::deck {

// *STATIC: one nonlinear static step per command, in deck order. The steps follow each other in
// time; each ends at its t_end.
void read_static(DeckReader& d, Block& b) {
  StaticStep step;
  step.where = b.where();
  if (const auto title = b.title()) step.title = *title;
  const Row r = b.row({"t_end", "dt_0", "dt_min", "dt_max", "nlgeom", "n_inc"});
  if (r.number_or_function(0, 0.0).function_id)
    r.fail(0, "a step end time given by fcn is not supported");
  const bool first = d.static_step_ends.empty();
  const double start = first ? 0.0 : d.static_step_ends.back();
  const double t_end = r.number(0);
  if (first) {
    r.require(t_end > 0.0, 0, "expected a step end time > 0");
  } else {
    r.require(t_end > start, 0,
              "expected a step end time greater than " + format_number(start) +
                  ", the t_end of the previous *STATIC (steps follow each other)");
  }
  const double period = t_end - start;
  step.period = period;
  for (std::size_t i : {1, 2, 3}) {
    if (r.number_or_function(i, 0.0).function_id)
      r.fail(i, "an increment given by fcn is not supported");
  }
  step.max_increment = r.number_or(3, period);
  r.require(step.max_increment > 0.0, 3, "expected a largest increment > 0");
  step.initial_increment = r.number_or(1, std::min(period, step.max_increment));
  r.require(step.initial_increment > 0.0 && step.initial_increment <= period, 1,
            "expected an initial increment in (0, " + format_number(period) +
                "], the length of the step");
  r.require(step.max_increment >= step.initial_increment, 3,
            "expected a largest increment >= dt_0 (" + format_number(step.initial_increment) + ")");
  step.min_increment = r.number_or(2, std::min(1e-5 * period, step.initial_increment));
  r.require(
      step.min_increment > 0.0 && step.min_increment <= step.initial_increment, 2,
      "expected a smallest increment in (0, dt_0 = " + format_number(step.initial_increment) + "]");
  const std::int64_t nlgeom = r.integer_or(4, 1);
  r.require(nlgeom == 0 || nlgeom == 1, 4,
            "expected 0 (small displacements) or 1 (large displacements)");
  step.nonlinear_geometry = nlgeom == 1;
  if (!step.nonlinear_geometry && !first && d.model.static_steps.back().nonlinear_geometry)
    r.fail(4,
           "large displacements stay on once a step has them (the previous *STATIC has nlgeom "
           "1): give nlgeom 1");
  const std::int64_t increments = r.integer_or(5, step.max_increments);
  r.require(increments >= 1 && increments <= 1000000000, 5,
            "expected a largest number of increments >= 1");
  step.max_increments = static_cast<int>(increments);
  if (auto r2 = b.optional_row({"tol_R", "tol_C", "n_iter"})) {
    if (r2->given(0)) {
      step.force_tolerance = r2->number(0);
      r2->require(*step.force_tolerance > 0.0 && *step.force_tolerance < 1.0, 0,
                  "expected a residual tolerance in (0, 1)");
    }
    if (r2->given(1)) {
      step.displacement_tolerance = r2->number(1);
      r2->require(*step.displacement_tolerance > 0.0 && *step.displacement_tolerance < 1.0, 1,
                  "expected a correction tolerance in (0, 1)");
    }
    if (r2->given(2)) {
      const std::int64_t n = r2->integer(2);
      r2->require(n >= 1 && n <= 1000, 2, "expected a number of Newton iterations in [1, 1000]");
      step.max_iterations = static_cast<int>(n);
    }
  }
  if (!b.done()) {
    const Line extra = b.raw_line("");
    throw InputError(b.where(extra), "unexpected line '" + extra.text +
                                         "': a *STATIC holds one step; give each further step "
                                         "its own *STATIC");
  }
  d.static_step_ends.push_back(t_end);
  d.model.static_steps.push_back(std::move(step));
}

// *PART_SOLID: the integration of a part's hexahedra. FULL (2 x 2 x 2 points, Abaqus C3D8) is for
// static steps; the explicit solver's hexahedra have one point.
void read_part_solid(DeckReader& d, Block& b) {
  if (b.done()) throw InputError(b.where(), "missing data line: expected pid, integration");
  while (!b.done()) {
    const Row r = b.row({"pid", "integration"});
    PendingPartSolid s;
    s.part = d.part_id(r, 0);
    s.where = r.where(0);
    s.integration_where = r.where(1);
    d.claim_id("*PART_SOLID of part", s.part, s.where);
    s.integration = word_choice(r, 1, Part::SolidIntegration::Reduced,
                                {{"REDUCED", Part::SolidIntegration::Reduced},
                                 {"1", Part::SolidIntegration::Reduced},
                                 {"FULL", Part::SolidIntegration::Full},
                                 {"8", Part::SolidIntegration::Full}},
                                "REDUCED (or 1: one point) or FULL (or 8: 2 x 2 x 2 points)");
    d.part_solids.push_back(s);
  }
}

}  // namespace abut::deck
