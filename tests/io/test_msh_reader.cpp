// The .msh reader (format 4.1, ASCII and binary; src/io/gmsh/msh_file.cpp) against Gmsh itself:
// files Gmsh's library writes read back to the mesh the library holds, the node orders of the
// solid types agree with the library's reference coordinates, and every damage to a file is an
// InputError at the line (ASCII) or byte (binary) where it is. Format: Gmsh reference manual,
// "MSH file format" (4.1).
#include <gmsh.h>
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "abut/core/error.hpp"
#include "abut/io/gmsh_mesh.hpp"
#include "test_files.hpp"

namespace abut {
namespace {

namespace fs = std::filesystem;

// One hexahedron with a physical volume, its bottom face in a physical surface and a corner in a
// physical point; entity blocks as Gmsh writes them. Lines are 1-based in messages: line k of the
// file is kCube[k - 1].
const std::vector<std::string> kCube = {
    "$MeshFormat",            // 1
    "4.1 0 8",                // 2
    "$EndMeshFormat",         // 3
    "$PhysicalNames",         // 4
    "3",                      // 5
    "0 3 \"corner\"",         // 6
    "2 2 \"bottom\"",         // 7
    "3 1 \"cube\"",           // 8
    "$EndPhysicalNames",      // 9
    "$Entities",              // 10
    "1 0 1 1",                // 11
    "1 0 0 0 1 3",            // 12
    "1 0 0 0 1 1 0 1 2 0",    // 13
    "1 0 0 0 1 1 1 1 1 1 1",  // 14
    "$EndEntities",           // 15
    "$Nodes",                 // 16
    "3 8 1 8",                // 17
    "0 1 0 1",                // 18
    "1",                      // 19
    "0 0 0",                  // 20
    "2 1 0 3",                // 21
    "2",                      // 22
    "3",                      // 23
    "4",                      // 24
    "1 0 0",                  // 25
    "1 1 0",                  // 26
    "0 1 0",                  // 27
    "3 1 0 4",                // 28
    "5",                      // 29
    "6",                      // 30
    "7",                      // 31
    "8",                      // 32
    "0 0 1",                  // 33
    "1 0 1",                  // 34
    "1 1 1",                  // 35
    "0 1 1",                  // 36
    "$EndNodes",              // 37
    "$Elements",              // 38
    "3 3 1 3",                // 39
    "0 1 15 1",               // 40
    "3 1",                    // 41
    "2 1 3 1",                // 42
    "2 1 4 3 2",              // 43
    "3 1 5 1",                // 44
    "1 1 2 3 4 5 6 7 8",      // 45
    "$EndElements",           // 46
};

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const std::string& l : lines) s += l + "\n";
  return s;
}

TEST(MshReader, AHandWrittenFileReadsAsWritten) {
  const gmsh::MshMesh m = gmsh::read_msh(joined(kCube), "cube.msh");
  EXPECT_FALSE(m.binary);
  ASSERT_EQ(m.node_tags.size(), 8u);
  EXPECT_EQ(m.node_tags[6], 7);
  EXPECT_EQ(m.coordinates[6][0], 1.0);
  EXPECT_EQ(m.coordinates[6][1], 1.0);
  EXPECT_EQ(m.coordinates[6][2], 1.0);
  EXPECT_EQ(m.node_places[6].line, 31u);  // the line of its tag
  ASSERT_EQ(m.blocks.size(), 3u);
  const gmsh::MshElementBlock& hex = m.blocks[2];
  EXPECT_EQ(hex.dim, 3);
  EXPECT_EQ(hex.type, 5);
  EXPECT_EQ(hex.tags, std::vector<std::int64_t>{1});
  EXPECT_EQ(hex.nodes, (std::vector<std::int64_t>{1, 2, 3, 4, 5, 6, 7, 8}));
  EXPECT_EQ(hex.places.at(0).line, 45u);
  EXPECT_EQ(m.blocks[1].nodes, (std::vector<std::int64_t>{1, 4, 3, 2}));
  EXPECT_EQ(m.entity_groups.at({3, 1}), std::vector<int>{1});
  EXPECT_EQ(m.entity_groups.at({2, 1}), std::vector<int>{2});
  EXPECT_EQ(m.entity_groups.at({0, 1}), std::vector<int>{3});
  EXPECT_EQ(m.group_names.at({2, 2}), "bottom");
  EXPECT_EQ(m.group_places.at({3, 1}).line, 8u);
  // Windows line ends and sections abut does not read ($Comments) change nothing.
  std::vector<std::string> other = kCube;
  for (std::string& l : other) l += "\r";
  other.insert(other.begin() + 3, {"$Comments", "made by hand", "$EndComments"});
  const gmsh::MshMesh same = gmsh::read_msh(joined(other), "cube.msh");
  EXPECT_EQ(same.blocks[2].nodes, hex.nodes);
  for (std::size_t k = 0; k < 8; ++k)
    for (int r = 0; r < 3; ++r) EXPECT_EQ(same.coordinates[k][r], m.coordinates[k][r]);
}

