// The thermal keywords (keyword_thermal.cpp, deck_finalize_thermal.cpp): *PROP_THERMAL and the
// thpid of the material lines, *INITIAL_TEMPERATURE, *BC_TEMPERATURE, *LOAD_THERMAL_SURFACE,
// *LOAD_THERMAL_CONVECTION; each read into Model::thermal, each error at its file:line and field.
#include <gmock/gmock.h>

#include <string>

#include "test_deck_helpers.hpp"

namespace abut {
namespace {

using testing::error_of;
using ::testing::HasSubstr;
using testing::kBoxModel;
using testing::model_of;

// A 2 x 2 x 1 box of 2 x 2 x 1 hexes (18 nodes) of steel with thermal property 7. The extra
// commands start at line 15.
const std::string kThermalBox = R"(*UNIT_SYSTEM
SI, C
*TIME
1.0e-3
*COMPONENT_BOX
1, 1, 2, 2, 1
0.0, 0.0, 0.0, 2.0, 2.0, 1.0
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3, 0, 7
*PROP_THERMAL
7, 460.0, 45.0, 1.2e-5, 0.85
*PART
"block"
1, 1
)";

std::string with(const std::string& extra) { return kThermalBox + extra; }

TEST(DeckThermal, PropThermalAndThpid) {
  const Model m = model_of(with("*PROP_THERMAL\n\"copper\"\n8, 385.0, 400.0\n"));
  ASSERT_EQ(m.thermal.properties.size(), 2u);
  const ThermalProperties& p = m.thermal.properties[0];
  EXPECT_EQ(p.id, 7);
  EXPECT_DOUBLE_EQ(p.specific_heat, 460.0);
  EXPECT_DOUBLE_EQ(p.conductivity, 45.0);
  EXPECT_DOUBLE_EQ(p.expansion, 1.2e-5);
  EXPECT_DOUBLE_EQ(p.taylor_quinney, 0.85);
  EXPECT_EQ(p.where.line, 11u);
  const ThermalProperties& q = m.thermal.properties[1];
  EXPECT_EQ(q.id, 8);
  EXPECT_DOUBLE_EQ(q.expansion, 0.0);       // default alpha
  EXPECT_DOUBLE_EQ(q.taylor_quinney, 0.9);  // default chi
  EXPECT_EQ(m.materials[0].thermal_id, 7);
  EXPECT_DOUBLE_EQ(m.thermal.initial_temperature, 0.0);  // no *INITIAL_TEMPERATURE
}

TEST(DeckThermal, ThpidOfEveryDeformableMaterial) {
  const Model m = model_of(with(R"(*MAT_METAL
2, 7800.0, 210.0e9, 0.3, 0, 7
3
*CURVE
3
0.0, 2.0e8
1.0, 3.0e8
*MAT_JC
4, 7800.0, 210.0e9, 0.3, 0, 7
2.0e8, 1.0e8, 0.5
*MAT_MOONEY_RIVLIN
5, 1100.0, 2.0e9, , , 7
1.0e6, 0.5e6
)"));
  for (const Material& mat : m.materials) EXPECT_EQ(mat.thermal_id, 7) << mat.id;
}

TEST(DeckThermal, PropThermalErrors) {
  InputError e = error_of(with("*PROP_THERMAL\n8, 0.0, 45.0\n"));
  EXPECT_EQ(e.where().line, 16u);
  EXPECT_EQ(e.where().field, "c_p");
  EXPECT_THAT(e.message(), HasSubstr("c_p > 0"));
  e = error_of(with("*PROP_THERMAL\n8, 460.0, -1.0\n"));
  EXPECT_EQ(e.where().field, "k");
  e = error_of(with("*PROP_THERMAL\n8, 460.0\n"));
  EXPECT_EQ(e.where().field, "k");
  e = error_of(with("*PROP_THERMAL\n8, 460.0, 45.0, 0.0, 1.5\n"));
  EXPECT_EQ(e.where().field, "chi");
  e = error_of(with("*PROP_THERMAL\n7, 460.0, 45.0\n"));
  EXPECT_EQ(e.where().line, 16u);
  EXPECT_EQ(e.where().field, "thpid");
  e = error_of(with("*PROP_THERMAL\n"));
  EXPECT_EQ(e.where().line, 15u);
  EXPECT_THAT(e.message(), HasSubstr("missing data line"));
}

TEST(DeckThermal, UnknownOrUnsupportedThpid) {
  std::string deck = kThermalBox;
  deck.replace(deck.find("0.3, 0, 7"), 9, "0.3, 0, 9");
  InputError e = error_of(deck);
  EXPECT_EQ(e.where().line, 9u);
  EXPECT_EQ(e.where().field, "thpid");
  EXPECT_THAT(e.message(), HasSubstr("thermal property 9 does not exist"));
  EXPECT_THAT(e.message(), HasSubstr("defined thermal properties: 7"));
}

// A rigid body conducts (a hot tool) but cannot expand: its alpha is reported, not applied.
TEST(DeckThermal, RigidMaterialConductsButDoesNotExpand) {
  std::string deck = kThermalBox;
  deck.replace(deck.find("*MAT_ELASTIC\n1, 7800.0, 210.0e9, 0.3, 0, 7"),
               std::string("*MAT_ELASTIC\n1, 7800.0, 210.0e9, 0.3, 0, 7").size(),
               "*MAT_RIGID\n1, 7800.0, , , , 7");
  const DeckResult r = testing::read(deck + "*BC_TEMPERATURE\nP, 1, 0, 300.0\n");
  ASSERT_EQ(r.model.materials.size(), 1u);
  EXPECT_EQ(r.model.materials[0].thermal_id, 7);
  EXPECT_EQ(r.model.thermal.prescribed.at(0).nodes.size(), 18u);
  EXPECT_THAT(r.notes, ::testing::Contains(HasSubstr("rigid material 1 at t.k:9 conducts heat but "
                                                     "does not expand")));
}

TEST(DeckThermal, ThermalKeywordWithoutThermalMaterial) {
  const InputError e = error_of(std::string(kBoxModel) + "*INITIAL_TEMPERATURE\nALL, 0, 20.0\n");
  EXPECT_EQ(e.where().keyword, "*INITIAL_TEMPERATURE");
  EXPECT_EQ(e.where().line, 13u);
  EXPECT_THAT(e.message(), HasSubstr("*INITIAL_TEMPERATURE has no effect"));
  EXPECT_THAT(e.message(), HasSubstr("thpid"));
}

// Shells of a thermal part carry a temperature (heat.hpp, thermal_node_flags): the conditions
// reach their nodes, the face loads their mid-surfaces.
TEST(DeckThermal, ShellNodesAndFaces) {
  const Model m = model_of(R"(*UNIT_SYSTEM
SI, C
*TIME
1.0e-3
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3, 0, 7
*PROP_THERMAL
7, 460.0, 45.0
*PART
1, 1, , 0.002
*NODE
1, 0.0, 0.0, 0.0
2, 1.0, 0.0, 0.0
3, 1.0, 1.0, 0.0
4, 0.0, 1.0, 0.0
5, 2.0, 0.0, 0.0
*ELEMENT_SHELL
1, 1, 1, 2, 3, 4
2, 1, 2, 5, 3, 3
*BC_TEMPERATURE
N, 5, 0, 80.0
*LOAD_THERMAL_CONVECTION
1, P, 1, 10.0, 20.0
)");
  ASSERT_EQ(m.thermal.prescribed.size(), 1u);
  EXPECT_EQ(m.thermal.prescribed[0].nodes.size(), 1u);
  ASSERT_EQ(m.thermal.convection.size(), 1u);
  EXPECT_EQ(m.thermal.convection[0].faces.size(), 2u);  // the quad and the triangle
}

// Static steps solve the steady temperature of each state (run_static.cpp): the deck keeps its
// heat.
TEST(DeckThermal, HeatInStaticSteps) {
  std::string deck = kThermalBox;
  deck.erase(deck.find("*TIME"), std::string("*TIME\n1.0e-3\n").size());
  const Model m = model_of(deck + "*STATIC\n2.0\n*BC_TEMPERATURE\nP, 1, 0, 80.0\n");
  ASSERT_EQ(m.static_steps.size(), 1u);
  EXPECT_EQ(m.thermal.prescribed.at(0).nodes.size(), 18u);
}

TEST(DeckThermal, InitialTemperature) {
  const Model m = model_of(with(R"(*INITIAL_TEMPERATURE
P, 1, 50.0
ALL, 0, 20.0
N, 1, 80.0
)"));
  // ALL sets the default and overrides the P row before it; the N row after it stays.
  EXPECT_DOUBLE_EQ(m.thermal.initial_temperature, 20.0);
  ASSERT_EQ(m.thermal.initial.size(), 1u);
  EXPECT_EQ(m.thermal.initial[0].nodes.size(), 1u);
  EXPECT_DOUBLE_EQ(m.thermal.initial[0].value, 80.0);
  EXPECT_EQ(m.thermal.initial[0].where.line, 18u);
  const Model m2 = model_of(with("*INITIAL_TEMPERATURE\nP, 1, 50.0\n"));
  ASSERT_EQ(m2.thermal.initial.size(), 1u);
  EXPECT_EQ(m2.thermal.initial[0].nodes.size(), 18u);
  const InputError e = error_of(with("*INITIAL_TEMPERATURE\nP, 1\n"));
  EXPECT_EQ(e.where().line, 16u);
  EXPECT_EQ(e.where().field, "T");
}

TEST(DeckThermal, BcTemperature) {
  const Model m = model_of(with(R"(*CURVE
5
0.0, 0.0
1.0, 100.0
*GEOMETRY_BOX
9
-0.1, -0.1, -0.1, 0.1, 2.1, 1.1
*BC_TEMPERATURE
G, 9, 5, 2.0
P, 1, , 300.0
)"));
  ASSERT_EQ(m.thermal.prescribed.size(), 2u);
  const PrescribedTemperature& g = m.thermal.prescribed[0];
  EXPECT_EQ(g.nodes.size(), 6u);  // the face x = 0: 3 x 2 nodes
  EXPECT_DOUBLE_EQ(g.scale, 2.0);
  EXPECT_DOUBLE_EQ(m.functions.value(g.curve, 0.5, {}), 50.0);
  EXPECT_EQ(g.where.line, 23u);
  const PrescribedTemperature& p = m.thermal.prescribed[1];
  EXPECT_FALSE(p.curve.valid());
  EXPECT_DOUBLE_EQ(p.scale, 300.0);
  EXPECT_EQ(p.nodes.size(), 18u);
}

TEST(DeckThermal, BcTemperatureErrors) {
  InputError e = error_of(with("*BC_TEMPERATURE\nP, 1\n"));
  EXPECT_EQ(e.where().line, 16u);
  EXPECT_EQ(e.where().field, "sf");
  EXPECT_THAT(e.message(), HasSubstr("give the temperature"));
  e = error_of(with("*BC_TEMPERATURE\nP, 1, 5, 1.0\n"));
  EXPECT_EQ(e.where().field, "cid");
  e = error_of(with("*BC_TEMPERATURE\nP, 2, , 1.0\n"));
  EXPECT_EQ(e.where().field, "enid");
  EXPECT_THAT(e.message(), HasSubstr("part 2 does not exist"));
  e = error_of(with("*BC_TEMPERATURE\nE, 1, , 1.0\n"));
  EXPECT_EQ(e.where().field, "entype");
  // A part whose material has no thpid carries no temperature.
  e = error_of(with(R"(*COMPONENT_BOX
2, 2, 1, 1, 1
5.0, 0.0, 0.0, 6.0, 1.0, 1.0
*MAT_ELASTIC
2, 7800.0, 210.0e9, 0.3
*PART
2, 2
*BC_TEMPERATURE
P, 2, , 1.0
)"));
  EXPECT_EQ(e.where().line, 23u);
  EXPECT_EQ(e.where().field, "enid");
  EXPECT_THAT(e.message(), HasSubstr("part 2 has no thermal properties"));
}

TEST(DeckThermal, LoadThermalSurface) {
  const Model m = model_of(with(R"(*CURVE
5
0.0, 1.0
1.0, 2.0
*GEOMETRY_BOX
9
-1.0, -1.0, 0.9, 3.0, 3.0, 1.1
*LOAD_THERMAL_SURFACE
"heating"
1, P, 1, 5, 1.0e4
2, G, 9, , 500.0
)"));
  ASSERT_EQ(m.thermal.fluxes.size(), 2u);
  EXPECT_EQ(m.thermal.fluxes[0].faces.size(), 16u);  // 4 + 4 + 8 exterior faces
  EXPECT_DOUBLE_EQ(m.thermal.fluxes[0].scale, 1.0e4);
  EXPECT_DOUBLE_EQ(m.functions.value(m.thermal.fluxes[0].curve, 0.5, {}), 1.5);
  EXPECT_EQ(m.thermal.fluxes[0].where.line, 24u);
  EXPECT_EQ(m.thermal.fluxes[1].faces.size(), 4u);  // the top z = 1
  EXPECT_FALSE(m.thermal.fluxes[1].curve.valid());
  EXPECT_DOUBLE_EQ(m.thermal.fluxes[1].scale, 500.0);
}

TEST(DeckThermal, LoadThermalSurfaceErrors) {
  InputError e = error_of(with("*LOAD_THERMAL_SURFACE\n1, P, 1, , 1.0, 0.5\n"));
  EXPECT_EQ(e.where().line, 16u);
  EXPECT_EQ(e.where().field, "t_beg");
  e = error_of(with("*LOAD_THERMAL_SURFACE\n1, P, 1, , 1.0, , 2.0\n"));
  EXPECT_EQ(e.where().field, "t_end");
  e = error_of(with("*LOAD_THERMAL_SURFACE\n1, P, 1, , 1.0, , , 1\n"));
  EXPECT_EQ(e.where().field, "erode");
  e = error_of(with("*LOAD_THERMAL_SURFACE\n1, FS, 1, , 1.0\n"));  // a face set (*SET_FACE)
  EXPECT_EQ(e.where().field, "enid");
  EXPECT_THAT(e.message(), HasSubstr("face set 1 does not exist"));
  e = error_of(with("*LOAD_THERMAL_SURFACE\n1, P, 1\n"));
  EXPECT_EQ(e.where().field, "sf");
  e = error_of(with("*LOAD_THERMAL_SURFACE\n1, P, 1, , 1.0\n1, P, 1, , 2.0\n"));
  EXPECT_EQ(e.where().line, 17u);
  EXPECT_EQ(e.where().field, "coid");
  // A region with no face of the box.
  e =
      error_of(with("*GEOMETRY_BOX\n9\n10, 10, 10, 11, 11, 11\n*LOAD_THERMAL_SURFACE\n1, G, 9, , "
                    "1.0\n"));
  EXPECT_EQ(e.where().line, 19u);
  EXPECT_EQ(e.where().field, "enid");
  EXPECT_THAT(e.message(), HasSubstr("no exterior face"));
}

TEST(DeckThermal, LoadThermalConvection) {
  const Model m = model_of(with("*LOAD_THERMAL_CONVECTION\n1, ALL, 0, 25.0, 20.0\n"));
  ASSERT_EQ(m.thermal.convection.size(), 1u);
  EXPECT_EQ(m.thermal.convection[0].faces.size(), 16u);
  EXPECT_DOUBLE_EQ(m.thermal.convection[0].coefficient, 25.0);
  EXPECT_DOUBLE_EQ(m.thermal.convection[0].ambient, 20.0);
  InputError e = error_of(with("*LOAD_THERMAL_CONVECTION\n1, P, 1, 0.0, 20.0\n"));
  EXPECT_EQ(e.where().line, 16u);
  EXPECT_EQ(e.where().field, "h");
  e = error_of(with("*LOAD_THERMAL_CONVECTION\n1, P, 1, 10.0\n"));
  EXPECT_EQ(e.where().field, "T_amb");
}

TEST(DeckThermal, UnitSystemTemperature) {
  std::string deck = kThermalBox;
  deck.replace(deck.find("SI, C"), 5, "SI, R");
  const InputError e = error_of(deck);
  EXPECT_EQ(e.where().line, 2u);
  EXPECT_EQ(e.where().field, "temperature");
}

}  // namespace
}  // namespace abut
