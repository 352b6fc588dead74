// *CONTACT_STABILIZATION (abut's own; OptiStruct CNTSTB, seed 003 comment 7): its fields into
// ContactSpec with OptiStruct's defaults, each mistake a file:line error at its field, and an
// explicit run refusing it at its line (it acts in static steps only).
#include <gmock/gmock.h>

#include <algorithm>

#include "test_deck_helpers.hpp"

namespace abut {
namespace {

using testing::error_of;
using testing::expect_explicit_refusal;
using ::testing::HasSubstr;
using testing::model_of;
using testing::with_contact;

TEST(DeckStabilization, FieldsAndDefaults) {
  const Model d = model_of(with_contact("*CONTACT_STABILIZATION\n5\n"));
  ASSERT_TRUE(d.contacts.at(0).stabilization.has_value());
  const ContactSpec::Stabilization& s = *d.contacts.at(0).stabilization;
  EXPECT_EQ(s.scale, 1.0);
  EXPECT_EQ(s.start, 1.0);  // OptiStruct's S0
  EXPECT_EQ(s.end, 0.0);    // and S1
  EXPECT_EQ(s.tangent_fraction, 1.0);
  EXPECT_FALSE(s.range.has_value());
  const Model g = model_of(with_contact("*CONTACT_STABILIZATION\n5, 10.0, 0.5, 0.1, 0.0, 0.2\n"));
  const ContactSpec::Stabilization& t = *g.contacts.at(0).stabilization;
  EXPECT_EQ(t.scale, 10.0);
  EXPECT_EQ(t.start, 0.5);
  EXPECT_EQ(t.end, 0.1);
  EXPECT_EQ(t.tangent_fraction, 0.0);
  EXPECT_EQ(t.range, 0.2);
}

TEST(DeckStabilization, MistakesAreLocated) {
  const auto field_of = [](const std::string& line) {
    const InputError e = error_of(with_contact("*CONTACT_STABILIZATION\n" + line + "\n"));
    EXPECT_EQ(e.where().file, "t.k") << e.what();
    return e.where().field;
  };
  EXPECT_EQ(field_of("5, 0.0"), "scale");
  EXPECT_EQ(field_of("5, 1, -1"), "s0");
  EXPECT_EQ(field_of("5, 1, 1, -0.5"), "s1");
  EXPECT_EQ(field_of("5, 1, 1, 0, -1"), "tfrac");
  EXPECT_EQ(field_of("5, 1, 1, 0, 1, 0"), "lmtgap");
  EXPECT_THAT(error_of(with_contact("*CONTACT_STABILIZATION\n7\n")).what(),
              HasSubstr("7"));  // no *CONTACT 7
}

TEST(DeckStabilization, ExplicitRunsRefuseIt) {
  expect_explicit_refusal(with_contact("*CONTACT_STABILIZATION\n5\n"), "static steps only");
}

}  // namespace
}  // namespace abut
