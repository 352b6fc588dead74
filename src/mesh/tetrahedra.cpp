// *CHANGE_TO_TETRAHEDRA (see tetrahedra.hpp).
//
// How one hex is cut, given its face diagonals from the lowest node of each face (Dompierre et
// al. 1999 give tables; this is a shorter construction of the same subdivision). Reflect the
// reference cube so that the hex's lowest node sits at the origin O: the three faces through O
// are cut through O. Look at the three faces through the opposite corner D = (1,1,1):
//  - none cut through D: the six diagonals are the edges of the tetrahedron on O and the three
//    face-diagonal neighbours of O; it and the four corner tetrahedra at the other four nodes
//    fill the cube (5 tetrahedra);
//  - the face x_d = 1 cut through D: its diagonal is parallel to the one of the face x_d = 0
//    (through O), and the plane through both cuts the cube into two triangular prisms along d.
//    Each prism takes 3 tetrahedra: the tetrahedron of its lowest node and the opposite triangle,
//    then the pyramid that is left, cut along its base quad's own diagonal from the lowest node
//    (6 tetrahedra). Every quad, the cutting plane included (O is its lowest node), is cut by the
//    one rule, so the prisms fit each other and the neighbours.
#include "abut/mesh/tetrahedra.hpp"

#include <algorithm>
#include <cstddef>
#include <unordered_map>

#include "abut/mesh/generators.hpp"
#include "mesh/hex_geometry.hpp"
#include "mesh/surface_smoothing.hpp"

namespace abut {
namespace {

using detail::edge_key;
using detail::kHexCorner;

// Corner bit code i + 2 j + 4 k of each local node (kHexCorner's (i, j, k)).
constexpr int bits_of(int local) {
  return kHexCorner[local][0] + 2 * kHexCorner[local][1] + 4 * kHexCorner[local][2];
}

using Tet = std::array<std::int8_t, 4>;

double reference_volume6(const Tet& t) {  // 6 x the signed volume on the unit cube
  double d[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) d[r][c] = kHexCorner[t[r + 1]][c] - kHexCorner[t[0]][c];
  return d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) -
         d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0]) +
         d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]);
}

[[noreturn]] void fail(const SourceLocation& where, const std::string& message) {
  if (where.file.empty()) throw InputError("*CHANGE_TO_TETRAHEDRA: " + message);
  throw InputError(where, message);
}

// A face shared by a hex that changes and one that does not (or changes to the other type)
// would not conform: refuse it, naming both hexes.
void check_interfaces(const Mesh& mesh, const std::vector<int>& target,
                      const std::vector<const SourceLocation*>& where) {
  std::unordered_map<detail::HexFace, std::size_t, detail::HexFaceHash> hex_of_face;
  for (std::size_t h = 0; h < mesh.hex_count(); ++h) {
    for (int face = 0; face < 6; ++face) {
      const auto [it, inserted] = hex_of_face.emplace(detail::sorted_face(mesh, h, face), h);
      const std::size_t other = it->second;
      if (inserted || target[other] == target[h]) continue;
      const auto name = [&](std::size_t e) {
        return "hex " + std::to_string(mesh.hex_id[e]) + " (part " +
               std::to_string(mesh.hex_part[e]) + ", " +
               (target[e] == 0   ? std::string("kept")
                : target[e] == 4 ? "tet4"
                                 : "tet10") +
               ")";
      };
      fail(*where[target[h] > target[other] ? h : other],
           "a face between " + name(h) + " and " + name(other) +
               " would not conform (triangles against a quadrilateral, or a midside node on one "
               "side only); change both sides alike, e.g. with a region covering the whole "
               "connected body");
    }
  }
}

}  // namespace

