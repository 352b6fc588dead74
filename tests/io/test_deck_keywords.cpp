// Each keyword's happy path and its range, reference and support checks.
#include <gmock/gmock.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "abut/io/run.hpp"
#include "test_deck_helpers.hpp"

namespace abut {
namespace {

using testing::error_of;
using ::testing::HasSubstr;
using testing::kBoxModel;
using testing::model_of;
using testing::read;
using testing::with_box;

TEST(DeckControl, UnitSystemTimeOutputAndTitle) {
  const Model m = read(R"(*TITLE
"Two blocks"
*UNIT_SYSTEM
MM/TON/S, C
*TIME
2.0e-3, 0.5, 1.0e-9, 1.0e-5, , 1.0e-4
*OUTPUT
1.0e-5, 1.0e-6
)")
                      .model;
  EXPECT_EQ(m.title, "Two blocks");
  EXPECT_EQ(m.units, UnitSystem::MMTONS);
  EXPECT_DOUBLE_EQ(m.time.end_time, 2.0e-3);
  EXPECT_DOUBLE_EQ(m.time.step_scale, 0.5);
  EXPECT_DOUBLE_EQ(m.time.min_step, 1.0e-9);
  EXPECT_DOUBLE_EQ(m.time.max_step, 1.0e-5);
  EXPECT_DOUBLE_EQ(m.time.start_time, 1.0e-4);
  EXPECT_DOUBLE_EQ(m.output.state_interval, 1.0e-5);
  EXPECT_DOUBLE_EQ(m.output.history_interval, 1.0e-6);
}

TEST(DeckControl, DefaultsOfTimeAndOutput) {
  const Model m = read("*TIME\n1.0\n").model;
  EXPECT_FALSE(m.units.has_value());
  EXPECT_DOUBLE_EQ(m.time.step_scale, 0.9);
  EXPECT_DOUBLE_EQ(m.time.min_step, 0.0);
  EXPECT_DOUBLE_EQ(m.time.max_step, 1e10);
  EXPECT_DOUBLE_EQ(m.output.state_interval, 0.0);  // 0: t_term/100 (the solver applies it)
}

TEST(DeckControl, RangesAndUnsupportedOptions) {
  EXPECT_EQ(error_of("*TIME\n0\n").where().field, "t_term");
  EXPECT_THAT(error_of("*TIME\n1, 1.5\n").message(), HasSubstr("(0, 1]"));
  EXPECT_THAT(error_of("*TIME\n1, , , , 100\n").message(),
              HasSubstr("mass scaling (ms_max) is not supported yet"));
  EXPECT_THAT(error_of("*TIME\nfcn(1)\n").message(), HasSubstr("not supported yet"));
  EXPECT_THAT(error_of("*UNIT_SYSTEM\nFURLONG\n*TIME\n1\n").message(),
              HasSubstr("expected SI, MMTONS"));
  EXPECT_THAT(error_of("*TIME\n1\n*TIME\n2\n").message(),
              HasSubstr("already has a *TIME at t.k:1"));
  EXPECT_THAT(error_of("*TIME\n1\n*OUTPUT\n1e-3, 1e-4, 1e-2\n").message(), HasSubstr("dt_db"));
  EXPECT_THAT(error_of("*TIME\n1\n*OUTPUT\n1e-3\n0, 0, P, 1\n").message(),
              HasSubstr("state-file output"));
}

// *OUTPUT_FIELDS (abut's own) chooses the fields of the states; an explicit run then writes those
// and part_id only.
TEST(DeckControl, OutputFieldsChooseTheStatesFields) {
  const Model m =
      model_of(with_box("*OUTPUT\n1.0e-3\n*OUTPUT_FIELDS\nDisplacement, velocity\n"
                        "von_mises_stress, velocity\n"));
  ASSERT_TRUE(m.output.state_fields.has_value());
  EXPECT_EQ(*m.output.state_fields,
            (std::vector<std::string>{"displacement", "velocity", "von_mises_stress"}));
  EXPECT_FALSE(model_of(kBoxModel).output.state_fields.has_value());  // every field
  const InputError unknown = error_of(with_box("*OUTPUT_FIELDS\ndisplacement, strain\n"));
  EXPECT_EQ(unknown.where().line, 14u);  // kBoxModel has 12 lines, then the keyword
  EXPECT_EQ(unknown.where().field, "field_2");
  EXPECT_THAT(unknown.message(), HasSubstr("expected a field of the states"));
  EXPECT_THAT(error_of(with_box("*OUTPUT_FIELDS\nvelocity\n*OUTPUT_FIELDS\nwear\n")).message(),
              HasSubstr("*OUTPUT_FIELDS is given twice"));

  const auto dir = std::filesystem::temp_directory_path() / "abut_test_output_fields";
  std::filesystem::remove_all(dir);
  std::ostringstream log;
  ASSERT_TRUE(run_simulation(m, {dir, 1, false}, log).stable) << log.str();
  std::ifstream vtu(dir / "states" / "state_0001.vtu");
  const std::string text((std::istreambuf_iterator<char>(vtu)), std::istreambuf_iterator<char>());
  for (const char* field : {"displacement", "velocity", "von_mises_stress", "part_id"})
    EXPECT_NE(text.find("Name=\"" + std::string(field) + "\""), std::string::npos) << field;
  for (const char* field : {"pressure", "plastic_strain", "thickness"})
    EXPECT_EQ(text.find("Name=\"" + std::string(field) + "\""), std::string::npos) << field;
  std::filesystem::remove_all(dir);
}

// A dt_min above the model's first stable step is the deck's error (the run could not take a
// step), at the dt_min field, not an instability of the run (found by deck_fuzz).
TEST(DeckControl, DtMinAboveTheFirstStableStepIsAnInputError) {
  std::string deck = kBoxModel;
  deck.replace(deck.find("1.0e-3\n"), 7, "1.0e-3, 1.0, 1.0e-2\n");
  const Model m = model_of(deck);
  try {
    Simulation sim(m);
    ADD_FAILURE() << "a run started with dt_min 1e-2 s on a steel box of 1 m elements";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 4u) << e.what();
    EXPECT_EQ(e.where().field, "dt_min") << e.what();
    EXPECT_THAT(e.message(), HasSubstr("above the initial stable time step"));
  }
}

TEST(DeckMesh, NodesWithConstraintsAndSolidElements) {
  const Model m = read(R"(*TIME
1
*NODE
10, 0, 0, 0, XYZ
20, 1, 0, 0, x
30, 1, 1, 0, zy
40, 0, 1, 0
50, 0, 0, 1, 0
60, 1, 0, 1
70, 1, 1, 1
80, 0, 1, 1
*ELEMENT_SOLID
7, 3, 10, 20, 30, 40, 50, 60, 70, 80
*MAT_RIGID
5, 7800.0
*PART
3, 5
)")
                      .model;
  ASSERT_EQ(m.mesh.nodes.size(), 8u);
  EXPECT_EQ(m.mesh.nodes.fixed[0], kFixX | kFixY | kFixZ);
  EXPECT_EQ(m.mesh.nodes.fixed[1], kFixX);
  EXPECT_EQ(m.mesh.nodes.fixed[2], kFixY | kFixZ);
  EXPECT_EQ(m.mesh.nodes.fixed[3], 0);
  ASSERT_EQ(m.mesh.hex_count(), 1u);
  EXPECT_EQ(m.mesh.hex_id[0], 7);
  EXPECT_EQ(m.mesh.hex_part[0], 3);
  EXPECT_EQ(m.mesh.hex_shape[0], -1);
  for (int k = 0; k < 8; ++k) EXPECT_EQ(m.mesh.hexes[0][k], k);
  EXPECT_TRUE(is_rigid(m.material_of_part(3)));
}

TEST(DeckMesh, ElementReferencesAreChecked) {
  const char* nodes =
      "*TIME\n1\n*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 1, 1, 0\n4, 0, 1, 0\n"
      "5, 0, 0, 1\n6, 1, 0, 1\n7, 1, 1, 1\n8, 0, 1, 1\n*MAT_RIGID\n1, 1000\n";
  const InputError missing_node =
      error_of(std::string(nodes) + "*PART\n1, 1\n*ELEMENT_SOLID\n1, 1, 1, 2, 9, 4, 5, 6, 7, 8\n");
  EXPECT_EQ(missing_node.where().line, 17u);
  EXPECT_EQ(missing_node.where().field, "n3");
  EXPECT_EQ(missing_node.message(), "node 9 does not exist");
  const InputError missing_part =
      error_of(std::string(nodes) + "*PART\n1, 1\n*ELEMENT_SOLID\n1, 2, 1, 2, 3, 4, 5, 6, 7, 8\n");
  EXPECT_EQ(missing_part.where().field, "pid");
  EXPECT_EQ(missing_part.message(), "part 2 does not exist (defined parts: 1)");
  EXPECT_THAT(error_of("*TIME\n1\n*NODE\n1, 0, 0, 0, XX\n").message(),
              HasSubstr("expected 0, X, Y, Z, XY"));
}

TEST(DeckMesh, BoxComponentOfTwoByTwoByOne) {
  const Model m = read(kBoxModel).model;
  EXPECT_EQ(m.mesh.nodes.size(), 18u);
  EXPECT_EQ(m.mesh.hex_count(), 4u);
  for (const auto p : m.mesh.hex_part) EXPECT_EQ(p, 1);
  double lo = 1e9, hi = -1e9;
  for (const double z : m.mesh.nodes.z) {
    lo = std::min(lo, z);
    hi = std::max(hi, z);
  }
  EXPECT_DOUBLE_EQ(lo, 0.0);
  EXPECT_DOUBLE_EQ(hi, 1.0);
  EXPECT_EQ(error_of("*TIME\n1\n*COMPONENT_BOX\n1, 1, 0, 1, 1\n0, 0, 0, 1, 1, 1\n").where().field,
            "N_x");
  EXPECT_THAT(error_of("*TIME\n1\n*COMPONENT_BOX\n1, 1, 1, 1, 1\n0, 0, 0, 1, 1, 0\n").message(),
              HasSubstr("non-zero size along z"));
  EXPECT_THAT(error_of("*TIME\n1\n*COMPONENT_BOX\n1, 1, 1, 1, 1, 4\n0, 0, 0, 1, 1, 1\n").message(),
              HasSubstr("local coordinate system (csysid) is not supported yet"));
}

TEST(DeckMesh, SphereComponentsSolidAndHollow) {
  const Model m = read(R"(*TIME
1
*COMPONENT_SPHERE
"solid"
1, 1, 3
0.0, 0.0, 0.03, 0.01
*COMPONENT_SPHERE
2, 2, 2
0.0, 0.0, 0.1, 0.01, 0.02
*MAT_RIGID
1, 1000
*PART
1, 1
2, 1
)")
                      .model;
  std::size_t part1 = 0, part2 = 0;
  for (const auto p : m.mesh.hex_part) (p == 1 ? part1 : part2) += 1;
  EXPECT_GT(part1, 0u);
  EXPECT_GT(part2, 0u);
  EXPECT_EQ(part1 + part2, m.mesh.hex_count());
  EXPECT_THAT(error_of("*TIME\n1\n*COMPONENT_SPHERE\n1, 1, 3\n0, 0, 0, 0.02, 0.01\n").message(),
              HasSubstr("outer radius > R1"));
  EXPECT_THAT(error_of("*TIME\n1\n*COMPONENT_SPHERE\n1, 1, 3, 4, 0, 90\n0, 0, 0, 0.02\n").message(),
              HasSubstr("sphere sector"));
  EXPECT_EQ(error_of("*TIME\n1\n*COMPONENT_SPHERE\n1, 1, 3\n0, 0, 0, -1\n").where().field, "R1");
}

TEST(DeckMesh, CylinderComponent) {
  const Model m = read(
                      "*TIME\n1\n*COMPONENT_CYLINDER\n1, 4, 3, 2\n0, 0, 0, 0, 0, 0.1, 0.02\n"
                      "*MAT_RIGID\n1, 1000\n*PART\n4, 1\n")
                      .model;
  EXPECT_GT(m.mesh.hex_count(), 0u);
  for (const auto p : m.mesh.hex_part) EXPECT_EQ(p, 4);
  EXPECT_EQ(error_of("*TIME\n1\n*COMPONENT_CYLINDER\n1, 4, 3, 2, 0, 3\n0, 0, 0, 0, 0, 0.1, 0.02\n")
                .where()
                .field,
            "symmetry");
  EXPECT_THAT(
      error_of("*TIME\n1\n*COMPONENT_CYLINDER\n1, 4, 3, 2\n0, 0, 0, 0, 0, 0, 0.02\n").message(),
      HasSubstr("differ from the first"));
}

TEST(DeckMesh, OrderChangeAndSmoothingAreReportedAsNotes) {
  const DeckResult r = read(with_box("*CHANGE_P-ORDER\nP, 1, 2\n*SMOOTH_MESH\nP, 1, 45.0\n"));
  EXPECT_FALSE(r.notes.empty());
  EXPECT_EQ(error_of(with_box("*CHANGE_P-ORDER\nP, 1, 4\n")).where().field, "order");
  EXPECT_THAT(error_of(with_box("*CHANGE_P-ORDER\nPS, 3, 2\n")).message(),
              HasSubstr("part set 3 does not exist"));
  EXPECT_THAT(error_of(with_box("*CHANGE_P-ORDER\nP, 1, 2, 8\n")).message(),
              HasSubstr("geometry 8 does not exist"));
  EXPECT_THAT(error_of(with_box("*SMOOTH_MESH\nP, 1, 200\n")).message(), HasSubstr("(0, 180]"));
  EXPECT_THAT(error_of(with_box("*SMOOTH_MESH\nP, 1, 30\n5\n")).message(), HasSubstr("csysid"));
  EXPECT_THAT(error_of(with_box("*SMOOTH_MESH\nNS, 1, 30\n")).message(),
              HasSubstr("entity type NS is not supported yet by abut for *SMOOTH_MESH"));
}

TEST(DeckMaterials, ElasticMooneyRivlinRigid) {
  const Model m = read(R"(*TIME
1
*MAT_ELASTIC
1, 7800.0, 210.0e9, 0.3
*MAT_MOONEY_RIVLIN
2, 1500.0, 3.0e9
1.0e6, 2.0e5, 1.0e2, 0.01, 3.0, 0.1, 4.0, 1.0
5.0, 10.0
*MAT_RIGID
3, 2700.0
)")
                      .model;
  ASSERT_EQ(m.materials.size(), 3u);
  const auto& e = std::get<ElasticParams>(m.find_material(1)->params);
  EXPECT_DOUBLE_EQ(e.young, 210.0e9);
  EXPECT_DOUBLE_EQ(e.poisson, 0.3);
  const auto& mr = std::get<MooneyRivlinParams>(m.find_material(2)->params);
  EXPECT_DOUBLE_EQ(mr.bulk, 3.0e9);
  EXPECT_DOUBLE_EQ(mr.c2, 2.0e5);
  EXPECT_EQ(mr.alpha, (std::array<double, 4>{1.0e2, 3.0, 4.0, 5.0}));
  EXPECT_EQ(mr.beta, (std::array<double, 4>{0.01, 0.1, 1.0, 10.0}));
  EXPECT_DOUBLE_EQ(density_of(m.find_material(3)->params), 2700.0);
}

TEST(DeckMaterials, RangesAndUnsupportedOptions) {
  const InputError nu = error_of("*TIME\n1\n*MAT_ELASTIC\n1, 7800.0, 210.0e9, 0.5\n");
  EXPECT_STREQ(nu.what(), "t.k:4: *MAT_ELASTIC, field 'nu': poisson must be in [0, 0.5), got 0.5");
  EXPECT_EQ(error_of("*TIME\n1\n*MAT_ELASTIC\n1, 0, 210.0e9, 0.3\n").where().field, "rho");
  EXPECT_EQ(error_of("*TIME\n1\n*MAT_ELASTIC\n1, 7800, -1, 0.3\n").where().field, "E");
  EXPECT_THAT(error_of("*TIME\n1\n*MAT_ELASTIC\n1, 7800, 1e9, 0.3, 4\n").message(),
              HasSubstr("damage property"));
  EXPECT_THAT(error_of("*TIME\n1\n*MAT_ELASTIC\n1, 7800, 1e9, 0.3\n0, 0, 0.05\n").message(),
              HasSubstr("material damping (c) is not supported yet"));
  EXPECT_EQ(error_of("*TIME\n1\n*MAT_MOONEY_RIVLIN\n1, 1500, 0\n1e6\n").where().field, "K");
  EXPECT_THAT(error_of("*TIME\n1\n*MAT_MOONEY_RIVLIN\n1, 1500, 3e9\n0, 0\n").message(),
              HasSubstr("C1 + C2 > 0"));
  EXPECT_EQ(error_of("*TIME\n1\n*MAT_MOONEY_RIVLIN\n1, 1500, 3e9\n1e6, 0, -1\n").where().field,
            "alpha1");
  EXPECT_THAT(error_of("*TIME\n1\n*MAT_MOONEY_RIVLIN\n1, 1500, 3e9\n").message(),
              HasSubstr("missing data line"));
}

TEST(DeckParts, TitlesSmoothingAngleAndReferences) {
  const DeckResult r = read(R"(*TIME
1
*COMPONENT_BOX
1, 1, 1, 1, 1
0, 0, 0, 1, 1, 1
*COMPONENT_BOX
2, 2, 1, 1, 1
0, 0, 2, 1, 1, 3
*MAT_RIGID
1, 1000
*PART
"first"
1, 1, , 1.0, 30.0
2, 1
*PART
3, 1
)");
  ASSERT_EQ(r.model.parts.size(), 3u);
  EXPECT_EQ(r.model.parts[0].title, "first");
  EXPECT_EQ(r.model.parts[1].title, "");
  EXPECT_EQ(r.model.parts[2].where.line, 16u);
  EXPECT_THAT(r.notes, ::testing::Contains("part 3 has no elements"));
  EXPECT_GE(r.notes.size(), 2u);  // the smoothing of part 1 (alpha_max = 30) reports too
  const InputError no_material = error_of("*TIME\n1\n*MAT_RIGID\n1, 1000\n*PART\n1, 2\n");
  EXPECT_EQ(no_material.where().field, "mid");
  EXPECT_EQ(no_material.message(), "material 2 does not exist (defined materials: 1)");
  const InputError no_part = error_of(
      "*TIME\n1\n*MAT_RIGID\n1, 1000\n*PART\n1, 1\n2, 1\n*COMPONENT_BOX\n1, 7, 1, 1, 1\n0, 0, 0, "
      "1, 1, 1\n");
  EXPECT_EQ(no_part.where().keyword, "*COMPONENT_BOX");
  EXPECT_EQ(no_part.message(), "part 7 does not exist (defined parts: 1, 2)");
  EXPECT_THAT(error_of("*TIME\n1\n*PART\n\"lonely title\"\n").message(),
              HasSubstr("must be followed by its pid, mid line"));
  // Erosion fields (IMPETUS *PART): read into the part; negative values are errors at their field.
  const Model eroding = testing::model_of(with_box("*PART\n2, 1, , , , 1e-9, 0.5, 0.3\n"));
  EXPECT_DOUBLE_EQ(eroding.parts.back().erosion.min_step, 1e-9);
  EXPECT_DOUBLE_EQ(eroding.parts.back().erosion.max_geometric_strain, 0.5);
  EXPECT_DOUBLE_EQ(eroding.parts.back().erosion.max_volumetric_strain, 0.3);
  EXPECT_EQ(error_of(with_box("*PART\n2, 1, , , , -1\n")).where().field, "dt_erode");
  EXPECT_EQ(error_of(with_box("*PART\n2, 1, , , , , 0\n")).where().field, "eps_geo_erode");
}

TEST(DeckSets, NodeAndPartSets) {
  const Model m = model_of(with_box(R"(*SET_NODE
"corners"
4
1, 3, 3
16, 18
*SET_PART
2
1, 1
)"));
  const auto nodes = m.nodes_of({EntityType::NodeSet, 4, {}});
  ASSERT_EQ(nodes.size(), 4u);  // sorted and unique
  EXPECT_EQ(m.mesh.nodes.id[nodes[0]], 1);
  EXPECT_EQ(m.mesh.nodes.id[nodes[3]], 18);
  EXPECT_EQ(m.parts_of({EntityType::PartSet, 2, {}}), (std::vector<std::int64_t>{1}));
  EXPECT_EQ(m.nodes_of({EntityType::PartSet, 2, {}}).size(), 18u);
  EXPECT_EQ(error_of(with_box("*SET_NODE\n4\n1, 99\n")).message(), "node 99 does not exist");
  EXPECT_EQ(error_of(with_box("*SET_PART\n4\n1, 5\n")).message(),
            "part 5 does not exist (defined parts: 1)");
  EXPECT_THAT(error_of(with_box("*SET_PART\n4\n")).message(), HasSubstr("member ids"));
}

TEST(DeckInitialVelocity, TranslationPlusRotationAboutACentre) {
  const Model m =
      model_of(with_box("*INITIAL_VELOCITY\nP, 1, 1.0, 2.0, 3.0, 0.0, 0.0, 10.0\n1.0, 1.0, 0.0\n"));
  ASSERT_EQ(m.vx0.size(), m.mesh.nodes.size());
  for (std::size_t i = 0; i < m.mesh.nodes.size(); ++i) {
    // v = v0 + omega x (p - p0) with omega = (0, 0, 10), p0 = (1, 1, 0).
    const double dx = m.mesh.nodes.x[i] - 1.0, dy = m.mesh.nodes.y[i] - 1.0;
    EXPECT_DOUBLE_EQ(m.vx0[i], 1.0 - 10.0 * dy);
    EXPECT_DOUBLE_EQ(m.vy0[i], 2.0 + 10.0 * dx);
    EXPECT_DOUBLE_EQ(m.vz0[i], 3.0);
  }
}

TEST(DeckInitialVelocity, LaterCommandsOverrideEarlierOnesOnTheirNodes) {
  const Model m = model_of(with_box(R"(*GEOMETRY_BOX
5
-1, -1, 0.5, 3, 3, 2
*INITIAL_VELOCITY
ALL, , 0, 0, -5
G, 5, 0, 0, 7
N, 1, 4, 0, -5
*FUNCTION
9
2.5
*INITIAL_VELOCITY
N, 2, fcn(9), 0, -5
)"));
  std::size_t top = 0;
  for (std::size_t i = 0; i < m.mesh.nodes.size(); ++i) {
    const bool is_top = m.mesh.nodes.z[i] > 0.5;
    top += is_top;
    EXPECT_DOUBLE_EQ(m.vz0[i], is_top ? 7.0 : -5.0);
  }
  EXPECT_EQ(top, 9u);
  EXPECT_DOUBLE_EQ(m.vx0[0], 4.0);  // node 1
  EXPECT_DOUBLE_EQ(m.vx0[1], 2.5);  // node 2: fcn(9) = 2.5
  EXPECT_THAT(error_of(with_box("*INITIAL_VELOCITY\nP, 2, 0, 0, 1\n")).message(),
              HasSubstr("part 2 does not exist"));
  EXPECT_THAT(error_of(with_box("*INITIAL_VELOCITY\nP, 1, fcn(4)\n")).message(), HasSubstr("4"));
  EXPECT_THAT(error_of(with_box("*INITIAL_VELOCITY\nP, 1, 0, 0, 1\n0, 0, 0, 1.0\n")).message(),
              HasSubstr("velocity gradient"));
  EXPECT_THAT(error_of(with_box("*INITIAL_VELOCITY\nSPH, 1, 0, 0, 1\n")).message(),
              HasSubstr("not supported yet"));
}

// Needs the real FunctionTable (variables in expressions); enable after the merge.
TEST(DeckInitialVelocity, FunctionOfTheNodeCoordinates) {
  const Model m =
      model_of(with_box("*FUNCTION\n1\n3.0 * X + Z\n*INITIAL_VELOCITY\nP, 1, fcn(1)\n"));
  for (std::size_t i = 0; i < m.mesh.nodes.size(); ++i) {
    EXPECT_DOUBLE_EQ(m.vx0[i], 3.0 * m.mesh.nodes.x[i] + m.mesh.nodes.z[i]);
  }
}

TEST(DeckBoundaryMotion, IdConstraintsAndPrescribedMotions) {
  const Model m = model_of(with_box(R"(*CURVE
"ramp"
3, 2.0, 10.0
0.0, 0.0
1.0, 1.0
*FUNCTION
4
1.0
*SET_NODE
1
1, 2, 3
*BC_MOTION
12
NS, 1, XY, , , , 0.1, 0.5
V, Z, 3, 2.0, 4
P, 1, 0
D, X, 4
)"));
  ASSERT_EQ(m.motions.size(), 2u);
  const MotionBoundary& a = m.motions[0];
  EXPECT_EQ(a.id, 12);
  EXPECT_EQ(a.entity.type, EntityType::NodeSet);
  EXPECT_EQ(a.fixed_translation, kFixX | kFixY);
  EXPECT_DOUBLE_EQ(a.begin_time, 0.1);
  EXPECT_DOUBLE_EQ(a.end_time, 0.5);
  ASSERT_EQ(a.motions.size(), 1u);
  EXPECT_EQ(a.motions[0].kind, PrescribedMotion::Kind::Velocity);
  EXPECT_EQ(a.motions[0].direction, 2);
  EXPECT_DOUBLE_EQ(a.motions[0].scale, 2.0);
  // The curve's scale factors apply: (0.5 * 2, 0.5 * 10) is on it.
  EXPECT_TRUE(m.functions.is_curve(a.motions[0].curve));
  EXPECT_DOUBLE_EQ(m.functions.value(a.motions[0].curve, 1.0, {}), 5.0);
  EXPECT_TRUE(a.motions[0].activation.valid());
  const MotionBoundary& b = m.motions[1];
  EXPECT_EQ(b.id, 0);
  EXPECT_EQ(b.fixed_translation, 0);
  EXPECT_DOUBLE_EQ(b.end_time, 1e10);
  ASSERT_EQ(b.motions.size(), 1u);
  EXPECT_EQ(b.motions[0].kind, PrescribedMotion::Kind::Displacement);
  EXPECT_FALSE(b.motions[0].activation.valid());
}

TEST(DeckBoundaryMotion, Errors) {
  EXPECT_THAT(error_of(with_box("*BC_MOTION\nP, 1, X\nV, X, 1\n")).message(),
              HasSubstr("already constrained"));
  EXPECT_THAT(error_of(with_box("*BC_MOTION\nP, 1, 0\n")).message(),
              HasSubstr("neither constrains"));
  EXPECT_THAT(error_of(with_box("*BC_MOTION\nP, 1, X, XYZ\n")).message(),
              HasSubstr("part 1 is a deformable solid"));
  EXPECT_THAT(error_of(with_box("*BC_MOTION\nN, 1, , , , , 1.0, 0.5\n")).message(),
              HasSubstr("t_end > t_beg"));
  EXPECT_THAT(error_of(with_box("*BC_MOTION\nP, 1\nV, X, 77\n")).message(), HasSubstr("77"));
  EXPECT_THAT(error_of(with_box("*BC_MOTION\nV, X, 1\n")).message(),
              HasSubstr("must follow an entype"));
  EXPECT_THAT(error_of(with_box("*BC_MOTION\nN, 99, X\n")).message(),
              HasSubstr("node 99 does not exist"));
  EXPECT_THAT(error_of(with_box("*BC_MOTION\nGS, 1, X\n")).message(),
              HasSubstr("not supported yet"));
  EXPECT_EQ(error_of(with_box("*BC_MOTION\nP, 1, W\n")).where().field, "bc_tr");
}

TEST(DeckBoundaryMotion, RotationsOfRigidParts) {
  const Model m =
      read(
          "*TIME\n1\n*COMPONENT_BOX\n1, 1, 1, 1, 1\n0, 0, 0, 1, 1, 1\n*MAT_RIGID\n1, 7800\n"
          "*PART\n1, 1\n*CURVE\n1\n0, 1\n*BC_MOTION\nP, 1, XY, XY\nV, RZ, 1\n")
          .model;
  EXPECT_EQ(m.motions[0].fixed_rotation, kFixX | kFixY);
  EXPECT_EQ(m.motions[0].motions[0].direction, 5);
}

TEST(DeckCurvesAndFunctions, Errors) {
  EXPECT_EQ(error_of("*TIME\n1\n*CURVE\n1\n0, 0\n1, 1\n0.5, 2\n").where().line, 7u);
  EXPECT_THAT(error_of("*TIME\n1\n*CURVE\n1, 1, 1, furlongs\n0, 0\n").message(),
              HasSubstr("expected time, length"));
  EXPECT_THAT(error_of("*TIME\n1\n*FUNCTION\n1, 1\nt\n").message(),
              HasSubstr("derivative > 0) are not supported yet"));
  EXPECT_THAT(error_of("*TIME\n1\n*FUNCTION\n1\n").message(), HasSubstr("expression"));
  EXPECT_THAT(error_of("*TIME\n1\n*CURVE\n1\n0, 0\n*FUNCTION\n1\n2\n").message(),
              HasSubstr("id 1 is already used"));
}

TEST(DeckLoads, Gravity) {
  const Model m =
      model_of(with_box("*CURVE\n1\n0.0, -9.81\n1.0, -9.81\n*LOAD_GRAVITY\nZ, 1, , , 2.0\n"));
  ASSERT_EQ(m.gravity.size(), 1u);
  EXPECT_EQ(m.gravity[0].direction, 2);
  EXPECT_DOUBLE_EQ(m.gravity[0].scale, 2.0);
  EXPECT_DOUBLE_EQ(m.functions.value(m.gravity[0].curve, 0.5, {}), -9.81);
  EXPECT_EQ(error_of(with_box("*LOAD_GRAVITY\nRZ, 1\n")).where().field, "direc");
  EXPECT_THAT(error_of(with_box("*LOAD_GRAVITY\nZ, 1, 1\n")).message(), HasSubstr("addmass"));
}

TEST(DeckGeometry, AllFiveKinds) {
  const Model m = model_of(with_box(R"(*GEOMETRY_BOX
"box"
1
1, 1, 1, 0, 0, 0
*GEOMETRY_SPHERE
2
0, 0, 1, 0.5, 0.75
*GEOMETRY_PIPE
3
0, 0, 0, 0, 0, 2, 0.1, 0.2
0.3, 0.4, 1, 0, 0, 90
*GEOMETRY_ELLIPSOID
4, 0
0, 0, 0, 1, 2, 3
*GEOMETRY_PART
5
1
)"));
  ASSERT_EQ(m.geometries.size(), 5u);
  const auto& box = std::get<GeometryBox>(m.find_geometry(1)->geometry);
  EXPECT_DOUBLE_EQ(box.corner1.x, 0.0);
  EXPECT_DOUBLE_EQ(box.corner2.x, 1.0);
  const auto& sphere = std::get<GeometrySphere>(m.find_geometry(2)->geometry);
  EXPECT_DOUBLE_EQ(sphere.radius2, 0.75);
  const auto& pipe = std::get<GeometryPipe>(m.find_geometry(3)->geometry);
  EXPECT_DOUBLE_EQ(pipe.radius3, 0.3);
  EXPECT_DOUBLE_EQ(pipe.radius4, 0.4);
  EXPECT_DOUBLE_EQ(pipe.reference.x, 1.0);
  EXPECT_DOUBLE_EQ(pipe.sector_angle, 90.0);
  EXPECT_DOUBLE_EQ(std::get<GeometryEllipsoid>(m.find_geometry(4)->geometry).semi_axes.z, 3.0);
  EXPECT_EQ(std::get<GeometryPart>(m.find_geometry(5)->geometry).part_id, 1);
  EXPECT_THAT(error_of(with_box("*GEOMETRY_PART\n5\n2\n")).message(),
              HasSubstr("part 2 does not exist"));
  EXPECT_THAT(error_of(with_box("*GEOMETRY_SPHERE\n2\n0, 0, 0, 1, 0.5\n")).message(),
              HasSubstr("outer radius > R1"));
  EXPECT_THAT(error_of(with_box("*GEOMETRY_BOX\n1, 3\n0, 0, 0, 1, 1, 1\n")).message(),
              HasSubstr("csysid"));
  EXPECT_THAT(
      error_of(with_box("*GEOMETRY_BOX\n1\n0, 0, 0, 1, 1, 1\n*GEOMETRY_SPHERE\n1\n0, 0, 0, 1\n"))
          .message(),
      HasSubstr("geometry 1 is already defined"));
}

TEST(DeckContact, AllFourLines) {
  const Model m = model_of(with_box(R"(*COMPONENT_BOX
2, 2, 1, 1, 1
0, 0, 2, 1, 1, 3
*PART
2, 1
*SET_PART
7
1, 2
*FUNCTION
3
0.2
*FUNCTION
5
1.0e-9
*GEOMETRY_BOX
8
-5, -5, -5, 5, 5, 5
*CONTACT
"blocks"
4, 3, 1
PS, 7, ALL, , fcn(3), 1.0e12, 0.001, 0.5
1, 0.2, 8, 8, 1.0e-4, 2.0e-4, 1.0e-5
5, 5, , 30.0, 1, 1, 1.0e6, 0
)"));
  ASSERT_EQ(m.contacts.size(), 1u);
  const ContactSpec& c = m.contacts[0];
  EXPECT_EQ(c.id, 4);
  EXPECT_EQ(c.title, "blocks");
  EXPECT_EQ(c.accuracy_level, 3);
  EXPECT_TRUE(c.accuracy_edge);
  EXPECT_EQ(c.surface1.type, EntityType::PartSet);
  EXPECT_EQ(c.surface1.id, 7);
  EXPECT_EQ(c.surface2.type, EntityType::All);
  ASSERT_TRUE(c.friction_function.valid());
  EXPECT_DOUBLE_EQ(m.functions.value(c.friction_function, {}), 0.2);
  EXPECT_EQ(c.penalty, 1.0e12);
  EXPECT_DOUBLE_EQ(c.begin_time, 0.001);
  EXPECT_DOUBLE_EQ(c.end_time, 0.5);
  EXPECT_TRUE(c.merge);
  EXPECT_DOUBLE_EQ(c.damping, 0.2);
  EXPECT_EQ(c.initial_geometry, 8);
  EXPECT_EQ(c.moving_geometry, 8);
  EXPECT_DOUBLE_EQ(c.initial_offset, 1.0e-4);
  EXPECT_EQ(c.initial_max, 2.0e-4);
  EXPECT_DOUBLE_EQ(c.edge_tolerance, 1.0e-5);
  EXPECT_TRUE(c.wear1.valid());
  EXPECT_TRUE(c.wear2.valid());
  EXPECT_FALSE(c.thermal.valid());
  EXPECT_DOUBLE_EQ(c.edge_angle, 30.0);
  EXPECT_TRUE(c.one_way);
  EXPECT_TRUE(c.no_internal);
  EXPECT_EQ(c.stick_stress, 1.0e6);
  EXPECT_FALSE(c.friction_heat);
}

TEST(DeckContact, DefaultsAndErrors) {
  const Model m = model_of(with_box("*CONTACT\n1\nP, 1, P, 1\n"));
  const ContactSpec& c = m.contacts[0];
  EXPECT_EQ(c.accuracy_level, 2);
  EXPECT_DOUBLE_EQ(c.friction, 0.0);
  EXPECT_FALSE(c.penalty.has_value());
  EXPECT_DOUBLE_EQ(c.end_time, 1e20);
  EXPECT_DOUBLE_EQ(c.damping, 0.1);
  EXPECT_FALSE(c.initial_max.has_value());
  EXPECT_DOUBLE_EQ(c.edge_angle, 20.0);
  EXPECT_THAT(error_of(with_box("*CONTACT\n1\nP, 1, P, 9\n")).message(),
              HasSubstr("part 9 does not exist"));
  EXPECT_THAT(error_of(with_box("*CONTACT\n1\nP, 1, N, 9\n")).message(),
              HasSubstr("not supported yet"));
  EXPECT_EQ(error_of(with_box("*CONTACT\n1\nP, 1, P, 1, -0.1\n")).where().field, "mu");
  EXPECT_THAT(error_of(with_box("*CONTACT\n1\nP, 1, P, 1\n0, 0.1, 3\n")).message(),
              HasSubstr("geometry 3 does not exist"));
  EXPECT_EQ(error_of(with_box("*CONTACT\n1\nP, 1, P, 1\n0\n0, 0, 7\n")).where().field,
            "fid_thermal");  // no *FUNCTION 7
  EXPECT_THAT(error_of(with_box("*CONTACT\n1\nP, 1, P, 1, fcn(6)\n")).message(), HasSubstr("6"));
}

}  // namespace
}  // namespace abut
