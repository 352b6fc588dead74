// *INCLUDE, INPUT=mesh.msh in an .inp deck (src/io/inp/inp_gmsh.cpp). The peer is Gmsh's own
// .inp export of the same mesh, written by Gmsh's library (its node order for C3D10 and its set
// names are its own implementation): reading the export must give the same model as including
// the .msh, node for node and element for element.
#include <gmsh.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "abut/io/deck.hpp"
#include "test_files.hpp"

namespace abut {
namespace {

namespace fs = std::filesystem;

class InpGmsh : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::fresh_dir("abut_inp_gmsh");
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) const {
    testing::write_text(dir_ / name, text);
    return (dir_ / name).string();
  }
  // Meshes `geo` with Gmsh's library and saves the mesh as each of `outputs` (by extension).
  void mesh(const std::string& geo, std::initializer_list<std::string> outputs) const {
    ::gmsh::initialize(0, nullptr, false);
    ::gmsh::option::setNumber("General.Terminal", 0);
    ::gmsh::option::setNumber("General.NumThreads", 1);
    ::gmsh::open(write("mesh.geo", geo));
    ::gmsh::model::mesh::generate(3);
    ::gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    for (const std::string& out : outputs) ::gmsh::write((dir_ / out).string());
    ::gmsh::finalize();
  }
  fs::path dir_;
};

const std::string kModel = R"(*MATERIAL, NAME=STEEL
*ELASTIC
210000, 0.3
*SOLID SECTION, ELSET=block, MATERIAL=STEEL
*STEP
*STATIC
*END STEP
)";

TEST_F(InpGmsh, AnIncludedMshIsTheModelOfGmshsOwnInpExport) {
  mesh(R"(SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 1, 1};
Physical Volume("block", 1) = {1};
Mesh.MeshSizeMax = 0.5;
Mesh.ElementOrder = 2;
)",
       {"block.msh", "block_gmsh.inp"});
  const Model from_msh =
      read_inp_with_notes(write("a.inp", "*INCLUDE, INPUT=block.msh\n" + kModel)).model;
  const Model from_export =
      read_inp_with_notes(write("b.inp", "*INCLUDE, INPUT=block_gmsh.inp\n" + kModel)).model;
  const Mesh& a = from_msh.mesh;
  const Mesh& b = from_export.mesh;
  ASSERT_EQ(a.solid_count(), b.solid_count());
  ASSERT_GT(a.solid_count(), 50u);
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  EXPECT_EQ(a.nodes.id, b.nodes.id);
  for (std::size_t n = 0; n < a.nodes.size(); ++n) {
    // Gmsh's .inp export prints coordinates with 14 significant digits ("1.3333333333333"):
    // within half a unit of the 14th digit of coordinates up to 2.
    EXPECT_NEAR(a.nodes.x[n], b.nodes.x[n], 1e-13);
    EXPECT_NEAR(a.nodes.y[n], b.nodes.y[n], 1e-13);
    EXPECT_NEAR(a.nodes.z[n], b.nodes.z[n], 1e-13);
  }
  for (std::size_t e = 0; e < a.solid_count(); ++e) {
    const SolidRef x = a.solid(e), y = b.solid(e);
    ASSERT_EQ(x.type, CellType::tet10);
    ASSERT_EQ(y.type, CellType::tet10);
    EXPECT_EQ(x.id, y.id);
    EXPECT_EQ(x.part, y.part);
    for (std::size_t k = 0; k < 10; ++k)
      EXPECT_EQ(a.nodes.id[static_cast<std::size_t>(x.nodes[k])],
                b.nodes.id[static_cast<std::size_t>(y.nodes[k])])
          << "element " << x.id << " node " << k;
  }
}

// A physical surface is a *SURFACE of solid faces and a node set; physical names name them.
TEST_F(InpGmsh, APhysicalSurfaceIsASurfaceAndANodeSet) {
  mesh(R"(SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 1, 1};
Physical Volume("block", 1) = {1};
Physical Surface("bottom", 2) = {Surface In BoundingBox{-1, -1, -0.1, 3, 2, 0.1}};
Mesh.MeshSizeMax = 0.5;
)",
       {"block.msh"});
  const Model m = read_inp_with_notes(write("a.inp", "*INCLUDE, INPUT=block.msh\n" + kModel)).model;
  const FaceSet* bottom = nullptr;
  for (const FaceSet& s : m.face_sets)
    if (s.name == "bottom") bottom = &s;
  ASSERT_NE(bottom, nullptr);
  EXPECT_GT(bottom->faces.size(), 8u);
  // Every face of the set lies at z = 0.
  for (const SolidFace& f : bottom->faces) {
    const SolidRef cell = m.mesh.solid(static_cast<std::size_t>(f.solid));
    const FaceTopology& face = topology(cell.type).faces[static_cast<std::size_t>(f.face)];
    for (int a = 0; a < face.size(); ++a)
      EXPECT_EQ(
          m.mesh.nodes
              .z[static_cast<std::size_t>(cell.nodes[static_cast<std::size_t>(face.nodes[a])])],
          0.0);
  }
}

TEST_F(InpGmsh, ErrorsAreLocated) {
  write("cube.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n");
  try {
    read_inp_with_notes(write("a.inp", "*INCLUDE, INPUT=cube.msh\n" + kModel));
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(fs::path(e.where().file).filename(), "cube.msh");
    EXPECT_EQ(e.where().line, 2u);
  }
  try {
    read_inp_with_notes(write("b.inp", "*INCLUDE, INPUT=cube.msh, SIZE=2\n" + kModel));
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 1u);
    EXPECT_EQ(e.where().field, "SIZE");
  }
  try {
    read_inp_with_notes(write("c.inp", "*INCLUDE, INPUT=none.msh\n" + kModel));
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 1u);
    EXPECT_NE(e.message().find("cannot open"), std::string::npos) << e.what();
  }
  // A mesh too large for the memory: refused at SIZE before Gmsh meshes (as *INCLUDE_GMSH h).
  write("big.geo", "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n");
  try {
    read_inp_with_notes(write("d.inp", "*INCLUDE, INPUT=big.geo, SIZE=1.0e-5\n" + kModel));
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 1u);
    EXPECT_EQ(e.where().field, "SIZE");
    EXPECT_NE(e.message().find("memory"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace abut
