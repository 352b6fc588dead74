// *CONTACT_FRICTION: the tangential law of a *CONTACT (coid = ctid). Laws from Metafor's contact
// materials (seed 002: Coulomb static/dynamic, Tresca, sticking), OptiStruct's TYPE (seed 003:
// STICK, FREEZE) and Radioss /INTER/TYPE25 (seed 004: Ifric 1 to 3, Ifiltr/Xfreq).
#include "deck_reader.hpp"

namespace abut::deck {
namespace {

using Law = ContactSpec::FrictionLaw;

const char* law_name(Law law) {
  switch (law) {
    case Law::Impetus:
      return "mu of *CONTACT";
    case Law::None:
      return "NONE";
    case Law::Coulomb:
      return "COULOMB";
    case Law::Tresca:
      return "TRESCA";
    case Law::Stick:
      return "STICK";
    case Law::Freeze:
      return "FREEZE";
    case Law::Viscous:
      return "VISCOUS";
    case Law::Darmstad:
      return "DARMSTAD";
    case Law::Renard:
      return "RENARD";
  }
  return "";
}

// Row r's line, naming a field of the next line (that is missing).
SourceLocation line_of(const Row& r, const std::string& field) {
  SourceLocation where = r.where();
  where.field = field;
  return where;
}

// A field the law does not read must be empty (nothing is ignored silently).
void unused(const Row& r, std::size_t i, Law law, const std::string& why = "") {
  if (r.given(i)) {
    r.fail(i, std::string("law ") + law_name(law) + " does not use " + r.where(i).field + why +
                  ": leave it empty");
  }
}

// The coefficients of line 2, c1..c6 (0 when empty).
std::array<double, 6> coefficients(const std::optional<Row>& r2) {
  std::array<double, 6> c{};
  if (r2)
    for (std::size_t k = 0; k < 6; ++k) c[k] = r2->number_or(k, 0.0);
  return c;
}

// Radioss Ifric = 3 (seed 004, comment 7): C1 = mu_s, C2 = mu_d, C3 = mu_max, C4 = mu_min,
// C5 = Vcr1, C6 = Vcr2, every one required.
std::array<double, 6> renard_coefficients(const Row& r1, const std::optional<Row>& r2) {
  if (!r2) {
    throw InputError(line_of(r1, "c1"),
                     "Renard friction needs line 2: c1..c6 = mu_s, mu_d, mu_max, mu_min, Vcr1, "
                     "Vcr2");
  }
  std::array<double, 6> c{};
  for (std::size_t k = 0; k < 6; ++k) c[k] = r2->number(k);
  r2->require(c[3] >= 0.0, 3, "expected the minimum friction coefficient mu_min >= 0");
  r2->require(c[3] <= c[0] && c[0] <= c[2], 0,
              "expected the static coefficient mu_s between mu_min (c4) and mu_max (c3)");
  r2->require(c[3] <= c[1] && c[1] <= c[2], 1,
              "expected the dynamic coefficient mu_d between mu_min (c4) and mu_max (c3)");
  r2->require(c[4] > 0.0, 4, "expected the first critical sliding speed Vcr1 > 0");
  r2->require(c[5] > c[4], 5, "expected the second critical sliding speed Vcr2 > Vcr1 (c5)");
  return c;
}

// The law line's fields (*CONTACT_FRICTION has coid before them and pen_t among them).
struct LawFields {
  std::size_t law, mu_s, mu_d, filter, xfreq;
};

// A tangential law as read: the law, its coefficients and its filter.
struct LawCard {
  Law law = Law::None;
  double mu_s = 0.0, mu_d = 0.0;
  std::array<double, 6> c{};
  FrictionFilter filter;
};

// The law of line r (fields f) and of the optional line 2 of coefficients, r2. For a part pair
// (*CONTACT_FRICTION_PAIR) the modes of the whole contact, STICK and FREEZE, are refused.
LawCard read_law(const Row& r, const std::optional<Row>& r2, LawFields f, bool pair) {
  const std::string laws =
      pair
          ? "a friction law: NONE, COULOMB, TRESCA, VISCOUS, DARMSTAD or RENARD (or Radioss Ifric "
            "1, 2, 3)"
          : "a friction law: NONE, COULOMB, TRESCA, STICK, FREEZE, VISCOUS, DARMSTAD or RENARD (or "
            "Radioss Ifric 1, 2, 3)";
  r.require(r.given(f.law), f.law, "expected " + laws);
  LawCard card;
  const Law law = card.law = word_choice(r, f.law, Law::Coulomb,
                                         {{"NONE", Law::None},
                                          {"COULOMB", Law::Coulomb},
                                          {"TRESCA", Law::Tresca},
                                          {"STICK", Law::Stick},
                                          {"FREEZE", Law::Freeze},
                                          {"VISCOUS", Law::Viscous},
                                          {"DARMSTAD", Law::Darmstad},
                                          {"RENARD", Law::Renard},
                                          {"1", Law::Viscous},
                                          {"2", Law::Darmstad},
                                          {"3", Law::Renard}},
                                         laws);
  if (pair && (law == Law::Stick || law == Law::Freeze)) {
    r.fail(f.law, std::string("law ") + law_name(law) +
                      " ties the whole contact: give it with *CONTACT_FRICTION, not for a part "
                      "pair");
  }
  const auto no_line2 = [&r2, law]() {
    if (!r2) return;
    for (std::size_t k = 0; k < 6; ++k) unused(*r2, k, law, " (line 2)");
  };
  switch (law) {
    case Law::Impetus:
    case Law::None:
    case Law::Stick:
    case Law::Freeze:
      unused(r, f.mu_s, law);
      unused(r, f.mu_d, law);
      no_line2();
      break;
    case Law::Coulomb:
      card.mu_s = r.number(f.mu_s);
      r.require(card.mu_s >= 0.0, f.mu_s, "expected a static friction coefficient >= 0");
      card.mu_d = r.number_or(f.mu_d, card.mu_s);
      r.require(card.mu_d >= 0.0 && card.mu_d <= card.mu_s, f.mu_d,
                "expected a dynamic friction coefficient in [0, mu_s] (empty: mu_s)");
      no_line2();
      break;
    case Law::Tresca: {
      // Metafor TrescaContactMaterial: TRESCA_STA_M, TRESCA_DYN_M, TRESCA_K.
      const double m_s = r.number(f.mu_s);
      r.require(m_s >= 0.0, f.mu_s, "expected the static shear factor m_s >= 0");
      const double m_d = r.number_or(f.mu_d, m_s);
      r.require(m_d >= 0.0 && m_d <= m_s, f.mu_d,
                "expected the dynamic shear factor m_d in [0, m_s] (empty: m_s)");
      if (!r2 || !r2->given(0)) {
        throw InputError(r2 ? r2->where(0) : line_of(r, "c1"),
                         "Tresca friction needs the shear yield stress k in c1 (line 2)");
      }
      const double k = r2->number(0);
      r2->require(k > 0.0, 0, "expected the shear yield stress k > 0");
      for (std::size_t i = 1; i < 6; ++i) unused(*r2, i, law, " (c1 is k)");
      card.c = {m_s, m_d, k, 0.0, 0.0, 0.0};
      break;
    }
    case Law::Viscous:
    case Law::Darmstad:
      card.mu_s = r.number_or(f.mu_s, 0.0);  // Radioss Fric
      unused(r, f.mu_d, law, " (mu_s is Radioss Fric)");
      card.c = coefficients(r2);
      if (law == Law::Viscous && r2) unused(*r2, 5, law, " (Ifric 1 has C1..C5)");
      break;
    case Law::Renard:
      unused(r, f.mu_s, law, " (c1 is mu_s)");
      unused(r, f.mu_d, law, " (c2 is mu_d)");
      card.c = renard_coefficients(r, r2);
      break;
  }

  const std::int64_t kind = r.integer_or(f.filter, 0);
  r.require(kind >= 0 && kind <= 3, f.filter,
            "expected a friction filter 0 (none), 1 (simple), 2 (period) or 3 (cut-off frequency)");
  if (kind != 0 && law == Law::None) unused(r, f.filter, law);
  static constexpr FrictionFilter::Kind kinds[] = {
      FrictionFilter::Kind::None, FrictionFilter::Kind::Simple, FrictionFilter::Kind::Period,
      FrictionFilter::Kind::Frequency};
  card.filter.kind = kinds[kind];
  if (r.given(f.xfreq)) {
    if (kind == 0) r.fail(f.xfreq, "xfreq is used only with a friction filter (filter 1, 2 or 3)");
    card.filter.xfreq = r.number(f.xfreq);
    r.require(card.filter.xfreq > 0.0, f.xfreq, "expected a filtering coefficient > 0");
    r.require(kind != 1 || card.filter.xfreq <= 1.0, f.xfreq,
              "expected a filtering coefficient in (0, 1] for the simple filter (filter 1)");
  }
  return card;
}

}  // namespace

void read_contact_friction(DeckReader& d, Block& b) {
  const Row r = b.row({"coid", "law", "mu_s", "mu_d", "pen_t", "filter", "xfreq", "tie"});
  const std::optional<Row> r2 = b.optional_row({"c1", "c2", "c3", "c4", "c5", "c6"});
  const LawCard card = read_law(r, r2, {1, 2, 3, 5, 6}, false);
  const Law law = card.law;

  std::optional<double> pen_t;
  if (r.given(4)) {
    if (law == Law::None) unused(r, 4, law);
    pen_t = r.number(4);
    r.require(*pen_t > 0.0, 4,
              "expected a tangential penalty > 0 [stress/length] (empty: the normal penalty)");
  }
  // FREEZE as a penalty tie (springs, the default) or as an exact kinematic tie (a constraint:
  // OptiStruct implements FREEZE as a TIE kinematic condition, seed 003 comment 10).
  bool exact = false;
  if (r.given(7)) {
    r.require(law == Law::Freeze, 7,
              "tie is an option of law FREEZE (PENALTY or EXACT): leave it empty for law " +
                  std::string(law_name(law)));
    exact = word_choice(r, 7, false, {{"PENALTY", false}, {"EXACT", true}},
                        "a tie kind: PENALTY (springs) or EXACT (a kinematic constraint)");
    if (exact) {
      unused(r, 4, law, " with tie EXACT (no springs)");
      if (card.filter.kind != FrictionFilter::Kind::None)
        unused(r, 5, law, " with tie EXACT (no springs)");
    }
  }

  contact_place(d, r, "tangential_law", 1);
  contact_place(d, r, "freeze", 1);
  contact_place(d, r, "tangential_penalty", 4);
  contact_place(d, r, "friction_filter", 5);
  if (exact) d.model.sources.set(SourceEntity::Tie, d.other_id(r, 0), "exact", r.where(7));
  refine_contact(d, r, [r, card, pen_t, exact](ContactSpec& spec) {
    if (spec.friction != 0.0 || spec.friction_function.valid()) {
      r.fail(1, "give friction either as mu on *CONTACT or with *CONTACT_FRICTION, not both (" +
                    contact_at(spec) + " has mu on line 2)");
    }
    if (card.law == Law::Freeze && spec.stick_stress) {
      r.fail(1,
             "law FREEZE ties the surfaces from the start and cannot be combined with the sticking "
             "contact (sigma_stick) of " +
                 contact_at(spec) + ": remove one of them");
    }
    spec.friction_law = card.law;
    spec.exact_tie = exact;
    spec.mu_static = card.mu_s;
    spec.mu_dynamic = card.mu_d;
    spec.friction_c = card.c;
    spec.tangential_penalty = pen_t;
    spec.friction_filter = card.filter;
  });
}

// *CONTACT_FRICTION_PAIR (abut's own; Radioss fric_ID, /FRICTION, seed 004): the law between the
// facets of two part sets of contact coid, in place of its *CONTACT_FRICTION law.
//   coid, entype_1, enid_1, entype_2, enid_2
//   law, mu_s, mu_d, filter, xfreq
//   c1, c2, c3, c4, c5, c6                       (Tresca, Radioss laws)
void read_contact_friction_pair(DeckReader& d, Block& b) {
  const Row r = b.row({"coid", "entype_1", "enid_1", "entype_2", "enid_2"});
  const auto set = [&d, &r](std::size_t type, std::size_t id) -> std::optional<EntityRef> {
    if (!r.given(type) && !r.given(id)) return std::nullopt;
    if (!r.given(type)) {
      r.fail(type, "expected an entity type P, PS or ALL before " + r.where(id).field +
                       " (leave both empty for every part of the contact)");
    }
    const EntityRef e =
        d.entity(r, type, id, {EntityType::Part, EntityType::PartSet, EntityType::All});
    d.entity_references.push_back(e);
    return e;
  };
  ContactSpec::FrictionPair pair;
  pair.set1 = set(1, 2);
  pair.set2 = set(3, 4);
  const Row law_row = b.row({"law", "mu_s", "mu_d", "filter", "xfreq"});
  const std::optional<Row> r2 = b.optional_row({"c1", "c2", "c3", "c4", "c5", "c6"});
  const LawCard card = read_law(law_row, r2, {0, 1, 2, 3, 4}, true);
  pair.law = card.law;
  pair.mu_static = card.mu_s;
  pair.mu_dynamic = card.mu_d;
  pair.c = card.c;
  pair.filter = card.filter;
  pair.where = law_row.where(0);
  refine_contact(
      d, r, [pair](ContactSpec& spec) { spec.friction_pairs.push_back(pair); }, true);
}

}  // namespace abut::deck
