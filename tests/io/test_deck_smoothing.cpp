// *CONTACT_SMOOTHING (abut's own; OptiStruct SMOOTH / SMSIDE / SMREG, seed 003): its fields into
// ContactSpec, each mistake a file:line error at its field, and an explicit run and an exact tie
// refusing it at its line.
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

TEST(DeckSmoothing, Sides) {
  const auto sides = [](const std::string& lines) {
    const Model m = model_of(with_contact("*CONTACT_SMOOTHING\n" + lines));
    const ContactSpec::Smoothing& s = m.contacts.at(0).smoothing.value();
    return std::pair{s.surface1, s.surface2};
  };
  EXPECT_EQ(sides("5, MAIN\n"), std::pair(false, true));
  EXPECT_EQ(sides("5, MASTER, ALL\n"), std::pair(false, true));
  EXPECT_EQ(sides("5, SECONDARY\n"), std::pair(true, false));
  EXPECT_EQ(sides("5, SLAVE\n"), std::pair(true, false));
  EXPECT_EQ(sides("5, BOTH\n"), std::pair(true, true));
  const Model m = model_of(with_contact("*CONTACT_SMOOTHING\n5, BOTH, , 45.0\n"));
  EXPECT_EQ(m.contacts.at(0).smoothing->crease, 45.0);
  EXPECT_FALSE(model_of(with_contact("*CONTACT_SMOOTHING\n5, BOTH\n"))
                   .contacts.at(0)
                   .smoothing->crease.has_value());
  EXPECT_FALSE(model_of(with_contact("")).contacts.at(0).smoothing.has_value());
}

TEST(DeckSmoothing, MistakesAreLocated) {
  const auto error = [](const std::string& line) {
    const InputError e = error_of(with_contact("*CONTACT_SMOOTHING\n" + line + "\n"));
    EXPECT_EQ(e.where().file, "t.k") << e.what();
    return e;
  };
  EXPECT_EQ(error("5").where().field, "side");
  EXPECT_EQ(error("5, TOP").where().field, "side");
  EXPECT_EQ(error("5, BOTH, 71").where().field, "region");
  EXPECT_THAT(error("5, BOTH, 71").what(), HasSubstr("face set"));
  EXPECT_EQ(error("5, BOTH, ALL, 0").where().field, "crease");
  EXPECT_EQ(error("5, BOTH, ALL, 190").where().field, "crease");
}

TEST(DeckSmoothing, ExplicitRunsRefuseIt) {
  expect_explicit_refusal(with_contact("*CONTACT_SMOOTHING\n5, BOTH\n"), "static steps only");
}

}  // namespace
}  // namespace abut