HexTetrahedra hex_tetrahedra(std::span<const std::int32_t, 8> rank) {
  int local_of[8];
  for (int a = 0; a < 8; ++a) local_of[bits_of(a)] = a;
  const int lowest = static_cast<int>(std::min_element(rank.begin(), rank.end()) - rank.begin());
  const int flip = bits_of(lowest);  // reflection taking the lowest node to the origin
  // Local node and rank of the reflected corner with bit code c.
  const auto node = [&](int c) { return local_of[c ^ flip]; };
  const auto rank_of = [&](int c) { return rank[static_cast<std::size_t>(node(c))]; };

  HexTetrahedra out;
  const auto add = [&](int c0, int c1, int c2, int c3) {
    Tet t{static_cast<std::int8_t>(node(c0)), static_cast<std::int8_t>(node(c1)),
          static_cast<std::int8_t>(node(c2)), static_cast<std::int8_t>(node(c3))};
    if (reference_volume6(t) < 0.0) std::swap(t[2], t[3]);
    out.tets[static_cast<std::size_t>(out.count++)] = t;
  };

  // Axis d whose face x_d = 1 is cut through D = 7: its lowest node is D or the node e_d.
  int axis = -1;
  for (int d = 0; d < 3 && axis < 0; ++d) {
    int low = -1;
    for (int c = 0; c < 8; ++c)
      if ((c >> d & 1) && (low < 0 || rank_of(c) < rank_of(low))) low = c;
    if (low == 7 || low == (1 << d)) axis = d;
  }
  if (axis < 0) {  // 5 tetrahedra: the even corners' one and one at each odd corner
    add(0, 3, 5, 6);
    for (const int odd : {1, 2, 4, 7}) add(odd, odd ^ 1, odd ^ 2, odd ^ 4);
    return out;
  }
  // Two prisms along the axis, cut by the plane through O, D and the edges along the axis at
  // (p, q) = (0, 0) and (1, 1).
  const int e = 1 << axis, p = 1 << ((axis + 1) % 3), q = 1 << ((axis + 2) % 3);
  for (const int side : {p, q}) {
    int a[3] = {0, p | q, side};  // the triangle at x_d = 0; b = a + e at x_d = 1
    int b[3] = {e, e | p | q, e | side};
    int low = 0;
    for (int i = 1; i < 6; ++i) {
      const int c = i < 3 ? a[i] : b[i - 3];
      const int best = low < 3 ? a[low] : b[low - 3];
      if (rank_of(c) < rank_of(best)) low = i;
    }
    if (low >= 3) std::swap(a, b);
    std::rotate(a, a + low % 3, a + 3);
    std::rotate(b, b + low % 3, b + 3);
    add(a[0], b[0], b[1], b[2]);  // the lowest node and the opposite triangle
    const int lowest_of_base =
        std::min({rank_of(a[1]), rank_of(a[2]), rank_of(b[1]), rank_of(b[2])});
    if (lowest_of_base == rank_of(a[1]) || lowest_of_base == rank_of(b[2])) {  // a1 - b2
      add(a[0], a[1], a[2], b[2]);
      add(a[0], a[1], b[2], b[1]);
    } else {  // a2 - b1
      add(a[0], a[1], a[2], b[1]);
      add(a[0], a[2], b[2], b[1]);
    }
  }
  return out;
}