struct Damage {
  std::size_t line;         // 1-based line of kCube replaced
  const char* replacement;  // its new text
  std::size_t error_line;   // where the error must be
  const char* says;         // a part of the message
};

TEST(MshReader, EveryDamageIsLocatedAtItsLine) {
  const Damage damages[] = {
      {2, "2.2 0 8", 2, "version 2.2"},
      {2, "4.1 0 4", 2, "data size 4"},
      {2, "4.1 2 8", 2, "file type"},
      {12, "1 0 0 0 x 3", 12, "got 'x'"},
      {17, "3 9 1 8", 17, "header says 9"},
      {22, "1", 22, "node 1 is given twice"},
      {26, "1 1 z", 26, "got 'z'"},
      {26, "1 1 nan", 26, "not a finite"},
      {39, "3 3 1 3 extra", 39, "entity dimension"},
      {42, "2 1 7 1", 42, "element type 7 is not supported"},
      {42, "3 1 3 1", 42, "dimension"},
      {42, "2 9 3 1", 42, "entity 9 of dimension 2 is not in $Entities"},
      {43, "2 1 4 3 9", 43, "node 9 is not in $Nodes"},
      {43, "2 1 4 3 4", 43, "repeats node 4"},
      {45, "1 1 2 3 4 5 6 7", 46, "expected a node tag"},
      {46, "$EndNodes", 46, "expected $EndElements"},
      {16, "$Elements", 16, "$Elements comes before $Nodes"},
      {1, "$Nodes", 1, "starts with $MeshFormat"},
      {11, "1 0 1 x", 11, "expected the number of entities"},
      {41, "1 1", 45, "element 1 is given twice"},
  };
  for (const Damage& d : damages) {
    std::vector<std::string> lines = kCube;
    lines[d.line - 1] = d.replacement;
    try {
      gmsh::read_msh(joined(lines), "cube.msh");
      ADD_FAILURE() << "no error for line " << d.line << " = '" << d.replacement << "'";
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().file, "cube.msh");
      EXPECT_EQ(e.where().line, d.error_line) << e.what();
      EXPECT_NE(e.message().find(d.says), std::string::npos) << e.what();
    }
  }
  // Cut short anywhere: an error, never a crash or a mesh.
  const std::string whole = joined(kCube);
  for (std::size_t n = 0; n + 1 < whole.size(); n += 7)
    EXPECT_THROW(gmsh::read_msh(whole.substr(0, n), "cube.msh"), InputError) << n;
}

