// VTU and PVD output. VtuWriter.WritesTwoHexSeriesForParaView and
// VtuWriter.WritesHexesThenShellsForParaView also produce the files that tests/io/test_vtu_vtk.py
// reads back with VTK's own reader; they write them to the directory in the environment variable
// ABUT_TEST_OUTPUT_DIR, or to ./test_io_output.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "abut/io/vtu_writer.hpp"
#include "test_files.hpp"
#include "vtu_arrays.hpp"

namespace abut {
namespace {

using testing::data_array;
using testing::file_text;

// Two unit cubes side by side along x: nodes (i, j, k) for i = 0..2, j, k = 0..1.
struct TwoHexes {
  std::vector<double> x, y, z;
  std::vector<Hex8> hexes;
  explicit TwoHexes(double shear) {
    for (int k = 0; k < 2; ++k) {
      for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 3; ++i) {
          x.push_back(i + shear * k);
          y.push_back(j);
          z.push_back(k);
        }
      }
    }
    const auto n = [](int i, int j, int k) {
      return static_cast<std::int32_t>(i + 3 * (j + 2 * k));
    };
    for (int i = 0; i < 2; ++i) {  // VTK_HEXAHEDRON order: bottom face counter-clockwise, then top
      hexes.push_back({n(i, 0, 0), n(i + 1, 0, 0), n(i + 1, 1, 0), n(i, 1, 0), n(i, 0, 1),
                       n(i + 1, 0, 1), n(i + 1, 1, 1), n(i, 1, 1)});
    }
  }
  std::vector<Quad4> shells;
  HexGridView view() const { return {x, y, z, hexes, shells}; }
};

std::filesystem::path output_dir() {
  const char* from_env = std::getenv("ABUT_TEST_OUTPUT_DIR");
  const std::filesystem::path dir = from_env != nullptr && *from_env != '\0'
                                        ? std::filesystem::path(from_env)
                                        : std::filesystem::current_path() / "test_io_output";
  std::filesystem::create_directories(dir);
  return dir;
}

// The fields tests/io/test_vtu_vtk.py checks: they are formulas of the written coordinates.
//   velocity = (1 + x, 2 y, -3 z), temperature = 300 + 10 x + y + 0.5 z,
//   part = 1, 2 per cell, center = mean of the cell's eight points.
void write_state(const std::filesystem::path& path, const TwoHexes& mesh) {
  std::vector<double> velocity, temperature;
  for (std::size_t i = 0; i < mesh.x.size(); ++i) {
    velocity.insert(velocity.end(), {1.0 + mesh.x[i], 2.0 * mesh.y[i], -3.0 * mesh.z[i]});
    temperature.push_back(300.0 + 10.0 * mesh.x[i] + mesh.y[i] + 0.5 * mesh.z[i]);
  }
  std::vector<double> part{1.0, 2.0}, center;
  for (const Hex8& hex : mesh.hexes) {
    double c[3] = {0.0, 0.0, 0.0};
    for (const auto node : hex) {
      c[0] += mesh.x[node] / 8.0;
      c[1] += mesh.y[node] / 8.0;
      c[2] += mesh.z[node] / 8.0;
    }
    center.insert(center.end(), {c[0], c[1], c[2]});
  }
  const FieldView point_fields[] = {{"velocity", 3, velocity}, {"temperature", 1, temperature}};
  const FieldView cell_fields[] = {{"part", 1, part}, {"center", 3, center}};
  write_vtu(path, mesh.view(), point_fields, cell_fields);
}

