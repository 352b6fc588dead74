// *CONTACT_THERMAL (abut's own): the heat conductance law of a *CONTACT other than the function of
// fid_thermal, and the share of the friction heat (fric_heat) that goes to surface 1. Laws:
// Metafor's pressure power law (seed 002), OptiStruct's open/closed conductance (seed 003) and
// Radioss's distance-dependent conductance (seed 004); laws/thermal.hpp has the formulas.
#include "deck_reader.hpp"

namespace abut::deck {

void read_contact_thermal(DeckReader& d, Block& b) {
  using Law = ContactSpec::Conductance::Law;
  const Row r = b.row({"coid", "law", "h_1", "h_2", "h_3", "f_heat"});
  const std::int64_t coid = d.other_id(r, 0);
  std::optional<ContactSpec::Conductance> conductance;
  if (r.given(1)) {
    ContactSpec::Conductance c;
    c.law = word_choice(r, 1, Law::Pressure,
                        {{"PRESSURE", Law::Pressure},
                         {"OPEN_CLOSED", Law::OpenClosed},
                         {"DISTANCE", Law::Distance}},
                        "PRESSURE (h = h_c0 (p / H_v)^w), OPEN_CLOSED (h_closed, h_open) or "
                        "DISTANCE (h = fid(gap))");
    switch (c.law) {
      case Law::Pressure:
        c.nominal = r.number(2);
        r.require(c.nominal >= 0.0, 2, "expected a nominal conductance h_c0 >= 0");
        c.hardness = r.number(3);
        r.require(c.hardness > 0.0, 3, "expected a hardness H_v > 0 [stress]");
        c.exponent = r.number_or(4, 1.0);
        r.require(c.exponent >= 0.0, 4, "expected an exponent w >= 0");
        break;
      case Law::OpenClosed:
        c.closed = r.number(2);
        r.require(c.closed >= 0.0, 2, "expected a closed-contact conductance >= 0");
        c.open = r.number_or(3, 0.0);
        r.require(c.open >= 0.0, 3, "expected an open-contact conductance >= 0");
        if (r.given(4)) r.fail(4, "law OPEN_CLOSED takes two values (h_closed, h_open)");
        break;
      case Law::Distance: {
        const auto fid = d.optional_other_id(r, 2);
        if (!fid)
          r.fail(2,
                 "law DISTANCE needs the *CURVE or *FUNCTION fid that gives the conductance as a "
                 "function of the gap");
        d.bind_function(*fid, r.where(2), [coid](Model& m, FunctionRef f) {
          for (ContactSpec& contact : m.contacts)
            if (contact.id == coid) contact.distance_conductance = f;
        });
        if (r.given(3) || r.given(4)) r.fail(r.given(3) ? 3 : 4, "law DISTANCE takes fid only");
        break;
      }
    }
    conductance = c;
  } else if (r.given(2) || r.given(3) || r.given(4)) {
    r.fail(1, "the values h_1, h_2, h_3 need a law (PRESSURE, OPEN_CLOSED or DISTANCE)");
  }
  const double share = r.number_or(5, 0.5);
  r.require(share >= 0.0 && share <= 1.0, 5,
            "expected the share of the friction heat going to surface 1 in [0, 1]");
  contact_place(d, r, "conductance", 1);
  refine_contact(d, r, [conductance, share](ContactSpec& c) {
    c.conductance = conductance;
    c.friction_heat_to_surface1 = share;
  });
}

}  // namespace abut::deck
