#pragma once
// Independent measures of a hex mesh for the mesh tests: volumes by Gauss quadrature of the
// trilinear map and the scaled Jacobian quality measure.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <set>
#include <tuple>
#include <vector>

#include "abut/mesh/mesh.hpp"

namespace abut::test {

inline std::array<Vec3, 8> corners(const Mesh& mesh, std::size_t h) {
  std::array<Vec3, 8> x;
  for (int a = 0; a < 8; ++a)
    x[a] = mesh.nodes.position(static_cast<std::size_t>(mesh.hexes[h][a]));
  return x;
}

// Jacobian determinant of the trilinear map at local coordinates (u, v, w) in [0, 1]^3.
inline double jacobian(const std::array<Vec3, 8>& x, double u, double v, double w) {
  constexpr int c[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                           {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  Vec3 du, dv, dw;
  for (int a = 0; a < 8; ++a) {
    const double fu = c[a][0] ? u : 1 - u, fv = c[a][1] ? v : 1 - v, fw = c[a][2] ? w : 1 - w;
    const double su = c[a][0] ? 1 : -1, sv = c[a][1] ? 1 : -1, sw = c[a][2] ? 1 : -1;
    du += (su * fv * fw) * x[a];
    dv += (fu * sv * fw) * x[a];
    dw += (fu * fv * sw) * x[a];
  }
  return dot(du, cross(dv, dw));
}

// Volume of the trilinear hex: 2x2x2 Gauss points integrate det J (degree <= 2 per
// coordinate) exactly.
inline double hex_volume(const Mesh& mesh, std::size_t h) {
  const auto x = corners(mesh, h);
  const double g[2] = {0.5 - 0.5 / std::sqrt(3.0), 0.5 + 0.5 / std::sqrt(3.0)};
  double v = 0.0;
  for (double u : g)
    for (double s : g)
      for (double w : g) v += 0.125 * jacobian(x, u, s, w);
  return v;
}

inline double total_volume(const Mesh& mesh) {
  double v = 0.0;
  for (std::size_t h = 0; h < mesh.hex_count(); ++h) v += hex_volume(mesh, h);
  return v;
}

inline double min_hex_volume(const Mesh& mesh) {
  double m = std::numeric_limits<double>::max();
  for (std::size_t h = 0; h < mesh.hex_count(); ++h) m = std::min(m, hex_volume(mesh, h));
  return m;
}

// Scaled Jacobian (Knupp, "Achieving finite element mesh quality via optimization of the
// Jacobian matrix norm and associated quantities", IJNME 48 (2000)): the smallest, over the 8
// corners, determinant of the three unit edge vectors leaving the corner. 1 for a cube.
inline double min_scaled_jacobian(const Mesh& mesh) {
  // Edge neighbours of each corner, ordered so that a right-handed hex gives +1.
  constexpr int n[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7},
                           {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};
  double worst = 1.0;
  for (std::size_t h = 0; h < mesh.hex_count(); ++h) {
    const auto x = corners(mesh, h);
    for (int a = 0; a < 8; ++a) {
      const Vec3 e0 = normalized(x[n[a][0]] - x[a]), e1 = normalized(x[n[a][1]] - x[a]),
                 e2 = normalized(x[n[a][2]] - x[a]);
      worst = std::min(worst, dot(e0, cross(e1, e2)));
    }
  }
  return worst;
}

// Number of node pairs closer than `tolerance` (duplicates that should have been merged).
inline std::size_t duplicate_nodes(const Mesh& mesh, double tolerance) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    for (std::size_t j = i + 1; j < mesh.nodes.size(); ++j)
      if (norm(mesh.nodes.position(i) - mesh.nodes.position(j)) < tolerance) ++count;
  return count;
}

// Nodes used by no hex.
inline std::size_t unused_nodes(const Mesh& mesh) {
  std::vector<char> used(mesh.nodes.size(), 0);
  for (const Hex8& hex : mesh.hexes)
    for (std::int32_t n : hex) used[static_cast<std::size_t>(n)] = 1;
  return static_cast<std::size_t>(std::count(used.begin(), used.end(), 0));
}

}  // namespace abut::test

namespace abut::test {

// Nodes on faces used by exactly one hex (the exterior surface), by sorted node quadruples.
inline std::vector<std::size_t> exterior_nodes(const Mesh& mesh) {
  constexpr int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                               {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
  std::map<std::array<std::int32_t, 4>, int> count;
  for (const Hex8& hex : mesh.hexes) {
    for (const auto& f : faces) {
      std::array<std::int32_t, 4> key{hex[f[0]], hex[f[1]], hex[f[2]], hex[f[3]]};
      std::sort(key.begin(), key.end());
      ++count[key];
    }
  }
  std::set<std::size_t> nodes;
  for (const auto& [key, n] : count)
    if (n == 1)
      for (std::int32_t v : key) nodes.insert(static_cast<std::size_t>(v));
  return {nodes.begin(), nodes.end()};
}

}  // namespace abut::test
