// *CHANGE_P-ORDER and *SMOOTH_MESH: an order-p hex becomes a Lagrange hexahedron on the
// (p + 1)^3 lattice of its nodes, or p x p x p linear hexes on the same lattice (see refine.hpp).
// New node positions, by priority:
//  1. hexes of generated components: the component's exact map at fractional grid coordinates;
//  2. other hexes: the trilinear map plus the bulge of their curved edges (transfinite edge
//     blending), where edges are curved only on a *SMOOTH_MESH surface (surface_smoothing.hpp).
// Nodes shared by neighbouring hexes are found by their place between shared corner nodes (not
// by position, so bodies that only touch stay apart); a count check then proves the refined mesh
// is conforming.
#include "abut/mesh/refine.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "abut/core/error.hpp"
#include "mesh/hex_geometry.hpp"
#include "mesh/surface_smoothing.hpp"

namespace abut {
namespace {

using detail::edge_key;
using detail::hex_centroid;
using detail::HexPoints;
using detail::kHexCorner;
using detail::kHexEdges;
using detail::sorted_face;
using Face = detail::HexFace;

// For every face: the hexes on it (one for an exterior face, two for an interior one).
struct FaceUse {
  std::size_t hex = 0;
  int face = 0;
  int count = 0;
};
using FaceUses = std::unordered_map<Face, FaceUse, detail::HexFaceHash>;
FaceUses face_uses(const Mesh& mesh) {
  FaceUses uses;
  for (std::size_t h = 0; h < mesh.hex_count(); ++h) {
    for (int f = 0; f < 6; ++f) {
      FaceUse& use = uses[sorted_face(mesh, h, f)];
      if (use.count++ == 0) {
        use.hex = h;
        use.face = f;
      }
    }
  }
  return uses;
}

// Hexes of `part` whose centroid lies in `region` (all of the part without a region).
// An error of one *CHANGE_P-ORDER or *SMOOTH_MESH line: at its deck line when it has one.
[[noreturn]] void fail(const SourceLocation& where, const char* keyword,
                       const std::string& message) {
  if (where.file.empty()) throw InputError(std::string(keyword) + ": " + message);
  throw InputError(where, message);
}

std::vector<std::size_t> select(const Mesh& mesh, std::int64_t part,
                                const std::optional<Geometry>& region, const char* keyword,
                                const SourceLocation& where) {
  std::vector<std::size_t> selected;
  bool part_exists = false;
  for (std::size_t h = 0; h < mesh.hex_count(); ++h) {
    if (mesh.hex_part[h] != part) continue;
    part_exists = true;
    if (!region || geometry_contains(*region, hex_centroid(mesh, h), mesh)) selected.push_back(h);
  }
  if (!part_exists) {
    fail(where, keyword, "refers to part " + std::to_string(part) + ", which has no hexahedra");
  }
  return selected;
}

std::string degrees(double angle) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", angle);
  return text;
}

std::string split_name(int p) {
  return std::to_string(p) + "x" + std::to_string(p) + "x" + std::to_string(p);
}

// Refining a hex puts new nodes on its edges; a neighbour sharing such an edge at another order
// would get hanging nodes. Refuse instead of producing a non-conforming mesh.
// `where[h]`: the line of the *CHANGE_P-ORDER that gave hex h its order (empty for order 1).
void check_conformity(const Mesh& mesh, const std::vector<int>& order,
                      const std::vector<const SourceLocation*>& where) {
  std::unordered_map<std::uint64_t, std::size_t> hex_of_edge;
  for (std::size_t h = 0; h < mesh.hex_count(); ++h) {
    for (const auto& e : kHexEdges) {
      const auto [it, inserted] =
          hex_of_edge.emplace(edge_key(mesh.hexes[h][e[0]], mesh.hexes[h][e[1]]), h);
      const std::size_t other = it->second;
      if (inserted || order[other] == order[h]) continue;
      const std::int64_t pa = mesh.hex_part[h], pb = mesh.hex_part[other];
      const std::string detail = " (hex " + std::to_string(mesh.hex_id[h]) + " order " +
                                 std::to_string(order[h]) + ", hex " +
                                 std::to_string(mesh.hex_id[other]) + " order " +
                                 std::to_string(order[other]) + ")";
      const SourceLocation& line = *where[order[h] > order[other] ? h : other];
      if (pa == pb) {
        fail(line, "*CHANGE_P-ORDER",
             "the region cuts through part " + std::to_string(pa) +
                 ": neighbouring hexes would get different orders and hanging nodes" + detail +
                 "; use a region that covers the whole connected part");
      }
      fail(line, "*CHANGE_P-ORDER",
           "parts " + std::to_string(std::min(pa, pb)) + " and " +
               std::to_string(std::max(pa, pb)) +
               " share nodes; refine both or neither (to the same order), otherwise "
               "the shared faces get hanging nodes" +
               detail);
    }
  }
}

// Trilinear map plus the bulge -c t (1 - t) of each curved edge, blended into the hex with the
// bilinear weight of the edge in the two other local coordinates. On a face this is the Coons
// patch of the four edge curves; inside, the edge-based transfinite interpolation.
Vec3 blended_point(const HexPoints& x, const std::array<Vec3, 12>& bulge, bool curved,
                   const double s[3]) {
  Vec3 p = detail::trilinear(x, s[0], s[1], s[2]);
  if (!curved) return p;
  for (int e = 0; e < 12; ++e) {
    const int along = e / 4;  // kHexEdges lists 4 edges along u, then v, then w
    const int* c = kHexCorner[kHexEdges[e][0]];
    double weight = s[along] * (1.0 - s[along]);
    for (int a = 0; a < 3; ++a) {
      if (a != along) weight *= c[a] == 1 ? s[a] : 1.0 - s[a];
    }
    p -= weight * bulge[e];
  }
  return p;
}

// Places the (p + 1)^3 lattice nodes of every hex of order p > 1 and replaces the hex by one
// Lagrange hexahedron on them (POrderForm::lagrange: hex27, hex64, same id and part) or by its
// p x p x p children (split: same part, new ids after the largest id). A new node is shared by
// the hexes whose lattices hold it, found by where it lies between the hex's corner nodes, not by
// its position: lattice point (i, j, k) of a hex has the trilinear weights prod (i or p - i) on
// its corners; the corners with non-zero weight (2 on an edge, 4 on a face, 8 inside) and their
// weights are the same from every hex around it (same order p: check_conformity), and two bodies
// that only touch share no corner node, so they stay apart.
void raise_order(Mesh& mesh, const std::vector<int>& order, const FaceUses& faces,
                 const std::unordered_map<std::uint64_t, Vec3>& curvature, POrderForm form) {
  const std::size_t hex_count = mesh.hex_count();
  std::size_t expected_new_nodes = 0, refined_hexes = 0;
  for (std::size_t h = 0; h < hex_count; ++h) {
    if (order[h] == 1) continue;
    ++refined_hexes;
    expected_new_nodes +=
        static_cast<std::size_t>((order[h] - 1) * (order[h] - 1) * (order[h] - 1));
  }
  if (refined_hexes == 0) return;
  {  // Each distinct edge and face of a refined hex owns (p-1) and (p-1)^2 new nodes.
    std::unordered_set<std::uint64_t> edges;
    for (std::size_t h = 0; h < hex_count; ++h) {
      if (order[h] == 1) continue;
      for (const auto& e : kHexEdges) {
        if (edges.insert(edge_key(mesh.hexes[h][e[0]], mesh.hexes[h][e[1]])).second) {
          expected_new_nodes += static_cast<std::size_t>(order[h] - 1);
        }
      }
    }
    for (const auto& [key, use] : faces) {
      const int p = order[use.hex];
      if (p > 1) expected_new_nodes += static_cast<std::size_t>((p - 1) * (p - 1));
    }
  }

  const std::size_t nodes_before = mesh.nodes.size();
  std::int64_t next_node = mesh.next_node_id(), next_hex = mesh.next_hex_id();
  // Sorted (corner node, weight) pairs, weights of a repeated node summed: the node they place.
  using Place = std::vector<std::pair<std::int32_t, int>>;
  std::map<Place, std::int32_t> placed;
  Mesh out;    // collects the new hex list; nodes are appended to mesh.nodes directly
  Mesh cells;  // the Lagrange hexahedra
  for (std::size_t h = 0; h < hex_count; ++h) {
    const int p = order[h];
    if (p == 1) {
      out.add_hex(mesh.hex_id[h], mesh.hex_part[h], mesh.hexes[h], mesh.hex_shape[h],
                  mesh.hex_cell[h], mesh.element_of(h));
      continue;
    }
    const std::int32_t shape = mesh.hex_shape[h];
    const HexCell cell = mesh.hex_cell[h];
    HexPoints x;
    for (int a = 0; a < 8; ++a) {
      x[a] = mesh.nodes.position(static_cast<std::size_t>(mesh.hexes[h][a]));
    }
    std::array<Vec3, 12> bulge{};
    bool curved = false;
    for (int e = 0; e < 12; ++e) {
      const auto it =
          curvature.find(edge_key(mesh.hexes[h][kHexEdges[e][0]], mesh.hexes[h][kHexEdges[e][1]]));
      if (shape < 0 && it != curvature.end()) {
        bulge[e] = it->second;
        curved = true;
      }
    }
    const int m = p + 1;
    std::vector<std::int32_t> lattice(static_cast<std::size_t>(m * m * m));
    auto at = [&](int i, int j, int k) -> std::int32_t& {
      return lattice[static_cast<std::size_t>((k * m + j) * m + i)];
    };
    for (int k = 0; k < m; ++k) {
      for (int j = 0; j < m; ++j) {
        for (int i = 0; i < m; ++i) {
          const bool corner = (i % p == 0) && (j % p == 0) && (k % p == 0);
          if (corner) {  // the hex's own node
            const int local = (k / p) * 4 + (j / p == 0 ? (i / p) : 3 - i / p);
            at(i, j, k) = mesh.hexes[h][local];
            continue;
          }
          const double s[3] = {static_cast<double>(i) / p, static_cast<double>(j) / p,
                               static_cast<double>(k) / p};
          const Vec3 point =
              shape >= 0 ? shape_point(mesh.shapes[static_cast<std::size_t>(shape)], cell.block,
                                       cell.lo + cell.size * Vec3{s[0], s[1], s[2]})
                         : blended_point(x, bulge, curved, s);
          Place place;
          for (int c = 0; c < 8; ++c) {
            const int* at_corner = kHexCorner[c];
            const int weight = (at_corner[0] ? i : p - i) * (at_corner[1] ? j : p - j) *
                               (at_corner[2] ? k : p - k);
            if (weight > 0) place.emplace_back(mesh.hexes[h][c], weight);
          }
          std::sort(place.begin(), place.end());
          Place merged;
          for (const auto& [node, weight] : place) {
            if (!merged.empty() && merged.back().first == node)
              merged.back().second += weight;
            else
              merged.emplace_back(node, weight);
          }
          const auto found = placed.find(merged);
          if (found != placed.end()) {
            at(i, j, k) = found->second;
          } else {
            at(i, j, k) = mesh.nodes.add(next_node++, point);
            placed.emplace(std::move(merged), at(i, j, k));
          }
        }
      }
    }
    if (form == POrderForm::lagrange) {  // the lattice in the cell's node order
      const CellType type = p == 2 ? CellType::hex27 : CellType::hex64;
      std::vector<std::int32_t> nodes;
      for (const auto& xi : topology(type).natural)
        nodes.push_back(at(static_cast<int>(std::lround(0.5 * (xi[0] + 1) * p)),
                           static_cast<int>(std::lround(0.5 * (xi[1] + 1) * p)),
                           static_cast<int>(std::lround(0.5 * (xi[2] + 1) * p))));
      cells.add_cell(type, mesh.hex_id[h], mesh.hex_part[h], nodes);
      continue;
    }
    for (int k = 0; k < p; ++k) {
      for (int j = 0; j < p; ++j) {
        for (int i = 0; i < p; ++i) {
          const Hex8 child{
              at(i, j, k),     at(i + 1, j, k),     at(i + 1, j + 1, k),     at(i, j + 1, k),
              at(i, j, k + 1), at(i + 1, j, k + 1), at(i + 1, j + 1, k + 1), at(i, j + 1, k + 1)};
          const double size = cell.size / p;
          const HexCell child_cell{
              cell.block,
              cell.lo + size * Vec3{static_cast<double>(i), static_cast<double>(j),
                                    static_cast<double>(k)},
              size};
          out.add_hex(next_hex++, mesh.hex_part[h], child, shape, child_cell, mesh.element_of(h));
        }
      }
    }
  }
  const std::size_t new_nodes = mesh.nodes.size() - nodes_before;
  mesh.take_hexes(std::move(out));
  for (const CellBlock& block : cells.cells)
    for (std::size_t c = 0; c < block.size(); ++c)
      mesh.add_cell(block.type, block.id[c], block.part[c], block.cell(c));
  if (new_nodes != expected_new_nodes) {
    throw InputError("*CHANGE_P-ORDER: refinement produced " + std::to_string(new_nodes) +
                     " new nodes where a conforming mesh has " +
                     std::to_string(expected_new_nodes) +
                     "; the hexes do not fit together edge to edge (a hex with a repeated corner "
                     "node, or neighbours that share corner nodes but not whole edges and faces)");
  }
}

}  // namespace