TEST(VtuWriter, WritesTwoHexSeriesForParaView) {
  const auto dir = output_dir();
  PvdSeries series(dir / "results.pvd");
  const TwoHexes initial(0.0), sheared(0.25);
  write_state(dir / "state_0000.vtu", initial);
  series.add(0.0, "state_0000.vtu");
  write_state(dir / "state_0001.vtu", sheared);
  series.add(1e-3, "state_0001.vtu");
  EXPECT_EQ(series.size(), 2u);

  EXPECT_FALSE(std::filesystem::exists(dir / "state_0001.vtu.tmp"));
  EXPECT_FALSE(std::filesystem::exists(dir / "results.pvd.tmp"));
  const std::string pvd = file_text(dir / "results.pvd");
  EXPECT_NE(pvd.find("<DataSet timestep=\"0\" part=\"0\" file=\"state_0000.vtu\"/>"),
            std::string::npos);
  EXPECT_NE(pvd.find("<DataSet timestep=\"0.001\" part=\"0\" file=\"state_0001.vtu\"/>"),
            std::string::npos);

  // Decode the second state here as well; VTK's reader checks it in test_vtu_vtk.py.
  const std::string vtu = file_text(dir / "state_0001.vtu");
  EXPECT_NE(vtu.find("<Piece NumberOfPoints=\"12\" NumberOfCells=\"2\">"), std::string::npos);
  const auto points = data_array<double>(vtu, "Points");
  ASSERT_EQ(points.size(), 36u);
  for (std::size_t i = 0; i < 12; ++i) {
    EXPECT_EQ(points[3 * i], sheared.x[i]);
    EXPECT_EQ(points[3 * i + 1], sheared.y[i]);
    EXPECT_EQ(points[3 * i + 2], sheared.z[i]);
  }
  const auto connectivity = data_array<std::int64_t>(vtu, "connectivity");
  ASSERT_EQ(connectivity.size(), 16u);
  for (std::size_t e = 0; e < 2; ++e) {
    for (std::size_t a = 0; a < 8; ++a) EXPECT_EQ(connectivity[8 * e + a], sheared.hexes[e][a]);
  }
  EXPECT_EQ(data_array<std::int64_t>(vtu, "offsets"), (std::vector<std::int64_t>{8, 16}));
  EXPECT_EQ(data_array<std::uint8_t>(vtu, "types"), (std::vector<std::uint8_t>{12, 12}));
  EXPECT_EQ(data_array<double>(vtu, "part"), (std::vector<double>{1.0, 2.0}));
  const auto velocity = data_array<double>(vtu, "velocity");
  ASSERT_EQ(velocity.size(), 36u);
  EXPECT_EQ(velocity[3 * 11], 1.0 + sheared.x[11]);
  EXPECT_EQ(velocity[3 * 11 + 2], -3.0 * sheared.z[11]);
}

// The two hexes with a quad shell on the top face of the first (normal +z) and a triangle on the
// top face of the second; test_vtu_vtk.py reads shells.vtu and checks the cells and their areas.
TEST(VtuWriter, WritesHexesThenShellsForParaView) {
  TwoHexes mesh(0.0);
  mesh.shells.push_back({6, 7, 10, 9});
  mesh.shells.push_back({7, 8, 11, 11});
  const std::vector<double> part{1.0, 1.0, 2.0, 3.0}, thickness{0.0, 0.0, 0.01, 0.02};
  const FieldView cell_fields[] = {{"part_id", 1, part}, {"thickness", 1, thickness}};
  const auto path = output_dir() / "shells.vtu";
  write_vtu(path, mesh.view(), {}, cell_fields);
  const std::string vtu = file_text(path);
  EXPECT_NE(vtu.find("<Piece NumberOfPoints=\"12\" NumberOfCells=\"4\">"), std::string::npos);
  const auto connectivity = data_array<std::int64_t>(vtu, "connectivity");
  ASSERT_EQ(connectivity.size(), 16u + 4u + 3u);
  EXPECT_EQ(std::vector<std::int64_t>(connectivity.begin() + 16, connectivity.end()),
            (std::vector<std::int64_t>{6, 7, 10, 9, 7, 8, 11}));
  EXPECT_EQ(data_array<std::int64_t>(vtu, "offsets"), (std::vector<std::int64_t>{8, 16, 20, 23}));
  EXPECT_EQ(data_array<std::uint8_t>(vtu, "types"),
            (std::vector<std::uint8_t>{kVtkHexahedron, kVtkHexahedron, kVtkQuad, kVtkTriangle}));
  EXPECT_EQ(data_array<double>(vtu, "thickness"), thickness);

  const std::vector<double> hexes_only{1.0, 1.0};
  const FieldView short_field[] = {{"part_id", 1, hexes_only}};
  EXPECT_THROW(write_vtu(output_dir() / "bad.vtu", mesh.view(), {}, short_field),
               std::invalid_argument);
  mesh.shells[1][3] = 12;  // one past the last node
  EXPECT_THROW(write_vtu(output_dir() / "bad.vtu", mesh.view(), {}, {}), std::invalid_argument);
}

