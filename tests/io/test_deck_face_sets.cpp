// *SET_FACE and the entity FS (issue 33): rows of corner nodes matched to the faces of the final
// mesh, in contacts, pressures and heat loads; every error at its row, saying why.
#include <gmock/gmock.h>

#include <algorithm>
#include <string>

#include "abut/solver/pressure_loads.hpp"
#include "test_deck_helpers.hpp"

namespace abut {
namespace {

using testing::error_of;
using ::testing::HasSubstr;
using testing::model_of;

// Two unit hexahedra stacked along z (nodes 1-4 at z = 0, 5-8 at z = 1, 9-12 at z = 2; the face
// 5-6-7-8 between them) and a unit shell beside them (nodes 13-16, part 2).
const std::string kStack = R"(*UNIT_SYSTEM
SI
*TIME
1.0e-3
*NODE
1, 0, 0, 0
2, 1, 0, 0
3, 1, 1, 0
4, 0, 1, 0
5, 0, 0, 1
6, 1, 0, 1
7, 1, 1, 1
8, 0, 1, 1
9, 0, 0, 2
10, 1, 0, 2
11, 1, 1, 2
12, 0, 1, 2
13, 3, 0, 0
14, 4, 0, 0
15, 4, 1, 0
16, 3, 1, 0
*ELEMENT_SOLID
1, 1, 1, 2, 3, 4, 5, 6, 7, 8
2, 1, 5, 6, 7, 8, 9, 10, 11, 12
*ELEMENT_SHELL
1, 2, 13, 14, 15, 16
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
"stack"
1, 1
"sheet"
2, 1, , 0.01
)";
// Its line count: a keyword after it starts on the next line.
const std::size_t kLines = static_cast<std::size_t>(std::count(kStack.begin(), kStack.end(), '\n'));

TEST(DeckFaceSets, RowsBecomeTheFacesTheyBound) {
  // Top of hex 2 (any corner order), bottom of hex 1 listed twice, a side of hex 1, the shell.
  const Model m = model_of(kStack +
                           "*SET_FACE\n\"marked\"\n11\n11, 12, 9, 10\n1, 4, 3, 2\n1, 2, 3, 4\n"
                           "1, 2, 6, 5\n14, 15, 16, 13\n");
  ASSERT_EQ(m.face_sets.size(), 1u);
  const FaceSet& s = m.face_sets[0];
  ASSERT_EQ(s.faces.size(), 3u);  // each face once, in solid and face order
  EXPECT_EQ(s.faces[0].solid, 0);
  EXPECT_EQ(s.faces[0].face, 0);  // bottom (S1)
  EXPECT_EQ(s.faces[1].solid, 0);
  EXPECT_EQ(s.faces[1].face, 2);  // y = 0 side (S3)
  EXPECT_EQ(s.faces[2].solid, 1);
  EXPECT_EQ(s.faces[2].face, 1);  // top (S2)
  EXPECT_EQ(s.shells, std::vector<std::int32_t>{0});
  const EntityRef fs{EntityType::FaceSet, 11, {}};
  EXPECT_EQ(m.nodes_of(fs).size(), 14u);  // 1-6, 9-12 and 13-16
}

TEST(DeckFaceSets, FaceSetsCarryContactsAndPressures) {
  const Model m = model_of(kStack + "*SET_FACE\n11\n9, 10, 11, 12\n*CONTACT\n1\nFS, 11, P, 2\n" +
                           "*CURVE\n9\n0.0, 1.0\n1.0, 1.0\n*LOAD_PRESSURE\nFS, 11, 9, 1.0e5\n");
  EXPECT_EQ(m.contacts.at(0).surface1.type, EntityType::FaceSet);
  // The pressure acts on the marked face only, outward as the element's face: +z on top.
  const std::vector<Quad4> faces = pressure_faces(m, m.pressures.at(0));
  ASSERT_EQ(faces.size(), 1u);
  const Vec3 area = face_vector_area(faces[0], m.mesh.nodes.x, m.mesh.nodes.y, m.mesh.nodes.z);
  EXPECT_DOUBLE_EQ(area.z, 1.0);
  EXPECT_DOUBLE_EQ(area.x, 0.0);
}

// Heat loads on a face set act on its faces only (the solid's top and the shell here).
TEST(DeckFaceSets, HeatLoadsActOnTheFaceSet) {
  std::string deck = kStack;
  deck.replace(deck.find("1, 7800.0, 210.0e9, 0.3\n"), 24,
               "1, 7800.0, 210.0e9, 0.3, 0, 7\n*PROP_THERMAL\n7, 460.0, 45.0\n");
  const Model m = model_of(deck + "*SET_FACE\n11\n9, 10, 11, 12\n13, 14, 15, 16\n" +
                           "*LOAD_THERMAL_SURFACE\n1, FS, 11, , 1.0e4\n" +
                           "*LOAD_THERMAL_CONVECTION\n2, FS, 11, 25.0, 20.0\n");
  for (const auto* faces : {&m.thermal.fluxes.at(0).faces, &m.thermal.convection.at(0).faces}) {
    ASSERT_EQ(faces->size(), 2u);
    std::vector<std::int64_t> ids;
    for (const auto& q : *faces)
      for (const std::int32_t n : q) ids.push_back(m.mesh.nodes.id[static_cast<std::size_t>(n)]);
    std::sort(ids.begin(), ids.end());
    EXPECT_EQ(ids, (std::vector<std::int64_t>{9, 10, 11, 12, 13, 14, 15, 16}));
  }
}

TEST(DeckFaceSets, ErrorsSayWhyAtTheRow) {
  const auto row_error = [](const std::string& row) {
    const InputError e = error_of(kStack + "*SET_FACE\n11\n" + row + "\n");
    EXPECT_EQ(e.where().line, kLines + 3) << e.what();
    return e.message();
  };
  EXPECT_THAT(row_error("5, 6, 7, 8"), HasSubstr("lies between two solid elements"));
  EXPECT_THAT(row_error("1, 2, 7, 8"), HasSubstr("does not bound a solid element or a shell"));
  EXPECT_THAT(row_error("1, 2, 3, 99"), HasSubstr("node 99 does not exist"));
  EXPECT_THAT(row_error("1, 1, 2, 2"), HasSubstr("fewer than 3 distinct corner nodes"));
  EXPECT_THAT(error_of(kStack + "*SET_FACE\n11\n").message(),
              HasSubstr("expected the corner node ids"));
  // A face set that does not exist, where a contact surface is asked for.
  const InputError e = error_of(kStack + "*CONTACT\n1\nFS, 12, P, 2\n");
  EXPECT_THAT(e.message(), HasSubstr("12"));
  EXPECT_EQ(e.where().line, kLines + 3);
}

}  // namespace
}  // namespace abut
