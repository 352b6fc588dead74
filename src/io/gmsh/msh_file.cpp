// Reading a Gmsh .msh file of format 4.1, ASCII or binary (Gmsh reference manual, "MSH file
// format", Gmsh 4.8): $MeshFormat, $PhysicalNames, $Entities, $Nodes and $Elements; other
// sections ($Periodic, $NodeData, ...) are skipped, as Gmsh does with sections it does not know.
// Every value is read with its place, so that an error names the file and the line (ASCII) or
// the byte offset (binary) where it is.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include "abut/core/error.hpp"
#include "abut/io/gmsh_mesh.hpp"

namespace abut::gmsh {
namespace {

// A cursor over the file: whitespace-separated numbers in ASCII sections, raw little-endian values
// of the file's machine in binary ones. Counts are checked against the bytes left before anything
// is allocated for them, so a damaged count cannot ask for more memory than the file could fill.
class Cursor {
 public:
  Cursor(std::string_view bytes, const std::string& file) : s_(bytes), file_(file) {}

  bool binary = false;       // values are raw bytes (the binary sections of a binary file)
  bool byte_places = false;  // places are byte offsets (every place of a binary file)
  std::string section;       // "$Nodes": the keyword of messages

  bool at_end() {
    skip_space();
    return pos_ >= s_.size();
  }
  std::size_t left() const { return s_.size() - pos_; }
  MshPlace place() const { return byte_places ? MshPlace{0, pos_} : MshPlace{line_ + 1, 0}; }

  [[noreturn]] void fail(const MshPlace& at, const std::string& message) const {
    SourceLocation where{file_, at.line, section, ""};
    if (at.line == 0)
      throw InputError(where, "at byte " + std::to_string(at.byte) + ": " + message);
    throw InputError(where, message);
  }
  [[noreturn]] void fail(const std::string& message) const { fail(place(), message); }

  // The next line, without its end; the cursor moves past it.
  std::string_view line() {
    const std::size_t end = std::min(s_.find('\n', pos_), s_.size());
    std::string_view l = s_.substr(pos_, end - pos_);
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    pos_ = end < s_.size() ? end + 1 : end;
    ++line_;
    return l;
  }
  // Skips blank lines; the next non-blank line, trimmed (empty at the end of the file).
  std::string_view next_line() {
    while (pos_ < s_.size()) {
      std::string_view l = trimmed(line());
      if (!l.empty()) return l;
    }
    return {};
  }
  // The place of the next value (for messages about it).
  MshPlace next_place() {
    if (!binary) skip_space();
    return place();
  }

  std::string_view token(const char* what) {
    skip_space();
    const std::size_t start = pos_;
    while (pos_ < s_.size() && !is_space(s_[pos_])) ++pos_;
    if (start == pos_) fail("the file ends where " + std::string(what) + " was expected");
    return s_.substr(start, pos_ - start);
  }

  // A whole number in [lo, hi]: an ASCII token, or in binary a 4-byte int or an 8-byte size_t.
  std::int64_t integer(const char* what, std::int64_t lo, std::int64_t hi, bool size_t_value) {
    const MshPlace at = next_place();
    std::int64_t v = 0;
    if (binary) {
      if (size_t_value) {
        std::uint64_t u = 0;
        raw(&u, sizeof u, what);
        v = u > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())
                ? std::numeric_limits<std::int64_t>::max()
                : static_cast<std::int64_t>(u);
      } else {
        std::int32_t i = 0;
        raw(&i, sizeof i, what);
        v = i;
      }
    } else {
      const std::string t(token(what));
      errno = 0;
      char* end = nullptr;
      const long long parsed = std::strtoll(t.c_str(), &end, 10);
      if (end == t.c_str() || *end != '\0' || errno == ERANGE)
        fail(at, "expected " + std::string(what) + ", got '" + excerpt(t) + "'");
      v = parsed;
    }
    if (v < lo || v > hi)
      fail(at, "expected " + std::string(what) + " in [" + std::to_string(lo) + ", " +
                   std::to_string(hi) + "], got " + std::to_string(v));
    return v;
  }
  int int_value(const char* what, std::int64_t lo = std::numeric_limits<int>::min(),
                std::int64_t hi = std::numeric_limits<int>::max()) {
    return static_cast<int>(integer(what, lo, hi, false));
  }
  // A count or a tag (size_t in binary files).
  std::int64_t size_value(const char* what, std::int64_t lo = 0,
                          std::int64_t hi = std::numeric_limits<std::int64_t>::max()) {
    return integer(what, lo, hi, true);
  }
  // A count of items of at least `values_each` values each, checked against what is left: a value
  // takes at least 2 bytes in ASCII (a digit and a separator), 4 in binary.
  std::size_t count(const char* what, std::size_t values_each) {
    const MshPlace at = next_place();
    const auto n = static_cast<std::size_t>(size_value(what));
    if (n > left() / (std::max<std::size_t>(values_each, 1) * (binary ? 4 : 2)))
      fail(at, std::string(what) + " is " + std::to_string(n) + ", more than the " +
                   std::to_string(left()) + " bytes left in the file can hold");
    return n;
  }

