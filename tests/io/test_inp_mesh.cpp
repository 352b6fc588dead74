// The .inp reader, model data: nodes, elements, sets, surfaces, materials and sections, and the
// syntax shared by every keyword (case, continuation lines, comments, *INCLUDE).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "abut/io/deck.hpp"

namespace abut {
namespace {

namespace fs = std::filesystem;

// Two unit cubes side by side along x: node id = 1 + i + 3 j + 6 k at (i, j, k).
const std::string kNodes = R"(*NODE, NSET=NALL
1, 0., 0., 0.
2, 1., 0., 0.
3, 2., 0., 0.
4, 0., 1., 0.
5, 1., 1., 0.
6, 2., 1., 0.
7, 0., 0., 1.
8, 1., 0., 1.
9, 2., 0., 1.
10, 0., 1., 1.
11, 1., 1., 1.
12, 2., 1., 1.
)";
const std::string kElements = R"(*ELEMENT, TYPE=C3D8, ELSET=EALL
1, 1, 2, 5, 4, 7, 8, 11, 10
2, 2, 3, 6, 5, 8, 9, 12, 11
)";
const std::string kSection = R"(*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL
)";
const std::string kStep = "*STEP\n*STATIC\n*END STEP\n";

DeckResult read(const std::string& text) { return read_inp_string_with_notes(text, "t.inp"); }
Model model_of(const std::string& text) { return read(text).model; }

std::set<std::int64_t> node_ids(const Model& m, const std::vector<std::int32_t>& nodes) {
  std::set<std::int64_t> ids;
  for (const std::int32_t n : nodes) ids.insert(m.mesh.nodes.id[static_cast<std::size_t>(n)]);
  return ids;
}

std::set<std::int64_t> face_ids(const Model& m, const SolidFace& f) {
  std::set<std::int64_t> ids;
  for (const int a : kHexFaces[f.face])
    ids.insert(m.mesh.nodes.id[static_cast<std::size_t>(m.mesh.hexes[f.solid][a])]);
  return ids;
}

// A node that no element uses is kept, and a note names it (the static solver gives it no
// equations, as CalculiX does).
TEST(InpMesh, NodeOfNoElementIsNoted) {
  const DeckResult r = read(kNodes + "13, 5., 5., 5.\n" + kElements + kSection + kStep);
  EXPECT_EQ(r.model.mesh.nodes.size(), 13u);
  bool noted = false;
  for (const std::string& note : r.notes)
    noted = noted || note.find("1 node (13) belongs to no element") != std::string::npos;
  EXPECT_TRUE(noted);
  for (const std::string& note : read(kNodes + kElements + kSection + kStep).notes)
    EXPECT_EQ(note.find("belong"), std::string::npos) << note;
}

TEST(InpMesh, NodesAndElementsKeepTheirIdsAndOrder) {
  const Model m = model_of(kNodes + kElements + kSection + kStep);
  ASSERT_EQ(m.mesh.nodes.size(), 12u);
  EXPECT_EQ(m.mesh.nodes.id[11], 12);
  EXPECT_EQ(m.mesh.nodes.x[2], 2.0);
  EXPECT_EQ(m.mesh.nodes.z[11], 1.0);
  ASSERT_EQ(m.mesh.hex_count(), 2u);
  EXPECT_EQ(m.mesh.hex_id[1], 2);
  // C3D8 node order is abut's: hex 2 is nodes 2, 3, 6, 5, 8, 9, 12, 11.
  const std::int64_t expected[8] = {2, 3, 6, 5, 8, 9, 12, 11};
  for (std::size_t k = 0; k < 8; ++k)
    EXPECT_EQ(m.mesh.nodes.id[static_cast<std::size_t>(m.mesh.hexes[1][k])], expected[k]);
  ASSERT_EQ(m.node_sets.size(), 1u);  // NALL
  EXPECT_EQ(m.node_sets[0].nodes.size(), 12u);
  EXPECT_EQ(m.vx0.size(), 12u);
  EXPECT_EQ(m.wz0.size(), 12u);
}

