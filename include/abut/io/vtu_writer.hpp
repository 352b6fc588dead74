#pragma once
// ParaView output: one VTK XML UnstructuredGrid file (.vtu) of solids (8-node hexahedra and the
// cell blocks of the other types, as their VTK cells: mesh/topology.hpp) and 4-node shells
// (quads, and triangles where n4 == n3) per state, and a
// ParaView data collection (.pvd) that lists the states with their times.
//
// Format: VTK XML file format version 1.0 (docs.vtk.org, "VTK File Formats", XML section), every
// DataArray inline with format="binary": base64 (RFC 4648) of a UInt64 byte count, followed by
// base64 of the raw little/big-endian values (native byte order, declared in the file).
// Points and fields are Float64, connectivity and offsets Int64, cell types UInt8.
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "abut/mesh/mesh.hpp"

namespace abut {

class StateArchive;

// VTK's cell type ids (vtkCellType.h: VTK_HEXAHEDRON = 12, VTK_QUAD = 9, VTK_TRIANGLE = 5).
inline constexpr unsigned char kVtkHexahedron = 12;
inline constexpr unsigned char kVtkQuad = 9;
inline constexpr unsigned char kVtkTriangle = 5;

// Base64 encoding with the standard alphabet and '=' padding (RFC 4648, section 4).
std::string base64_encode(std::span<const std::byte> bytes);

// Points (structure of arrays, as abut::Nodes), hexahedra, shells and cell blocks by node index.
// The cells of the file are the hexahedra, then the cells of each block (Mesh::solid numbering),
// then the shells (a shell with n4 == n3 is written as a triangle), so cell fields hold the solid
// values first, then the shell values.
struct HexGridView {
  std::span<const double> x, y, z;
  std::span<const Hex8> hexes;
  std::span<const Quad4> shells;
  std::span<const CellBlock> cells = {};
};

// The mesh in its reference configuration.
inline HexGridView hex_grid(const Mesh& mesh) {
  return {mesh.nodes.x, mesh.nodes.y, mesh.nodes.z, mesh.hexes, mesh.shells, mesh.cells};
}

// One named output field: `components` values per point (or per cell), interleaved, so a vector
// field is x0 y0 z0 x1 y1 z1 ... and values.size() == count * components.
struct FieldView {
  std::string name;
  int components = 1;
  std::span<const double> values;
};

// Writes `grid` with its point and cell fields to `path` (normally *.vtu). The file is written
// under a temporary name and renamed, so an interrupted run never leaves a half file.
// Throws std::invalid_argument for inconsistent sizes or node indices out of range, and
// std::runtime_error when the file cannot be written.
void write_vtu(const std::filesystem::path& path, const HexGridView& grid,
               std::span<const FieldView> point_fields, std::span<const FieldView> cell_fields);

// A time series of states for ParaView. After every add() the .pvd file is rewritten (atomically)
// so the series on disk is complete up to the last state, even if the run stops.
class PvdSeries {
 public:
  explicit PvdSeries(std::filesystem::path pvd_path);

  // Appends the state at `time` stored in `vtu_file`, a path relative to the .pvd's directory.
  // Times must increase strictly (ParaView would show only one of two equal times).
  void add(double time, const std::string& vtu_file);

  const std::filesystem::path& path() const { return path_; }
  std::size_t size() const { return states_.size(); }
  // Restart: saves or loads the list of states; loading keeps those whose file is on disk
  // beside the .pvd and rewrites it.
  void archive(StateArchive& a);

 private:
  struct State {
    double time;
    std::string file;
    void archive(StateArchive& a);
  };
  std::filesystem::path path_;
  std::vector<State> states_;
};

}  // namespace abut
