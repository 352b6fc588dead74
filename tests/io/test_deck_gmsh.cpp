// *INCLUDE_GMSH (src/io/keyword_gmsh.cpp; docs/deck-reference.md): what the physical groups of a
// Gmsh mesh become, every element type abut reads from Gmsh with its node order checked by
// geometry, and the errors, each located.
#include <gmsh.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "abut/mesh/shape_functions.hpp"
#include "abut/mesh/skin.hpp"
#include "test_deck_helpers.hpp"
#include "test_files.hpp"

namespace abut {
namespace {

namespace fs = std::filesystem;

class DeckGmsh : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::fresh_dir("abut_deck_gmsh");
    fs::create_directories(dir_);
    fs::copy_file(std::string(ABUT_SOURCE_DIR) + "/tests/io/decks/cube.msh", dir_ / "cube.msh");
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) const {
    testing::write_text(dir_ / name, text);
    return (dir_ / name).string();
  }
  DeckResult read(const std::string& deck) const {
    return read_deck_with_notes(write("deck.k", deck));
  }
  // The error reading `deck` raises.
  InputError error(const std::string& deck) const {
    try {
      read(deck);
    } catch (const InputError& e) {
      return e;
    }
    ADD_FAILURE() << "no error for\n" << deck;
    return InputError("none");
  }

  fs::path dir_;
};

const std::string kSteel = "*MAT_ELASTIC\n1, 7800.0, 210.0e9, 0.3\n";

// cube.msh: hex 1 in physical volume 1 "cube", its bottom quad 2 in physical surface 2
// "bottom", node 1 in physical point 3 "corner".
TEST_F(DeckGmsh, PhysicalGroupsBecomePartsFaceSetsAndNodeSets) {
  const DeckResult r = read("*TIME\n1.0\n*INCLUDE_GMSH\ncube.msh\n" + kSteel +
                            "*PART\n1, 1\n*BC_MOTION\nNS, 3, XYZ\n");
  const Model& m = r.model;
  ASSERT_EQ(m.mesh.hex_count(), 1u);
  EXPECT_EQ(m.mesh.hex_id[0], 1);
  EXPECT_EQ(m.mesh.hex_part[0], 1);
  EXPECT_EQ(m.mesh.nodes.size(), 8u);
  ASSERT_EQ(m.face_sets.size(), 1u);
  EXPECT_EQ(m.face_sets[0].id, 2);
  EXPECT_EQ(m.face_sets[0].name, "bottom");
  ASSERT_EQ(m.face_sets[0].faces.size(), 1u);
  EXPECT_EQ(m.face_sets[0].faces[0].face, 0);  // S1, the bottom (zeta = -1)
  // Node sets 2 (the bottom's 4 nodes) and 3 (node 1).
  ASSERT_EQ(m.node_sets.size(), 2u);
  std::map<std::int64_t, std::size_t> sizes;
  for (const NodeSet& s : m.node_sets) sizes[s.id] = s.nodes.size();
  EXPECT_EQ(sizes.at(2), 4u);
  EXPECT_EQ(sizes.at(3), 1u);
}

TEST_F(DeckGmsh, OffsetsAndPlacementApply) {
  const DeckResult r = read(
      "*TIME\n1.0\n*INCLUDE_GMSH\ncube.msh\n,\n2, 2, 2, 100, 200, 10, 0, 1000\n0, 0, 0, 5, 0, 0\n" +
      kSteel + "*PART\n11, 1\n");
  const Model& m = r.model;
  EXPECT_EQ(m.mesh.hex_id[0], 201);
  EXPECT_EQ(m.mesh.hex_part[0], 11);
  EXPECT_EQ(m.mesh.nodes.id[0], 101);
  std::set<std::int64_t> sets;
  for (const NodeSet& s : m.node_sets) sets.insert(s.id);
  EXPECT_EQ(sets, (std::set<std::int64_t>{1002, 1003}));
  EXPECT_EQ(m.face_sets.at(0).id, 1002);
  // Node 7 at (1, 1, 1): scaled by 2, moved by 5 along x.
  const auto seven =
      std::find(m.mesh.nodes.id.begin(), m.mesh.nodes.id.end(), 107) - m.mesh.nodes.id.begin();
  EXPECT_EQ(m.mesh.nodes.x[static_cast<std::size_t>(seven)], 7.0);
  EXPECT_EQ(m.mesh.nodes.z[static_cast<std::size_t>(seven)], 2.0);
}

