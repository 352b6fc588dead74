#include "abut/io/vtu_writer.hpp"

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string_view>

#include "abut/core/state_archive.hpp"
#include "io/output_file.hpp"

namespace abut {
namespace {

constexpr std::string_view kAlphabet =
    "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

// Appends the four characters of one 3-byte group; `count` (1..3) bytes are real, the rest is
// '=' padding (RFC 4648, section 4).
void append_group(std::string& out, const unsigned char* group, std::size_t count) {
  const unsigned bits = (unsigned{group[0]} << 16) | (count > 1 ? unsigned{group[1]} << 8 : 0u) |
                        (count > 2 ? unsigned{group[2]} : 0u);
  out += kAlphabet[(bits >> 18) & 63u];
  out += kAlphabet[(bits >> 12) & 63u];
  out += count > 1 ? kAlphabet[(bits >> 6) & 63u] : '=';
  out += count > 2 ? kAlphabet[bits & 63u] : '=';
}

// Base64 encoder writing to a file as bytes arrive, so large arrays need no encoded copy.
class Base64Stream {
 public:
  explicit Base64Stream(std::ofstream& out) : out_(out) { text_.reserve(kFlushSize + 4); }

  template <class T>
  void put(T value) {
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    for (const unsigned char b : bytes) {
      group_[pending_++] = b;
      if (pending_ == 3) {
        append_group(text_, group_.data(), 3);
        pending_ = 0;
        if (text_.size() >= kFlushSize) flush();
      }
    }
  }

  // Pads the last group and writes everything out; the next put() starts a new base64 block.
  void finish() {
    if (pending_ > 0) append_group(text_, group_.data(), pending_);
    pending_ = 0;
    flush();
  }

 private:
  static constexpr std::size_t kFlushSize = 1 << 16;
  void flush() {
    out_.write(text_.data(), static_cast<std::streamsize>(text_.size()));
    text_.clear();
  }