// The element types: abut's node k is Gmsh's node gmsh_node_order[k], the node with the same
// reference coordinates in Gmsh's library (getElementProperties).
TEST(MshReader, NodeOrdersMatchGmshsReferenceCoordinates) {
  ::gmsh::initialize(0, nullptr, false);
  ::gmsh::option::setNumber("General.Terminal", 0);
  for (const CellType type : kCellTypes) {
    const std::span<const std::int8_t> order = gmsh::gmsh_node_order(type);
    if (type == CellType::hex64) {
      EXPECT_TRUE(order.empty());
      continue;
    }
    const CellTopology& t = topology(type);
    int number = 0;
    for (int g = 1; g < 100; ++g) {
      const gmsh::GmshElementType* e = gmsh::element_type(g);
      if (e && e->cell == type) number = g;
    }
    ASSERT_NE(number, 0) << t.name;
    std::string name;
    int dim = 0, order_p = 0, nodes = 0, primary = 0;
    std::vector<double> local;
    ::gmsh::model::mesh::getElementProperties(number, name, dim, order_p, nodes, local, primary);
    ASSERT_EQ(nodes, t.nodes) << t.name;
    ASSERT_EQ(nodes, gmsh::element_type(number)->nodes);
    for (int k = 0; k < t.nodes; ++k) {
      const auto g = static_cast<std::size_t>(order[static_cast<std::size_t>(k)]);
      for (std::size_t r = 0; r < 3; ++r)
        EXPECT_EQ(local[3 * g + r], t.natural[static_cast<std::size_t>(k)][r])
            << t.name << " node " << k;
    }
  }
  ::gmsh::finalize();
}

// A cylinder meshed by Gmsh's library (tetrahedra of order 2, physical groups), written as ASCII
// and binary .msh, reads back to the library's own mesh (mesh_cad of the same .geo), value for
// value; damage to the binary file is located by byte.
class GmshWritten : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::fresh_dir("abut_msh");
    testing::write_text(dir_ / "can.geo", R"(SetFactory("OpenCASCADE");
Cylinder(1) = {0, 0, 0, 0, 0, 0.02, 0.01};
Physical Volume("can", 7) = {1};
Physical Surface("bottom", 8) = {3};
Physical Curve("rim", 9) = {3};
Mesh.MeshSizeMax = 0.005;
Mesh.ElementOrder = 2;
)");
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(bool binary) {
    const fs::path out = dir_ / (binary ? "can_binary.msh" : "can_ascii.msh");
    ::gmsh::initialize(0, nullptr, false);
    ::gmsh::option::setNumber("General.Terminal", 0);
    ::gmsh::option::setNumber("General.NumThreads", 1);
    ::gmsh::open((dir_ / "can.geo").string());
    ::gmsh::model::mesh::generate(3);
    ::gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
    ::gmsh::option::setNumber("Mesh.Binary", binary ? 1 : 0);
    ::gmsh::write(out.string());
    ::gmsh::finalize();
    return out.string();
  }

  fs::path dir_;
};

// `digits`: Gmsh writes ASCII coordinates with 16 significant digits (printf "%.16g"), which
// does not always give back the double it held (17 would); binary files hold the doubles.
void expect_same_mesh(const gmsh::MshMesh& a, const gmsh::MshMesh& b, bool binary) {
  EXPECT_EQ(a.node_tags, b.node_tags);
  ASSERT_EQ(a.coordinates.size(), b.coordinates.size());
  for (std::size_t k = 0; k < a.coordinates.size(); ++k) {
    for (int r = 0; r < 3; ++r) {
      if (binary)
        EXPECT_EQ(a.coordinates[k][r], b.coordinates[k][r]);
      else
        EXPECT_NEAR(a.coordinates[k][r], b.coordinates[k][r], 1e-15 * 0.02);
    }
  }
  EXPECT_EQ(a.entity_groups, b.entity_groups);
  EXPECT_EQ(a.group_names, b.group_names);
  // The library also lists the elements of entities without a group; a saved file has only those
  // with one.
  std::vector<const gmsh::MshElementBlock*> grouped;
  for (const gmsh::MshElementBlock& block : b.blocks)
    if (b.entity_groups.count({block.dim, block.entity})) grouped.push_back(&block);
  ASSERT_EQ(a.blocks.size(), grouped.size());
  for (std::size_t k = 0; k < a.blocks.size(); ++k) {
    EXPECT_EQ(a.blocks[k].type, grouped[k]->type);
    EXPECT_EQ(a.blocks[k].entity, grouped[k]->entity);
    EXPECT_EQ(a.blocks[k].tags, grouped[k]->tags);
    EXPECT_EQ(a.blocks[k].nodes, grouped[k]->nodes);
  }
}

