// *MERGE_DUPLICATED_NODES at the end of reading: nodes of entity s that lie within tol of a node
// of entity m are replaced by that node in every element and leave the mesh. It runs once every
// element and node set holds node indices and before refinement, contact adjustment, pressure
// faces and initial velocities take node indices up, so that only the elements, the node sets and
// the reader's id look-up have to follow the new numbering.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "abut/mesh/node_removal.hpp"
#include "deck_reader.hpp"

namespace abut::deck {
namespace {

std::string at(const SourceLocation& where) {
  return where.file + ":" + std::to_string(where.line);
}

std::string describe(const EntityRef& e) {
  return e.type == EntityType::All ? "ALL" : entity_word(e.type) + " " + std::to_string(e.id);
}

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// Nodes in no element: 10^-6 of the model's diagonal (its extent is all there is to go by).
double free_node_tolerance(const Nodes& nodes) {
  if (nodes.size() == 0) return 1.0;
  Vec3 lo = nodes.position(0), hi = lo;
  for (std::size_t i = 1; i < nodes.size(); ++i) {
    const Vec3 p = nodes.position(i);
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  const double extent = norm(hi - lo);
  return extent > 0.0 ? 1e-6 * extent : 1.0;
}

// Fraction of the shortest edge at a node within which another node is the same node: far below
// any element, far above the rounding of coordinates written with 8 or more digits.
constexpr double kEdgeFraction = 1e-4;
// Relative rounding of a coordinate (a few hundred ulps): the tolerance is never below it, so
// that fine meshes far from the origin still join.
constexpr double kRounding = 1e-13;

// The default tolerance of every node: a fraction of the shortest edge of the hexahedra and shells
// that meet at it (the local node spacing, not the model's size, so that the nodes of a slender
// model stay apart), never below the rounding of its coordinates. A pair of nodes merges within
// the smaller of their two tolerances (coincident_replacements).
std::vector<double> default_tolerances(const Mesh& mesh) {
  const Nodes& nodes = mesh.nodes;
  constexpr double kNone = std::numeric_limits<double>::infinity();
  std::vector<double> shortest(nodes.size(), kNone);
  const auto edge = [&](std::int32_t a, std::int32_t b) {
    const auto i = static_cast<std::size_t>(a), j = static_cast<std::size_t>(b);
    const double length = norm(nodes.position(i) - nodes.position(j));
    // A zero edge (a degenerate element) or one that overflows says nothing about the spacing.
    if (!(length > 0.0) || !std::isfinite(length)) return;
    shortest[i] = std::min(shortest[i], length);
    shortest[j] = std::min(shortest[j], length);
  };
  // The 12 edges of a hexahedron (VTK_HEXAHEDRON order).
  constexpr int kEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                 {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  for (const Hex8& h : mesh.hexes) {
    for (const auto& e : kEdges) edge(h[e[0]], h[e[1]]);
  }
  for (const Quad4& q : mesh.shells) {
    const int corners = is_triangle(q) ? 3 : 4;
    for (int k = 0; k < corners; ++k) edge(q[k], q[(k + 1) % corners]);
  }
  std::vector<double> tolerance(nodes.size());
  std::optional<double> free_node;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (shortest[i] == kNone) {
      if (!free_node) free_node = free_node_tolerance(nodes);
      tolerance[i] = *free_node;
      continue;
    }
    const Vec3 p = nodes.position(i);
    const double reach = std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
    tolerance[i] = std::max(kEdgeFraction * shortest[i], kRounding * reach);
  }
  return tolerance;
}

// An element that would lose a corner to the merge has no volume (or area) left: the tolerance
// is larger than the element, which is an error of the deck rather than something to run.
void require_distinct_corners(const Mesh& mesh, const std::vector<std::int32_t>& new_index,
                              const PendingMerge& m, const std::string& tol) {
  const auto fail = [&](const std::string& element) {
    throw InputError(with_field(m.where, "tol"),
                     "merging nodes within " + tol + " would join two corners of " + element +
                         ": give a tolerance smaller than the elements");
  };
  const auto index = [&](std::int32_t n) { return new_index[static_cast<std::size_t>(n)]; };
  for (std::size_t h = 0; h < mesh.hex_count(); ++h) {
    Hex8 q = mesh.hexes[h];
    for (std::int32_t& n : q) n = index(n);
    std::sort(q.begin(), q.end());
    if (std::adjacent_find(q.begin(), q.end()) != q.end())
      fail("hexahedron " + std::to_string(mesh.hex_id[h]));
  }
  for (const CellBlock& block : mesh.cells)
    for (std::size_t c = 0; c < block.size(); ++c) {
      std::vector<std::int32_t> nodes;
      for (const std::int32_t n : block.cell(c)) nodes.push_back(index(n));
      std::sort(nodes.begin(), nodes.end());
      if (std::adjacent_find(nodes.begin(), nodes.end()) != nodes.end())
        fail(std::string(element_label(block.type)) + " element " + std::to_string(block.id[c]));
    }
  for (std::size_t s = 0; s < mesh.shell_count(); ++s) {
    const Quad4& q = mesh.shells[s];
    // A triangle repeats n3 as n4 (is_triangle); a quad must keep four nodes.
    const std::size_t corners = is_triangle(q) ? 3 : 4;
    std::vector<std::int32_t> c;
    for (std::size_t k = 0; k < corners; ++k) c.push_back(index(q[k]));
    std::sort(c.begin(), c.end());
    if (std::adjacent_find(c.begin(), c.end()) != c.end())
      fail("shell " + std::to_string(mesh.shell_id[s]));
  }
}

}  // namespace

void DeckReader::require_unmerged(const EntityRef& entity) const {
  if (entity.type != EntityType::Node) return;
  const auto it = merged_nodes_.find(entity.id);
  if (it == merged_nodes_.end()) return;
  const auto& [survivor, command] = it->second;
  throw InputError(entity.where, "node " + std::to_string(entity.id) + " was merged into node " +
                                     std::to_string(survivor) + " by *MERGE_DUPLICATED_NODES at " +
                                     at(merges[command].where) + ": refer to node " +
                                     std::to_string(survivor));
}

void DeckReader::merge_duplicated_nodes() {
  Mesh& mesh = model.mesh;
  for (std::size_t k = 0; k < merges.size(); ++k) {
    const PendingMerge& m = merges[k];
    require_unmerged(m.secondary);
    require_unmerged(m.main);
    const std::string command = "*MERGE_DUPLICATED_NODES at " + at(m.where);
    const std::vector<std::int32_t> secondary = model.nodes_of(m.secondary);
    const std::vector<std::int32_t> main = model.nodes_of(m.main);
    if (secondary.empty())
      notes.push_back(command + ": " + describe(m.secondary) + " has no nodes");
    if (main.empty()) notes.push_back(command + ": " + describe(m.main) + " has no nodes");
    // The tolerance as the notes and errors give it.
    const std::string tol = m.tolerance ? number(*m.tolerance)
                                        : "the default tolerance (" + number(kEdgeFraction) +
                                              " of the shortest edge at each node)";
    const std::vector<std::int32_t> replacement =
        m.tolerance
            ? coincident_replacements(mesh.nodes, secondary, main, *m.tolerance)
            : coincident_replacements(mesh.nodes, secondary, main, default_tolerances(mesh));
    const auto merged = static_cast<std::size_t>(std::count_if(
        replacement.begin(), replacement.end(), [](std::int32_t r) { return r >= 0; }));
    if (merged == 0) {
      if (!secondary.empty() && !main.empty()) {
        notes.push_back(command + " merged no nodes: no node of " + describe(m.secondary) +
                        " lies within " + tol + " of a node of " + describe(m.main));
      }
      continue;
    }

    const std::vector<std::int64_t> old_ids = mesh.nodes.id;
    std::vector<std::int32_t> new_index(replacement.size());
    for (std::size_t i = 0; i < replacement.size(); ++i) {
      new_index[i] = replacement[i] >= 0 ? replacement[i] : static_cast<std::int32_t>(i);
    }
    require_distinct_corners(mesh, new_index, m, tol);
    for (std::size_t i = 0; i < replacement.size(); ++i) {
      if (replacement[i] >= 0) {
        merged_nodes_[old_ids[i]] = {old_ids[static_cast<std::size_t>(replacement[i])], k};
      }
    }
    // A node that an earlier command merged into one that goes now: name the one that stays.
    for (auto& [id, into] : merged_nodes_) {
      const auto next = merged_nodes_.find(into.first);
      if (next != merged_nodes_.end()) into.first = next->second.first;
    }

    const std::vector<std::int32_t> renumbered = remove_nodes(mesh, replacement);
    for (NodeSet& set : model.node_sets) {
      for (std::int32_t& n : set.nodes) n = renumbered[static_cast<std::size_t>(n)];
      std::sort(set.nodes.begin(), set.nodes.end());
      set.nodes.erase(std::unique(set.nodes.begin(), set.nodes.end()), set.nodes.end());
    }
    node_index_.clear();
    for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
      node_index_.emplace(mesh.nodes.id[i], static_cast<std::int32_t>(i));
    notes.push_back(command + " merged " + std::to_string(merged) + " nodes");
  }
  // Commands that name a node by its id (entype N) must not name one that is gone.
  for (const EntityRef& e : entity_references) require_unmerged(e);
}

}  // namespace abut::deck