TEST(InpMesh, SectionsBecomePartsWithTheirIntegration) {
  const Model m = model_of(kNodes + R"(*ELEMENT, TYPE=C3D8, ELSET=LEFT
1, 1, 2, 5, 4, 7, 8, 11, 10
*ELEMENT, TYPE=C3D8R, ELSET=RIGHT
2, 2, 3, 6, 5, 8, 9, 12, 11
*MATERIAL, NAME=SOFT
*ELASTIC
1000., 0.25
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*DENSITY
7.8e-9
*SOLID SECTION, ELSET=RIGHT, MATERIAL=STEEL
*SOLID SECTION, ELSET=LEFT, MATERIAL=SOFT
)" + kStep);
  ASSERT_EQ(m.parts.size(), 2u);
  EXPECT_EQ(m.parts[0].id, 1);
  EXPECT_EQ(m.parts[0].title, "RIGHT");
  EXPECT_EQ(m.parts[0].solid_integration, Part::SolidIntegration::Reduced);
  EXPECT_EQ(m.parts[1].title, "LEFT");
  EXPECT_EQ(m.parts[1].solid_integration, Part::SolidIntegration::Full);
  EXPECT_EQ(m.mesh.hex_part[0], 2);  // element 1 is in LEFT, the second section
  EXPECT_EQ(m.mesh.hex_part[1], 1);
  const auto& steel = std::get<ElasticParams>(m.material_of_part(1));
  EXPECT_EQ(steel.young, 210000.0);
  EXPECT_EQ(steel.poisson, 0.3);
  EXPECT_EQ(steel.density, 7.8e-9);
  const auto& soft = std::get<ElasticParams>(m.material_of_part(2));
  EXPECT_EQ(soft.young, 1000.0);
  EXPECT_EQ(soft.density, 0.0);  // no *DENSITY: 0, fine for static steps
}

// *PLASTIC makes the material J2 plastic with the table as its flow curve (constant beyond the
// last point, as in CalculiX).
TEST(InpMesh, PlasticMaterialHasItsFlowCurve) {
  const Model m = model_of(kNodes + R"(*ELEMENT, TYPE=C3D8, ELSET=EALL
1, 1, 2, 5, 4, 7, 8, 11, 10
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*PLASTIC
250., 0.
350., 0.1
*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL
)" + kStep);
  const auto& steel = std::get<MetalParams>(m.material_of_part(1));
  EXPECT_EQ(steel.young, 210000.0);
  EXPECT_EQ(steel.poisson, 0.3);
  EXPECT_FALSE(steel.johnson_cook);
  const Variables v;
  EXPECT_DOUBLE_EQ(m.functions.value(steel.flow_curve, 0.0, v), 250.0);
  EXPECT_DOUBLE_EQ(m.functions.value(steel.flow_curve, 0.05, v), 300.0);
  EXPECT_DOUBLE_EQ(m.functions.value(steel.flow_curve, 0.5, v), 350.0);
}

TEST(InpMesh, OneSectionOverTwoElementTypesMakesTwoParts) {
  const Model m = model_of(kNodes + R"(*ELEMENT, TYPE=C3D8R, ELSET=EALL
1, 1, 2, 5, 4, 7, 8, 11, 10
*ELEMENT, TYPE=C3D8, ELSET=EALL
2, 2, 3, 6, 5, 8, 9, 12, 11
)" + kSection + kStep);
  ASSERT_EQ(m.parts.size(), 2u);
  EXPECT_EQ(m.parts[0].title, "EALL (C3D8R)");
  EXPECT_EQ(m.parts[0].solid_integration, Part::SolidIntegration::Reduced);
  EXPECT_EQ(m.parts[1].title, "EALL (C3D8)");
  EXPECT_EQ(m.parts[1].solid_integration, Part::SolidIntegration::Full);
  EXPECT_EQ(m.parts[0].material_id, m.parts[1].material_id);
}

