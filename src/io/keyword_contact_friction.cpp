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

}  // namespace

void read_contact_friction(DeckReader& d, Block& b) {
  const Row r = b.row({"coid", "law", "mu_s", "mu_d", "pen_t", "filter", "xfreq", "tie"});
  const std::string laws =
      "a friction law: NONE, COULOMB, TRESCA, STICK, FREEZE, VISCOUS, DARMSTAD or RENARD (or "
      "Radioss Ifric 1, 2, 3)";
  r.require(r.given(1), 1, "expected " + laws);
  const Law law = word_choice(r, 1, Law::Coulomb,
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
  const std::optional<Row> r2 = b.optional_row({"c1", "c2", "c3", "c4", "c5", "c6"});
  const auto no_line2 = [&r2, law]() {
    if (!r2) return;
    for (std::size_t k = 0; k < 6; ++k) unused(*r2, k, law, " (line 2)");
  };

  double mu_s = 0.0, mu_d = 0.0;
  std::array<double, 6> c{};
  switch (law) {
    case Law::Impetus:
    case Law::None:
    case Law::Stick:
    case Law::Freeze:
      unused(r, 2, law);
      unused(r, 3, law);
      no_line2();
      break;
    case Law::Coulomb:
      mu_s = r.number(2);
      r.require(mu_s >= 0.0, 2, "expected a static friction coefficient >= 0");
      mu_d = r.number_or(3, mu_s);
      r.require(mu_d >= 0.0 && mu_d <= mu_s, 3,
                "expected a dynamic friction coefficient in [0, mu_s] (empty: mu_s)");
      no_line2();
      break;
    case Law::Tresca: {
      // Metafor TrescaContactMaterial: TRESCA_STA_M, TRESCA_DYN_M, TRESCA_K.
      const double m_s = r.number(2);
      r.require(m_s >= 0.0, 2, "expected the static shear factor m_s >= 0");
      const double m_d = r.number_or(3, m_s);
      r.require(m_d >= 0.0 && m_d <= m_s, 3,
                "expected the dynamic shear factor m_d in [0, m_s] (empty: m_s)");
      if (!r2 || !r2->given(0)) {
        throw InputError(r2 ? r2->where(0) : line_of(r, "c1"),
                         "Tresca friction needs the shear yield stress k in c1 (line 2)");
      }
      const double k = r2->number(0);
      r2->require(k > 0.0, 0, "expected the shear yield stress k > 0");
      for (std::size_t i = 1; i < 6; ++i) unused(*r2, i, law, " (c1 is k)");
      c = {m_s, m_d, k, 0.0, 0.0, 0.0};
      break;
    }
    case Law::Viscous:
    case Law::Darmstad:
      mu_s = r.number_or(2, 0.0);  // Radioss Fric
      unused(r, 3, law, " (mu_s is Radioss Fric)");
      c = coefficients(r2);
      if (law == Law::Viscous && r2) unused(*r2, 5, law, " (Ifric 1 has C1..C5)");
      break;
    case Law::Renard:
      unused(r, 2, law, " (c1 is mu_s)");
      unused(r, 3, law, " (c2 is mu_d)");
      c = renard_coefficients(r, r2);
      break;
  }

  std::optional<double> pen_t;
  if (r.given(4)) {
    if (law == Law::None) unused(r, 4, law);
    pen_t = r.number(4);
    r.require(*pen_t > 0.0, 4,
              "expected a tangential penalty > 0 [stress/length] (empty: the normal penalty)");
  }
  FrictionFilter filter;
  const std::int64_t kind = r.integer_or(5, 0);
  r.require(kind >= 0 && kind <= 3, 5,
            "expected a friction filter 0 (none), 1 (simple), 2 (period) or 3 (cut-off frequency)");
  if (kind != 0 && law == Law::None) unused(r, 5, law);
  static constexpr FrictionFilter::Kind kinds[] = {
      FrictionFilter::Kind::None, FrictionFilter::Kind::Simple, FrictionFilter::Kind::Period,
      FrictionFilter::Kind::Frequency};
  filter.kind = kinds[kind];
  if (r.given(6)) {
    if (kind == 0) r.fail(6, "xfreq is used only with a friction filter (filter 1, 2 or 3)");
    filter.xfreq = r.number(6);
    r.require(filter.xfreq > 0.0, 6, "expected a filtering coefficient > 0");
    r.require(kind != 1 || filter.xfreq <= 1.0, 6,
              "expected a filtering coefficient in (0, 1] for the simple filter (filter 1)");
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
      if (kind != 0) unused(r, 5, law, " with tie EXACT (no springs)");
    }
  }

  refine_contact(d, r, [r, law, mu_s, mu_d, c, pen_t, filter, exact](ContactSpec& spec) {
    if (spec.friction != 0.0 || spec.friction_function.valid()) {
      r.fail(1, "give friction either as mu on *CONTACT or with *CONTACT_FRICTION, not both (" +
                    contact_at(spec) + " has mu on line 2)");
    }
    if (law == Law::Freeze && spec.stick_stress) {
      r.fail(1,
             "law FREEZE ties the surfaces from the start and cannot be combined with the sticking "
             "contact (sigma_stick) of " +
                 contact_at(spec) + ": remove one of them");
    }
    spec.friction_law = law;
    spec.exact_tie = exact;
    spec.mu_static = mu_s;
    spec.mu_dynamic = mu_d;
    spec.friction_c = c;
    spec.tangential_penalty = pen_t;
    spec.friction_filter = filter;
    spec.friction_where = r.where();
  });
}

}  // namespace abut::deck
