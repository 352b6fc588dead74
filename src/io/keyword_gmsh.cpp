// *INCLUDE_GMSH (abut's own): a mesh from Gmsh, read from a .msh file or made at read time from
// a .geo, STEP or BREP file, placed like an *INCLUDE. Its physical groups become the deck's
// entities (docs/deck-reference.md, *INCLUDE_GMSH):
//   physical volume N   -> the solids of part N (its *PART gives the material)
//   physical surface N  -> face set N (and, when *PART N gives a thickness h, the shells of part N)
//   physical surface, curve or point N -> node set N (the nodes of its elements)
// A mesh without physical groups takes its volumes and surfaces in their place (volume 3 is part 3,
// surface 5 face set and node set 5), as Gmsh saves every element of such a mesh. Elements of
// entities outside every group are left out, as Gmsh leaves them out when it saves (a note says how
// many).
#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <unordered_map>

#include "abut/io/gmsh_mesh.hpp"
#include "deck_reader.hpp"
#include "memory_budget.hpp"

namespace abut::deck {
namespace {

class Importer {
 public:
  Importer(DeckReader& d, const gmsh::MshMesh& m, const IncludeFrame& frame,
           const SourceLocation& where)
      : d_(d), m_(m), frame_(frame), where_(where) {}

  void run() {
    std::unordered_map<std::int64_t, std::size_t> node_of;
    for (std::size_t k = 0; k < m_.node_tags.size(); ++k) node_of.emplace(m_.node_tags[k], k);
    std::vector<char> used(m_.node_tags.size(), 0);
    std::size_t left_out = 0;
    for (const gmsh::MshElementBlock& block : m_.blocks) {
      const std::vector<int> groups = gmsh::block_groups(m_, block);
      if (groups.empty()) {
        // Solids only: a mesh from CAD also has the elements of every surface, curve and point.
        if (block.dim == 3) left_out += block.size();
        continue;
      }
      for (const std::int64_t n : block.nodes) used[node_of.at(n)] = 1;
      if (block.dim == 3) {
        add_solids(block, groups);
      } else {
        for (const int g : groups) {
          if (block.dim == 2) add_faces(block, g);
          add_to_node_set(block, g);
        }
      }
    }
    for (std::size_t k = 0; k < m_.node_tags.size(); ++k) {
      if (!used[k]) continue;
      const SourceLocation at =
          place(m_.node_places.empty() ? gmsh::MshPlace{} : m_.node_places[k], "$Nodes");
      d_.add_node(shifted(m_.node_tags[k], frame_.offsets.node, at, "node"),
                  frame_.transform.point(m_.coordinates[k]), 0, at);
    }
    for (auto& [key, set] : face_sets_) {
      d_.model.face_sets.push_back(std::move(set.first));
      d_.face_sets.push_back(std::move(set.second));
      d_.face_sets.back().index = d_.model.face_sets.size() - 1;
    }
    for (auto& [key, set] : node_sets_) {
      d_.model.node_sets.push_back(std::move(set.first));
      d_.node_sets.push_back(std::move(set.second));
      d_.node_sets.back().index = d_.model.node_sets.size() - 1;
    }
    for (auto& [key, part] : parts_) d_.gmsh_parts.push_back(std::move(part));
    if (left_out > 0) {
      d_.notes.push_back(
          where_.file + ":" + std::to_string(where_.line) +
          ": *INCLUDE_GMSH: " + std::to_string(left_out) + " solid elements of " + m_.file +
          " lie in volumes of no physical group and were left out, as Gmsh leaves them out "
          "when it saves a mesh with physical groups");
    }
  }

 private:
  // Where a group is named in the file (its $PhysicalNames or $Entities line), else the keyword.
  SourceLocation group_where(int dim, int tag) const {
    const auto it = m_.group_places.find({dim, tag});
    if (it == m_.group_places.end()) return where_;
    return place(it->second, "");
  }
  SourceLocation place(const gmsh::MshPlace& p, const char* section) const {
    if (p.line == 0 && p.byte == 0) return where_;  // a mesh made from CAD: the keyword
    return {m_.file, p.line, section, ""};
  }
  SourceLocation element_place(const gmsh::MshElementBlock& block, std::size_t e) const {
    return place(block.places.empty() ? gmsh::MshPlace{} : block.places[e], "$Elements");
  }

  static std::int64_t shifted(std::int64_t tag, std::int64_t offset, const SourceLocation& at,
                              const char* what) {
    std::int64_t sum = 0;
    if (__builtin_add_overflow(tag, offset, &sum))
      throw InputError(at, std::string(what) + " " + std::to_string(tag) +
                               " plus the *INCLUDE_GMSH id offset " + std::to_string(offset) +
                               " exceeds the largest id");
    return sum;
  }

