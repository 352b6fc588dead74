// Sources (abut/model/sources.hpp): the places of the model's settings in the input and the input's
// words for them, which readers fill and solvers read.
#include <gtest/gtest.h>

#include <stdexcept>

#include "abut/model/sources.hpp"

namespace abut {
namespace {

TEST(Sources, APlaceIsKeptByEntityIdAndSetting) {
  Sources s;
  const SourceLocation normal{"m.k", 12, "*CONTACT_NORMAL", "depth"};
  s.set(SourceEntity::Contact, 3, "detection_depth", normal);
  EXPECT_TRUE(s.given(SourceEntity::Contact, 3, "detection_depth"));
  EXPECT_EQ(s.of(SourceEntity::Contact, 3, "detection_depth").line, 12u);
  EXPECT_EQ(s.of(SourceEntity::Contact, 3, "detection_depth").field, "depth");
  // Another contact, another setting, a tie of the same id: not given, so the fallback.
  const SourceLocation card{"m.k", 7, "*CONTACT", ""};
  EXPECT_FALSE(s.given(SourceEntity::Contact, 4, "detection_depth"));
  EXPECT_EQ(s.of(SourceEntity::Contact, 4, "detection_depth", card).line, 7u);
  EXPECT_EQ(s.of(SourceEntity::Contact, 3, "clearance", card).line, 7u);
  EXPECT_TRUE(s.of(SourceEntity::Tie, 3, "detection_depth").file.empty());
  // A later record replaces an earlier one (the card read last is the one that acts).
  s.set(SourceEntity::Contact, 3, "detection_depth", {"m.k", 20, "*CONTACT_NORMAL", "depth"});
  EXPECT_EQ(s.of(SourceEntity::Contact, 3, "detection_depth").line, 20u);
}

TEST(Sources, AnUnknownSettingOrConceptIsAProgrammingError) {
  Sources s;
  // Every name is the model's: a misspelt one would silently lose its place, so it throws.
  EXPECT_THROW(s.set(SourceEntity::Contact, 1, "depth", {}), std::logic_error);
  EXPECT_THROW(static_cast<void>(s.given(SourceEntity::Time, 0, "dt_min")), std::logic_error);
  EXPECT_THROW(static_cast<void>(s.of(SourceEntity::Tie, 1, "pfac")), std::logic_error);
  EXPECT_THROW(s.name("pfac", "pfac of *CONTACT"), std::logic_error);
  EXPECT_THROW(static_cast<void>(s.words("dt_min")), std::logic_error);
}

TEST(Sources, EachEntityListsItsSettingsOnce) {
  // A tie's own settings are those its search can refuse; the time control's are its steps.
  EXPECT_TRUE(Sources::has_setting(SourceEntity::Tie, "edge_angle"));
  EXPECT_TRUE(Sources::has_setting(SourceEntity::Contact, "edge_angle"));
  EXPECT_FALSE(Sources::has_setting(SourceEntity::Contact, "exact"));
  EXPECT_FALSE(Sources::has_setting(SourceEntity::Tie, "penalty"));
  EXPECT_EQ(Sources::settings(SourceEntity::Time).size(), 2u);
  for (const std::string_view name : Sources::settings(SourceEntity::Tie))
    EXPECT_TRUE(Sources::has_setting(SourceEntity::Tie, name)) << name;
}

TEST(Sources, TheInputsWordsReplaceTheModels) {
  Sources s;
  EXPECT_EQ(s.words("min_step"), "the minimum time step");
  s.name("min_step", "dt_min of *TIME");
  EXPECT_EQ(s.words("min_step"), "dt_min of *TIME");
  EXPECT_EQ(s.words("max_step"), "the maximum time step");  // not named: the model's
}

}  // namespace
}  // namespace abut