// Cell blocks follow the hexahedra, each cell in VTK's node order: a wedge's triangles turn the
// other way in VTK (mesh/topology.hpp), a 10-node tetrahedron keeps the Abaqus order.
TEST(VtuWriter, WritesCellBlocksInVtkOrderAfterTheHexahedra) {
  TwoHexes mesh(0.0);
  HexGridView view = mesh.view();
  std::vector<CellBlock> blocks(2);
  blocks[0].type = CellType::wedge6;
  blocks[0].nodes = {0, 1, 3, 6, 7, 9};
  blocks[0].id = {3};
  blocks[0].part = {1};
  blocks[1].type = CellType::tet10;
  blocks[1].nodes = {0, 1, 3, 6, 2, 4, 5, 7, 8, 9};
  blocks[1].id = {4};
  blocks[1].part = {1};
  view.cells = blocks;
  const auto path = output_dir() / "blocks.vtu";
  write_vtu(path, view, {}, {});
  const std::string vtu = file_text(path);
  EXPECT_NE(vtu.find("<Piece NumberOfPoints=\"12\" NumberOfCells=\"4\">"), std::string::npos);
  const auto connectivity = data_array<std::int64_t>(vtu, "connectivity");
  ASSERT_EQ(connectivity.size(), 16u + 6u + 10u);
  EXPECT_EQ(std::vector<std::int64_t>(connectivity.begin() + 16, connectivity.end()),
            (std::vector<std::int64_t>{0, 3, 1, 6, 9, 7, 0, 1, 3, 6, 2, 4, 5, 7, 8, 9}));
  EXPECT_EQ(data_array<std::int64_t>(vtu, "offsets"), (std::vector<std::int64_t>{8, 16, 22, 32}));
  EXPECT_EQ(data_array<std::uint8_t>(vtu, "types"), (std::vector<std::uint8_t>{12, 12, 13, 24}));
  blocks[1].nodes[9] = 12;  // one past the last node
  EXPECT_THROW(write_vtu(output_dir() / "bad.vtu", view, {}, {}), std::invalid_argument);
}

TEST(VtuWriter, RejectsInconsistentInput) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("abut_test_vtu_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  TwoHexes mesh(0.0);
  const std::vector<double> too_short(35, 0.0);
  const FieldView bad_vector[] = {{"velocity", 3, too_short}};
  EXPECT_THROW(write_vtu(dir / "a.vtu", mesh.view(), bad_vector, {}), std::invalid_argument);
  const std::vector<double> one(2, 1.0);
  const FieldView unnamed[] = {{"", 1, one}};
  EXPECT_THROW(write_vtu(dir / "a.vtu", mesh.view(), {}, unnamed), std::invalid_argument);
  mesh.hexes[1][7] = 12;  // one past the last node
  EXPECT_THROW(write_vtu(dir / "a.vtu", mesh.view(), {}, {}), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(dir / "a.vtu"));
  EXPECT_THROW(write_vtu(dir / "missing" / "a.vtu", TwoHexes(0.0).view(), {}, {}),
               std::runtime_error);
  std::filesystem::remove_all(dir);
}

TEST(VtuWriter, WritesAMeshInItsReferenceConfiguration) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("abut_test_mesh_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const TwoHexes two(0.0);
  Mesh mesh;
  for (std::size_t i = 0; i < two.x.size(); ++i) {
    mesh.nodes.add(static_cast<std::int64_t>(100 + i), {two.x[i], two.y[i], two.z[i]});
  }
  mesh.hexes = two.hexes;
  write_vtu(dir / "mesh.vtu", hex_grid(mesh), {}, {});
  const std::string vtu = file_text(dir / "mesh.vtu");
  EXPECT_EQ(data_array<double>(vtu, "Points")[3 * 7], two.x[7]);
  EXPECT_EQ(data_array<std::int64_t>(vtu, "connectivity")[15], two.hexes[1][7]);
  std::filesystem::remove_all(dir);
}

TEST(PvdSeries, RequiresIncreasingTimes) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("abut_test_pvd_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  PvdSeries series(dir / "results.pvd");
  series.add(0.5, "a.vtu");
  EXPECT_THROW(series.add(0.5, "b.vtu"), std::invalid_argument);
  EXPECT_THROW(series.add(0.25, "b.vtu"), std::invalid_argument);
  series.add(1.0, "b&c.vtu");
  EXPECT_NE(file_text(dir / "results.pvd").find("file=\"b&amp;c.vtu\""), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace abut
