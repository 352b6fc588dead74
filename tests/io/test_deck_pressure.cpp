// *LOAD_PRESSURE: rows entype, enid, cid, sf; entity and curve references are checked once the
// deck is in, and an entity without faces is an error at its enid field.
#include <gmock/gmock.h>

#include "test_deck_helpers.hpp"

namespace abut {
namespace {

using testing::error_of;
using ::testing::HasSubstr;
using testing::kBoxModel;
using testing::model_of;
using testing::with_box;

const char* kRamp = "*CURVE\n5\n0.0, 0.0\n1.0, 1.0e6\n";

TEST(DeckPressure, RowsOfEveryEntityType) {
  const Model m = model_of(with_box(std::string(kRamp) + R"(*SET_PART
3
1
*GEOMETRY_BOX
9
-1, -1, -1, 3, 3, 0.1
*LOAD_PRESSURE
P, 1, 5
PS, 3, 5, 2.5
ALL, 0, 5
G, 9, 5, -1
)"));
  ASSERT_EQ(m.pressures.size(), 4u);
  EXPECT_EQ(m.pressures[0].entity.type, EntityType::Part);
  EXPECT_EQ(m.pressures[0].entity.id, 1);
  EXPECT_DOUBLE_EQ(m.pressures[0].scale, 1.0);  // default sf
  EXPECT_EQ(m.pressures[1].entity.type, EntityType::PartSet);
  EXPECT_DOUBLE_EQ(m.pressures[1].scale, 2.5);
  EXPECT_EQ(m.pressures[2].entity.type, EntityType::All);
  EXPECT_EQ(m.pressures[3].entity.type, EntityType::GeometryRegion);
  EXPECT_DOUBLE_EQ(m.pressures[3].scale, -1.0);
  for (const PressureLoad& p : m.pressures)
    EXPECT_DOUBLE_EQ(m.functions.value(p.curve, 0.5, {}), 0.5e6);
  EXPECT_EQ(m.pressures[0].where.line, 24u);
}

TEST(DeckPressure, MissingReferences) {
  InputError e = error_of(with_box(std::string(kRamp) + "*LOAD_PRESSURE\nP, 4, 5\n"));
  EXPECT_EQ(e.where().field, "enid");
  EXPECT_EQ(e.where().line, 18u);
  EXPECT_THAT(e.message(), HasSubstr("part 4 does not exist"));
  e = error_of(with_box(std::string(kRamp) + "*LOAD_PRESSURE\nPS, 4, 5\n"));
  EXPECT_THAT(e.message(), HasSubstr("part set 4 does not exist"));
  e = error_of(with_box(std::string(kRamp) + "*LOAD_PRESSURE\nG, 4, 5\n"));
  EXPECT_EQ(e.where().field, "enid");
  EXPECT_THAT(e.message(), HasSubstr("geometry 4 does not exist"));
  e = error_of(with_box("*LOAD_PRESSURE\nP, 1, 6\n"));
  EXPECT_EQ(e.where().field, "cid");
  EXPECT_EQ(e.where().line, 14u);
  e = error_of(with_box("*LOAD_PRESSURE\nP, 1\n"));
  EXPECT_EQ(e.where().field, "cid");
}

TEST(DeckPressure, AnEntityWithoutFaces) {
  // A region that holds a node, but not every node of any exterior face.
  InputError e = error_of(with_box(std::string(kRamp) + R"(*GEOMETRY_SPHERE
8
1, 1, 0, 0.1
*LOAD_PRESSURE
G, 8, 5
)"));
  EXPECT_EQ(e.where().field, "enid");
  EXPECT_EQ(e.where().line, 21u);
  EXPECT_THAT(e.message(), HasSubstr("has no exterior face of a solid element and no shell"));
  // A part without elements.
  EXPECT_THAT(e.message(), HasSubstr("the region of geometry 8"));
  e = error_of(with_box(std::string(kRamp) + R"(*PART
"empty"
2, 1
*LOAD_PRESSURE
P, 2, 5
)"));
  EXPECT_THAT(e.message(), HasSubstr("has no exterior face of a solid element and no shell"));
}

TEST(DeckPressure, UnsupportedEntityTypesAndEmptyCommand) {
  EXPECT_THAT(error_of(with_box(std::string(kRamp) + "*LOAD_PRESSURE\nNS, 1, 5\n")).message(),
              HasSubstr("entity type NS is not supported yet"));
  EXPECT_EQ(error_of(with_box(std::string(kRamp) + "*LOAD_PRESSURE\nP, 1, 5, 1, 7\n")).where().line,
            18u);
  EXPECT_THAT(error_of(with_box("*LOAD_PRESSURE\n")).message(), HasSubstr("missing data line"));
}

}  // namespace
}  // namespace abut
