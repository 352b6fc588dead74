// The shell part of the end of reading: shell nodes resolved and checked, what a part with shells
// needs (a thickness, a material the shell element has, no hexes alongside), *PART_SHELL, and the
// commands that cannot take shell parts yet (contact surfaces, *CHANGE_P-ORDER, *SMOOTH_MESH).
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "abut/mesh/shell_generators.hpp"
#include "deck_reader.hpp"

namespace abut::deck {
namespace {

struct PartElements {
  bool hexes = false, shells = false;
};

std::map<std::int64_t, PartElements> elements_by_part(const Mesh& mesh) {
  std::map<std::int64_t, PartElements> parts;
  for (const std::int64_t p : mesh.hex_part) parts[p].hexes = true;
  for (const CellBlock& b : mesh.cells)
    for (const std::int64_t p : b.part) parts[p].hexes = true;
  for (const std::int64_t p : mesh.shell_part) parts[p].shells = true;
  return parts;
}

// A shell whose nodes are collinear or coincide has no normal: an error at its row. The
// tolerance is relative to the longest diagonal, so it does not depend on the units.
void require_area(const Mesh& mesh, const ShellNodes& e, const SourceLocation& where) {
  const Quad4& q = mesh.shells[e.shell];
  const auto x = [&](int k) { return mesh.nodes.position(static_cast<std::size_t>(q[k])); };
  const double diagonal = std::max({norm(x(2) - x(0)), norm(x(3) - x(1)), norm(x(1) - x(0))});
  if (norm(shell_area_vector(mesh.nodes, q)) <= 1e-10 * diagonal * diagonal) {
    throw InputError(where, "shell " + std::to_string(mesh.shell_id[e.shell]) +
                                " has zero area: its nodes coincide or lie on one line");
  }
}

// Refining hexes puts nodes on their faces that a shell attached to them would not share.
// `change`: what would be done to the hex ("refining it").
void require_unrefined_shell_nodes(const Mesh& mesh, const std::vector<std::int64_t>& parts,
                                   const SourceLocation& where, const std::string& change) {
  std::vector<std::uint8_t> on_shell(mesh.nodes.size(), 0);
  for (const Quad4& q : mesh.shells)
    for (const std::int32_t n : q) on_shell[static_cast<std::size_t>(n)] = 1;
  for (std::size_t h = 0; h < mesh.hex_count(); ++h) {
    if (!std::binary_search(parts.begin(), parts.end(), mesh.hex_part[h])) continue;
    for (const std::int32_t n : mesh.hexes[h]) {
      if (on_shell[static_cast<std::size_t>(n)]) {
        throw InputError(where, "hexahedron " + std::to_string(mesh.hex_id[h]) + " of part " +
                                    std::to_string(mesh.hex_part[h]) +
                                    " shares nodes with shells: " + change +
                                    " would detach them, "
                                    "which is not supported yet by abut");
      }
    }
  }
}

}  // namespace

void DeckReader::resolve_shell_nodes() {
  Mesh& mesh = model.mesh;
  for (const ShellNodes& e : shell_nodes) {
    for (std::size_t k = 0; k < 4; ++k) {
      const std::int32_t index = node_index(e.node_ids[k]);
      if (index < 0) {
        throw InputError(shell_where(e, "n" + std::to_string(k + 1)),
                         "node " + std::to_string(e.node_ids[k]) + " does not exist");
      }
      mesh.shells[e.shell][k] = index;
    }
  }
  for (const ShellNodes& e : shell_nodes) require_area(mesh, e, shell_where(e, ""));
}

void DeckReader::resolve_shells() {
  Mesh& mesh = model.mesh;

  const std::map<std::int64_t, PartElements> elements = elements_by_part(mesh);
  const auto has_shells = [&](std::int64_t part) {
    const auto it = elements.find(part);
    return it != elements.end() && it->second.shells;
  };
  for (const Part& p : model.parts) {
    if (!has_shells(p.id)) continue;
    const std::string part = "part " + std::to_string(p.id);
    if (elements.at(p.id).hexes) {
      throw InputError(p.where, part +
                                    " holds both hexahedra and shells: give each kind of "
                                    "element a part of its own");
    }
    if (!parts_with_thickness.count(p.id)) {
      throw InputError(with_field(p.where, "h"),
                       part +
                           " has shells: give their thickness h (the reference default of 1 "
                           "is no sensible thickness in any unit system)");
    }
    if (std::holds_alternative<MooneyRivlinParams>(model.material_of_part(p.id))) {
      throw InputError(with_field(p.where, "mid"),
                       "*MAT_MOONEY_RIVLIN on shells (" + part +
                           ") is not supported yet by abut; shells take *MAT_ELASTIC, "
                           "*MAT_METAL, *MAT_JC or *MAT_RIGID");
    }
  }

  std::set<std::int64_t> part_ids;
  for (const Part& p : model.parts) part_ids.insert(p.id);
  for (const PendingPartShell& s : part_shells) {
    const auto part = std::find_if(model.parts.begin(), model.parts.end(),
                                   [&s](const Part& p) { return p.id == s.part; });
    if (part == model.parts.end()) {
      throw InputError(s.where, "part " + std::to_string(s.part) +
                                    " does not exist (defined parts: " + joined(part_ids) + ")");
    }
    part->shell_points = s.points;
    part->shell_hourglass = s.hourglass;
    if (!has_shells(s.part))
      notes.push_back("*PART_SHELL of part " + std::to_string(s.part) + ": the part has no shells");
  }

  if (mesh.shell_count() == 0) return;
  const auto require_solid_parts = [&](const EntityRef& entity, const std::string& command) {
    std::vector<std::int64_t> parts = model.parts_of(entity);
    for (const std::int64_t p : parts) {
      if (entity.type != EntityType::All && has_shells(p)) {
        throw InputError(entity.where, command + " of shell parts (part " + std::to_string(p) +
                                           ") is not supported yet by abut");
      }
    }
    std::sort(parts.begin(), parts.end());
    return parts;
  };
  for (const PendingOrder& o : orders) {
    const std::vector<std::int64_t> parts = require_solid_parts(o.entity, "*CHANGE_P-ORDER");
    if (o.order > 1) require_unrefined_shell_nodes(mesh, parts, o.entity.where, "refining it");
  }
  for (const PendingTetrahedra& t : tetrahedra) {
    const std::vector<std::int64_t> parts = require_solid_parts(t.entity, "*CHANGE_TO_TETRAHEDRA");
    if (t.type == CellType::tet10)
      require_unrefined_shell_nodes(mesh, parts, t.entity.where,
                                    "giving its tetrahedra midside nodes");
  }
  for (const PendingSmoothing& s : smoothing) require_solid_parts(s.entity, "surface smoothing");
}

}  // namespace abut::deck
