#include "deck_reader.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "memory_budget.hpp"

namespace abut {
namespace fs = std::filesystem;

namespace deck {
namespace {

constexpr int kMaxIncludeDepth = 32;

// The keyword of an element's rows, kept as a literal: element records are many and small.
const char* keyword_name(const std::string& keyword) {
  for (const char* name : {"*ELEMENT_SOLID", "*ELEMENT_SHELL", "$Elements", "*INCLUDE_GMSH"})
    if (keyword == name) return name;
  throw std::logic_error("element rows of an unexpected keyword " + keyword);
}

// Lines end at LF, CRLF or a lone CR (classic Mac OS), so that no CR reaches a message. A UTF-8
// byte-order mark that some Windows editors write at the start of a file is not part of the deck.
std::vector<std::string> split_lines(std::string_view text) {
  constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
  if (text.starts_with(kByteOrderMark)) text.remove_prefix(kByteOrderMark.size());
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find_first_of("\r\n", start);
    if (end == std::string_view::npos) {
      lines.emplace_back(text.substr(start));
      break;
    }
    lines.emplace_back(text.substr(start, end - start));
    start = end + (text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n' ? 2 : 1);
  }
  return lines;
}

}  // namespace

std::string entity_word(EntityType t) {
  switch (t) {
    case EntityType::Node:
      return "N";
    case EntityType::NodeSet:
      return "NS";
    case EntityType::Part:
      return "P";
    case EntityType::PartSet:
      return "PS";
    case EntityType::All:
      return "ALL";
    case EntityType::GeometryRegion:
      return "G";
    case EntityType::FaceSet:  // *SET_FACE (an .inp *SURFACE, TYPE=ELEMENT too)
      return "FS";
    case EntityType::Tool:
      return "TOOL";
  }
  return "";
}

void DeckReader::read_file(const fs::path& path, const IncludeFrame& frame, int depth) {
  // A device or a pipe (/dev/zero) may never end: a deck is a regular file.
  std::error_code regular_ec;
  if (fs::exists(path, regular_ec) && !fs::is_regular_file(path, regular_ec))
    throw InputError("'" + path.string() + "' is not a regular file: a deck must be a file");
  const auto bytes = fs::file_size(path, regular_ec);
  if (!regular_ec) require_readable(path.string(), static_cast<double>(bytes), available_memory());
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot open deck file '" + path.string() + "'");
  std::ostringstream text;
  text << in.rdbuf();
  std::error_code ec;
  include_stack_.push_back(fs::weakly_canonical(path, ec).string());
  read_text(text.str(), path.string(), frame, depth);
  include_stack_.pop_back();
}

void DeckReader::read_text(const std::string& text, const std::string& name,
                           const IncludeFrame& frame, int depth) {
  frames_.push_back(frame);
  read_lines(split_lines(text), name, depth);
  frames_.pop_back();
}

void DeckReader::read_lines(const std::vector<std::string>& lines, const std::string& name,
                            int depth) {
  files.push_back(name);
  std::optional<std::string> keyword;
  std::size_t keyword_line = 0;
  std::vector<Line> data;
  // Returns false when the block was *END.
  const auto flush = [&]() {
    if (!keyword) return true;
    if (*keyword == "*END") return false;
    Block block(*keyword, name, keyword_line, std::move(data), parameters);
    data.clear();
    dispatch(block, depth);
    return true;
  };
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::size_t number = i + 1;
    // A line this long is not a deck line (a binary file, a missing line end): refuse it before
    // anything searches or echoes it.
    if (lines[i].size() > kMaxLineLength)
      throw InputError(SourceLocation{name, number, "", ""},
                       "line of " + std::to_string(lines[i].size()) +
                           " characters; deck lines are at most " + std::to_string(kMaxLineLength) +
                           " characters long");
    const std::string text = trim(lines[i]);
    if (text.empty() || text.front() == '#' || text.front() == '$') continue;
    if (depth == 0) end_line = number;
    const SourceLocation here{name, number, keyword.value_or(""), ""};
    if (text.front() == '~') {
      throw InputError(here,
                       "control directives such as " + text.substr(0, text.find_first_of(" \t(")) +
                           " (~if, ~repeat, ~convert_from_...) are not supported yet by abut");
    }
    if (text.front() == '*') {
      if (!flush()) return;
      const auto end = text.find_first_of(" \t,");
      keyword = upper(text.substr(0, end));
      keyword_line = number;
      if (end != std::string::npos && !trim(text.substr(end)).empty()) {
        throw InputError({name, number, *keyword, ""},
                         "unexpected text after the keyword: put the data on the next line");
      }
      continue;
    }
    if (!keyword)
      throw InputError(here, "data line before the first *KEYWORD: '" + excerpt(text) + "'");
    data.push_back({text, number});
  }
  flush();
}

void DeckReader::dispatch(Block& block, int depth) {
  const std::string& kw = block.keyword();
  if (kw == "*INCLUDE") {
    read_include(block, depth);
    return;
  }
  if (const KeywordReader reader = find_keyword_reader(kw)) {
    reader(*this, block);
    block.finish();
    return;
  }
  if (is_known_impetus_keyword(kw))
    throw InputError(block.where(),
                     kw + " is not supported yet by abut" +
                         (kw == "*OUTPUT_NODE"
                              ? " (abut's *OUTPUT_NODE_HISTORY follows chosen nodes in nodes.csv)"
                              : ""));
  std::string message = "unknown keyword " + excerpt(kw);
  if (const auto suggestion = closest_keyword(kw)) message += "; did you mean " + *suggestion + "?";
  throw InputError(SourceLocation{block.file(), block.where().line, "", ""}, message);
}

void DeckReader::read_include(Block& block, int depth) {
  const Line name_line = block.raw_line("the file name");
  const std::string file_name = unquote(name_line.text);
  if (file_name.empty()) throw InputError(block.where(name_line), "expected a file name");

  IncludeFrame child = placement(block);

  const fs::path path = frame().directory / fs::path(file_name);
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    throw InputError(block.where(name_line), "cannot open included file '" + path.string() + "'");
  }
  const std::string canonical = fs::weakly_canonical(path, ec).string();
  for (const auto& open : include_stack_) {
    if (open == canonical) {
      throw InputError(block.where(name_line),
                       "'" + path.string() + "' includes itself (include cycle)");
    }
  }
  if (depth + 1 > kMaxIncludeDepth) {
    throw InputError(block.where(name_line),
                     "includes nested deeper than " + std::to_string(kMaxIncludeDepth) + " levels");
  }
  child.directory = path.parent_path();
  block.finish();
  read_file(path, child, depth + 1);
}

