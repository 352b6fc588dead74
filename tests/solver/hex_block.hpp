#pragma once
// A structured block of hexes for the tests that go from a mesh to contact.
#include "abut/mesh/mesh.hpp"

namespace abut::testing {

// A structured nx*ny*nz block of hexes (VTK node order) from `lo` to `hi`, in part `part`.
inline void add_hex_block(Mesh& mesh, std::int64_t part, int nx, int ny, int nz, Vec3 lo, Vec3 hi) {
  const auto first = static_cast<std::int32_t>(mesh.nodes.size());
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        mesh.nodes.add(mesh.next_node_id(),
                       {lo.x + (hi.x - lo.x) * i / nx, lo.y + (hi.y - lo.y) * j / ny,
                        lo.z + (hi.z - lo.z) * k / nz});
  auto n = [&](int i, int j, int k) { return first + (k * (ny + 1) + j) * (nx + 1) + i; };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        mesh.hexes.push_back({n(i, j, k), n(i + 1, j, k), n(i + 1, j + 1, k), n(i, j + 1, k),
                              n(i, j, k + 1), n(i + 1, j, k + 1), n(i + 1, j + 1, k + 1),
                              n(i, j + 1, k + 1)});
        mesh.hex_id.push_back(mesh.next_hex_id());
        mesh.hex_part.push_back(part);
        mesh.hex_shape.push_back(-1);
      }
}

}  // namespace abut::testing