// A plate of 2 x 1 quadrilaterals in physical surface 4: shells of part 4 when *PART 4 gives a
// thickness, and face set 4 of those shells.
TEST_F(DeckGmsh, APhysicalSurfaceWithAThicknessIsShells) {
  write("plate.msh", R"($MeshFormat
4.1 0 8
$EndMeshFormat
$Entities
0 0 1 0
1 0 0 0 2 1 0 1 4 0
$EndEntities
$Nodes
1 6 1 6
2 1 0 6
1
2
3
4
5
6
0 0 0
1 0 0
2 0 0
0 1 0
1 1 0
2 1 0
$EndNodes
$Elements
1 2 1 2
2 1 3 2
1 1 2 5 4
2 2 3 6 5
$EndElements
)");
  const DeckResult r =
      read("*TIME\n1.0\n*INCLUDE_GMSH\nplate.msh\n" + kSteel + "*PART\n4, 1, , 0.01\n");
  EXPECT_EQ(r.model.mesh.shell_count(), 2u);
  EXPECT_EQ(r.model.mesh.shell_part[1], 4);
  ASSERT_EQ(r.model.face_sets.size(), 1u);
  EXPECT_EQ(r.model.face_sets[0].shells.size(), 2u);
}

// Gmsh meshes of a 2 x 1 x 1 box with every solid type abut reads from Gmsh (its own node
// orders turned into abut's, tested through geometry): every element has a positive volume, the
// volumes add up to the box's, and the exterior faces' areas to its surface, 10. A wrong node
// order turns elements inside out or leaves faces inside.
TEST_F(DeckGmsh, EverySolidTypeFillsTheBoxItMeshes) {
  struct Case {
    const char* name;
    CellType type;
    const char* options;  // .geo lines after the box
  };
  const Case cases[] = {
      {"tet4", CellType::tet4, "Mesh.MeshSizeMax = 0.5;"},
      {"tet10", CellType::tet10, "Mesh.MeshSizeMax = 0.5; Mesh.ElementOrder = 2;"},
      {"hex8", CellType::hex8,
       "Transfinite Curve{:} = 3; Transfinite Surface{:}; Transfinite Volume{1}; "
       "Recombine Surface{:};"},
      {"hex20", CellType::hex20,
       "Transfinite Curve{:} = 3; Transfinite Surface{:}; Transfinite Volume{1}; "
       "Recombine Surface{:}; Mesh.ElementOrder = 2; Mesh.SecondOrderIncomplete = 1;"},
      {"hex27", CellType::hex27,
       "Transfinite Curve{:} = 3; Transfinite Surface{:}; Transfinite Volume{1}; "
       "Recombine Surface{:}; Mesh.ElementOrder = 2;"},
  };
  for (const Case& c : cases) {
    write("box.geo", std::string("SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 2, 1, 1};\n") +
                         c.options + "\nPhysical Volume(1) = {1};\n");
    const DeckResult r = read("*TIME\n1.0\n*INCLUDE_GMSH\nbox.geo\n" + kSteel + "*PART\n1, 1\n");
    const Mesh& mesh = r.model.mesh;
    ASSERT_GT(mesh.solid_count(), 0u) << c.name;
    double volume = 0.0;
    for (std::size_t e = 0; e < mesh.solid_count(); ++e) {
      const SolidRef cell = mesh.solid(e);
      ASSERT_EQ(cell.type, c.type) << c.name;
      std::vector<double> x;
      for (const std::int32_t n : cell.nodes) {
        const auto k = static_cast<std::size_t>(n);
        x.insert(x.end(), {mesh.nodes.x[k], mesh.nodes.y[k], mesh.nodes.z[k]});
      }
      const double v = cell_volume(cell.type, x);
      EXPECT_GT(v, 0.0) << c.name << " element " << cell.id;
      volume += v;
    }
    EXPECT_NEAR(volume, 2.0, 1e-12) << c.name;
    double area = 0.0;
    const std::vector<std::int64_t> part{1};
    std::set<std::pair<std::size_t, int>> seen;  // a quadratic face comes as several facets
    for (const SkinFace& f : exterior_faces(mesh, part, false)) {
      if (!seen.emplace(static_cast<std::size_t>(f.solid), f.face).second) continue;
      const FaceTopology& face = topology(mesh.solid(f.solid).type).faces[f.face];
      const SolidRef cell = mesh.solid(f.solid);
      std::vector<double> x;
      for (int a = 0; a < face.size(); ++a) {
        const auto k =
            static_cast<std::size_t>(cell.nodes[static_cast<std::size_t>(face.nodes[a])]);
        x.insert(x.end(), {mesh.nodes.x[k], mesh.nodes.y[k], mesh.nodes.z[k]});
      }
      area += face_area(face.type, x);
    }
    EXPECT_NEAR(area, 10.0, 1e-12) << c.name;
  }
}