TEST_F(GmshWritten, AsciiAndBinaryFilesReadBackToGmshsMesh) {
  const gmsh::MshMesh library = gmsh::mesh_cad(dir_ / "can.geo", {});
  const gmsh::MshMesh ascii = gmsh::read_msh_file(write(false));
  const gmsh::MshMesh binary = gmsh::read_msh_file(write(true));
  EXPECT_FALSE(ascii.binary);
  EXPECT_TRUE(binary.binary);
  std::size_t tets = 0;
  for (const gmsh::MshElementBlock& b : ascii.blocks)
    if (b.type == 11) tets += b.size();
  EXPECT_GT(tets, 100u);
  // The saved files hold the nodes of the grouped elements only; compare with the library's
  // mesh restricted to them.
  gmsh::MshMesh kept = library;
  kept.node_tags.clear();
  kept.coordinates.clear();
  std::vector<char> used;
  for (std::size_t k = 0; k < library.node_tags.size(); ++k) {
    bool any = false;
    for (const gmsh::MshElementBlock& b : library.blocks)
      if (library.entity_groups.count({b.dim, b.entity}))
        any =
            any || std::find(b.nodes.begin(), b.nodes.end(), library.node_tags[k]) != b.nodes.end();
    if (any) {
      kept.node_tags.push_back(library.node_tags[k]);
      kept.coordinates.push_back(library.coordinates[k]);
    }
  }
  if (ascii.node_tags.size() == library.node_tags.size()) kept = library;  // Gmsh saved them all
  expect_same_mesh(ascii, kept, false);
  expect_same_mesh(binary, kept, true);
}

TEST_F(GmshWritten, DamageToABinaryFileIsLocatedByByte) {
  const std::string path = write(true);
  const std::string bytes = testing::file_text(path);
  // The integer 1 after the version line, written in the other byte order.
  const std::size_t one = bytes.find("4.1 1 8\n") + 8;
  std::string swapped = bytes;
  std::swap(swapped[one], swapped[one + 3]);
  try {
    gmsh::read_msh(swapped, "can.msh");
    ADD_FAILURE() << "no error for a swapped byte order";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 0u);
    EXPECT_NE(e.message().find("at byte " + std::to_string(one) + ":"), std::string::npos)
        << e.what();
  }
  // A node count made huge: refused at its byte, before any memory is taken for it.
  const std::size_t nodes = bytes.find("$Nodes\n") + 7;
  std::string huge = bytes;
  const std::uint64_t big = 1ull << 60;
  std::memcpy(&huge[nodes + 8], &big, 8);  // the second size_t: the number of nodes
  try {
    gmsh::read_msh(huge, "can.msh");
    ADD_FAILURE() << "no error for a huge node count";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().keyword, "$Nodes");
    EXPECT_NE(e.message().find("at byte " + std::to_string(nodes + 8) + ":"), std::string::npos)
        << e.what();
  }
  // Cut short anywhere: an error with a byte offset inside the file.
  for (std::size_t n = one + 8; n < bytes.rfind("$EndElements"); n += bytes.size() / 97) {
    try {
      gmsh::read_msh(bytes.substr(0, n), "can.msh");
      ADD_FAILURE() << "no error for the file cut at " << n;
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().file, "can.msh");
      const auto at = e.message().find("at byte ");
      ASSERT_NE(at, std::string::npos) << e.what();
      EXPECT_LE(std::stoull(e.message().substr(at + 8)), n) << e.what();
    }
  }
}

}  // namespace
}  // namespace abut
