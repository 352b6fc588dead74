// *CONTACT_TOOL (abut's own; Metafor's analytic rigid contact matrices, seed 002) and a *CONTACT
// naming it as surface 2 (entype_2 TOOL): read into Model::tools, and each mistake a file:line
// error at its field; what a tool contact does not do is refused at the field that asks for it.
#include <gmock/gmock.h>

#include <cmath>

#include "test_deck_helpers.hpp"

namespace abut {
namespace {

using testing::error_of;
using ::testing::HasSubstr;
using testing::kBoxModel;
using testing::model_of;

// The box of kBoxModel against tool 7 (`tool`: its lines) in *CONTACT 5, plus `extra`.
std::string with_tool(const std::string& tool, const std::string& extra = "",
                      const std::string& contact = "P, 1, TOOL, 7, 0.2, 1e9") {
  return std::string(kBoxModel) + "*CURVE\n3\n0, 1\n1, 1\n*CONTACT_TOOL\n" + tool +
         "*CONTACT\n5\n" + contact + "\n" + extra;
}

std::size_t line_of(const std::string& text, const std::string& needle) {
  const std::size_t at = text.rfind(needle);
  EXPECT_NE(at, std::string::npos) << needle;
  std::size_t line = 1;
  for (std::size_t i = 0; i < at && i < text.size(); ++i) line += text[i] == '\n';
  return line;
}

void expect_error(const std::string& deck, const std::string& needle, const std::string& field,
                  const std::string& message) {
  const InputError e = error_of(deck);
  EXPECT_EQ(e.where().file, "t.k") << e.what();
  EXPECT_EQ(e.where().line, line_of(deck, needle)) << e.what();
  EXPECT_EQ(e.where().field, field) << e.what();
  EXPECT_THAT(e.what(), HasSubstr(message));
}

TEST(DeckContactTool, ShapesSidesAndMotion) {
  const Model m =
      model_of(with_tool("7, CYLINDER, INSIDE\n0, 0, 0, 0, 0, 2, 0.5, 3\n"
                         "3, 2.0, , , , , 3, 10\n"
                         "*CONTACT_TOOL\n8, SPHERE\n1, 2, 3, , , , 0.25\n"
                         "*CONTACT_TOOL\n9, PLANE\n0, 0, -1, 3, 0, 4\n"));
  ASSERT_EQ(m.tools.size(), 3u);
  const RigidTool& c = m.tools[0];
  EXPECT_EQ(c.id, 7);
  EXPECT_EQ(c.tool.shape, ToolShape::Cylinder);
  EXPECT_EQ(c.tool.side, ToolSide::Inside);
  EXPECT_EQ(c.tool.axis.z, 1.0);  // normalised
  EXPECT_EQ(c.tool.radius, 0.5);
  EXPECT_EQ(c.tool.length, 3.0);
  EXPECT_TRUE(c.velocity[0].valid());
  EXPECT_EQ(c.velocity_scale[0], 2.0);
  EXPECT_FALSE(c.velocity[1].valid());
  EXPECT_TRUE(c.spin.valid());
  EXPECT_EQ(c.spin_scale, 10.0);
  EXPECT_EQ(m.tools[1].tool.shape, ToolShape::Sphere);
  EXPECT_EQ(m.tools[1].tool.side, ToolSide::Outside);  // the default
  EXPECT_EQ(m.tools[1].tool.point.z, 3.0);
  EXPECT_TRUE(std::isinf(m.tools[2].tool.length));
  EXPECT_DOUBLE_EQ(m.tools[2].tool.axis.x, 0.6);
  EXPECT_EQ(m.contacts.at(0).surface2.type, EntityType::Tool);
  EXPECT_EQ(m.contacts.at(0).surface2.id, 7);
}

TEST(DeckContactTool, MistakesNameTheirFileLineAndField) {
  const std::string plane = "7, PLANE\n0, 0, 0, 0, 0, 1\n";
  expect_error(with_tool("7, CONE\n0, 0, 0, 0, 0, 1\n"), "7, CONE", "shape",
               "PLANE, CYLINDER or SPHERE");
  expect_error(with_tool("7\n0, 0, 0, 0, 0, 1\n"), "7\n", "shape", "expected a tool shape");
  expect_error(with_tool("7, PLANE, ABOVE\n0, 0, 0, 0, 0, 1\n"), "7, PLANE", "side", "OUTSIDE");
  expect_error(with_tool("7, PLANE\n0, 0, 0, 0, 0, 0\n"), "0, 0, 0, 0, 0, 0", "nx",
               "nonzero normal");
  expect_error(with_tool("7, CYLINDER\n0, 0, 0, 0, 0, 0, 1\n"), "0, 0, 0, 0, 0, 0, 1", "nx",
               "nonzero axis");
  expect_error(with_tool("7, SPHERE\n0, 0, 0, , , , 0\n"), "0, 0, 0, , , , 0", "radius",
               "radius > 0");
  expect_error(with_tool("7, CYLINDER\n0, 0, 0, 1, 0, 0, -1\n"), "0, 0, 0, 1, 0, 0, -1", "radius",
               "radius > 0");
  expect_error(with_tool("7, CYLINDER\n0, 0, 0, 1, 0, 0, 1, 0\n"), "0, 0, 0, 1, 0, 0, 1, 0",
               "length", "length > 0");
  expect_error(with_tool("7, PLANE\n0, 0, 0, 0, 0, 1, 2\n"), "0, 0, 0, 0, 0, 1, 2", "radius",
               "no radius");
  expect_error(with_tool("7, SPHERE\n0, 0, 0, 0, 0, 1, 2\n"), "0, 0, 0, 0, 0, 1, 2", "nx",
               "no direction");
  expect_error(with_tool("7, PLANE\n0, 0, 0, 0, 0, 1\n, , , , , , 3\n"), ", , , , , , 3",
               "fid_spin", "only a cylinder spins");
  expect_error(with_tool("7, PLANE\n0, 0, 0, 0, 0, 1\n, 2\n"), ", 2\n", "sf_vx",
               "without its curve");
  // The tool a contact names must exist, and a tool is surface 2 only.
  expect_error(with_tool(plane, "", "P, 1, TOOL, 8, 0.2, 1e9"), "TOOL, 8", "enid_2",
               "tool 8 does not exist");
  expect_error(with_tool(plane, "", "TOOL, 7, P, 1, 0.2, 1e9"), "TOOL, 7, P", "entype_1",
               "surface 2 only");
  // What a tool contact does not do, at the field that asks for it.
  expect_error(with_tool(plane, "*CONTACT_DISCRETIZATION\n5, N2S, 1\n"), "5, N2S, 1", "symmetric",
               "symmetric contact with an analytic tool");
  expect_error(with_tool(plane, "*CONTACT_DISCRETIZATION\n5, S2S\n"), "5, S2S", "method",
               "surface-to-surface contact with an analytic tool");
  expect_error(with_tool(plane, "*CONTACT_EROSION\n5, KEEP\n"), "5, KEEP", "facets",
               "*CONTACT_EROSION with an analytic tool");
  expect_error(with_tool(plane, "*CONTACT_FRICTION\n5, FREEZE, , , , , , EXACT\n", "P, 1, TOOL, 7"),
               "P, 1, TOOL, 7", "enid_2", "an analytic tool (*CONTACT_TOOL) cannot be tied");
  expect_error(with_tool(plane, "*CONTACT_GAP\n5, , , , , , , , , ROUND\n"), "5, , , , ,", "ishape",
               "ishape with an analytic tool");
}

// Metafor's matrix segments: a plane strip (width along a direction in the plane) and a
// cylinder's arc (from a radial direction, in degrees), their directions made unit and projected
// off the normal or axis; the mistakes located at their fields.
TEST(DeckContactTool, SegmentsWithEnds) {
  const Model m =
      model_of(with_tool("7, PLANE\n0, 0, 0, 0, 0, 1, , , 2, 0, 1, 4.5\n"
                         "*CONTACT_TOOL\n8, CYLINDER, INSIDE\n"
                         "0, 0, 0, 0, 0, 1, 10, , -1, 0, 0, 180\n"));
  ASSERT_EQ(m.tools.size(), 2u);
  EXPECT_EQ(m.tools[0].tool.start.x, 1.0);  // (2, 0, 1) off the normal z, made unit
  EXPECT_EQ(m.tools[0].tool.span, 4.5);
  EXPECT_EQ(m.tools[1].tool.start.x, -1.0);
  EXPECT_NEAR(m.tools[1].tool.span, 3.14159265358979323846, 1e-15);
  EXPECT_FALSE(
      std::isfinite(model_of(with_tool("7, PLANE\n0, 0, 0, 0, 0, 1\n")).tools[0].tool.span));
  const std::string along = with_tool("7, PLANE\n0, 0, 0, 0, 0, 1, , , 0, 0, 3, 1\n");
  expect_error(along, "0, 0, 0, 0, 0, 1, , , 0, 0, 3, 1", "dx", "a direction in the plane");
  const std::string wide = with_tool("7, CYLINDER\n0, 0, 0, 0, 0, 1, 1, , 1, 0, 0, 400\n");
  expect_error(wide, "0, 0, 0, 0, 0, 1, 1, , 1, 0, 0, 400", "span", "(0, 360] degrees");
  const std::string ball = with_tool("7, SPHERE\n0, 0, 0, , , , 1, , 1, 0, 0, 90\n");
  expect_error(ball, "0, 0, 0, , , , 1, , 1, 0, 0, 90", "dx", "a sphere has no ends");
  const std::string turning =
      with_tool("7, CYLINDER\n0, 0, 0, 0, 0, 1, 1, , 1, 0, 0, 90\n, , , , , , 3\n");
  expect_error(turning, ", , , , , , 3", "fid_spin", "an arc does not spin");
}

// Static steps take tools (tests/verification/test_static_tool.cpp); what a tool refuses is
// refused at the deck, in either kind of run.
TEST(DeckContactTool, StaticStepsTakeTools) {
  std::string deck = std::string(kBoxModel);
  deck.erase(deck.find("*TIME\n1.0e-3\n"), std::string("*TIME\n1.0e-3\n").size());
  deck += "*CONTACT_TOOL\n7, PLANE\n0, 0, 0, 0, 0, 1\n*CONTACT\n5\nP, 1, TOOL, 7\n*STATIC\n1.0\n";
  const Model m = model_of(deck);
  EXPECT_EQ(m.contacts.at(0).surface2.type, EntityType::Tool);
  EXPECT_EQ(m.static_steps.size(), 1u);
}

}  // namespace
}  // namespace abut
