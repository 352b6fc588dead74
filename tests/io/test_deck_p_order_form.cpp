// *CONTROL_P-ORDER (abut's own): what *CHANGE_P-ORDER makes of a hex, one Lagrange hexahedron of
// order p (LAGRANGE) or p x p x p linear hexahedra (SPLIT, the default); its errors at their file
// and line.
#include <gmock/gmock.h>

#include <string>

#include "test_deck_helpers.hpp"

namespace abut {
namespace {

using testing::error_of;
using ::testing::HasSubstr;
using testing::model_of;
using testing::with_box;

TEST(DeckPOrderForm, SplitByDefaultLagrangeOnRequest) {
  const Model split = model_of(with_box("*CHANGE_P-ORDER\nP, 1, 2\n"));
  EXPECT_EQ(split.mesh.hex_count(), 4u * 8u);
  EXPECT_TRUE(split.mesh.cells.empty());
  for (const std::string form : {"LAGRANGE", "lagrange"}) {
    const Model lagrange =
        model_of(with_box("*CONTROL_P-ORDER\n" + form + "\n*CHANGE_P-ORDER\nP, 1, 3\n"));
    EXPECT_EQ(lagrange.mesh.hex_count(), 0u);
    ASSERT_EQ(lagrange.mesh.cells.size(), 1u);
    EXPECT_EQ(lagrange.mesh.cells[0].type, CellType::hex64);
    EXPECT_EQ(lagrange.mesh.cells[0].size(), 4u);
    EXPECT_EQ(lagrange.mesh.nodes.size(), 7u * 7u * 4u);  // the lattice of the split
  }
  // Without *CHANGE_P-ORDER the keyword changes nothing.
  EXPECT_EQ(model_of(with_box("*CONTROL_P-ORDER\nLAGRANGE\n")).mesh.hex_count(), 4u);
}

TEST(DeckPOrderForm, Errors) {
  InputError e = error_of(with_box("*CONTROL_P-ORDER\nCUBIC\n"));
  EXPECT_EQ(e.where().line, 14u);
  EXPECT_EQ(e.where().field, "form");
  EXPECT_THAT(e.message(), HasSubstr("expected LAGRANGE or SPLIT"));
  e = error_of(with_box("*CONTROL_P-ORDER\nSPLIT\n*CONTROL_P-ORDER\nSPLIT\n"));
  EXPECT_EQ(e.where().line, 15u);
  EXPECT_THAT(e.message(), HasSubstr("already has a *CONTROL_P-ORDER at t.k:13"));
  EXPECT_THAT(error_of(with_box("*CONTROL_P-ORDER\n")).message(), HasSubstr("missing data line"));
  EXPECT_EQ(error_of(with_box("*CONTROL_P-ORDER\nSPLIT, 1\n")).where().line, 14u);
}

}  // namespace
}  // namespace abut
