#pragma once
// Small meshes and a prescribed-motion driver for element tests.
#include <array>
#include <cstdint>
#include <vector>

#include "abut/core/vec3.hpp"
#include "abut/element/solid_block.hpp"
#include "abut/mesh/mesh.hpp"

namespace abut::test {

// Nodes of a box grid of nx*ny*nz hexahedra of size hx*hy*hz, interior and boundary nodes
// moved by a fixed pseudo-random offset of relative size `distortion` (0 = regular grid).
inline Nodes box_grid(int nx, int ny, int nz, Vec3 size, double distortion,
                      std::vector<Hex8>& hexes) {
  Nodes nodes;
  std::uint32_t seed = 12345u;
  const auto jitter = [&]() {  // deterministic LCG in [-1, 1]
    seed = seed * 1664525u + 1013904223u;
    return (static_cast<double>(seed >> 8) / static_cast<double>(1u << 24)) * 2.0 - 1.0;
  };
  const Vec3 h{size.x / nx, size.y / ny, size.z / nz};
  for (int k = 0; k <= nz; ++k) {
    for (int j = 0; j <= ny; ++j) {
      for (int i = 0; i <= nx; ++i) {
        Vec3 p{i * h.x, j * h.y, k * h.z};
        p += Vec3{jitter() * h.x, jitter() * h.y, jitter() * h.z} * distortion;
        nodes.add(static_cast<std::int64_t>(nodes.size()) + 1, p);
      }
    }
  }
  const auto id = [&](int i, int j, int k) {
    return static_cast<std::int32_t>(i + (nx + 1) * (j + (ny + 1) * k));
  };
  hexes.clear();
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        hexes.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                         id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
                         id(i, j + 1, k + 1)});
      }
    }
  }
  return nodes;
}

// A single visibly distorted hexahedron (no two faces parallel, warped faces).
inline Nodes distorted_hex(std::vector<Hex8>& hexes) {
  Nodes nodes;
  const Vec3 p[8] = {{0.0, 0.0, 0.0},  {1.1, 0.1, -0.05}, {1.3, 1.2, 0.1},  {-0.1, 0.9, 0.05},
                     {0.1, -0.1, 1.0}, {1.0, 0.05, 1.2},  {1.2, 1.1, 0.95}, {0.05, 1.05, 1.1}};
  for (int a = 0; a < 8; ++a) nodes.add(a + 1, p[a]);
  hexes = {Hex8{0, 1, 2, 3, 4, 5, 6, 7}};
  return nodes;
}

// Moves the nodes along a prescribed motion x = f(X) and supplies the solver's state:
// v^{n-1/2} = (x^n - x^{n-1}) / dt, as the central-difference scheme would have it.
class Motion {
 public:
  explicit Motion(const Nodes& reference)
      : reference_(reference),
        x_(reference.x),
        y_(reference.y),
        z_(reference.z),
        vx_(reference.size(), 0.0),
        vy_(reference.size(), 0.0),
        vz_(reference.size(), 0.0) {}

  NodalState state() const {
    return {x_.data(), y_.data(), z_.data(), vx_.data(), vy_.data(), vz_.data()};
  }

  template <class Map>
  void move(Map&& map, double dt) {
    for (std::size_t i = 0; i < x_.size(); ++i) {
      const Vec3 p = map(reference_.position(i));
      vx_[i] = (p.x - x_[i]) / dt;
      vy_[i] = (p.y - y_[i]) / dt;
      vz_[i] = (p.z - z_[i]) / dt;
      x_[i] = p.x;
      y_[i] = p.y;
      z_[i] = p.z;
    }
  }

  Vec3 position(std::size_t i) const { return {x_[i], y_[i], z_[i]}; }

 private:
  const Nodes& reference_;
  std::vector<double> x_, y_, z_, vx_, vy_, vz_;
};

// Matrix-vector product with a row-major 3x3 matrix.
inline Vec3 mat_vec(const std::array<double, 9>& m, const Vec3& v) {
  return {m[0] * v.x + m[1] * v.y + m[2] * v.z, m[3] * v.x + m[4] * v.y + m[5] * v.z,
          m[6] * v.x + m[7] * v.y + m[8] * v.z};
}

}  // namespace abut::test