  // Node tags with the include's node offset.
  template <class Tags>
  Tags node_ids(Tags tags, const SourceLocation& at) const {
    for (std::int64_t& t : tags) t = shifted(t, frame_.offsets.node, at, "node");
    return tags;
  }

  void add_solids(const gmsh::MshElementBlock& block, const std::vector<int>& groups) {
    const SourceLocation block_at = place(block.where, "$Elements");
    if (groups.size() > 1) {
      throw InputError(block_at, "volume " + std::to_string(block.entity) + " of " + m_.file +
                                     " is in physical groups " + std::to_string(groups[0]) +
                                     " and " + std::to_string(groups[1]) +
                                     ": each physical volume is a part, and an element belongs "
                                     "to one part");
    }
    const std::int64_t part = shifted(groups[0], frame_.offsets.part, block_at, "part");
    if (!parts_.count({3, part})) {
      GmshPart p;
      p.part = part;
      p.dim = 3;
      p.group = gmsh::group_label(m_, 3, groups[0]);
      p.where = where_;
      parts_.emplace(std::make_pair(3, part), std::move(p));
    }
    const CellType cell = *gmsh::element_type(block.type)->cell;
    for (std::size_t e = 0; e < block.size(); ++e) {
      const SourceLocation at = element_place(block, e);
      const std::int64_t id = shifted(block.tags[e], frame_.offsets.element, at, "element");
      std::vector<std::int64_t> nodes = node_ids(gmsh::solid_nodes(block, e), at);
      if (cell == CellType::hex8) {
        std::array<std::int64_t, 8> hex{};
        std::copy(nodes.begin(), nodes.end(), hex.begin());
        d_.add_element(id, part, hex, at);
      } else {
        std::vector<std::size_t> fields(nodes.size());
        for (std::size_t k = 0; k < fields.size(); ++k) fields[k] = k + 1;
        d_.add_cell(id, part, cell, std::move(nodes), std::move(fields),
                    m_.node_places.empty() ? "*INCLUDE_GMSH" : "$Elements", at);
      }
    }
  }

  // A physical surface: the faces of face set g, and the shells part g would have.
  void add_faces(const gmsh::MshElementBlock& block, int g) {
    const int type = block.type;
    PendingFaceSet& pending = face_set(g).second;
    GmshPart& shells = shell_part(g);
    for (std::size_t e = 0; e < block.size(); ++e) {
      const SourceLocation at = element_place(block, e);
      PendingFaceSet::Face face;
      face.nodes = node_ids(gmsh::face_corners(block, e), at);
      face.where = at;
      pending.faces.push_back(face);
      GmshPart::Shell shell;
      shell.id = shifted(block.tags[e], frame_.offsets.element, at, "element");
      shell.nodes = face.nodes;
      shell.linear = type == 2 || type == 3;  // tri3, quad4
      shell.where = at;
      shells.shells.push_back(shell);
    }
  }

  std::pair<FaceSet, PendingFaceSet>& face_set(int g) {
    const auto it = face_sets_.find(g);
    if (it != face_sets_.end()) return it->second;
    const SourceLocation at = group_where(2, g);
    FaceSet set;
    set.id = shifted(g, frame_.offsets.other, at, "face set");
    set.where = at;
    set.name = gmsh::group_name(m_, 2, g);
    d_.claim_id("face set", set.id, at);
    return face_sets_.emplace(g, std::make_pair(std::move(set), PendingFaceSet{})).first->second;
  }

  GmshPart& shell_part(int g) {
    const std::int64_t part = shifted(g, frame_.offsets.part, where_, "part");
    const auto it = parts_.find({2, part});
    if (it != parts_.end()) return it->second;
    GmshPart p;
    p.part = part;
    p.dim = 2;
    p.group = gmsh::group_label(m_, 2, g);
    p.where = where_;
    return parts_.emplace(std::make_pair(2, part), std::move(p)).first->second;
  }

  void add_to_node_set(const gmsh::MshElementBlock& block, int g) {
    auto it = node_sets_.find({block.dim, g});
    if (it == node_sets_.end()) {
      const SourceLocation at = group_where(block.dim, g);
      NodeSet set;
      set.id = shifted(g, frame_.offsets.other, at, "node set");
      d_.claim_id("node set", set.id, at);
      it = node_sets_.emplace(std::make_pair(block.dim, g), std::make_pair(set, PendingNodeSet{}))
               .first;
    }
    PendingNodeSet& pending = it->second.second;
    auto& seen = node_set_members_[{block.dim, g}];
    for (std::size_t e = 0; e < block.size(); ++e) {
      const SourceLocation at = element_place(block, e);
      const auto per = static_cast<std::ptrdiff_t>(gmsh::element_type(block.type)->nodes);
      const auto first = block.nodes.begin() + static_cast<std::ptrdiff_t>(e) * per;
      for (const std::int64_t id : node_ids(std::vector<std::int64_t>(first, first + per), at))
        if (seen.insert(id).second) pending.nodes.push_back({id, at});
    }
  }