  std::ofstream& out_;
  std::string text_;
  std::array<unsigned char, 3> group_{};
  std::size_t pending_ = 0;
};

// One DataArray: `values(put)` must put exactly `count` values of type T. The UInt64 header (the
// byte count of the data) is encoded as its own base64 block, as VTK's own writer does.
template <class T, class Values>
void write_data_array(std::ofstream& out, std::string_view type, std::string_view name,
                      int components, std::size_t count, Values&& values) {
  out << "        <DataArray type=\"" << type << "\" Name=\"" << output_file::xml_escaped(name)
      << "\" NumberOfComponents=\"" << components << "\" format=\"binary\">\n          ";
  Base64Stream stream(out);
  stream.put(static_cast<std::uint64_t>(count * sizeof(T)));
  stream.finish();
  values(stream);
  stream.finish();
  out << "\n        </DataArray>\n";
}

void check_field(const FieldView& field, std::size_t count, std::string_view where) {
  if (field.name.empty()) throw std::invalid_argument(std::string(where) + " field without a name");
  if (field.components < 1) {
    throw std::invalid_argument(std::string(where) + " field '" + field.name +
                                "' needs at least one component");
  }
  if (field.values.size() != count * static_cast<std::size_t>(field.components)) {
    throw std::invalid_argument(std::string(where) + " field '" + field.name + "' has " +
                                std::to_string(field.values.size()) + " values, expected " +
                                std::to_string(count) + " x " + std::to_string(field.components));
  }
}

void check_grid(const HexGridView& grid) {
  const std::size_t n = grid.x.size();
  if (grid.y.size() != n || grid.z.size() != n) {
    throw std::invalid_argument("write_vtu: x, y and z coordinate arrays differ in length");
  }
  for (std::size_t e = 0; e < grid.hexes.size(); ++e) {
    for (const std::int32_t node : grid.hexes[e]) {
      if (node < 0 || static_cast<std::size_t>(node) >= n) {
        throw std::invalid_argument("write_vtu: hexahedron " + std::to_string(e) +
                                    " refers to node index " + std::to_string(node) + " of " +
                                    std::to_string(n) + " points");
      }
    }
  }
  for (const CellBlock& block : grid.cells) {
    for (const std::int32_t node : block.nodes) {
      if (node < 0 || static_cast<std::size_t>(node) >= n) {
        throw std::invalid_argument("write_vtu: a " + std::string(topology(block.type).name) +
                                    " cell refers to node index " + std::to_string(node) + " of " +
                                    std::to_string(n) + " points");
      }
    }
  }
  for (std::size_t e = 0; e < grid.shells.size(); ++e) {
    for (const std::int32_t node : grid.shells[e]) {
      if (node < 0 || static_cast<std::size_t>(node) >= n) {
        throw std::invalid_argument("write_vtu: shell " + std::to_string(e) +
                                    " refers to node index " + std::to_string(node) + " of " +
                                    std::to_string(n) + " points");
      }
    }
  }
}

// Nodes a shell cell lists: 3 for a triangle (n4 == n3), else 4.
std::size_t shell_corners(const Quad4& shell) { return is_triangle(shell) ? 3 : 4; }

void write_fields(std::ofstream& out, std::string_view tag, std::span<const FieldView> fields) {
  out << "      <" << tag << ">\n";
  for (const FieldView& field : fields) {
    write_data_array<double>(out, "Float64", field.name, field.components, field.values.size(),
                             [&](Base64Stream& s) {
                               for (const double v : field.values) s.put(v);
                             });
  }
  out << "      </" << tag << ">\n";
}

// Shortest text that reads back to the same double (std::to_chars without precision).
std::string exact_text(double value) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

}  // namespace

std::string base64_encode(std::span<const std::byte> bytes) {
  std::string text;
  text.reserve((bytes.size() + 2) / 3 * 4);
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  std::size_t i = 0;
  for (; i + 3 <= bytes.size(); i += 3) append_group(text, data + i, 3);
  if (i < bytes.size()) append_group(text, data + i, bytes.size() - i);
  return text;
}

void write_vtu(const std::filesystem::path& path, const HexGridView& grid,
               std::span<const FieldView> point_fields, std::span<const FieldView> cell_fields) {
  check_grid(grid);
  const std::size_t points = grid.x.size();
  std::size_t cells = grid.hexes.size() + grid.shells.size();
  std::size_t connectivity = 8 * grid.hexes.size();
  for (const CellBlock& block : grid.cells) {
    cells += block.size();
    connectivity += block.nodes.size();
  }
  for (const Quad4& shell : grid.shells) connectivity += shell_corners(shell);
  for (const FieldView& f : point_fields) check_field(f, points, "point");
  for (const FieldView& f : cell_fields) check_field(f, cells, "cell");

  const std::filesystem::path temporary = output_file::temporary_for(path);
  try {
    std::ofstream out = output_file::open(temporary);
    const char* byte_order =
        std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"" << byte_order
        << "\" header_type=\"UInt64\">\n"
        << "  <UnstructuredGrid>\n"
        << "    <Piece NumberOfPoints=\"" << points << "\" NumberOfCells=\"" << cells << "\">\n";

    out << "      <Points>\n";
    write_data_array<double>(out, "Float64", "Points", 3, 3 * points, [&](Base64Stream& s) {
      for (std::size_t i = 0; i < points; ++i) {
        s.put(grid.x[i]);
        s.put(grid.y[i]);
        s.put(grid.z[i]);
      }
    });
    out << "      </Points>\n";

    out << "      <Cells>\n";
    write_data_array<std::int64_t>(out, "Int64", "connectivity", 1, connectivity,
                                   [&](Base64Stream& s) {
                                     for (const Hex8& hex : grid.hexes)
                                       for (const std::int32_t node : hex)
                                         s.put(static_cast<std::int64_t>(node));
                                     for (const CellBlock& block : grid.cells) {
                                       const auto order = topology(block.type).vtk_order;
                                       for (std::size_t c = 0; c < block.size(); ++c)
                                         for (const std::int8_t k : order)
                                           s.put(static_cast<std::int64_t>(
                                               block.cell(c)[static_cast<std::size_t>(k)]));
                                     }
                                     for (const Quad4& shell : grid.shells)
                                       for (std::size_t k = 0; k < shell_corners(shell); ++k)
                                         s.put(static_cast<std::int64_t>(shell[k]));
                                   });
    write_data_array<std::int64_t>(out, "Int64", "offsets", 1, cells, [&](Base64Stream& s) {
      std::int64_t offset = 0;
      for (std::size_t e = 0; e < grid.hexes.size(); ++e) s.put(offset += 8);
      for (const CellBlock& block : grid.cells)
        for (std::size_t c = 0; c < block.size(); ++c)
          s.put(offset += static_cast<std::int64_t>(block.nodes_per_cell()));
      for (const Quad4& shell : grid.shells)
        s.put(offset += static_cast<std::int64_t>(shell_corners(shell)));
    });
    write_data_array<std::uint8_t>(out, "UInt8", "types", 1, cells, [&](Base64Stream& s) {
      for (std::size_t e = 0; e < grid.hexes.size(); ++e) s.put(kVtkHexahedron);
      for (const CellBlock& block : grid.cells)
        for (std::size_t c = 0; c < block.size(); ++c)
          s.put(static_cast<std::uint8_t>(topology(block.type).vtk_type));
      for (const Quad4& shell : grid.shells) s.put(is_triangle(shell) ? kVtkTriangle : kVtkQuad);
    });
    out << "      </Cells>\n";

    write_fields(out, "PointData", point_fields);
    write_fields(out, "CellData", cell_fields);
    out << "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
    out.close();
    output_file::check(out, temporary);
  } catch (...) {
    output_file::discard(temporary);
    throw;
  }
  output_file::commit(temporary, path);
}

PvdSeries::PvdSeries(std::filesystem::path pvd_path) : path_(std::move(pvd_path)) {}

void PvdSeries::add(double time, const std::string& vtu_file) {
  if (!std::isfinite(time)) throw std::invalid_argument("PvdSeries: state time is not finite");
  if (!states_.empty() && !(time > states_.back().time)) {
    throw std::invalid_argument("PvdSeries: state time " + exact_text(time) +
                                " does not follow the previous time " +
                                exact_text(states_.back().time));
  }
  states_.push_back({time, vtu_file});

  std::string text =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\">\n"
      "  <Collection>\n";
  for (const State& state : states_) {
    text += "    <DataSet timestep=\"" + exact_text(state.time) + "\" part=\"0\" file=\"" +
            output_file::xml_escaped(state.file) + "\"/>\n";
  }
  text += "  </Collection>\n</VTKFile>\n";
  output_file::replace(path_, text);
}

void PvdSeries::State::archive(StateArchive& a) { a.values(time, file); }

void PvdSeries::archive(StateArchive& a) {
  std::uint64_t count = states_.size();
  a.value(count);
  if (a.saving()) {
    for (State& state : states_) state.archive(a);
    return;
  }
  std::vector<State> saved(count);
  for (State& state : saved) state.archive(a);
  states_.clear();
  std::error_code ignored;
  for (const State& state : saved)
    if (std::filesystem::exists(path_.parent_path() / state.file, ignored))
      add(state.time, state.file);
}

}  // namespace abut