TEST_F(DeckGmsh, WedgesFromAnExtrusionFillTheirPrism) {
  write("prism.geo", R"(Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3} = 3;
out[] = Extrude {0, 0, 2} { Surface{1}; Layers{4}; Recombine; };
Physical Volume(1) = {out[1]};
)");
  const Mesh mesh =
      read("*TIME\n1.0\n*INCLUDE_GMSH\nprism.geo\n" + kSteel + "*PART\n1, 1\n").model.mesh;
  ASSERT_GT(mesh.solid_count(), 0u);
  double volume = 0.0;
  for (std::size_t e = 0; e < mesh.solid_count(); ++e) {
    const SolidRef cell = mesh.solid(e);
    ASSERT_EQ(cell.type, CellType::wedge6);
    std::vector<double> x;
    for (const std::int32_t n : cell.nodes) {
      const auto k = static_cast<std::size_t>(n);
      x.insert(x.end(), {mesh.nodes.x[k], mesh.nodes.y[k], mesh.nodes.z[k]});
    }
    const double v = cell_volume(cell.type, x);
    EXPECT_GT(v, 0.0);
    volume += v;
  }
  EXPECT_NEAR(volume, 1.0, 1e-12);  // half of 1 x 1, 2 tall
}

// h is the element size: a unit cube meshed at h has about 6 / h^3 tetrahedra (a cube of side h
// cut into 6), whatever sizes Gmsh would take by itself (about a tenth of the cube). The estimate
// counts the inside: it holds from 4 elements across (at 2 across, h = 0.5, the boundary's
// triangles set the count: 101 for 48).
TEST_F(DeckGmsh, TheMeshSizeIsTheElementSize) {
  write("cube.geo", "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n");
  for (const double h : {0.25, 0.125}) {
    const DeckResult r = read("*TIME\n1.0\n*INCLUDE_GMSH\ncube.geo\n" + std::to_string(h) + "\n" +
                              kSteel + "*PART\n1, 1\n");
    const double expected = 6.0 / (h * h * h);
    const auto tets = static_cast<double>(r.model.mesh.solid_count());
    EXPECT_GT(tets, 0.5 * expected) << h;
    EXPECT_LT(tets, 2.0 * expected) << h;
  }
}