IncludeFrame DeckReader::placement(Block& block) const {
  Vec3 scale{1, 1, 1}, from, to, x_axis{1, 0, 0}, y_axis{0, 1, 0};
  bool mirror = false;
  IdOffsets offsets;
  if (auto r = block.optional_row({"sf_x", "sf_y", "sf_z", "nid_offset", "eid_offset", "pid_offset",
                                   "mid_offset", "gid_offset"})) {
    for (int k = 0; k < 3; ++k) {
      scale[k] = r->number_or(k, 1.0);
      r->require(scale[k] != 0.0, k, "expected a non-zero scale factor");
    }
    std::int64_t* targets[] = {&offsets.node, &offsets.element, &offsets.part, &offsets.material,
                               &offsets.other};
    const std::int64_t* outer[] = {&frame().offsets.node, &frame().offsets.element,
                                   &frame().offsets.part, &frame().offsets.material,
                                   &frame().offsets.other};
    for (std::size_t k = 3; k < 8; ++k) {
      *targets[k - 3] = r->integer_or(k, 0);
      r->require(*targets[k - 3] >= 0, k, "expected an offset >= 0");
      // Nested includes add their offsets: the sum must still fit (it would wrap silently).
      std::int64_t total = 0;
      if (__builtin_add_overflow(*targets[k - 3], *outer[k - 3], &total))
        r->fail(k, "this offset plus the enclosing *INCLUDE's offset " +
                       std::to_string(*outer[k - 3]) + " exceeds the largest id " +
                       std::to_string(std::numeric_limits<std::int64_t>::max()));
    }
  }
  if (auto r = block.optional_row({"x0", "y0", "z0", "x1", "y1", "z1"})) {
    for (int k = 0; k < 3; ++k) {
      from[k] = r->number_or(static_cast<std::size_t>(k), 0.0);
      to[k] = r->number_or(static_cast<std::size_t>(k + 3), 0.0);
    }
  }
  if (auto r = block.optional_row({"x_x", "x_y", "x_z", "y_x", "y_y", "y_z", "mirror"})) {
    const bool any_x = r->given(0) || r->given(1) || r->given(2);
    const bool any_y = r->given(3) || r->given(4) || r->given(5);
    if (any_x) x_axis = {r->number_or(0, 0.0), r->number_or(1, 0.0), r->number_or(2, 0.0)};
    if (any_y) y_axis = {r->number_or(3, 0.0), r->number_or(4, 0.0), r->number_or(5, 0.0)};
    r->require(norm(x_axis) > 0.0, 0, "expected a non-zero x axis");
    r->require(norm(y_axis) > 0.0, 3, "expected a non-zero y axis");
    if (std::fabs(dot(x_axis, y_axis)) > 1e-9 * norm(x_axis) * norm(y_axis)) {
      r->fail(3, "the new y axis must be perpendicular to the new x axis");
    }
    mirror = r->flag(6);
  }

  IncludeFrame child;
  child.transform =
      frame().transform.after(include_transform(scale, from, to, x_axis, y_axis, mirror));
  child.offsets = frame().offsets + offsets;
  return child;
}

