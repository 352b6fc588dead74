// *CONTACT_SMOOTHING (abut's own, after OptiStruct's SMOOTH continuation lines of CONTACT: SMSIDE,
// SMREG; seed 003): the sides of a surface-to-surface contact that meet as smooth surfaces fitted
// to their facets (smoothing.hpp; the solver side is src/solver/static/static_contacts.cpp).
#include "deck_reader.hpp"

namespace abut::deck {

void read_contact_smoothing(DeckReader& d, Block& b) {
  const Row r = b.row({"coid", "side", "region", "crease"});
  enum class Side { Main, Secondary, Both };
  const Side side = word_choice(r, 1, Side::Both,
                                {{"MAIN", Side::Main},
                                 {"MASTER", Side::Main},
                                 {"SECONDARY", Side::Secondary},
                                 {"SLAVE", Side::Secondary},
                                 {"BOTH", Side::Both}},
                                "MAIN (OptiStruct MASTER: surface 2), SECONDARY (SLAVE: surface 1) "
                                "or BOTH");
  if (!r.given(1)) r.fail(1, "expected the side to smooth: MAIN, SECONDARY or BOTH (SMSIDE)");
  // SMREG: ALL, or the setid of a *SET_FACE (OptiStruct's SURF id).
  std::optional<EntityRef> region;
  if (r.given(2) && r.word(2) != "ALL") {
    region = EntityRef{EntityType::FaceSet, d.other_id(r, 2), r.where(2)};
    d.entity_references.push_back(*region);
  }
  std::optional<double> crease;
  if (r.given(3)) {
    crease = r.number(3);
    r.require(*crease > 0.0 && *crease <= 180.0, 3, "expected a crease angle in (0, 180] degrees");
  }
  const SourceLocation where = r.where();
  // OptiStruct's repeated SMOOTH lines name a side (and a region) each: here BOTH.
  refine_contact(d, r, [side, crease, region, where](ContactSpec& c) {
    c.smoothing =
        ContactSpec::Smoothing{side != Side::Main, side != Side::Secondary, crease, region, where};
  });
}

}  // namespace abut::deck
