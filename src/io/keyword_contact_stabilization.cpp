// *CONTACT_STABILIZATION (abut's own, after OptiStruct's CNTSTB bulk entry: SCALE, S0, S1, TFRAC,
// LMTGAP; seed 003 comment 7): viscous stabilization of a contact's nearby surfaces in static
// steps (laws/stabilization.hpp; the solver side is src/solver/static/static_contacts.cpp).
#include "deck_reader.hpp"

namespace abut::deck {

void read_contact_stabilization(DeckReader& d, Block& b) {
  const Row r = b.row({"coid", "scale", "s0", "s1", "tfrac", "lmtgap"});
  ContactSpec::Stabilization s;
  s.scale = r.number_or(1, 1.0);
  r.require(s.scale > 0.0, 1, "expected a scale > 0 (1: abut's damping coefficient)");
  s.start = r.number_or(2, 1.0);
  r.require(s.start >= 0.0, 2, "expected a factor >= 0 at the start of each static step");
  s.end = r.number_or(3, 0.0);
  r.require(s.end >= 0.0, 3, "expected a factor >= 0 at the end of each static step");
  s.tangent_fraction = r.number_or(4, 1.0);
  r.require(s.tangent_fraction >= 0.0, 4, "expected a tangential fraction >= 0");
  if (r.given(5)) {
    s.range = r.number(5);
    r.require(*s.range > 0.0, 5, "expected an opening > 0 beyond which nothing is damped");
  }
  s.where = r.where();
  refine_contact(d, r, [s](ContactSpec& c) { c.stabilization = s; });
}

}  // namespace abut::deck