std::vector<std::string> refine_and_smooth(Mesh& mesh, const std::vector<OrderChange>& orders,
                                           const std::vector<SurfaceSmoothing>& smoothing,
                                           const RefinementCheck& check, POrderForm form) {
  const std::size_t hex_count = mesh.hex_count();
  mesh.hex_shape.resize(hex_count, -1);
  mesh.hex_cell.resize(hex_count);
  std::vector<std::string> notes;

  // 1. Final order of every hex: the highest order that selects it (orders only go up).
  std::vector<int> order(hex_count, 1);
  const SourceLocation nowhere;
  std::vector<const SourceLocation*> order_where(hex_count, &nowhere);
  std::vector<std::vector<std::size_t>> order_selection;  // per (change, part), for the notes
  for (const OrderChange& change : orders) {
    if (change.order < 1 || change.order > 3) {
      fail(change.where, "*CHANGE_P-ORDER",
           "order must be 1, 2 or 3 (got " + std::to_string(change.order) + ")");
    }
    for (std::int64_t part : change.parts) {
      order_selection.push_back(
          select(mesh, part, change.region, "*CHANGE_P-ORDER", change.where));
      for (std::size_t h : order_selection.back()) {
        if (change.order > order[h]) order_where[h] = &change.where;
        order[h] = std::max(order[h], change.order);
      }
    }
  }
  if (check) {  // first: the conformity check alone takes seconds on a mesh too large
    // A structured block of order-p hexes gains (p-1)^3 interior, 3 (p-1)^2 face and 3 (p-1) edge
    // nodes per hex: p^3 - 1, like its hexes.
    MeshSize added;
    std::size_t highest = 0;
    for (std::size_t h = 0; h < hex_count; ++h) {
      const double p = order[h];
      added.elements += p * p * p - 1.0;
      if (order[h] > order[highest]) highest = h;
    }
    added.nodes = added.elements;
    if (added.elements > 0.0) check(added, *order_where[highest]);
  }
  check_conformity(mesh, order, order_where);

  // 2. Curved edges of the *SMOOTH_MESH surfaces (exterior faces of hexes without exact shape).
  const auto faces = face_uses(mesh);
  std::unordered_map<std::uint64_t, Vec3> curvature;
  for (const SurfaceSmoothing& smooth : smoothing) {
    if (smooth.internal) {
      fail(smooth.where, "*SMOOTH_MESH",
           "internal = 1 (smoothing internal interfaces) is not supported yet; use 0");
    }
    if (!(smooth.max_angle > 0.0 && smooth.max_angle <= 180.0)) {
      fail(smooth.where, "*SMOOTH_MESH",
           "angle must be in (0, 180] degrees (got " + degrees(smooth.max_angle) + ")");
    }
    for (std::int64_t part : smooth.parts) {
      std::vector<char> chosen(hex_count, 0);
      std::size_t refined = 0, exact = 0;
      for (std::size_t h : select(mesh, part, smooth.region, "*SMOOTH_MESH", smooth.where)) {
        chosen[h] = 1;
        if (order[h] > 1) ++(mesh.hex_shape[h] >= 0 ? exact : refined);
      }
      std::vector<Face> surface;
      for (const auto& [key, use] : faces) {
        if (use.count != 1 || !chosen[use.hex] || mesh.hex_shape[use.hex] >= 0) continue;
        Face f;
        for (int a = 0; a < 4; ++a) f[a] = mesh.hexes[use.hex][kHexFaces[use.face][a]];
        surface.push_back(f);
      }
      const std::string who = "part " + std::to_string(part) + ": *SMOOTH_MESH ";
      if (refined + exact == 0) {
        notes.push_back(who +
                        "moves no nodes: its hexes stay linear (smoothing places only the "
                        "new nodes of *CHANGE_P-ORDER)");
        continue;
      }
      if (exact > 0) {
        notes.push_back(who + "not needed for " + std::to_string(exact) +
                        " refined hexes of generated components: their new nodes follow the "
                        "exact component shape");
      }
      if (refined == 0) continue;
      std::size_t rejected = 0;
      const auto curved =
          detail::smooth_edge_curvatures(mesh.nodes, surface, smooth.max_angle, rejected);
      curvature.insert(curved.begin(), curved.end());
      notes.push_back(who + std::to_string(surface.size()) +
                      " exterior faces made smooth (Nagata patches) for the new nodes of " +
                      std::to_string(refined) + " refined hexes; " + std::to_string(curved.size()) +
                      " edges curved, edges with face angles >= " + degrees(smooth.max_angle) +
                      " degrees kept straight" +
                      (rejected > 0 ? "; " + std::to_string(rejected) +
                                          " edges kept straight because the averaged normals "
                                          "disagree with the facets"
                                    : std::string()));
    }
  }

  // 3. Split. A count of new nodes that does not add up is a fault of the refinement as a whole:
  // it is reported at the first *CHANGE_P-ORDER line.
  try {
    raise_order(mesh, order, faces, curvature, form);
  } catch (const InputError& e) {
    if (!e.where().file.empty() || orders.empty() || orders.front().where.file.empty()) throw;
    std::string message = e.message();
    const std::string prefix = "*CHANGE_P-ORDER: ";
    if (message.starts_with(prefix)) message.erase(0, prefix.size());
    throw InputError(orders.front().where, message);
  }

  // 4. One note per (order change, part).
  std::size_t selection = 0;
  for (const OrderChange& change : orders) {
    for (std::int64_t part : change.parts) {
      const auto& chosen = order_selection[selection++];
      std::size_t split = 0, higher = 0;
      for (std::size_t h : chosen) ++(order[h] == change.order ? split : higher);
      std::string note = "part " + std::to_string(part) + ": ";
      if (chosen.empty()) {
        note += "no hex centroid inside the *CHANGE_P-ORDER region; nothing changed";
      } else if (change.order == 1) {
        note += std::to_string(chosen.size()) + " hexes stay linear (order 1)";
      } else if (form == POrderForm::lagrange) {
        note += std::to_string(split) + " hexes made " +
                std::to_string((change.order + 1) * (change.order + 1) * (change.order + 1)) +
                "-node Lagrange hexahedra (order " + std::to_string(change.order) + ")";
      } else {
        note += std::to_string(split) + " hexes split " + split_name(change.order) + " into " +
                std::to_string(
                    split * static_cast<std::size_t>(change.order * change.order * change.order)) +
                " (order " + std::to_string(change.order) + " represented by its nodal resolution)";
        if (higher > 0) {
          note += "; " + std::to_string(higher) + " selected hexes got a higher order elsewhere";
        }
      }
      notes.push_back(note);
    }
  }
  return notes;
}

}  // namespace abut