std::int64_t DeckReader::offset_id(const Row& r, std::size_t i, std::int64_t id,
                                   std::int64_t offset) {
  std::int64_t sum = 0;
  if (__builtin_add_overflow(id, offset, &sum))
    r.fail(i, "id " + std::to_string(id) + " plus the *INCLUDE id offset " +
                  std::to_string(offset) + " exceeds the largest id " +
                  std::to_string(std::numeric_limits<std::int64_t>::max()));
  return sum;
}

std::optional<std::int64_t> DeckReader::optional_other_id(const Row& r, std::size_t i) const {
  const auto id = r.optional_id(i);
  if (!id) return std::nullopt;
  return offset_id(r, i, *id, frame().offsets.other);
}

std::optional<std::int64_t> DeckReader::function_id(const Row& r, std::size_t i,
                                                    const Row::NumberOrFunction& v) const {
  if (!v.function_id) return std::nullopt;
  return offset_id(r, i, *v.function_id, frame().offsets.other);
}

EntityRef DeckReader::entity(const Row& r, std::size_t type_field, std::size_t id_field,
                             std::initializer_list<EntityType> allowed) const {
  const std::string word = r.word(type_field);
  std::string expected;
  for (const EntityType t : allowed) expected += (expected.empty() ? "" : ", ") + entity_word(t);
  std::optional<EntityType> type;
  for (const EntityType t : allowed) {
    if (word == entity_word(t)) type = t;
  }
  if (!type) {
    static const char* const other_types[] = {"N", "NS", "P",  "PS", "ALL", "G",
                                              "E", "ES", "GS", "FS", "DP",  "SPH"};
    for (const char* t : other_types) {
      if (word == t) {
        r.fail(type_field, "entity type " + word + " is not supported yet by abut for " +
                               r.where().keyword + " (supported: " + expected + ")");
      }
    }
    r.fail(type_field,
           "expected an entity type (" + expected + "), got '" + r.text(type_field) + "'");
  }
  EntityRef e;
  e.type = *type;
  e.where = r.where(id_field);
  switch (e.type) {
    case EntityType::All:
      e.id = 0;
      break;  // enid is ignored
    case EntityType::Node:
      e.id = node_id(r, id_field);
      break;
    case EntityType::Part:
      e.id = part_id(r, id_field);
      break;
    default:
      e.id = other_id(r, id_field);
      break;
  }
  return e;
}

