// *SURFACE INTERACTION with *SURFACE BEHAVIOR and *FRICTION, *CONTACT PAIR, and *CHANGE FRICTION
// and *CHANGE SURFACE BEHAVIOR in a step. The pairs become ContactSpecs in finish_contacts
// (inp_finish_steps.cpp), once every surface and interaction is known (a pair may name an
// interaction defined after it).
#include "inp_reader.hpp"

namespace abut::inp {
namespace {

const DataLine& only_line(const Reader& r, const Card& c, const std::string& what) {
  if (c.data.empty()) throw InputError(r.where(c), "the data line with " + what + " is missing");
  if (c.data.size() > 1) {
    throw InputError(r.where(Reader::loc(c.data[1]), c.keyword),
                     "unexpected data line: " + c.keyword + " takes one line (" + what + ")");
  }
  return c.data.front();
}

}  // namespace

void read_surface_interaction(Reader& r, const Card& c) {
  check_parameters(r, c, {{"NAME"}});
  no_data(r, c, "its properties follow as *SURFACE BEHAVIOR and *FRICTION");
  const std::string name = required_parameter(r, c, "NAME");
  const auto [it, inserted] = r.interaction_names.emplace(upper_name(name), r.interactions.size());
  if (!inserted) {
    throw InputError(r.where(c, "NAME"), "surface interaction " + name + " is already defined at " +
                                             r.at(r.interactions[it->second].defined));
  }
  r.interactions.push_back({name, r.loc(c), std::nullopt, std::nullopt});
  r.interaction = r.interactions.size() - 1;
}

void read_surface_behavior(Reader& r, const Card& c) {
  using Kind = ParameterRule::Kind;
  check_parameters(r, c,
                   {{"PRESSURE-OVERCLOSURE"},
                    {"NO SEPARATION", Kind::Unsupported},
                    {"AUGMENTED LAGRANGE", Kind::Unsupported},
                    {"PENALTY", Kind::Unsupported},
                    {"DIRECT", Kind::Unsupported}});
  if (!has_parameter(c, "PRESSURE-OVERCLOSURE")) {
    throw InputError(r.where(c),
                     "PRESSURE-OVERCLOSURE= is missing: give LINEAR, EXPONENTIAL, TABULAR or TIED "
                     "(hard contact, the Abaqus default, is not supported yet by abut)");
  }
  const std::string law =
      parameter_choice(r, c, "PRESSURE-OVERCLOSURE",
                       {"LINEAR", "EXPONENTIAL", "TABULAR", "TIED", "HARD", "SCALE FACTOR"}, "");
  Behaviour b;
  b.where = r.loc(c);
  if (law == "HARD" || law == "SCALE FACTOR") {
    throw InputError(r.where(c, "PRESSURE-OVERCLOSURE"),
                     "PRESSURE-OVERCLOSURE=" + law +
                         " is not supported yet by abut: use LINEAR (penalty slope), "
                         "EXPONENTIAL, TABULAR or TIED");
  }
  if (law == "TABULAR") {
    b.kind = Behaviour::Kind::Tabular;
    for (const DataLine& l : c.data) {
      const Fields f(r, c, l);
      f.at_most(2, "pressure, overclosure");
      const double pressure = f.number(0, "pressure");
      const double overclosure = f.number(1, "overclosure");
      if (!b.overclosure.empty() && !(overclosure > b.overclosure.back())) {
        f.fail("overclosure", "the overclosures of a table must increase from line to line");
      }
      b.pressure.push_back(pressure);
      b.overclosure.push_back(overclosure);
    }
    if (b.pressure.size() < 2) {
      throw InputError(r.where(c),
                       "a TABULAR pressure-overclosure law needs at least two "
                       "(pressure, overclosure) lines");
    }
  } else {
    const Fields f(r, c, only_line(r, c, law == "EXPONENTIAL" ? "c0, p0" : "the slope K"));
    if (law == "EXPONENTIAL") {
      b.kind = Behaviour::Kind::Exponential;
      f.at_most(2, "c0, p0");
      b.c0 = f.number(0, "c0");
      b.p0 = f.number(1, "p0");
      if (!(b.c0 > 0.0)) f.fail("c0", "expected the distance c0 > 0 (pressure 1% of p0 there)");
      if (!(b.p0 > 0.0)) f.fail("p0", "expected the pressure at zero distance p0 > 0");
    } else {
      b.kind = law == "TIED" ? Behaviour::Kind::Tied : Behaviour::Kind::Linear;
      f.at_most(law == "TIED" ? 1 : 3, law == "TIED" ? "K" : "K, sigma_inf, c0");
      b.slope = f.number(0, "K");
      if (!(b.slope > 0.0)) f.fail("K", "expected a penalty slope K > 0 [pressure/length]");
      if (f.given(1) || f.given(2)) {
        r.notes.push_back(r.at(f.loc()) +
                          ": sigma_inf and c0 of a LINEAR pressure-overclosure law (CalculiX "
                          "node-to-surface contact: tension at large clearance, clearance where "
                          "the contact element is made) are not used by abut: its penalty is "
                          "linear in the penetration and zero when open");
      }
    }
  }
  if (r.change_behaviour) {
    if (b.kind == Behaviour::Kind::Tied) {
      throw InputError(r.where(c, "PRESSURE-OVERCLOSURE"),
                       "changing a contact to TIED between steps is not supported yet by abut "
                       "(LINEAR, EXPONENTIAL and TABULAR are)");
    }
    r.step().changes.back().behaviour = std::move(b);
    r.change_behaviour = false;
    return;
  }
  r.interactions[*r.interaction].behaviour = std::move(b);
}

void read_friction(Reader& r, const Card& c) {
  using Kind = ParameterRule::Kind;
  check_parameters(r, c,
                   {{"ROUGH", Kind::Unsupported},
                    {"SLIP TOLERANCE", Kind::Unsupported},
                    {"ELASTIC SLIP", Kind::Unsupported},
                    {"LAGRANGE", Kind::Unsupported},
                    {"TAUMAX", Kind::Unsupported},
                    {"EXPONENTIAL DECAY", Kind::Unsupported},
                    {"ANISOTROPIC", Kind::Unsupported},
                    {"USER", Kind::Unsupported},
                    {"DEPENDENCIES", Kind::Unsupported}});
  const Fields f(r, c, only_line(r, c, "the friction coefficient and the stick slope"));
  f.at_most(2, "mu, stick slope");
  FrictionRecord fr;
  fr.where = f.loc();
  fr.mu = f.number(0, "mu");
  if (!(fr.mu >= 0.0)) f.fail("mu", "expected a friction coefficient >= 0");
  if (f.given(1)) {
    fr.stick_slope = f.number(1, "stick slope");
    if (!(*fr.stick_slope > 0.0)) {
      f.fail("stick slope", "expected a stick slope > 0 [stress/length]");
    }
  }
  if (r.change_friction) {
    r.step().changes.back().friction = fr;
    r.change_friction = false;
    return;
  }
  r.interactions[*r.interaction].friction = fr;
}

void read_contact_pair(Reader& r, const Card& c) {
  check_parameters(r, c,
                   {{"INTERACTION"},
                    {"TYPE"},
                    {"ADJUST"},
                    {"SMALL SLIDING", ParameterRule::Kind::Flag},
                    {"TIED", ParameterRule::Kind::Unsupported,
                     "use *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TIED"}});
  PairRecord p;
  p.card = r.loc(c);
  p.interaction = required_parameter(r, c, "INTERACTION");
  if (!has_parameter(c, "TYPE")) {
    throw InputError(r.where(c),
                     "TYPE= is missing: give TYPE=NODE TO SURFACE or TYPE=SURFACE TO SURFACE");
  }
  p.node_to_surface = parameter_choice(r, c, "TYPE", {"NODE TO SURFACE", "SURFACE TO SURFACE"},
                                       "") == "NODE TO SURFACE";
  if (const auto adjust = parameter_value(c, "ADJUST")) {
    const auto depth = inp_number(*adjust);
    if (!depth) {
      throw InputError(r.where(c, "ADJUST"),
                       "ADJUST=<node set> is not supported yet by abut: give a distance (slave "
                       "nodes closer to the master surface than it are moved onto it)");
    }
    if (!(*depth > 0.0)) {
      throw InputError(r.where(c, "ADJUST"),
                       "expected ADJUST= a distance > 0 (ADJUST=0, moving only the penetrating "
                       "nodes, is not supported yet by abut)");
    }
    p.adjust = *depth;
  }
  if (has_parameter(c, "SMALL SLIDING")) {
    if (p.node_to_surface) {
      p.small_sliding = true;
    } else {
      r.note(c,
             "SMALL SLIDING applies to node-to-surface contact only (CalculiX): ignored for "
             "this surface-to-surface pair");
    }
  }
  if (c.data.empty())
    throw InputError(r.where(c), "the line 'slave surface, master surface' is missing");
  for (const DataLine& l : c.data) {
    const Fields f(r, c, l);
    f.at_most(2, "slave surface, master surface");
    if (!f.given(0)) f.fail("slave", "the slave surface name is missing");
    if (!f.given(1)) f.fail("master", "the master surface name is missing");
    PairRecord pair = p;
    pair.slave = f.text(0);
    pair.master = f.text(1);
    pair.where = f.loc();
    r.pairs.push_back(std::move(pair));
  }
}

// *TIE, NAME=..., POSITION TOLERANCE=..., ADJUST=NO (CalculiX User's Manual, *TIE): the slave
// surface's nodes within the tolerance of the master faces are tied to them, as abut's exact tie.
// CalculiX moves the slave nodes onto the master surface by default (ADJUST=YES); abut keeps their
// initial gaps, so ADJUST=NO must be given.
void read_tie(Reader& r, const Card& c) {
  using Kind = ParameterRule::Kind;
  check_parameters(r, c,
                   {{"NAME"},
                    {"POSITION TOLERANCE"},
                    {"ADJUST"},
                    {"MULTISTAGE", Kind::Unsupported},
                    {"FLUID CYCLIC", Kind::Unsupported},
                    {"CYCLIC SYMMETRY", Kind::Unsupported}});
  TieRecord t;
  t.card = r.loc(c);
  t.name = required_parameter(r, c, "NAME");
  const auto adjust = parameter_value(c, "ADJUST");
  if (!adjust || upper_name(*adjust) != "NO") {
    throw InputError(
        r.where(c, "ADJUST"),
        "ADJUST=YES (CalculiX's default) moves the slave nodes onto the master "
        "surface, which abut's tie does not do yet: give ADJUST=NO (the tie then keeps "
        "each node's initial gap)");
  }
  if (const auto tolerance = parameter_value(c, "POSITION TOLERANCE")) {
    t.tolerance = inp_number(*tolerance);
    if (!t.tolerance || !(*t.tolerance > 0.0))
      throw InputError(r.where(c, "POSITION TOLERANCE"), "expected a position tolerance > 0");
  }
  if (c.data.size() != 1)
    throw InputError(r.where(c), "expected one line 'slave surface, master surface'");
  const Fields f(r, c, c.data.front());
  f.at_most(2, "slave surface, master surface");
  if (!f.given(0)) f.fail("slave", "the slave surface name is missing");
  if (!f.given(1)) f.fail("master", "the master surface name is missing");
  t.slave = f.text(0);
  t.master = f.text(1);
  t.where = f.loc();
  r.ties.push_back(std::move(t));
}

void read_change_friction(Reader& r, const Card& c) {
  check_parameters(r, c, {{"INTERACTION"}, {"RESET", ParameterRule::Kind::Unsupported}});
  no_data(r, c, "the new values follow on a *FRICTION card");
  ChangeRecord change;
  change.interaction = required_parameter(r, c, "INTERACTION");
  change.where = r.loc(c);
  r.step().changes.push_back(std::move(change));
  r.change_friction = true;
}

// *CHANGE SURFACE BEHAVIOR, INTERACTION=name, followed by the new *SURFACE BEHAVIOR (CalculiX
// User's Manual, *CHANGE SURFACE BEHAVIOR).
void read_change_surface_behavior(Reader& r, const Card& c) {
  check_parameters(r, c, {{"INTERACTION"}});
  no_data(r, c, "the new law follows on a *SURFACE BEHAVIOR card");
  ChangeRecord change;
  change.interaction = required_parameter(r, c, "INTERACTION");
  change.surface_behaviour = true;
  change.where = r.loc(c);
  r.step().changes.push_back(std::move(change));
  r.change_behaviour = true;
}

}  // namespace abut::inp
