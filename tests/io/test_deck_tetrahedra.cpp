// *CHANGE_TO_TETRAHEDRA (abut's own): the hexahedra of parts cut into 4- or 10-node tetrahedra
// after *CHANGE_P-ORDER; its errors at their file and line.
#include <gmock/gmock.h>

#include <string>

#include "test_deck_helpers.hpp"

namespace abut {
namespace {

using testing::error_of;
using ::testing::HasSubstr;
using testing::model_of;
using testing::read;
using testing::with_box;

TEST(DeckTetrahedra, FourAndTenNodes) {
  const DeckResult four = read(with_box("*CHANGE_TO_TETRAHEDRA\nP, 1, 4\n"));
  const Mesh& m4 = four.model.mesh;
  EXPECT_EQ(m4.hex_count(), 0u);
  ASSERT_EQ(m4.cells.size(), 1u);
  EXPECT_EQ(m4.cells[0].type, CellType::tet4);
  EXPECT_GE(m4.cells[0].size(), 4u * 5u);
  EXPECT_LE(m4.cells[0].size(), 4u * 6u);
  EXPECT_EQ(m4.nodes.size(), 3u * 3u * 2u);  // no new nodes
  bool noted = false;
  for (const std::string& note : four.notes)
    noted = noted || note.find("part 1: 4 hexes cut into") != std::string::npos;
  EXPECT_TRUE(noted);

  const Mesh m10 = model_of(with_box("*CHANGE_TO_TETRAHEDRA\nALL, 0, 10\n")).mesh;
  ASSERT_EQ(m10.cells.size(), 1u);
  EXPECT_EQ(m10.cells[0].type, CellType::tet10);
  EXPECT_GT(m10.nodes.size(), 18u);

  // After *CHANGE_P-ORDER SPLIT: the children are cut (4 x 8 hexes).
  const Mesh refined =
      model_of(with_box("*CHANGE_P-ORDER\nP, 1, 2\n*CHANGE_TO_TETRAHEDRA\nP, 1, 4\n")).mesh;
  EXPECT_GE(refined.cells.at(0).size(), 32u * 5u);
}

TEST(DeckTetrahedra, Errors) {
  InputError e = error_of(with_box("*CHANGE_TO_TETRAHEDRA\nP, 1, 8\n"));
  EXPECT_EQ(e.where().line, 14u);
  EXPECT_EQ(e.where().field, "nodes");
  EXPECT_THAT(e.message(), HasSubstr("expected 4 or 10"));
  EXPECT_THAT(error_of(with_box("*CHANGE_TO_TETRAHEDRA\n")).message(),
              HasSubstr("missing data line"));
  // Half of the box: the cut would not conform to the hexes kept.
  e = error_of(
      with_box("*GEOMETRY_BOX\n7\n-1, -1, -1, 1, 3, 3\n*CHANGE_TO_TETRAHEDRA\nP, 1, 4, 7\n"));
  EXPECT_EQ(e.where().line, 17u);
  EXPECT_THAT(e.message(), HasSubstr("would not conform"));
  // Lagrange hexahedra are not 8-node hexahedra.
  e =
      error_of(with_box("*CONTROL_P-ORDER\nLAGRANGE\n*CHANGE_P-ORDER\nP, 1, 2\n"
                        "*CHANGE_TO_TETRAHEDRA\nP, 1, 4\n"));
  EXPECT_EQ(e.where().line, 18u);
  EXPECT_THAT(e.message(), HasSubstr("part 1 has hex27 elements"));
}

}  // namespace
}  // namespace abut