TEST(InpMesh, SetsWithGenerateAndNestedNames) {
  const Model m = model_of(kNodes + kElements + kSection + R"(*NSET, NSET=ODD, GENERATE
1, 11, 2
*NSET, NSET=MIX
ODD, 2,
4
*NSET, NSET=ODD
12
*ELSET, ELSET=SECOND, GENERATE
2, 2
*BOUNDARY
MIX, 1, 3
*STEP
*STATIC
*EL PRINT, ELSET=SECOND
S
*END STEP
)");
  // NALL, ODD, MIX: ids in order of definition.
  ASSERT_EQ(m.node_sets.size(), 3u);
  EXPECT_EQ(node_ids(m, m.node_sets[1].nodes), (std::set<std::int64_t>{1, 3, 5, 7, 9, 11, 12}));
  // MIX copied ODD as it was then (without 12, added later).
  EXPECT_EQ(node_ids(m, m.node_sets[2].nodes), (std::set<std::int64_t>{1, 2, 3, 4, 5, 7, 9, 11}));
  EXPECT_EQ(m.static_steps[0].displacements.size(), 8u * 3u);
  ASSERT_EQ(m.static_steps[0].prints.size(), 1u);
  EXPECT_EQ(m.static_steps[0].prints[0].members, (std::vector<std::int32_t>{1}));
}

TEST(InpMesh, SurfaceFacesS1ToS6AreTheCalculixFaces) {
  std::string surfaces;
  for (int k = 1; k <= 6; ++k)
    surfaces += "*SURFACE, NAME=F" + std::to_string(k) + "\n1, S" + std::to_string(k) + "\n";
  const Model m = model_of(kNodes + kElements + kSection + surfaces + kStep);
  ASSERT_EQ(m.face_sets.size(), 6u);
  // CalculiX hexahedron faces (manual, *SURFACE): 1-2-3-4, 5-8-7-6, 1-5-6-2, 2-6-7-3, 3-7-8-4,
  // 4-8-5-1 in the element's node numbering; element 1 is 1, 2, 5, 4, 7, 8, 11, 10.
  const std::int64_t element[8] = {1, 2, 5, 4, 7, 8, 11, 10};
  const int calculix[6][4] = {{1, 2, 3, 4}, {5, 8, 7, 6}, {1, 5, 6, 2},
                              {2, 6, 7, 3}, {3, 7, 8, 4}, {4, 8, 5, 1}};
  for (int k = 0; k < 6; ++k) {
    const FaceSet& s = m.face_sets[static_cast<std::size_t>(k)];
    EXPECT_EQ(s.name, "F" + std::to_string(k + 1));
    EXPECT_EQ(s.id, k + 1);
    ASSERT_EQ(s.faces.size(), 1u);
    EXPECT_EQ(s.faces[0].solid, 0);
    EXPECT_EQ(s.faces[0].face, k);
    std::set<std::int64_t> expected;
    for (const int a : calculix[k]) expected.insert(element[a - 1]);
    EXPECT_EQ(face_ids(m, s.faces[0]), expected) << "S" << k + 1;
  }
}

TEST(InpMesh, SurfacesFromElementSetsAndNodes) {
  const Model m = model_of(kNodes + kElements + kSection + R"(*NSET, NSET=TOP
7, 8
*SURFACE, NAME=BOTTOM
EALL, S1
*SURFACE, NAME=TIPS, TYPE=NODE
TOP
12, 1.0
)" + kStep);
  ASSERT_EQ(m.face_sets.size(), 1u);
  ASSERT_EQ(m.face_sets[0].faces.size(), 2u);
  EXPECT_EQ(m.face_sets[0].faces[1].solid, 1);
  EXPECT_EQ(face_ids(m, m.face_sets[0].faces[1]), (std::set<std::int64_t>{2, 3, 5, 6}));
  // NALL, TOP, then the node surface as a node set of its own.
  ASSERT_EQ(m.node_sets.size(), 3u);
  EXPECT_EQ(node_ids(m, m.node_sets[2].nodes), (std::set<std::int64_t>{7, 8, 12}));
}

TEST(InpMesh, HeadingIsTheTitle) {
  const Model m = model_of("*HEADING\nTwo cubes\n" + kNodes + kElements + kSection + kStep);
  EXPECT_EQ(m.title, "Two cubes");
  EXPECT_EQ(m.deck_path, "t.inp");
}

