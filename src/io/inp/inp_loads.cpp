// *AMPLITUDE, *EQUATION, *BOUNDARY, *CLOAD and *DLOAD, kept card by card with their OP and
// AMPLITUDE; finish_steps (inp_finish_steps.cpp) resolves OP=NEW/MOD over the steps.
#include "../deck_text.hpp"
#include "inp_reader.hpp"

namespace abut::inp {
namespace {

using Kind = ParameterRule::Kind;

// A degree of freedom 1..3 of a solid node -> 0..2; `what` names the field.
int translation_dof(const Fields& f, std::size_t i, const std::string& what) {
  const std::int64_t dof = f.integer(i, what);
  if (dof >= 1 && dof <= 3) return static_cast<int>(dof - 1);
  if (dof >= 4 && dof <= 6) {
    f.fail(what,
           "degrees of freedom 4 to 6 are rotations, which the nodes of solid elements "
           "(C3D8) do not have: use 1 to 3 (x, y, z)");
  }
  if (dof == 11) f.fail(what, "temperature (degree of freedom 11) is not supported yet by abut");
  f.fail(what, "expected a degree of freedom 1, 2 or 3 (x, y, z), got " + std::to_string(dof));
}

LoadCard load_card(Reader& r, const Card& c, LoadKind kind) {
  LoadCard card;
  card.kind = kind;
  card.op_new = parameter_choice(r, c, "OP", {"MOD", "NEW"}, "MOD") == "NEW";
  card.amplitude = parameter_value(c, "AMPLITUDE").value_or("");
  card.where = r.loc(c);
  // OP=NEW without data lines removes every condition of this kind (CalculiX, *CLOAD: "OP=NEW
  // ... all previous concentrated loads are removed").
  if (c.data.empty() && !card.op_new) {
    throw InputError(r.where(c), c.keyword +
                                     " has no data lines (only OP=NEW may have none: it "
                                     "removes the previous ones)");
  }
  return card;
}

void store(Reader& r, LoadCard&& card) {
  if (r.in_step) {
    r.step().loads.push_back(std::move(card));
  } else {
    r.model_loads.push_back(std::move(card));
  }
}

}  // namespace

void read_amplitude(Reader& r, const Card& c) {
  check_parameters(r, c,
                   {{"NAME"},
                    {"TIME"},
                    {"DEFINITION"},
                    {"VALUE"},
                    {"USER", Kind::Unsupported, "user subroutines"},
                    {"SMOOTH", Kind::Unsupported, "abut interpolates amplitudes linearly"},
                    {"SHIFTX", Kind::Unsupported},
                    {"SHIFTY", Kind::Unsupported},
                    {"SCALEX", Kind::Unsupported},
                    {"SCALEY", Kind::Unsupported}});
  AmplitudeRecord a;
  a.name = required_parameter(r, c, "NAME");
  a.where = r.loc(c);
  a.total_time =
      parameter_choice(r, c, "TIME", {"STEP TIME", "TOTAL TIME"}, "STEP TIME") == "TOTAL TIME";
  if (parameter_choice(r, c, "DEFINITION",
                       {"TABULAR", "EQUALLY SPACED", "PERIODIC", "MODULATED", "DECAY",
                        "SMOOTH STEP", "SOLUTION DEPENDENT", "BUBBLE", "USER"},
                       "TABULAR") != "TABULAR") {
    throw InputError(r.where(c, "DEFINITION"),
                     "only DEFINITION=TABULAR amplitudes (time, value pairs) are supported yet");
  }
  if (parameter_choice(r, c, "VALUE", {"RELATIVE", "ABSOLUTE"}, "RELATIVE") != "RELATIVE") {
    throw InputError(r.where(c, "VALUE"),
                     "VALUE=ABSOLUTE is not supported yet by abut: amplitudes scale the values "
                     "of the load cards (VALUE=RELATIVE)");
  }
  const auto [it, inserted] = r.amplitude_names.emplace(upper_name(a.name), r.amplitudes.size());
  if (!inserted) {
    throw InputError(r.where(c, "NAME"), "amplitude " + a.name + " is already defined at " +
                                             r.at(r.amplitudes[it->second].where));
  }
  for (const DataLine& l : c.data) {
    const Fields f(r, c, l);
    std::size_t n = f.size();
    while (n > 0 && !f.given(n - 1)) --n;  // trailing commas
    if (n % 2 != 0) f.fail("", "expected time, value pairs (an even number of fields)");
    for (std::size_t i = 0; i < n; i += 2) {
      const double t = f.number(i, "time");
      const double v = f.number(i + 1, "amplitude");
      if (!a.time.empty() && !(t > a.time.back())) {
        f.fail("time", "the times of an amplitude must increase");
      }
      a.time.push_back(t);
      a.value.push_back(v);
    }
  }
  if (a.time.empty()) throw InputError(r.where(c), "the amplitude has no (time, value) pairs");
  r.amplitudes.push_back(std::move(a));
}

void read_equation(Reader& r, const Card& c) {
  check_parameters(r, c,
                   {{"REMOVE", Kind::Unsupported},
                    {"REMOVE ALL", Kind::Unsupported},
                    {"INPUT", Kind::Unsupported, "use *INCLUDE"}});
  std::size_t expected = 0;  // terms still to come for r.equations.back()
  for (const DataLine& l : c.data) {
    const Fields f(r, c, l);
    std::size_t n = f.size();
    while (n > 0 && !f.given(n - 1)) --n;
    if (expected == 0) {
      f.at_most(1, "the number of terms of the equation");
      const std::int64_t terms = f.integer(0, "number of terms");
      if (terms < 1) f.fail("number of terms", "expected at least one term");
      expected = static_cast<std::size_t>(terms);
      r.equations.push_back({{}, f.loc()});
      continue;
    }
    if (n % 3 != 0) f.fail("", "expected terms 'node, degree of freedom, coefficient'");
    if (n / 3 > expected) {
      f.fail("", "more terms than the equation's count (" +
                     std::to_string(r.equations.back().terms.size() + expected) + ")");
    }
    for (std::size_t i = 0; i < n; i += 3) {
      EquationRecord::Term t;
      const Item node = f.item(i, "node");
      if (!node.name.empty()) {
        f.fail("node",
               "node sets in *EQUATION are not supported yet by abut: write one "
               "equation per node");
      }
      t.node = node.id;
      t.dof = translation_dof(f, i + 1, "dof");
      t.coefficient = f.number(i + 2, "coefficient");
      t.where = f.loc();
      if (r.equations.back().terms.empty() && t.coefficient == 0.0) {
        f.fail("coefficient",
               "the first term is the dependent one: its coefficient must not "
               "be 0");
      }
      r.equations.back().terms.push_back(t);
      --expected;
    }
  }
  if (expected != 0) {
    throw InputError(
        r.where(r.equations.back().where, c.keyword),
        "the equation has fewer terms than its count: " + std::to_string(expected) + " missing");
  }
}

void read_boundary(Reader& r, const Card& c) {
  check_parameters(r, c,
                   {{"OP"},
                    {"AMPLITUDE"},
                    {"TYPE"},
                    {"FIXED", Kind::Unsupported},
                    {"USER", Kind::Unsupported, "user subroutines"},
                    {"SUBMODEL", Kind::Unsupported},
                    {"STEP", Kind::Unsupported},
                    {"MASS FLOW", Kind::Unsupported},
                    {"LOAD CASE", Kind::Unsupported},
                    {"TIME DELAY", Kind::Unsupported}});
  if (parameter_choice(r, c, "TYPE", {"DISPLACEMENT", "VELOCITY", "ACCELERATION"},
                       "DISPLACEMENT") != "DISPLACEMENT") {
    throw InputError(r.where(c, "TYPE"),
                     "only displacements (TYPE=DISPLACEMENT) are supported "
                     "yet in the static steps of abut");
  }
  LoadCard card = load_card(r, c, LoadKind::Boundary);
  for (const DataLine& l : c.data) {
    const Fields f(r, c, l);
    f.at_most(4, "node or node set, first dof, last dof, value");
    LoadLine line;
    line.target = f.item(0, "node");
    const std::string label = deck::upper(f.text(1));
    // Abaqus boundary types; on solid nodes only their translations count.
    struct Type {
      const char* name;
      int first, last, second_first, second_last;
    };
    static const Type types[] = {{"ENCASTRE", 0, 2, -1, -1}, {"PINNED", 0, 2, -1, -1},
                                 {"XSYMM", 0, 0, -1, -1},    {"YSYMM", 1, 1, -1, -1},
                                 {"ZSYMM", 2, 2, -1, -1},    {"XASYMM", 1, 2, -1, -1},
                                 {"YASYMM", 0, 0, 2, 2},     {"ZASYMM", 0, 1, -1, -1}};
    const Type* type = nullptr;
    for (const Type& t : types)
      if (label == t.name) type = &t;
    if (type) {
      f.at_most(2, "node or node set, boundary type");
      line.first = type->first;
      line.last = type->last;
      card.lines.push_back(line);
      if (type->second_first >= 0) {
        line.first = type->second_first;
        line.last = type->second_last;
        card.lines.push_back(line);
      }
      continue;
    }
    line.first = translation_dof(f, 1, "first dof");
    line.last = f.given(2) ? translation_dof(f, 2, "last dof") : line.first;
    if (line.last < line.first) f.fail("last dof", "expected last dof >= first dof");
    line.value = f.number_or(3, "value", 0.0);
    card.lines.push_back(line);
  }
  store(r, std::move(card));
}

void read_cload(Reader& r, const Card& c) {
  check_parameters(r, c,
                   {{"OP"},
                    {"AMPLITUDE"},
                    {"FOLLOWER", Kind::Unsupported},
                    {"USER", Kind::Unsupported, "user subroutines"},
                    {"SUBMODEL", Kind::Unsupported},
                    {"STEP", Kind::Unsupported},
                    {"SECTOR", Kind::Unsupported},
                    {"LOAD CASE", Kind::Unsupported},
                    {"TIME DELAY", Kind::Unsupported}});
  LoadCard card = load_card(r, c, LoadKind::Force);
  for (const DataLine& l : c.data) {
    const Fields f(r, c, l);
    f.at_most(3, "node or node set, dof, magnitude");
    LoadLine line;
    line.target = f.item(0, "node");
    line.first = line.last = translation_dof(f, 1, "dof");
    line.value = f.number(2, "magnitude");
    card.lines.push_back(line);
  }
  store(r, std::move(card));
}

void read_dload(Reader& r, const Card& c) {
  check_parameters(r, c,
                   {{"OP"},
                    {"AMPLITUDE"},
                    {"FOLLOWER", Kind::Unsupported},
                    {"SECTOR", Kind::Unsupported},
                    {"LOAD CASE", Kind::Unsupported},
                    {"TIME DELAY", Kind::Unsupported}});
  LoadCard card = load_card(r, c, LoadKind::Pressure);
  for (const DataLine& l : c.data) {
    const Fields f(r, c, l);
    LoadLine line;
    line.target = f.item(0, "element");
    const std::string label = deck::upper(f.text(1));
    if (label.size() != 2 || label[0] != 'P' || label[1] < '1' || label[1] > '6') {
      f.fail("load type",
             "load type '" + f.text(1) +
                 "' is not supported yet by abut: it reads uniform pressures P1 to P6 on the "
                 "faces S1 to S6 of solid elements (gravity, centrifugal, edge and non-uniform "
                 "loads are not supported yet)");
    }
    f.at_most(3, "element or element set, Pn, magnitude");
    line.first = line.last = label[1] - '1';
    line.value = f.number(2, "magnitude");
    card.lines.push_back(line);
  }
  store(r, std::move(card));
}

}  // namespace abut::inp
