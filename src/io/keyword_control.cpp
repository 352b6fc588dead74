// *TITLE, *PARAMETER, *PARAMETER_DEFAULT, *UNIT_SYSTEM, *TIME, *OUTPUT, *OUTPUT_FIELDS,
// *OUTPUT_NODE_HISTORY, *CONTROL_BULK_VISCOSITY, *CONTROL_P-ORDER.
#include <algorithm>
#include <cctype>

#include "abut/core/functions.hpp"
#include "deck_reader.hpp"

namespace abut::deck {
namespace {

// One `%name = expression, "description", rid, quantity` row. The description, rid and
// quantity serve the IMPETUS GUI and unit conversion; abut checks their form only.
void read_parameter_rows(DeckReader& d, Block& b, bool only_if_undefined) {
  while (!b.done()) {
    const Line line = b.raw_line("%name = expression");
    const SourceLocation where = b.where(line);
    const Row row(split_fields(line.text), where,
                  {"%name = expression", "description", "rid", "quantity"});
    const std::string& definition = row.text(0);
    const auto equals = definition.find('=');
    if (definition.empty() || definition.front() != '%' || equals == std::string::npos) {
      row.fail(0, "expected %name = expression, got '" + definition + "'");
    }
    const std::string name = trim(definition.substr(1, equals - 1));
    const std::string expression = trim(definition.substr(equals + 1));
    if (!is_parameter_name(name)) {
      row.fail(
          0, "expected a parameter name of letters, digits and '_' after '%', got '" + name + "'");
    }
    if (expression.empty()) row.fail(0, "missing expression after '='");
    if (row.given(2)) row.integer(2);
    if (only_if_undefined && d.parameters.contains(name)) continue;
    double value = 0.0;
    try {
      value = evaluate_constant_expression(d.parameters.substitute(expression, row.where(0), true));
    } catch (const InputError& e) {
      if (!e.where().file.empty()) throw;
      row.fail(0, "cannot evaluate '" + expression + "': " + e.message());
    }
    d.parameters.define(name, value, row.where(0));
  }
}

// A keyword a deck holds once: records where it is, or fails at a second one naming the first.
void once_per_deck(std::optional<SourceLocation>& first, const Block& b, const char* keyword) {
  if (first) {
    throw InputError(b.where(), std::string("the deck already has a ") + keyword + " at " +
                                    first->file + ":" + std::to_string(first->line));
  }
  first = b.where();
}

}  // namespace

void read_title(DeckReader& d, Block& b) {
  once_per_deck(d.title_where, b, "*TITLE");
  if (!b.done()) d.model.title = unquote(b.raw_line("the title").text);
}

void read_parameter(DeckReader& d, Block& b) { read_parameter_rows(d, b, false); }

void read_parameter_default(DeckReader& d, Block& b) { read_parameter_rows(d, b, true); }

void read_unit_system(DeckReader& d, Block& b) {
  once_per_deck(d.units_where, b, "*UNIT_SYSTEM");
  const Row r = b.row({"units", "temperature"});
  const auto units = parse_unit_system(r.word(0));
  if (!units)
    r.fail(0, "expected SI, MMTONS, CMGUS, IPS, MMKGMS, CMGS, MMGMS or MMMGMS, got '" + r.text(0) +
                  "'");
  d.model.units = units;
  // The temperature unit is checked and not stored: the heat solver uses temperature differences
  // only (conduction, convection, expansion), so the deck's temperatures, its thermal properties
  // and its initial and prescribed temperatures must simply use the same unit. K and C share
  // the size of a degree; with F, c_p, k, alpha and h must be given per degree F.
  if (r.given(1)) {
    const std::string t = r.word(1);
    r.require(t == "K" || t == "C" || t == "F", 1, "expected K, C or F");
  }
}

void read_time(DeckReader& d, Block& b) {
  once_per_deck(d.time_where, b, "*TIME");
  const Row r = b.row({"t_term", "sf_dt", "dt_min", "dt_max", "ms_max", "t_start"});
  TimeControl& t = d.model.time;
  if (r.number_or_function(0, 0.0).function_id)
    r.fail(0, "a termination time given by fcn is not supported yet by abut");
  t.end_time = r.number(0);
  r.require(t.end_time > 0.0, 0, "expected a termination time > 0");
  t.step_scale = r.number_or(1, t.step_scale);
  r.require(t.step_scale > 0.0 && t.step_scale <= 1.0, 1,
            "expected a time-step scale factor in (0, 1]");
  for (std::size_t i : {2, 3}) {
    if (r.number_or_function(i, 0.0).function_id)
      r.fail(i, "a time-step limit given by fcn is not supported yet by abut");
  }
  t.min_step = r.number_or(2, t.min_step);
  d.model.sources.set(SourceEntity::Time, 0, "min_step", r.where(2));
  d.model.sources.set(SourceEntity::Time, 0, "max_step", r.where(3));
  r.require(t.min_step >= 0.0, 2, "expected a minimum time step >= 0");
  t.max_step = r.number_or(3, t.max_step);
  r.require(t.max_step > 0.0, 3, "expected a maximum time step > 0");
  r.require(t.max_step >= t.min_step, 3, "expected a maximum time step >= dt_min");
  r.unsupported_unless(4, 1e10, "mass scaling (ms_max)");
  t.start_time = r.number_or(5, t.start_time);
  r.require(t.start_time >= 0.0 && t.start_time < t.end_time, 5,
            "expected a start time in [0, t_term)");
}

void read_output(DeckReader& d, Block& b) {
  if (!d.output_where) d.output_where = b.where();
  const Row r = b.row({"dt_imp", "dt_ascii", "dt_db", "fragment"});
  OutputRequests& o = d.model.output;
  o.state_interval = r.number_or(0, 0.0);
  r.require(o.state_interval >= 0.0, 0, "expected an interval >= 0 (0 or empty: t_term/100)");
  o.history_interval = r.number_or(1, 0.0);
  r.require(o.history_interval >= 0.0, 1, "expected an interval >= 0 (0 or empty: t_term/1000)");
  r.unsupported_unless(2, 0.0, "database/state-file output (dt_db)");
  r.unsupported_unless(3, 0.0, "fragment output");
  if (auto r2 = b.optional_row({"nfilter", "efilter", "entype_res", "enid_res", "N_res"})) {
    r2->unsupported_unless(0, 0.0, "node output filtering (nfilter)");
    r2->unsupported_unless(1, 0.0, "element output filtering (efilter)");
    for (std::size_t i : {2, 3, 4}) r2->unsupported(i, "state-file output");
  }
}

// *OUTPUT_FIELDS (abut's own): the fields of the states, by their names in ParaView (kStateFields
// of abut/model/output.hpp), up to eight per row and as many rows as needed. Without it the states
// carry every field the run has; part_id is always written.
void read_output_fields(DeckReader& d, Block& b) {
  OutputRequests& o = d.model.output;
  if (d.output_fields_where)
    throw InputError(b.where(), "*OUTPUT_FIELDS is given twice (first at line " +
                                    std::to_string(d.output_fields_where->line) +
                                    "): list every field in one");
  std::vector<std::string> names;
  for (int i = 1; i <= 8; ++i) names.push_back("field_" + std::to_string(i));
  o.state_fields.emplace();
  std::string known;
  for (const std::string_view f : kStateFields)
    known += (known.empty() ? "" : ", ") + std::string(f);
  for (std::optional<Row> r = b.row(names); r; r = b.optional_row(names)) {
    for (std::size_t i = 0; i < r->size(); ++i) {
      if (!r->given(i)) continue;
      std::string field = r->text(i);
      std::transform(field.begin(), field.end(), field.begin(),
                     [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
      r->require(is_state_field(field), i, "expected a field of the states (" + known + ")");
      if (std::find(o.state_fields->begin(), o.state_fields->end(), field) == o.state_fields->end())
        o.state_fields->push_back(field);
    }
  }
  d.output_fields_where = b.where();
}

// *OUTPUT_NODE_HISTORY (abut's own; IMPETUS follows chosen nodes in node.out with *OUTPUT_NODE,
// whose card the seeds do not give): one `entype, enid` per row, as many rows as needed; the
// nodes of every entity are followed in nodes.csv at each history output.
void read_output_node_history(DeckReader& d, Block& b) {
  const std::vector<std::string> names{"entype", "enid"};
  for (std::optional<Row> r = b.row(names); r; r = b.optional_row(names)) {
    const EntityRef e =
        d.entity(*r, 0, 1,
                 {EntityType::Node, EntityType::NodeSet, EntityType::Part, EntityType::PartSet,
                  EntityType::All, EntityType::GeometryRegion});
    d.model.output.history_nodes.push_back(e);
    d.entity_references.push_back(e);
  }
}

// *CONTROL_BULK_VISCOSITY (abut's own; IMPETUS has no such command): LS-DYNA's keyword of the
// same name, its fields Q1 (quadratic) and Q2 (linear) with its defaults 1.5 and 0.06 (LS-DYNA
// Keyword User's Manual, *CONTROL_BULK_VISCOSITY; ANSYS's EDBVIS gives the same defaults). They
// apply to every deformable hexahedron; shells have no bulk viscosity. 0 and 0 switch it off,
// e.g. to compare an elastic impact with 1-D wave theory or with an implicit code.
void read_control_bulk_viscosity(DeckReader& d, Block& b) {
  once_per_deck(d.bulk_viscosity_where, b, "*CONTROL_BULK_VISCOSITY");
  const Row r = b.row({"q1", "q2"});
  BulkViscosity& q = d.model.bulk_viscosity;
  q.quadratic = r.number_or(0, q.quadratic);
  r.require(q.quadratic >= 0.0, 0, "expected a quadratic coefficient >= 0 (0: none)");
  q.linear = r.number_or(1, q.linear);
  r.require(q.linear >= 0.0, 1, "expected a linear coefficient >= 0 (0: none)");
}

// *CONTROL_P-ORDER (abut's own): what an order raised by *CHANGE_P-ORDER becomes, LAGRANGE (one
// Lagrange hexahedron of order p, IMPETUS's elements) or SPLIT (p x p x p one-point hexahedra on
// the same nodes).
void read_control_p_order(DeckReader& d, Block& b) {
  once_per_deck(d.p_order_form_where, b, "*CONTROL_P-ORDER");
  const Row r = b.row({"form"});
  const std::string form = r.word(0);
  r.require(form == "LAGRANGE" || form == "SPLIT", 0, "expected LAGRANGE or SPLIT");
  d.p_order_form = form == "LAGRANGE" ? POrderForm::lagrange : POrderForm::split;
}

}  // namespace abut::deck