std::vector<std::string> change_to_tetrahedra(Mesh& mesh,
                                              const std::vector<TetrahedraChange>& changes,
                                              const RefinementCheck& check) {
  const std::size_t hex_count = mesh.hex_count();
  mesh.hex_shape.resize(hex_count, -1);
  mesh.hex_cell.resize(hex_count);

  // 1. What each hex becomes: 0 (kept), 4 or 10 nodes; the larger request wins.
  std::vector<int> target(hex_count, 0);
  const SourceLocation nowhere;
  std::vector<const SourceLocation*> where(hex_count, &nowhere);
  std::vector<std::vector<std::size_t>> selections;  // per (change, part), for the notes
  for (const TetrahedraChange& change : changes) {
    if (change.type != CellType::tet4 && change.type != CellType::tet10)
      fail(change.where, "expected 4- or 10-node tetrahedra");
    const int nodes = topology(change.type).nodes;
    for (const std::int64_t part : change.parts) {
      std::vector<std::size_t> chosen;
      bool part_has_hexes = false;
      for (std::size_t h = 0; h < hex_count; ++h) {
        if (mesh.hex_part[h] != part) continue;
        part_has_hexes = true;
        if (change.region &&
            !geometry_contains(*change.region, detail::hex_centroid(mesh, h), mesh))
          continue;
        chosen.push_back(h);
        if (nodes > target[h]) where[h] = &change.where;
        target[h] = std::max(target[h], nodes);
      }
      if (!part_has_hexes)
        fail(change.where, "part " + std::to_string(part) +
                               " has no 8-node hexahedra to change (tetrahedra are made from "
                               "hexahedra: generated components, *ELEMENT_SOLID, or *CHANGE_P-"
                               "ORDER with SPLIT)");
      selections.push_back(std::move(chosen));
    }
  }
  std::size_t changed = 0, quadratic = 0;
  const SourceLocation* first = &nowhere;
  for (std::size_t h = 0; h < hex_count; ++h) {
    if (target[h] == 0) continue;
    if (changed++ == 0) first = where[h];
    if (target[h] == 10) ++quadratic;
  }
  if (changed == 0) return {};
  if (check) {  // 6 tetrahedra per hex at most; a 10-node one adds about 7 nodes per hex
    check({5.0 * static_cast<double>(changed), 7.0 * static_cast<double>(quadratic)}, *first);
  }
  check_interfaces(mesh, target, where);

  // 2. Cut the hexes; midside nodes are shared through their edge.
  std::int64_t next_id = mesh.next_hex_id(), next_node = mesh.next_node_id();
  std::unordered_map<std::uint64_t, std::int32_t> midside;
  Mesh kept;
  std::vector<std::size_t> tets_of_hex(hex_count, 0);
  for (std::size_t h = 0; h < hex_count; ++h) {
    const Hex8& hex = mesh.hexes[h];
    if (target[h] == 0) {
      kept.add_hex(mesh.hex_id[h], mesh.hex_part[h], hex, mesh.hex_shape[h], mesh.hex_cell[h],
                   mesh.element_of(h));
      continue;
    }
    for (int a = 0; a < 8; ++a)
      for (int b = a + 1; b < 8; ++b)
        if (hex[a] == hex[b])
          fail(*where[h], "hex " + std::to_string(mesh.hex_id[h]) +
                              " repeats a node (a degenerate hexahedron): it cannot be cut");
    const HexTetrahedra cut = hex_tetrahedra(std::span<const std::int32_t, 8>(hex));
    const detail::HexPoints x = detail::hex_points(mesh, h);
    const std::int32_t shape = mesh.hex_shape[h];
    const HexCell& cell = mesh.hex_cell[h];
    const CellType type = target[h] == 4 ? CellType::tet4 : CellType::tet10;
    for (int t = 0; t < cut.count; ++t) {
      const Tet& local = cut.tets[static_cast<std::size_t>(t)];
      std::array<std::int32_t, 10> nodes{};
      for (int a = 0; a < 4; ++a) nodes[static_cast<std::size_t>(a)] = hex[local[a]];
      const Vec3 x0 = x[local[0]];
      if (dot(x[local[1]] - x0, cross(x[local[2]] - x0, x[local[3]] - x0)) <= 0.0)
        fail(*where[h], "hex " + std::to_string(mesh.hex_id[h]) +
                            " is too distorted to be cut: one of its tetrahedra would be "
                            "inverted or flat");
      if (type == CellType::tet10) {
        for (const EdgeTopology& edge : topology(CellType::tet10).edges) {
          const int la = local[edge.a], lb = local[edge.b];
          const std::int32_t na = hex[la], nb = hex[lb];
          const auto [it, inserted] = midside.emplace(edge_key(na, nb), 0);
          if (inserted) {
            const double s[3] = {0.5 * (kHexCorner[la][0] + kHexCorner[lb][0]),
                                 0.5 * (kHexCorner[la][1] + kHexCorner[lb][1]),
                                 0.5 * (kHexCorner[la][2] + kHexCorner[lb][2])};
            const Vec3 point =
                shape >= 0 ? shape_point(mesh.shapes[static_cast<std::size_t>(shape)], cell.block,
                                         cell.lo + cell.size * Vec3{s[0], s[1], s[2]})
                           : detail::trilinear(x, s[0], s[1], s[2]);
            const auto fixed =
                static_cast<std::uint8_t>(mesh.nodes.fixed[static_cast<std::size_t>(na)] &
                                          mesh.nodes.fixed[static_cast<std::size_t>(nb)]);
            it->second = mesh.nodes.add(next_node++, point, fixed);
          }
          nodes[static_cast<std::size_t>(edge.mid)] = it->second;
        }
      }
      mesh.add_cell(type, next_id++, mesh.hex_part[h],
                    std::span<const std::int32_t>(nodes.data(), type == CellType::tet4 ? 4 : 10));
    }
    tets_of_hex[h] = static_cast<std::size_t>(cut.count);
  }
  mesh.take_hexes(std::move(kept));

  // 3. One note per (line, part).
  std::vector<std::string> notes;
  std::size_t selection = 0;
  for (const TetrahedraChange& change : changes) {
    for (const std::int64_t part : change.parts) {
      const auto& chosen = selections[selection++];
      std::string note = "part " + std::to_string(part) + ": ";
      if (chosen.empty()) {
        notes.push_back(note +
                        "no hex centroid inside the *CHANGE_TO_TETRAHEDRA region; "
                        "nothing changed");
        continue;
      }
      std::size_t tets = 0, mine = 0;
      for (const std::size_t h : chosen) {
        if (target[h] != topology(change.type).nodes) continue;
        ++mine;
        tets += tets_of_hex[h];
      }
      note += std::to_string(mine) + " hexes cut into " + std::to_string(tets) + " " +
              (change.type == CellType::tet4 ? "4" : "10") +
              "-node tetrahedra (5 or 6 each, faces cut through their lowest node)";
      if (mine < chosen.size())
        note += "; " + std::to_string(chosen.size() - mine) +
                " selected hexes became 10-node tetrahedra by another line";
      notes.push_back(note);
    }
  }
  return notes;
}

}  // namespace abut