  double real(const char* what) {
    const MshPlace at = next_place();
    double v = 0.0;
    if (binary) {
      raw(&v, sizeof v, what);
    } else {
      const std::string t(token(what));
      char* end = nullptr;
      v = std::strtod(t.c_str(), &end);
      if (end == t.c_str() || *end != '\0')
        fail(at, "expected " + std::string(what) + ", got '" + excerpt(t) + "'");
    }
    if (!std::isfinite(v)) fail(at, std::string(what) + " is not a finite number");
    return v;
  }

  // After a section's data: its end line ("$EndNodes"), alone on its line.
  void expect_end(const std::string& end) {
    if (binary) {
      // The binary data ends with a line break before the end line.
      if (pos_ < s_.size() && s_[pos_] == '\n') {
        ++pos_;
      } else if (pos_ + 1 < s_.size() && s_[pos_] == '\r' && s_[pos_ + 1] == '\n') {
        pos_ += 2;
      }
    }
    const MshPlace at = next_place();
    const std::string_view l = next_line();
    if (l != end)
      fail(at, "expected " + end + " after the section's data, got '" + excerpt(std::string(l)) +
                   "' (a count in the section does not match its data)");
  }

  static std::string excerpt(const std::string& t) {
    std::string e;
    for (const char c : t.substr(0, 40)) e += (c >= 32 && c < 127) ? c : '?';
    return t.size() > 40 ? e + "..." : e;
  }