void DeckReader::require_unrotated(const SourceLocation& where, const std::string& what) const {
  if (!frame().transform.keeps_directions()) {
    throw InputError(where, what +
                                " inside an *INCLUDE that rotates or mirrors its content is not "
                                "supported yet by abut");
  }
}

void DeckReader::generate(const std::function<void()>& generator, const SourceLocation& where,
                          const MeshSize& size) {
  Mesh& mesh = model.mesh;
  const MeshSize total{static_cast<double>(mesh.hex_count() + mesh.shell_count()) + size.elements,
                       static_cast<double>(mesh.nodes.size()) + size.nodes};
  require_memory(total, available_memory(), where);
  const std::size_t first_node = mesh.nodes.size();
  const std::size_t first_hex = mesh.hex_count();
  const std::size_t first_shell = mesh.shell_count();
  try {
    generator();
  } catch (const InputError& e) {
    if (!e.where().file.empty()) throw;
    throw InputError(where, e.message());
  }
  for (std::size_t i = first_node; i < mesh.nodes.size(); ++i) {
    if (!node_index_.emplace(mesh.nodes.id[i], static_cast<std::int32_t>(i)).second) {
      throw InputError(where,
                       "generated node id " + std::to_string(mesh.nodes.id[i]) + " already exists");
    }
  }
  for (std::size_t h = first_hex; h < mesh.hex_count(); ++h) {
    if (!hex_ids_.insert(mesh.hex_id[h]).second) {
      throw InputError(
          where, "generated element id " + std::to_string(mesh.hex_id[h]) + " already exists");
    }
  }
  for (std::size_t s = first_shell; s < mesh.shell_count(); ++s) {
    if (!shell_ids_.insert(mesh.shell_id[s]).second) {
      throw InputError(
          where, "generated shell id " + std::to_string(mesh.shell_id[s]) + " already exists");
    }
  }
  mesh_sources.push_back({first_hex, mesh.hex_count(), where, first_shell, mesh.shell_count()});
}

void DeckReader::add_node(std::int64_t id, const Vec3& p, std::uint8_t fixed,
                          const SourceLocation& where) {
  const auto index = static_cast<std::int32_t>(model.mesh.nodes.size());
  if (!node_index_.emplace(id, index).second) {
    throw InputError(where, "node " + std::to_string(id) + " is already defined");
  }
  model.mesh.nodes.add(id, p, fixed);
}

void DeckReader::add_element(std::int64_t id, std::int64_t part,
                             const std::array<std::int64_t, 8>& node_ids,
                             const SourceLocation& where) {
  if (!hex_ids_.insert(id).second) {
    throw InputError(where, "element " + std::to_string(id) + " is already defined");
  }
  Mesh& mesh = model.mesh;
  element_nodes.push_back({mesh.hex_count(), node_ids, file_index(where.file), where.line,
                           keyword_name(where.keyword)});
  Hex8 hex;
  hex.fill(-1);
  mesh.hexes.push_back(hex);
  mesh.hex_id.push_back(id);
  mesh.hex_part.push_back(part);
  mesh.hex_shape.push_back(-1);
}

SourceLocation DeckReader::element_where(const ElementNodes& e, const std::string& field) const {
  return {files[e.file], e.line, e.keyword, field};
}

void DeckReader::add_cell(std::int64_t id, std::int64_t part, CellType type,
                          std::vector<std::int64_t> node_ids, std::vector<std::size_t> fields,
                          const char* keyword, const SourceLocation& where) {
  if (!hex_ids_.insert(id).second)
    throw InputError(where, "element " + std::to_string(id) + " is already defined");
  if (frame().transform.mirrors())
    throw InputError(where, "a mirrored *INCLUDE of " + std::string(element_label(type)) +
                                " elements is not supported yet by abut (hexahedra are)");
  Mesh& mesh = model.mesh;
  std::size_t cell = 0;
  for (const CellBlock& b : mesh.cells)
    if (b.type == type) cell = b.size();
  const std::vector<std::int32_t> unresolved(node_ids.size(), -1);
  mesh.add_cell(type, id, part, unresolved);
  cell_nodes.push_back({type, cell, std::move(node_ids), keyword, std::move(fields),
                        file_index(where.file), where.line});
}