TEST(InpSyntax, KeywordsParametersAndNamesIgnoreCase) {
  const Model m = model_of(R"(** lower case everywhere, blanks in keywords
*node, nset=nall
1, 0., 0., 0.
2, 1., 0., 0.
4, 0., 1., 0.
5, 1., 1., 0.
7, 0., 0., 1.
8, 1., 0., 1.
10, 0., 1., 1.
11, 1., 1., 1.
*element, type=c3d8r, elset=Eall
1, 1, 2, 5, 4, 7, 8, 11, 10
*Material, Name=Steel
*elastic, type=iso
210000., 0.3
*solid   section, elset=EALL, material=STEEL
*boundary
NAll, 1, 3
*Step, nlgeom=yes
*static, direct
0.5, 1.
*node print, nset=NALL, totals=Only
u
*EndStep
)");
  EXPECT_EQ(m.mesh.hex_count(), 1u);
  EXPECT_EQ(m.parts.at(0).solid_integration, Part::SolidIntegration::Reduced);
  const StaticStep& s = m.static_steps.at(0);
  EXPECT_TRUE(s.nonlinear_geometry);
  EXPECT_TRUE(s.fixed_increments);
  EXPECT_EQ(s.initial_increment, 0.5);
  EXPECT_EQ(s.displacements.size(), 24u);
  ASSERT_EQ(s.prints.size(), 1u);
  EXPECT_EQ(s.prints[0].quantities, (std::vector<std::string>{"U"}));
  EXPECT_TRUE(s.prints[0].totals_only);
}

TEST(InpSyntax, ContinuationLinesCommentsAndBlankLines) {
  const Model m = model_of(kNodes + R"(** the keyword line goes on after a trailing comma
*ELEMENT, TYPE=C3D8,

   ELSET=EALL
** an element split over two lines
1, 1, 2, 5, 4,
   7, 8, 11, 10
2, 2, 3, 6, 5, 8, 9, 12, 11,
)" + kSection + kStep);
  ASSERT_EQ(m.mesh.hex_count(), 2u);
  EXPECT_EQ(m.mesh.nodes.id[static_cast<std::size_t>(m.mesh.hexes[0][7])], 10);
  EXPECT_EQ(m.parts.at(0).title, "EALL");
}

// A scratch directory with the given files, removed at the end of the test.
class InpInclude : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("abut_inp_include_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "mesh");
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p;
  }
  fs::path dir_;
};

TEST_F(InpInclude, IncludesAreRelativeToTheIncludingFileAndMayHoldDataLines) {
  write("mesh/nodes.txt", kNodes.substr(kNodes.find('\n') + 1));  // data lines only
  write("mesh/mesh.inp", "*NODE, NSET=NALL\n*INCLUDE, INPUT=nodes.txt\n" + kElements);
  const fs::path main =
      write("model.inp", "*INCLUDE, INPUT=\"mesh/mesh.inp\"\n" + kSection + kStep);
  // read_deck picks the .inp reader by the extension.
  const Model m = read_deck(main.string());
  EXPECT_EQ(m.mesh.nodes.size(), 12u);
  EXPECT_EQ(m.mesh.hex_count(), 2u);
  EXPECT_EQ(m.node_sets.at(0).nodes.size(), 12u);
  const fs::path upper = write("MODEL2.INP", "*INCLUDE, INPUT=mesh/mesh.inp\n" + kSection + kStep);
  EXPECT_EQ(read_deck(upper.string()).mesh.hex_count(), 2u);
}

TEST_F(InpInclude, MissingFileAndCyclesAreErrorsAtTheIncludeLine) {
  const fs::path main = write("model.inp", kNodes + "*INCLUDE, INPUT=mesh/missing.inp\n");
  try {
    read_inp_with_notes(main.string());
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, main.string());
    EXPECT_EQ(e.where().line, 14u);
    EXPECT_NE(e.message().find("cannot open the included file"), std::string::npos) << e.what();
  }
  const fs::path a = write("a.inp", "** a\n*INCLUDE, INPUT=b.inp\n");
  write("b.inp", "*INCLUDE, INPUT=a.inp\n");
  try {
    read_inp_with_notes(a.string());
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("includes itself"), std::string::npos) << e.what();
    EXPECT_EQ(e.where().line, 1u);
    EXPECT_NE(e.where().file.find("b.inp"), std::string::npos);
  }
}

}  // namespace
}  // namespace abut
