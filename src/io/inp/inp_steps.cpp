// *STEP ... *END STEP with its procedure *STATIC, the print requests (*NODE PRINT, *EL PRINT,
// *CONTACT PRINT) and *CONTROLS. The loads of a step are in inp_loads.cpp; finish_steps
// (inp_finish_steps.cpp) makes the StaticSteps.
#include <algorithm>

#include "../deck_text.hpp"
#include "inp_reader.hpp"

namespace abut::inp {
namespace {

using Kind = ParameterRule::Kind;

// NAME, NAME=YES or NAME=NO.
bool yes_no(const Reader& r, const Card& c, std::string_view key) {
  const Parameter* p = find_parameter(c, key);
  if (p && !p->has_value) return true;
  return parameter_choice(r, c, key, {"YES", "NO"}, "YES") == "YES";
}

// Print keys abut knows for each kind of request; keys longer than four letters are read by their
// first four, as CalculiX does (CDISP = CDIS, CSTRESS = CSTR).
struct PrintKeys {
  std::vector<std::string_view> available;
  std::vector<std::string_view> unavailable;  // CalculiX keys for fields abut does not compute
};

const PrintKeys& keys_of(PrintRequest::Kind kind) {
  static const PrintKeys node{{"U", "RF"},
                              {"NT", "TS", "TSF", "TTF", "PN", "PSF", "PTF", "MACH", "CP", "VF",
                               "MF", "RFL", "PS", "PT", "V"}};
  static const PrintKeys element{{"S", "E", "ME", "PEEQ", "ENER", "ELSE", "EVOL"},
                                 {"CEEQ", "SDV", "HFL", "SVF", "ELKE"}};
  static const PrintKeys contact{{"CDIS", "CSTR", "CELS"}, {"CNUM"}};
  switch (kind) {
    case PrintRequest::Kind::Node:
      return node;
    case PrintRequest::Kind::Element:
      return element;
    case PrintRequest::Kind::Contact:
      return contact;
  }
  return node;
}

void read_print(Reader& r, const Card& c, PrintRequest::Kind kind) {
  PrintCard p;
  p.kind = kind;
  p.where = r.loc(c);
  const char* set_key = kind == PrintRequest::Kind::Element ? "ELSET" : "NSET";
  p.set = parameter_value(c, set_key).value_or("");
  if (const auto frequency = parameter_value(c, "FREQUENCY")) {
    const auto n = deck::parse_integer(*frequency);
    if (!n || *n < 1) {
      throw InputError(
          r.where(c, "FREQUENCY"),
          "expected FREQUENCY= an integer >= 1 (every n-th increment), got '" + *frequency + "'");
    }
    p.frequency = static_cast<int>(*n);
  }
  const std::string totals = parameter_choice(r, c, "TOTALS", {"YES", "ONLY", "NO"}, "NO");
  p.totals = totals != "NO";
  p.totals_only = totals == "ONLY";
  if (c.data.empty()) {
    throw InputError(r.where(c), "the line with the keys to print (e.g. U, RF) is missing");
  }
  const PrintKeys& keys = keys_of(kind);
  std::string dropped;
  for (const DataLine& l : c.data) {
    const Fields f(r, c, l);
    for (std::size_t i = 0; i < f.size(); ++i) {
      if (!f.given(i)) continue;
      std::string key = deck::upper(f.text(i));
      const auto known = [&](const std::vector<std::string_view>& list) {
        for (const std::string_view k : list) {
          if (key == k || (key.size() > 4 && key.substr(0, 4) == k)) {
            key = std::string(k);
            return true;
          }
        }
        return false;
      };
      if (known(keys.available)) {
        if (std::find(p.quantities.begin(), p.quantities.end(), key) == p.quantities.end())
          p.quantities.push_back(key);
      } else if (known(keys.unavailable)) {
        dropped += (dropped.empty() ? "" : ", ") + key;
      } else {
        std::string list;
        for (const std::string_view k : keys.available)
          list += (list.empty() ? "" : ", ") + std::string(k);
        f.fail("key",
               "unknown key '" + f.text(i) + "' for " + c.keyword + " (abut prints " + list + ")");
      }
    }
  }
  if (!dropped.empty()) {
    r.note(c, c.keyword + ": " + dropped +
                  " left out (fields of thermal, fluid or plastic analyses, which abut does not "
                  "compute)");
  }
  // Kept without quantities too: it still replaces the previous step's requests of its kind.
  r.step().prints.push_back(std::move(p));
}

}  // namespace

void read_step(Reader& r, const Card& c) {
  check_parameters(
      r, c,
      {{"NLGEOM", Kind::FlagOrValue},
       {"INC"},
       {"NAME"},
       {"AMPLITUDE"},
       {"PERTURBATION", Kind::Unsupported, "linear perturbation steps"},
       {"INCF", Kind::Ignored, "applies to 3D fluid calculations: ignored"},
       {"UNSYMM", Kind::Ignored, "is ignored: abut chooses its linear solver itself"},
       {"EXTRAPOLATION", Kind::Ignored, "is ignored: abut uses its own Newton controls"},
       {"TURBULENCE MODEL", Kind::Unsupported, "fluid calculations"},
       {"SHOCK SMOOTHING", Kind::Unsupported, "fluid calculations"}});
  StepRecord s;
  s.where = r.loc(c);
  if (has_parameter(c, "NLGEOM")) s.nlgeom = yes_no(r, c, "NLGEOM");
  const bool was_on = std::any_of(r.steps.begin(), r.steps.end(),
                                  [](const StepRecord& p) { return p.nlgeom.value_or(false); });
  if (s.nlgeom == false && was_on) {
    throw InputError(r.where(c, "NLGEOM"),
                     "NLGEOM cannot be switched off once an earlier step has switched it on "
                     "(CalculiX and Abaqus keep it on): remove NLGEOM=NO");
  }
  if (const auto inc = parameter_value(c, "INC")) {
    const auto n = deck::parse_integer(*inc);
    if (!n || *n < 1) {
      throw InputError(r.where(c, "INC"),
                       "expected INC= the maximum number of increments (>= 1), got '" + *inc + "'");
    }
    s.max_increments = static_cast<int>(std::min<std::int64_t>(*n, 1000000000));
  }
  if (parameter_choice(r, c, "AMPLITUDE", {"RAMP", "STEP"}, "RAMP") != "RAMP") {
    throw InputError(r.where(c, "AMPLITUDE"),
                     "AMPLITUDE=STEP is not supported yet by abut: loads of static steps ramp "
                     "linearly over the step (or follow an *AMPLITUDE)");
  }
  if (c.data.size() > 1) {
    throw InputError(r.where(Reader::loc(c.data[1]), c.keyword),
                     "unexpected data line: *STEP takes at most one line (the step's title)");
  }
  s.title = parameter_value(c, "NAME").value_or(c.data.empty() ? "" : c.data.front().text);
  if (s.title.empty()) s.title = "Step " + std::to_string(r.steps.size() + 1);
  s.force_tolerance = r.force_tolerance;
  s.displacement_tolerance = r.displacement_tolerance;
  r.steps.push_back(std::move(s));
  r.in_step = true;
  r.history_output = false;  // a step's output requests start afresh (Abaqus)
}

void read_static(Reader& r, const Card& c) {
  check_parameters(r, c,
                   {{"DIRECT", Kind::FlagOrValue},
                    {"SOLVER", Kind::Ignored,
                     "is ignored: abut solves with its own sparse direct solver (CHOLMOD/UMFPACK)"},
                    {"TIME RESET", Kind::Unsupported},
                    {"TOTAL TIME AT START", Kind::Unsupported},
                    {"EXPLICIT", Kind::Unsupported, "fluid calculations"},
                    {"RIKS", Kind::Unsupported, "arc-length (Riks) steps"},
                    {"STABILIZE", Kind::Unsupported, "automatic stabilisation"},
                    {"ALLSDTOL", Kind::Unsupported, "automatic stabilisation"},
                    {"LONG TERM", Kind::Unsupported}});
  StepRecord& s = r.step();
  if (s.has_procedure) {
    throw InputError(r.where(c), "the step of " + r.at(s.where) +
                                     " has a procedure already: one *STATIC per step");
  }
  s.has_procedure = true;
  if (const Parameter* p = find_parameter(c, "DIRECT")) {
    s.direct = !p->has_value || lookup_key(p->value) != "NO";
  }
  if (c.data.size() > 1) {
    throw InputError(r.where(Reader::loc(c.data[1]), c.keyword),
                     "unexpected data line: *STATIC takes one line (initial increment, period, "
                     "minimum increment, maximum increment)");
  }
  if (c.data.empty()) return;
  const Fields f(r, c, c.data.front());
  f.at_most(4, "initial increment, time period, minimum increment, maximum increment");
  s.initial = f.number_or(0, "initial increment", 1.0);
  s.period = f.number_or(1, "time period", 1.0);
  if (!(s.period > 0.0)) f.fail("time period", "expected a time period > 0");
  if (!(s.initial > 0.0 && s.initial <= s.period)) {
    f.fail("initial increment", "expected an initial increment in (0, time period]");
  }
  if (f.given(2)) {
    s.min_increment = f.number(2, "minimum increment");
    if (!(*s.min_increment > 0.0 && *s.min_increment <= s.initial)) {
      f.fail("minimum increment", "expected a minimum increment in (0, initial increment]");
    }
  }
  if (f.given(3)) {
    s.max_increment = f.number(3, "maximum increment");
    if (!(*s.max_increment >= s.initial)) {
      f.fail("maximum increment", "expected a maximum increment >= the initial increment");
    }
  }
}

void read_end_step(Reader& r, const Card& c) {
  check_parameters(r, c, {});
  no_data(r, c);
  if (!r.step().has_procedure) {
    throw InputError(r.where(r.step().where, "*STEP"),
                     "the step has no procedure: abut runs static steps, so add *STATIC (the "
                     "step ends at " +
                         r.at(r.loc(c)) + ")");
  }
  r.in_step = false;
}

void read_node_print(Reader& r, const Card& c) {
  check_parameters(r, c,
                   {{"NSET"},
                    {"FREQUENCY"},
                    {"TOTALS"},
                    {"GLOBAL"},
                    {"TIME POINTS", Kind::Unsupported, "use FREQUENCY"},
                    {"FREQUENCYF", Kind::Ignored, "applies to 3D fluid calculations: ignored"}});
  parameter_choice(r, c, "GLOBAL", {"YES", "NO"}, "NO");  // no *TRANSFORM: local is global
  read_print(r, c, PrintRequest::Kind::Node);
}

void read_el_print(Reader& r, const Card& c) {
  check_parameters(r, c,
                   {{"ELSET"},
                    {"FREQUENCY"},
                    {"TOTALS"},
                    {"GLOBAL"},
                    {"TIME POINTS", Kind::Unsupported, "use FREQUENCY"},
                    {"FREQUENCYF", Kind::Ignored, "applies to 3D fluid calculations: ignored"}});
  parameter_choice(r, c, "GLOBAL", {"YES", "NO"}, "NO");  // no *ORIENTATION: local is global
  read_print(r, c, PrintRequest::Kind::Element);
}

void read_contact_print(Reader& r, const Card& c) {
  check_parameters(
      r, c,
      {{"NSET"}, {"FREQUENCY"}, {"TOTALS"}, {"TIME POINTS", Kind::Unsupported, "use FREQUENCY"}});
  read_print(r, c, PrintRequest::Kind::Contact);
}

// *CONTROLS, PARAMETERS=FIELD sets the Newton tolerances of the displacement field: R_n, the
// largest residual over the average force, and C_n, the largest correction over the largest
// displacement increment (CalculiX User's Manual, "*CONTROLS" and section "Convergence criteria";
// defaults 0.005 and 0.02, abut's). They hold from here on, in this step and the next ones, until
// RESET; the further values of the line (q0, qu, R_P, epsilon, C_epsilon, R_l) are not used by
// abut's Newton and are skipped with a note. Other PARAMETERS (TIME INCREMENTATION, LINE SEARCH)
// are skipped: abut uses its own increment controls.
void read_controls(Reader& r, const Card& c) {
  check_parameters(r, c,
                   {{"PARAMETERS", Kind::FlagOrValue},
                    {"RESET", Kind::FlagOrValue},
                    {"FIELD", Kind::FlagOrValue},
                    {"ANALYSIS", Kind::FlagOrValue},
                    {"TYPE", Kind::FlagOrValue}});
  const auto apply = [&r] {
    if (r.in_step) {
      r.step().force_tolerance = r.force_tolerance;
      r.step().displacement_tolerance = r.displacement_tolerance;
    }
  };
  if (has_parameter(c, "RESET")) {
    r.force_tolerance.reset();
    r.displacement_tolerance.reset();
    apply();
    return;
  }
  const std::string parameters = deck::upper(parameter_value(c, "PARAMETERS").value_or(""));
  const std::string field = deck::upper(parameter_value(c, "FIELD").value_or("DISPLACEMENT"));
  if (parameters != "FIELD" || field != "DISPLACEMENT") {
    r.note(c,
           "*CONTROLS skipped: abut uses its own increment controls and sets only the "
           "Newton tolerances of the displacement field (PARAMETERS=FIELD)");
    return;
  }
  if (c.data.empty()) return;
  const Fields f(r, c, c.data.front());
  const auto tolerance = [&](std::size_t i, const char* name, std::optional<double>& out) {
    if (!f.given(i)) return;
    const double v = f.number(i, name);
    if (!(v > 0.0 && v < 1.0)) f.fail(name, "expected a tolerance between 0 and 1");
    out = v;
  };
  tolerance(0, "R_n", r.force_tolerance);
  tolerance(1, "C_n", r.displacement_tolerance);
  for (std::size_t i = 2; i < f.size(); ++i)
    if (f.given(i)) {
      r.note(c,
             "*CONTROLS: only R_n and C_n act in abut; the further values of the line are "
             "skipped");
      break;
    }
  if (c.data.size() > 1)
    r.note(c, "*CONTROLS: the lines after the first (line search, cutbacks) are skipped");
  apply();
}

}  // namespace abut::inp
