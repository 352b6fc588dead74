// *CONTACT_DEPENDENCY: Metafor's parameter dependencies (seed 002, the "Dependency" column of its
// contact materials) on the laws of a *CONTACT: a parameter is its value times a *CURVE or
// *FUNCTION of the time (TM) or of the penetration (GD) (laws/dependency.hpp).
//   PFAC  TIME  PEN_NORMALE (TM): the normal law's pressure times f(t)
//   MU_S  TIME  COEF_FROT_STA, TRESCA_STA_M (TM): the static coefficient or shear factor
//   MU_D  TIME  COEF_FROT_DYN, TRESCA_DYN_M (TM): the dynamic one
//   K     TIME  TRESCA_K: the shear yield stress (seed 002 gives it no dependency; abut allows TM)
//   PEN_T TIME  PEN_TANGENT (TM); PEN_T GAP: PEN_TANGENT (GD) of the variable-penalty materials
// A gap-dependent normal penalty is *CONTACT_NORMAL law CURVE (it gives the pressure itself).
#include "deck_reader.hpp"

namespace abut::deck {
namespace {

using Parameter = ContactSpec::Dependency::Parameter;

const char* name_of(Parameter p) { return ContactSpec::Dependency{p, false, {}}.name(); }

FunctionRef ContactSpec::*member_of(Parameter p, bool gap) {
  switch (p) {
    case Parameter::Pfac:
      return &ContactSpec::pfac_in_time;
    case Parameter::MuStatic:
      return &ContactSpec::mu_static_in_time;
    case Parameter::MuDynamic:
      return &ContactSpec::mu_dynamic_in_time;
    case Parameter::Yield:
      return &ContactSpec::yield_in_time;
    case Parameter::PenT:
      return gap ? &ContactSpec::pen_t_of_gap : &ContactSpec::pen_t_in_time;
  }
  return nullptr;
}

}  // namespace

void read_contact_dependency(DeckReader& d, Block& b) {
  const Row r = b.row({"coid"});
  const std::int64_t coid = d.other_id(r, 0);
  const std::vector<std::string> names = {"parameter", "variable", "fid"};
  std::vector<ContactSpec::Dependency> entries;
  std::optional<Row> row = b.row(names);
  for (; row; row = b.optional_row(names)) {
    row->require(row->given(0), 0, "expected a parameter PFAC, MU_S, MU_D, K or PEN_T");
    const Parameter p = word_choice(*row, 0, Parameter::Pfac,
                                    {{"PFAC", Parameter::Pfac},
                                     {"PEN_NORMALE", Parameter::Pfac},
                                     {"MU_S", Parameter::MuStatic},
                                     {"COEF_FROT_STA", Parameter::MuStatic},
                                     {"TRESCA_STA_M", Parameter::MuStatic},
                                     {"MU_D", Parameter::MuDynamic},
                                     {"COEF_FROT_DYN", Parameter::MuDynamic},
                                     {"TRESCA_DYN_M", Parameter::MuDynamic},
                                     {"K", Parameter::Yield},
                                     {"TRESCA_K", Parameter::Yield},
                                     {"PEN_T", Parameter::PenT},
                                     {"PEN_TANGENT", Parameter::PenT}},
                                    "a parameter PFAC, MU_S, MU_D, K or PEN_T (or Metafor's name)");
    row->require(row->given(1), 1, "expected the variable: TIME (or TM) or GAP (or GD)");
    const bool gap =
        word_choice(*row, 1, false, {{"TIME", false}, {"TM", false}, {"GAP", true}, {"GD", true}},
                    "TIME (or TM) or GAP (or GD)");
    if (gap && p == Parameter::Pfac) {
      row->fail(1,
                "a gap-dependent normal penalty is *CONTACT_NORMAL law CURVE, whose curve gives "
                "the pressure as a function of the penetration (tabulate PEN_NORMALE(d) x d)");
    }
    if (gap && p != Parameter::PenT) {
      row->fail(1, std::string("only PEN_T depends on the gap (Metafor GD); ") + name_of(p) +
                       " takes TIME");
    }
    for (const ContactSpec::Dependency& e : entries)
      if (e.parameter == p && e.gap == gap) {
        row->fail(0, std::string(name_of(p)) + (gap ? " GAP" : " TIME") +
                         " is given twice: give each dependency once");
      }
    const std::int64_t fid = d.other_id(*row, 2);
    FunctionRef ContactSpec::*member = member_of(p, gap);
    d.bind_function(fid, row->where(2), [coid, member](Model& m, FunctionRef f) {
      for (ContactSpec& c : m.contacts)
        if (c.id == coid) c.*member = f;  // a missing contact is reported at coid
    });
    entries.push_back({p, gap, row->where(0)});
  }
  d.model.sources.set(SourceEntity::Contact, d.other_id(r, 0), "dependencies", r.where());
  refine_contact(d, r, [entries](ContactSpec& c) { c.dependencies = entries; });
}

// Once every keyword of the contact is in: a dependency must have a parameter to act on.
void check_contact_dependency(const ContactSpec& c) {
  using Law = ContactSpec::FrictionLaw;
  const Law law = c.friction_law;
  const bool frictionless = law == Law::None || (law == Law::Impetus && c.friction == 0.0 &&
                                                 !c.friction_function.valid());
  for (const ContactSpec::Dependency& e : c.dependencies) {
    const auto fail = [&](const std::string& why) {
      throw InputError(e.where, std::string(e.name()) + " of *CONTACT_DEPENDENCY: " + why + " (" +
                                    contact_at(c) + ")");
    };
    if (e.parameter == Parameter::Pfac && law == Law::Freeze)
      fail("law FREEZE ties the points with the constant penalty; remove the dependency");
    if ((e.parameter == Parameter::MuStatic || e.parameter == Parameter::MuDynamic) &&
        law != Law::Coulomb && law != Law::Tresca) {
      fail(
          "a time-dependent friction coefficient needs *CONTACT_FRICTION COULOMB (mu_s, mu_d) or "
          "TRESCA (m_s, m_d); for mu of *CONTACT use mu = fcn(fid) of t");
    }
    if (e.parameter == Parameter::Yield && law != Law::Tresca)
      fail("K is the shear yield stress of *CONTACT_FRICTION TRESCA");
    if (e.parameter == Parameter::PenT && (frictionless || law == Law::Freeze)) {
      fail(std::string("the contact has no tangential spring to scale (friction ") +
           (law == Law::Freeze ? "FREEZE ties with the constant penalty)" : "NONE)"));
    }
  }
}

}  // namespace abut::deck
