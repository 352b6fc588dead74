// *CONTACT_GAP, *CONTACT_EDGE and *CONTACT_EROSION (issue 9): fields, defaults, Radioss synonyms
// and every error at its line and field. Fixtures as in test_deck_contact_laws.cpp.
#include <gmock/gmock.h>

#include <algorithm>
#include <string>

#include "test_deck_helpers.hpp"

namespace abut {
namespace {

using testing::error_of;
using ::testing::HasSubstr;
using testing::model_of;

// Two elastic blocks, one on the other, and node set 5; no *CONTACT yet.
const std::string kTwoBlocks = R"(*UNIT_SYSTEM
SI
*TIME
1.0e-3
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, 0.0, 0.0, 2.0, 2.0, 1.0
*COMPONENT_BOX
2, 2, 1, 1, 1
0.0, 0.0, 1.0, 1.0, 1.0, 2.0
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*PART
1, 1
2, 1
*SET_NODE
5
1, 2
*SET_PART
7
1, 2
*CURVE
9
0.0, 0.0
1.0, 1.0e9
)";
// ... with *CONTACT 3 between parts 1 and 2; the keyword under test starts on line kLine.
const std::string kContact = kTwoBlocks + "*CONTACT\n3\nP, 1, P, 2\n";

std::size_t lines_of(const std::string& s) {
  return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n'));
}
const std::size_t kLine = lines_of(kContact) + 1;

// The one contact of `extra` appended to the two blocks with *CONTACT 3.
ContactSpec contact_of(const std::string& extra) {
  const Model m = model_of(kContact + extra);
  EXPECT_EQ(m.contacts.size(), 1u);
  return m.contacts.at(0);
}

// Where the deck with `extra` gives `setting` of contact 3 (Sources; empty: not given).
SourceLocation place_of(const std::string& extra, std::string_view setting) {
  return model_of(kContact + extra).sources.of(SourceEntity::Contact, 3, setting);
}

// The error of `extra` appended to the two blocks with *CONTACT 3: its message, checked to be at
// line kLine + row_offset (the keyword's first row is kLine + 1) and in field `field`.
std::string error_at(const std::string& extra, std::size_t line, const std::string& field) {
  const InputError e = error_of(kContact + extra);
  EXPECT_EQ(e.where().file, "t.k") << e.what();
  EXPECT_EQ(e.where().line, line) << e.what();
  EXPECT_EQ(e.where().field, field) << e.what();
  return e.message();
}

TEST(DeckContactGap, RadiossVariableGaps) {
  ContactSpec c = contact_of("*CONTACT_GAP\n3\n");
  EXPECT_DOUBLE_EQ(c.gaps.scale, 1.0);
  EXPECT_FALSE(c.gaps.mesh_fraction.has_value());
  EXPECT_FALSE(c.gaps.skip_close);
  EXPECT_FALSE(c.gaps.zero_at_free_edges);
  EXPECT_EQ(place_of("*CONTACT_GAP\n3\n", "gaps").line, kLine + 1);
  EXPECT_EQ(place_of("*CONTACT_GAP\n3\n", "shell_sides").field, "shell_side");
  c = contact_of("*CONTACT_GAP\n3, 3, 0.8, , 2.0e-3, 1.0e-3, 1\n");
  ASSERT_TRUE(c.gaps.mesh_fraction.has_value());
  EXPECT_DOUBLE_EQ(*c.gaps.mesh_fraction, 0.4);  // the Radioss default %mesh_size
  EXPECT_DOUBLE_EQ(c.gaps.scale, 0.8);
  EXPECT_DOUBLE_EQ(c.gaps.max_secondary, 2.0e-3);
  EXPECT_DOUBLE_EQ(c.gaps.max_main, 1.0e-3);
  EXPECT_TRUE(c.gaps.zero_at_free_edges);
  EXPECT_DOUBLE_EQ(*contact_of("*CONTACT_GAP\n3, 3.0, , 0.25\n").gaps.mesh_fraction, 0.25);
  EXPECT_TRUE(contact_of("*CONTACT_GAP\n3, 2\n").gaps.skip_close);
  EXPECT_FALSE(contact_of("*CONTACT_GAP\n3, 1, , , , , 1000\n").gaps.zero_at_free_edges);
  // Radioss Ishape: abut's default ends the surface at the border; 1 square, 2 round.
  using Border = GapSettings::Border;
  EXPECT_EQ(contact_of("*CONTACT_GAP\n3\n").gaps.border, Border::Cut);
  EXPECT_EQ(contact_of("*CONTACT_GAP\n3, , , , , , , , , 1\n").gaps.border, Border::Square);
  EXPECT_EQ(contact_of("*CONTACT_GAP\n3, , , , , , , , , square\n").gaps.border, Border::Square);
  EXPECT_EQ(contact_of("*CONTACT_GAP\n3, , , , , , , , , 2\n").gaps.border, Border::Round);
  EXPECT_EQ(contact_of("*CONTACT_GAP\n3, , , , , , , , , ROUND\n").gaps.border, Border::Round);
}

TEST(DeckContactGap, Errors) {
  const std::size_t l = kLine + 1;
  EXPECT_THAT(error_at("*CONTACT_GAP\n3, 4\n", l, "igap"), HasSubstr("expected 1"));
  EXPECT_THAT(error_at("*CONTACT_GAP\n3, 1, -1\n", l, "gap_scale"), HasSubstr(">= 0"));
  EXPECT_THAT(error_at("*CONTACT_GAP\n3, 1, , 0.4\n", l, "pct_mesh"), HasSubstr("igap = 3"));
  EXPECT_THAT(error_at("*CONTACT_GAP\n3, 3, , 0\n", l, "pct_mesh"), HasSubstr("> 0"));
  EXPECT_THAT(error_at("*CONTACT_GAP\n3, 1, , , 0\n", l, "gap_max_s"), HasSubstr("> 0"));
  EXPECT_THAT(error_at("*CONTACT_GAP\n3, 1, , , , -1\n", l, "gap_max_m"), HasSubstr("> 0"));
  EXPECT_THAT(error_at("*CONTACT_GAP\n3, 1, , , , , 2\n", l, "igap0"), HasSubstr("1000"));
  EXPECT_THAT(error_at("*CONTACT_GAP\n3, 1, , , , , , -1e-3\n", l, "gpad"),
              HasSubstr("expected a padding >= 0"));
  EXPECT_THAT(error_at("*CONTACT_GAP\n3, 3, , , , , , 1e-3\n", l, "gpad"),
              HasSubstr("cannot be combined with igap 3"));
  EXPECT_THAT(error_at("*CONTACT_GAP\n3, , , , , , , , SIDEWAYS\n", l, "shell_side"),
              HasSubstr("NORM, REVNORM or OVERLAP"));
  EXPECT_THAT(error_at("*CONTACT_GAP\n3, , , , , , , , , 3\n", l, "ishape"),
              HasSubstr("SQUARE (Radioss Ishape 1) or ROUND (Ishape 2)"));
}

TEST(DeckContactEdge, RadiossEdgeOptions) {
  EXPECT_EQ(contact_of("*CONTACT_EDGE\n3\n").edges.selection, EdgeSelection::None);
  EXPECT_EQ(contact_of("*CONTACT_EDGE\n3, 1000\n").edges.selection, EdgeSelection::None);
  EXPECT_EQ(contact_of("*CONTACT_EDGE\n3, 1\n").edges.selection, EdgeSelection::ShellBorders);
  EXPECT_EQ(contact_of("*CONTACT_EDGE\n3, borders\n").edges.selection, EdgeSelection::ShellBorders);
  ContactSpec c = contact_of("*CONTACT_EDGE\n3, 11, 120\n");
  EXPECT_EQ(c.edges.selection, EdgeSelection::SharpSolidEdges);
  EXPECT_DOUBLE_EQ(c.edges.angle, 120.0);
  EXPECT_EQ(place_of("*CONTACT_EDGE\n3, SHARP_ALL_SHELLS\n", "edges").line, kLine + 1);
  c = contact_of("*CONTACT_EDGE\n3, SHARP_ALL_SHELLS\n");
  EXPECT_EQ(c.edges.selection, EdgeSelection::SharpSolidAllShells);
  EXPECT_DOUBLE_EQ(c.edges.angle, 135.0);  // the Radioss default
  EXPECT_EQ(contact_of("*CONTACT_EDGE\n3, 22\n").edges.selection, EdgeSelection::AllEdges);
  const std::size_t l = kLine + 1;
  EXPECT_THAT(error_at("*CONTACT_EDGE\n3, 7\n", l, "iedge"), HasSubstr("expected NONE"));
  EXPECT_THAT(error_at("*CONTACT_EDGE\n3, NONE, 135\n", l, "edge_angle"), HasSubstr("SHARP"));
  EXPECT_THAT(error_at("*CONTACT_EDGE\n3, 11, 0\n", l, "edge_angle"), HasSubstr("(0, 180]"));
}

TEST(DeckContactErosion, FacetsAndFreeNodes) {
  ContactSpec c = contact_of("*CONTACT_EROSION\n3\n");
  EXPECT_TRUE(c.erosion.remove_facets);
  EXPECT_TRUE(c.erosion.keep_free_nodes);
  c = contact_of("*CONTACT_EROSION\n3, KEEP\n");
  EXPECT_FALSE(c.erosion.remove_facets);
  c = contact_of("*CONTACT_EROSION\n3, , remove\n");  // Abaqus nodal erosion
  EXPECT_TRUE(c.erosion.remove_facets);
  EXPECT_FALSE(c.erosion.keep_free_nodes);
  for (const char* idel : {"1", "2"}) {  // Radioss Idel 1, 2: segments and free nodes leave
    c = contact_of(std::string("*CONTACT_EROSION\n3, ") + idel + "\n");
    EXPECT_TRUE(c.erosion.remove_facets);
    EXPECT_FALSE(c.erosion.keep_free_nodes);
  }
  EXPECT_FALSE(contact_of("*CONTACT_EROSION\n3, 1000\n").erosion.remove_facets);
  const std::size_t l = kLine + 1;
  EXPECT_THAT(error_at("*CONTACT_EROSION\n3, DELETE\n", l, "facets"), HasSubstr("REMOVE"));
  EXPECT_THAT(error_at("*CONTACT_EROSION\n3, , 1\n", l, "free_nodes"), HasSubstr("KEEP"));
}

}  // namespace
}  // namespace abut