TEST_F(DeckGmsh, ErrorsAreLocated) {
  // A physical volume without its *PART: at the *INCLUDE_GMSH line, naming the group.
  InputError e = error("*TIME\n1.0\n*INCLUDE_GMSH\ncube.msh\n" + kSteel + "*PART\n2, 1\n");
  EXPECT_EQ(e.where().line, 4u);
  EXPECT_NE(e.message().find("physical volume 1 \"cube\" of"), std::string::npos) << e.what();
  EXPECT_NE(e.message().find("no *PART"), std::string::npos) << e.what();
  // h for a .msh file.
  e = error("*TIME\n1.0\n*INCLUDE_GMSH\ncube.msh\n0.1\n");
  EXPECT_EQ(e.where().line, 5u);
  EXPECT_EQ(e.where().field, "h");
  // A STEP file without h.
  write("part.step", "not read");
  e = error("*TIME\n1.0\n*INCLUDE_GMSH\npart.step\n");
  EXPECT_EQ(e.where().line, 4u);
  EXPECT_NE(e.message().find("give h"), std::string::npos) << e.what();
  // Another kind of file.
  e = error("*TIME\n1.0\n*INCLUDE_GMSH\nmesh.vtk\n");
  EXPECT_EQ(e.where().line, 4u);
  // A mirror.
  e = error("*TIME\n1.0\n*INCLUDE_GMSH\ncube.msh\n,\n-1\n");
  EXPECT_NE(e.message().find("mirrored"), std::string::npos) << e.what();
  // A missing file.
  e = error("*TIME\n1.0\n*INCLUDE_GMSH\nnone.msh\n");
  EXPECT_NE(e.message().find("cannot open"), std::string::npos) << e.what();
  // An error inside the .msh file: its own file and line.
  std::string text = testing::file_text(dir_ / "cube.msh");
  text.replace(text.find("2 1 4 3 2"), 9, "2 1 4 3 9");
  write("bad.msh", text);
  e = error("*TIME\n1.0\n*INCLUDE_GMSH\nbad.msh\n");
  EXPECT_EQ(fs::path(e.where().file).filename(), "bad.msh");
  EXPECT_EQ(e.where().line, 43u);
  // A .geo syntax error: Gmsh's message, with the script's line.
  write("broken.geo", "Point(1) = {0, 0, 0};\nPoint(2) = {1, 0 0};\n");
  e = error("*TIME\n1.0\n*INCLUDE_GMSH\nbroken.geo\n");
  EXPECT_EQ(e.where().line, 4u);
  EXPECT_NE(e.message().find("line 2"), std::string::npos) << e.what();
  // A mesh too large for the memory: refused before Gmsh meshes.
  write("big.geo", "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n");
  e = error("*TIME\n1.0\n*INCLUDE_GMSH\nbig.geo\n1.0e-5\n");
  EXPECT_EQ(e.where().line, 4u);
  EXPECT_NE(e.message().find("memory"), std::string::npos) << e.what();
  // The same tag for a physical curve and a physical surface: two node sets of one id.
  write("two.geo", R"(SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Physical Volume(1) = {1};
Physical Surface(7) = {1};
Physical Curve(7) = {1};
)");
  e = error("*TIME\n1.0\n*INCLUDE_GMSH\ntwo.geo\n0.5\n" + kSteel + "*PART\n1, 1\n");
  EXPECT_NE(e.message().find("node set 7 is already defined"), std::string::npos) << e.what();
}

// Elements of entities outside every physical group are left out, with a note.
TEST_F(DeckGmsh, ElementsOutsideTheGroupsAreLeftOutWithANote) {
  write("two_boxes.geo", R"(SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Box(2) = {2, 0, 0, 1, 1, 1};
Physical Volume(1) = {1};
)");
  const DeckResult r =
      read("*TIME\n1.0\n*INCLUDE_GMSH\ntwo_boxes.geo\n0.5\n" + kSteel + "*PART\n1, 1\n");
  for (std::size_t k = 0; k < r.model.mesh.nodes.size(); ++k)
    EXPECT_LE(r.model.mesh.nodes.x[k], 1.0);
  bool noted = false;
  for (const std::string& n : r.notes)
    noted = noted || n.find("solid elements of") != std::string::npos;
  EXPECT_TRUE(noted);
}

}  // namespace
}  // namespace abut
