// *CONTROL_BULK_VISCOSITY (abut's own in the IMPETUS dialect; LS-DYNA's keyword of that name, its
// Q1 and Q2 with LS-DYNA's defaults 1.5 and 0.06): defaults, values, and its errors, each at its
// file and line: a negative coefficient, a second keyword, a static deck.
#include <gmock/gmock.h>

#include <string>

#include "abut/element/solid_block.hpp"
#include "test_deck_helpers.hpp"

namespace abut {
namespace {

using testing::error_of;
using ::testing::HasSubstr;
using testing::kBoxModel;
using testing::model_of;
using testing::with_box;

TEST(DeckBulkViscosity, WithoutTheKeywordTheHexahedraKeepLsDynasDefaults) {
  const Model m = model_of(kBoxModel);
  // One definition of the default: the element's constants, which are LS-DYNA's.
  EXPECT_EQ(m.bulk_viscosity.quadratic, SolidBlock::kDefaultBulkViscosityQuadratic);
  EXPECT_EQ(m.bulk_viscosity.linear, SolidBlock::kDefaultBulkViscosityLinear);
  EXPECT_EQ(m.bulk_viscosity.quadratic, 1.5);
  EXPECT_EQ(m.bulk_viscosity.linear, 0.06);
}

TEST(DeckBulkViscosity, ValuesAndEmptyFields) {
  const Model off = model_of(with_box("*CONTROL_BULK_VISCOSITY\n0.0, 0\n"));
  EXPECT_EQ(off.bulk_viscosity.quadratic, 0.0);
  EXPECT_EQ(off.bulk_viscosity.linear, 0.0);
  const Model both = model_of(with_box("*CONTROL_BULK_VISCOSITY\n1.2, 0.05\n"));
  EXPECT_EQ(both.bulk_viscosity.quadratic, 1.2);
  EXPECT_EQ(both.bulk_viscosity.linear, 0.05);
  // An empty field keeps its default.
  const Model q1 = model_of(with_box("*CONTROL_BULK_VISCOSITY\n2.0\n"));
  EXPECT_EQ(q1.bulk_viscosity.quadratic, 2.0);
  EXPECT_EQ(q1.bulk_viscosity.linear, 0.06);
  const Model q2 = model_of(with_box("*CONTROL_BULK_VISCOSITY\n, 0.0\n"));
  EXPECT_EQ(q2.bulk_viscosity.quadratic, 1.5);
  EXPECT_EQ(q2.bulk_viscosity.linear, 0.0);
  // Parameters and expressions as in any numeric field.
  const Model p =
      model_of("*PARAMETER\n%q = 0.75\n" + with_box("*CONTROL_BULK_VISCOSITY\n%q, [%q/10]\n"));
  EXPECT_EQ(p.bulk_viscosity.quadratic, 0.75);
  EXPECT_DOUBLE_EQ(p.bulk_viscosity.linear, 0.075);
}

TEST(DeckBulkViscosity, Errors) {
  const std::size_t line = 14;  // the data line after kBoxModel's 12 lines and the keyword
  InputError e = error_of(with_box("*CONTROL_BULK_VISCOSITY\n-1.5, 0.06\n"));
  EXPECT_EQ(e.where().line, line);
  EXPECT_EQ(e.where().field, "q1");
  EXPECT_THAT(e.message(), HasSubstr("expected a quadratic coefficient >= 0"));
  e = error_of(with_box("*CONTROL_BULK_VISCOSITY\n1.5, -0.06\n"));
  EXPECT_EQ(e.where().line, line);
  EXPECT_EQ(e.where().field, "q2");
  EXPECT_THAT(e.message(), HasSubstr("expected a linear coefficient >= 0"));
  e = error_of(with_box("*CONTROL_BULK_VISCOSITY\n1.5, abc\n"));
  EXPECT_EQ(e.where().field, "q2");
  // At most once per deck: the second names the first.
  e = error_of(with_box("*CONTROL_BULK_VISCOSITY\n0, 0\n*CONTROL_BULK_VISCOSITY\n0, 0\n"));
  EXPECT_EQ(e.where().line, 15u);
  EXPECT_THAT(e.message(), HasSubstr("already has a *CONTROL_BULK_VISCOSITY at t.k:13"));
  // Its data line is required; LS-DYNA's further fields (TYPE, BTYPE, ...) are not read.
  EXPECT_THAT(error_of(with_box("*CONTROL_BULK_VISCOSITY\n")).message(),
              HasSubstr("missing data line"));
  EXPECT_EQ(error_of(with_box("*CONTROL_BULK_VISCOSITY\n1.5, 0.06, 1\n")).where().line, line);
}

// The error is at the keyword's line (a static deck has no *TIME) and names the *STATIC.
TEST(DeckBulkViscosity, AStaticDeckRefusesIt) {
  const std::string deck = R"(*COMPONENT_BOX
1, 1, 2, 2, 2
0.0, 0.0, 0.0, 1.0, 1.0, 2.0
*MAT_ELASTIC
1, 7800.0, 1000.0, 0.3
*PART
1, 1
*STATIC
1.0
*CONTROL_BULK_VISCOSITY
0.0, 0.0
)";
  const InputError e = error_of(deck);
  EXPECT_EQ(e.where().file, "t.k");
  EXPECT_EQ(e.where().line, 10u);
  EXPECT_THAT(e.message(), HasSubstr("remove *CONTROL_BULK_VISCOSITY"));
  EXPECT_THAT(e.message(), HasSubstr("the deck has *STATIC at t.k:8"));
}

}  // namespace
}  // namespace abut