 private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
  static std::string_view trimmed(std::string_view l) {
    while (!l.empty() && is_space(l.front())) l.remove_prefix(1);
    while (!l.empty() && is_space(l.back())) l.remove_suffix(1);
    return l;
  }
  void skip_space() {
    while (pos_ < s_.size() && is_space(s_[pos_])) {
      if (s_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }
  void raw(void* out, std::size_t n, const char* what) {
    if (left() < n) fail("the file ends where " + std::string(what) + " was expected");
    std::memcpy(out, s_.data() + pos_, n);
    pos_ += n;
  }

  std::string_view s_;
  std::string file_;
  std::size_t pos_ = 0;
  std::size_t line_ = 0;  // line breaks passed: the cursor is on line line_ + 1
};

void read_format(Cursor& c) {
  c.section = "$MeshFormat";
  const MshPlace at = c.next_place();
  const std::string version(c.token("the version"));
  if (version != "4.1") {
    c.fail(at, "this file is of MSH version " + Cursor::excerpt(version) +
                   "; abut reads version 4.1 (save it again from Gmsh with "
                   "Mesh.MshFileVersion = 4.1, or gmsh FILE -save -format msh41)");
  }
  const int file_type = c.int_value("the file type (0 ASCII, 1 binary)", 0, 1);
  const MshPlace size_at = c.next_place();
  const int data_size = c.int_value("the data size");
  if (data_size != 8)
    c.fail(size_at, "data size " + std::to_string(data_size) +
                        ": abut reads files written with 8-byte size_t");
  c.line();  // the rest of the version line
  if (file_type == 1) {
    c.binary = true;
    c.byte_places = true;
    const MshPlace one_at = c.place();
    const int one = c.int_value("the integer 1 of a binary file");
    if (one != 1)
      c.fail(one_at, "the integer 1 reads " + std::to_string(one) +
                         ": the file was written on a machine of the other byte order");
  }
  c.expect_end("$EndMeshFormat");
}

void read_physical_names(Cursor& c, MshMesh& m) {
  c.section = "$PhysicalNames";
  const bool was_binary = c.binary;
  c.binary = false;  // always ASCII
  const std::int64_t n = c.int_value("the number of physical names", 0);
  for (std::int64_t k = 0; k < n; ++k) {
    const MshPlace at = c.next_place();
    const int dim = c.int_value("a dimension", 0, 3);
    const int tag = c.int_value("a physical tag");
    std::string name(c.line());
    const auto first = name.find('"'), last = name.rfind('"');
    if (first == std::string::npos || last == first)
      c.fail(at, "expected a physical name in double quotes after the tag");
    name = name.substr(first + 1, last - first - 1);
    m.group_names[{dim, tag}] = name;
    m.group_places.emplace(std::make_pair(dim, tag), at);
  }
  c.expect_end("$EndPhysicalNames");
  c.binary = was_binary;
}

// Each entity's physical groups; bounding boxes and boundaries are read past.
void read_entities(Cursor& c, MshMesh& m, std::set<std::pair<int, int>>& entities) {
  c.section = "$Entities";
  std::size_t counts[4];
  for (std::size_t& n : counts) n = c.count("the number of entities", 1);
  for (int dim = 0; dim < 4; ++dim) {
    for (std::size_t k = 0; k < counts[dim]; ++k) {
      const MshPlace at = c.next_place();
      const int tag = c.int_value("an entity tag");
      for (int j = 0; j < (dim == 0 ? 3 : 6); ++j) c.real("a coordinate of the bounding box");
      const std::size_t groups = c.count("the number of physical tags", 1);
      std::vector<int> tags;
      for (std::size_t g = 0; g < groups; ++g) {
        const MshPlace group_at = c.next_place();
        tags.push_back(c.int_value("a physical tag"));
        m.group_places.emplace(std::make_pair(dim, tags.back()), group_at);
      }
      if (dim > 0) {
        const std::size_t bounds = c.count("the number of bounding entities", 1);
        for (std::size_t b = 0; b < bounds; ++b) c.int_value("a bounding entity tag");
      }
      if (!entities.emplace(dim, tag).second)
        c.fail(at, "entity " + std::to_string(tag) + " of dimension " + std::to_string(dim) +
                       " is given twice");
      if (!tags.empty()) m.entity_groups[{dim, tag}] = tags;
    }
  }
  c.expect_end("$EndEntities");
}

void read_nodes(Cursor& c, MshMesh& m, std::unordered_map<std::int64_t, std::size_t>& index) {
  c.section = "$Nodes";
  const MshPlace header = c.next_place();
  const std::size_t blocks = c.count("the number of entity blocks", 4);
  const std::size_t total = c.count("the number of nodes", 4);
  c.size_value("the smallest node tag");
  c.size_value("the largest node tag");
  m.node_tags.reserve(total);
  m.coordinates.reserve(total);
  for (std::size_t b = 0; b < blocks; ++b) {
    const int dim = c.int_value("an entity dimension", 0, 3);
    c.int_value("an entity tag");
    const MshPlace parametric_at = c.next_place();
    const int parametric = c.int_value("the parametric flag (0 or 1)", 0, 1);
    if (parametric == 1 && dim == 0)
      c.fail(parametric_at, "a point entity has no parametric coordinates");
    const std::size_t n = c.count("the number of nodes in the block", 4);
    for (std::size_t k = 0; k < n; ++k) {
      const MshPlace at = c.next_place();
      const std::int64_t tag = c.size_value("a node tag", 1);
      if (!index.emplace(tag, m.node_tags.size()).second)
        c.fail(at, "node " + std::to_string(tag) + " is given twice");
      m.node_tags.push_back(tag);
      m.node_places.push_back(at);
    }
    for (std::size_t k = 0; k < n; ++k) {
      Vec3 x;
      for (int d = 0; d < 3; ++d) x[d] = c.real("a node coordinate");
      for (int d = 0; d < (parametric ? dim : 0); ++d) c.real("a parametric coordinate");
      m.coordinates.push_back(x);
    }
  }
  if (m.node_tags.size() != total)
    c.fail(header, "the blocks hold " + std::to_string(m.node_tags.size()) +
                       " nodes, the header says " + std::to_string(total));
  c.expect_end("$EndNodes");
}

void read_elements(Cursor& c, MshMesh& m,
                   const std::unordered_map<std::int64_t, std::size_t>& node_index,
                   bool have_entities, const std::set<std::pair<int, int>>& entities) {
  c.section = "$Elements";
  const MshPlace header = c.next_place();
  const std::size_t blocks = c.count("the number of entity blocks", 4);
  const std::size_t total = c.count("the number of elements", 2);
  c.size_value("the smallest element tag");
  c.size_value("the largest element tag");
  std::unordered_set<std::int64_t> seen;
  std::size_t read = 0;
  for (std::size_t b = 0; b < blocks; ++b) {
    MshElementBlock block;
    block.where = c.next_place();
    block.dim = c.int_value("an entity dimension", 0, 3);
    block.entity = c.int_value("an entity tag");
    const MshPlace type_at = c.next_place();
    block.type = c.int_value("an element type");
    const GmshElementType* type = element_type(block.type);
    if (!type)
      c.fail(type_at, "element type " + std::to_string(block.type) +
                          " is not supported by abut (it reads " + element_type_list() + ")");
    if (type->dim != block.dim)
      c.fail(type_at, std::string(type->name) + " elements are of dimension " +
                          std::to_string(type->dim) + ", the block's entity of dimension " +
                          std::to_string(block.dim));
    if (have_entities && !entities.count({block.dim, block.entity}))
      c.fail(block.where, "entity " + std::to_string(block.entity) + " of dimension " +
                              std::to_string(block.dim) + " is not in $Entities");
    const auto per = static_cast<std::size_t>(type->nodes);
    const std::size_t n = c.count("the number of elements in the block", per + 1);
    block.tags.reserve(n);
    block.nodes.reserve(n * per);
    for (std::size_t k = 0; k < n; ++k) {
      const MshPlace at = c.next_place();
      const std::int64_t tag = c.size_value("an element tag", 1);
      if (!seen.insert(tag).second)
        c.fail(at, "element " + std::to_string(tag) + " is given twice");
      for (std::size_t j = 0; j < per; ++j) {
        const MshPlace node_at = c.next_place();
        const std::int64_t node = c.size_value("a node tag", 1);
        if (!node_index.count(node))
          c.fail(node_at, "element " + std::to_string(tag) + ": node " + std::to_string(node) +
                              " is not in $Nodes");
        for (std::size_t i = block.nodes.size() - j; i < block.nodes.size(); ++i)
          if (block.nodes[i] == node)
            c.fail(node_at,
                   "element " + std::to_string(tag) + " repeats node " + std::to_string(node));
        block.nodes.push_back(node);
      }
      block.tags.push_back(tag);
      block.places.push_back(at);
    }
    read += n;
    m.blocks.push_back(std::move(block));
  }
  if (read != total)
    c.fail(header, "the blocks hold " + std::to_string(read) + " elements, the header says " +
                       std::to_string(total));
  c.expect_end("$EndElements");
}

// Past an unknown section: up to its end line.
void skip_section(Cursor& c, const std::string& name, const MshPlace& at) {
  const std::string end = "$End" + name.substr(1);
  while (!c.at_end()) {
    if (c.next_line() == end) return;
  }
  c.fail(at, "section " + name + " has no " + end);
}

}  // namespace

MshMesh read_msh(std::string_view bytes, const std::string& file) {
  MshMesh m;
  m.file = file;
  Cursor c(bytes, file);
  std::unordered_map<std::int64_t, std::size_t> node_index;
  std::set<std::pair<int, int>> entities;
  bool have_format = false, have_entities = false, have_nodes = false, have_elements = false;
  while (!c.at_end()) {
    c.section.clear();
    const MshPlace at = c.next_place();
    const std::string name(c.next_line());
    if (name.empty() || name[0] != '$')
      c.fail(at, "expected a section such as $Nodes, got '" + Cursor::excerpt(name) + "'");
    if (!have_format && name != "$MeshFormat")
      c.fail(at, "a .msh file starts with $MeshFormat, not '" + Cursor::excerpt(name) + "'");
    const auto once = [&](bool& have) {
      if (have) c.fail(at, "section " + name + " is given twice");
      have = true;
    };
    if (name == "$MeshFormat") {
      once(have_format);
      read_format(c);
    } else if (name == "$PhysicalNames") {
      read_physical_names(c, m);
    } else if (name == "$Entities") {
      once(have_entities);
      read_entities(c, m, entities);
    } else if (name == "$PartitionedEntities") {
      c.fail(at, "partitioned meshes are not supported yet by abut: save the mesh unpartitioned");
    } else if (name == "$Nodes") {
      once(have_nodes);
      read_nodes(c, m, node_index);
    } else if (name == "$Elements") {
      if (!have_nodes) c.fail(at, "$Elements comes before $Nodes");
      once(have_elements);
      read_elements(c, m, node_index, have_entities, entities);
    } else {
      skip_section(c, name, at);
    }
  }
  if (!have_format) c.fail(MshPlace{1, 0}, "an empty file: a .msh file starts with $MeshFormat");
  if (!have_nodes) c.fail(MshPlace{1, 0}, "the file has no $Nodes section");
  if (!have_elements) c.fail(MshPlace{1, 0}, "the file has no $Elements section");
  m.binary = c.binary;
  return m;
}

MshMesh read_msh_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(SourceLocation{path.string(), 0, "", ""}, "cannot open the file");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return read_msh(bytes, path.string());
}

}  // namespace abut::gmsh
