#pragma once
// Nodes as structure of arrays and 8-node hexahedra (VTK_HEXAHEDRON node order: 0-3 counter-
// clockwise on the bottom face seen from above, 4-7 above them).
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "abut/core/vec3.hpp"

namespace abut {

// Bit mask of constrained translations, as in *NODE bc and *BC_MOTION bc_tr.
enum DofMask : std::uint8_t { kFixX = 1, kFixY = 2, kFixZ = 4 };

struct Nodes {
  std::vector<double> x, y, z;       // coordinates
  std::vector<std::int64_t> id;      // user node ids
  std::vector<std::uint8_t> fixed;   // DofMask bits

  std::size_t size() const { return x.size(); }
  Vec3 position(std::size_t i) const { return {x[i], y[i], z[i]}; }
  std::int32_t add(std::int64_t user_id, const Vec3& p, std::uint8_t fixed_mask = 0) {
    x.push_back(p.x);
    y.push_back(p.y);
    z.push_back(p.z);
    id.push_back(user_id);
    fixed.push_back(fixed_mask);
    return static_cast<std::int32_t>(x.size() - 1);
  }
};

using Hex8 = std::array<std::int32_t, 8>;  // node indices (not user ids)

struct Mesh {
  Nodes nodes;
  std::vector<Hex8> hexes;
  std::vector<std::int64_t> hex_id;    // user element ids
  std::vector<std::int64_t> hex_part;  // user part id of each hex
  // Index into `shapes` of the generated component a hex came from, or -1 (given by *NODE /
  // *ELEMENT_SOLID). Lets refinement put new boundary nodes on the exact geometry.
  std::vector<std::int32_t> hex_shape;

  std::size_t hex_count() const { return hexes.size(); }
  std::int64_t next_node_id() const;
  std::int64_t next_hex_id() const;
};

}  // namespace abut