SourceLocation DeckReader::cell_where(const CellNodes& e, const std::string& field) const {
  return {files[e.file], e.line, e.keyword, field};
}

void DeckReader::add_shell(std::int64_t id, std::int64_t part,
                           const std::array<std::int64_t, 4>& node_ids,
                           const SourceLocation& where) {
  if (!shell_ids_.insert(id).second) {
    throw InputError(where, "shell " + std::to_string(id) + " is already defined");
  }
  Mesh& mesh = model.mesh;
  shell_nodes.push_back({mesh.shell_count(), node_ids, file_index(where.file), where.line,
                         keyword_name(where.keyword)});
  mesh.add_shell(id, part, {-1, -1, -1, -1});
}

SourceLocation DeckReader::shell_where(const ShellNodes& e, const std::string& field) const {
  return {files[e.file], e.line, e.keyword, field};
}

void DeckReader::claim_id(const std::string& kind, std::int64_t id, const SourceLocation& where) {
  const auto [it, inserted] = claimed_ids_.emplace(std::make_pair(kind, id), where);
  if (!inserted) {
    throw InputError(where, kind + " " + std::to_string(id) + " is already defined at " +
                                it->second.file + ":" + std::to_string(it->second.line));
  }
}

std::size_t DeckReader::file_index(const std::string& name) {
  for (std::size_t k = files.size(); k-- > 0;)
    if (files[k] == name) return k;
  files.push_back(name);
  return files.size() - 1;
}

std::int32_t DeckReader::node_index(std::int64_t id) const {
  const auto it = node_index_.find(id);
  return it == node_index_.end() ? -1 : it->second;
}

std::uint8_t parse_dof_mask(const Row& r, std::size_t i) {
  if (!r.given(i) || r.text(i) == "0") return 0;
  const std::string w = upper(r.text(i));
  std::uint8_t mask = 0;
  for (const char c : w) {
    const std::uint8_t bit = c == 'X' ? kFixX : c == 'Y' ? kFixY : c == 'Z' ? kFixZ : 0;
    if (bit == 0 || (mask & bit) != 0) {
      r.fail(i, "expected 0, X, Y, Z, XY, YZ, ZX or XYZ, got '" + r.text(i) + "'");
    }
    mask = static_cast<std::uint8_t>(mask | bit);
  }
  return mask;
}

int parse_direction(const Row& r, std::size_t i, bool rotations) {
  const std::string w = r.word(i);
  static const char* const names[] = {"X", "Y", "Z", "RX", "RY", "RZ"};
  for (int d = 0; d < 6; ++d) {
    if (w == names[d]) {
      if (d >= 3 && !rotations) break;
      return d;
    }
  }
  r.fail(i, std::string("expected ") + (rotations ? "X, Y, Z, RX, RY or RZ" : "X, Y or Z") +
                ", got '" + r.text(i) + "'");
}

}  // namespace deck

DeckResult read_deck_with_notes(const std::string& path) {
  if (deck::upper(fs::path(path).extension().string()) == ".INP") return read_inp_with_notes(path);
  deck::DeckReader reader;
  reader.model.deck_path = path;
  deck::IncludeFrame frame;
  frame.directory = fs::path(path).parent_path();
  reader.read_file(path, frame, 0);
  return reader.finish();
}

DeckResult read_deck_string_with_notes(const std::string& text, const std::string& name) {
  deck::DeckReader reader;
  reader.model.deck_path = name;
  reader.read_text(text, name, deck::IncludeFrame{}, 0);
  return reader.finish();
}

Model read_deck(const std::string& path) { return read_deck_with_notes(path).model; }

Model read_deck_string(const std::string& text, const std::string& name) {
  return read_deck_string_with_notes(text, name).model;
}

}  // namespace abut
