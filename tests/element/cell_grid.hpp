#pragma once
// A box meshed with cells of any type (mesh/topology.hpp) for element tests: a grid of nx*ny*nz
// hexahedra whose corners may be moved, each hexahedron kept (hex8, hex20), split into 6
// tetrahedra around its main diagonal (Freudenthal-Kuhn; conforming between neighbours because
// every cube is split the same way) or into 2 wedges along the diagonal 0-2 of its bottom face.
// Midside nodes sit halfway along their (straight) edge and are shared between neighbours; the
// Lagrange hexahedra (hex27, hex64) take the nodes of their lattice where the hexahedron's
// trilinear map puts them, shared between neighbours too. With
// `map`, every node (midside nodes included) is then taken from the box to map(position): the
// quadratic cells of a curved body have their midside nodes on it.
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <utility>
#include <vector>

#include "abut/core/vec3.hpp"
#include "abut/mesh/mesh.hpp"

namespace abut::test {

struct CellGrid {
  Nodes nodes;
  std::vector<std::vector<std::int32_t>> cells;
  std::vector<std::uint8_t> on_boundary;  // per node: on the box's surface
};

inline CellGrid cell_grid(CellType type, int nx, int ny, int nz, Vec3 size,
                          const std::function<Vec3(int, int, int, Vec3)>& move = {},
                          const std::function<Vec3(Vec3)>& map = {}) {
  CellGrid g;
  const auto id = [&](int i, int j, int k) {
    return static_cast<std::int32_t>(i + (nx + 1) * (j + (ny + 1) * k));
  };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        Vec3 p{size.x * i / nx, size.y * j / ny, size.z * k / nz};
        if (move) p = move(i, j, k, p);
        g.nodes.add(static_cast<std::int64_t>(g.nodes.size()) + 1, p);
        g.on_boundary.push_back(i == 0 || j == 0 || k == 0 || i == nx || j == ny || k == nz);
      }
  const CellTopology& t = topology(type);
  std::map<std::pair<std::int32_t, std::int32_t>, std::int32_t> midside;
  const auto mid = [&](std::int32_t a, std::int32_t b) {
    const auto key = std::minmax(a, b);
    const auto it = midside.find(key);
    if (it != midside.end()) return it->second;
    const Vec3 p = (g.nodes.position(a) + g.nodes.position(b)) * 0.5;
    const std::int32_t n = g.nodes.add(static_cast<std::int64_t>(g.nodes.size()) + 1, p);
    g.on_boundary.push_back(g.on_boundary[a] && g.on_boundary[b] &&
                            ((p.x == 0.0 || p.x == size.x) || (p.y == 0.0 || p.y == size.y) ||
                             (p.z == 0.0 || p.z == size.z)));
    midside.emplace(key, n);
    return n;
  };
  const auto add = [&](std::vector<std::int32_t> corners) {
    corners.resize(static_cast<std::size_t>(t.nodes), -1);
    for (const EdgeTopology& e : t.edges)
      if (e.mid >= 0) corners[e.mid] = mid(corners[e.a], corners[e.b]);
    g.cells.push_back(std::move(corners));
  };
  // Lagrange hexahedra: the node at lattice place (I, J, K) of the whole box (p per cell).
  std::map<std::array<int, 3>, std::int32_t> lattice;
  const auto lagrange = [&](const std::int32_t(&h)[8], int i, int j, int k) {
    const int p = t.order;
    std::vector<std::int32_t> cell(static_cast<std::size_t>(t.nodes));
    for (int a = 0; a < t.nodes; ++a) {
      const auto& xi = t.natural[static_cast<std::size_t>(a)];
      if (a < 8) {
        cell[a] = h[a];
        continue;
      }
      const std::array<int, 3> place = {
          p * i + static_cast<int>(std::lround(0.5 * (xi[0] + 1) * p)),
          p * j + static_cast<int>(std::lround(0.5 * (xi[1] + 1) * p)),
          p * k + static_cast<int>(std::lround(0.5 * (xi[2] + 1) * p))};
      const auto it = lattice.find(place);
      if (it != lattice.end()) {
        cell[a] = it->second;
        continue;
      }
      Vec3 x{};
      const auto& corner = topology(CellType::hex8).natural;
      for (int c = 0; c < 8; ++c)
        x += g.nodes.position(h[c]) * ((1 + xi[0] * corner[c][0]) * (1 + xi[1] * corner[c][1]) *
                                       (1 + xi[2] * corner[c][2]) / 8.0);
      cell[a] = g.nodes.add(static_cast<std::int64_t>(g.nodes.size()) + 1, x);
      g.on_boundary.push_back(place[0] == 0 || place[1] == 0 || place[2] == 0 ||
                              place[0] == p * nx || place[1] == p * ny || place[2] == p * nz);
      lattice.emplace(place, cell[a]);
    }
    g.cells.push_back(std::move(cell));
  };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const std::int32_t h[8] = {
            id(i, j, k),     id(i + 1, j, k),     id(i + 1, j + 1, k),     id(i, j + 1, k),
            id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        switch (type) {
          case CellType::hex8:
          case CellType::hex20:
            add({h, h + 8});
            break;
          case CellType::hex27:
          case CellType::hex64:
            lagrange(h, i, j, k);
            break;
          case CellType::tet4:
          case CellType::tet10: {
            // Around the diagonal 0-6, each tetrahedron positively oriented (node 3 on the side
            // the right-hand normal of 0-1-2 points to).
            constexpr int kTets[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                                         {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
            for (const auto& tet : kTets) {
              std::vector<std::int32_t> c = {h[tet[0]], h[tet[1]], h[tet[2]], h[tet[3]]};
              const Vec3 p0 = g.nodes.position(c[0]);
              const double v = dot(cross(g.nodes.position(c[1]) - p0, g.nodes.position(c[2]) - p0),
                                   g.nodes.position(c[3]) - p0);
              if (v < 0.0) std::swap(c[1], c[2]);
              add(c);
            }
            break;
          }
          case CellType::wedge6:
            add({h[0], h[1], h[2], h[4], h[5], h[6]});
            add({h[0], h[2], h[3], h[4], h[6], h[7]});
            break;
        }
      }
  if (map)
    for (std::size_t a = 0; a < g.nodes.size(); ++a) {
      const Vec3 p = map(g.nodes.position(a));
      g.nodes.x[a] = p.x;
      g.nodes.y[a] = p.y;
      g.nodes.z[a] = p.z;
    }
  return g;
}

}  // namespace abut::test