  DeckReader& d_;
  const gmsh::MshMesh& m_;
  const IncludeFrame& frame_;
  SourceLocation where_;  // the *INCLUDE_GMSH file name
  std::map<int, std::pair<FaceSet, PendingFaceSet>> face_sets_;
  std::map<std::pair<int, int>, std::pair<NodeSet, PendingNodeSet>> node_sets_;
  std::map<std::pair<int, int>, std::set<std::int64_t>> node_set_members_;
  std::map<std::pair<int, std::int64_t>, GmshPart> parts_;  // (dim, part id)
};

}  // namespace

void read_include_gmsh(DeckReader& d, Block& b) {
  const Line name_line = b.raw_line("the file name");
  const SourceLocation file_where = b.where(name_line);
  const std::string file_name = unquote(name_line.text);
  if (file_name.empty()) throw InputError(file_where, "expected a file name");
  const std::filesystem::path path = d.frame().directory / std::filesystem::path(file_name);
  const std::optional<gmsh::GmshFile> kind = gmsh::gmsh_file_kind(path);
  if (!kind) throw InputError(file_where, "'" + file_name + "': expected " + gmsh::kGmshFileKinds);
  gmsh::CadMeshing meshing;
  if (auto r = b.optional_row({"h", "order"})) {
    if (*kind == gmsh::GmshFile::mesh && (r->given(0) || r->given(1)))
      r->fail(r->given(0) ? 0 : 1,
              "a .msh file is meshed already: h and order are for .geo, STEP and BREP files "
              "(leave the line empty: a comma alone)");
    if (r->given(0)) {
      meshing.size = r->number(0);
      r->require(meshing.size > 0.0, 0, "expected a mesh size h > 0");
    }
    if (r->given(1)) {
      const std::int64_t order = r->integer(1);
      r->require(order == 1 || order == 2, 1, "expected the element order 1 (tet4) or 2 (tet10)");
      meshing.order = static_cast<int>(order);
    }
    if (*kind == gmsh::GmshFile::cad && meshing.size == 0.0)
      r->fail(0, "a STEP or BREP file has no mesh sizes: give h, the element size");
  } else if (*kind == gmsh::GmshFile::cad) {
    throw InputError(file_where,
                     "a STEP or BREP file has no mesh sizes: give h, the element "
                     "size, on the line after the file name");
  }
  IncludeFrame frame = d.placement(b);
  if (frame.transform.mirrors())
    throw InputError(file_where, "a mirrored *INCLUDE_GMSH is not supported yet by abut");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(file_where, "cannot open '" + path.string() + "'");
  gmsh::MshMesh mesh;
  if (*kind == gmsh::GmshFile::mesh) {
    mesh = gmsh::read_msh_file(path);
  } else {
    meshing.check_size = [&](double elements, double nodes) {
      const Mesh& now = d.model.mesh;
      require_memory({static_cast<double>(now.solid_count() + now.shell_count()) + elements,
                      static_cast<double>(now.nodes.size()) + nodes},
                     available_memory(), file_where);
    };
    try {
      mesh = gmsh::mesh_cad(path, meshing);
    } catch (const InputError& e) {
      throw InputError(file_where, e.message());
    }
  }
  Importer(d, mesh, frame, file_where).run();
}

void DeckReader::finish_gmsh() {
  std::set<std::int64_t> parts;
  for (const Part& p : model.parts) parts.insert(p.id);
  for (const GmshPart& g : gmsh_parts) {
    if (g.dim == 3 && !parts.count(g.part)) {
      std::string defined;
      for (const std::int64_t id : parts)
        defined += (defined.empty() ? "" : ", ") + std::to_string(id);
      throw InputError(g.where, g.group + " is part " + std::to_string(g.part) +
                                    ", which no *PART defines (defined parts: " +
                                    (defined.empty() ? "none" : defined) + ")");
    }
    if (g.dim != 2 || !parts_with_thickness.count(g.part)) continue;
    for (const GmshPart::Shell& s : g.shells) {
      if (!s.linear) {
        throw InputError(s.where, "element " + std::to_string(s.id) + " of " + g.group +
                                      " has midside nodes: part " + std::to_string(g.part) +
                                      " has a thickness, so its elements are shells, and abut's "
                                      "shells have 3 or 4 nodes");
      }
      add_shell(s.id, g.part, s.nodes, s.where);
    }
  }
}

}  // namespace abut::deck
