#pragma once
// Nodes as structure of arrays and 8-node hexahedra (VTK_HEXAHEDRON node order: 0-3 counter-
// clockwise on the bottom face seen from above, 4-7 above them).
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <variant>
#include <vector>

#include "abut/core/vec3.hpp"
#include "abut/mesh/topology.hpp"

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

// 4-node shell (node indices, counter-clockwise about the shell normal (x3 - x1) x (x4 - x2)).
// A triangle repeats its third node: n4 == n3.
using Quad4 = std::array<std::int32_t, 4>;
inline bool is_triangle(const Quad4& q) { return q[3] == q[2]; }

// Exact shapes of generated components. A component is a set of structured blocks; its map
// takes (block, grid coordinates) to a point. Grid coordinates run from 0 to the element count
// along each block axis, and block axes 0, 1, 2 follow hex local axes 0->1, 0->3, 0->4, so a
// generated hex is the grid cube [lo, lo + size]^3 of one block (HexCell). Refinement evaluates
// the map at fractional grid coordinates, which puts new boundary nodes on the true geometry.
struct HexCell {
  std::int32_t block = 0;
  Vec3 lo;            // grid coordinates of hex node 0
  double size = 1.0;  // edge length in grid units (1 when generated, 1/p after refinement)
};

struct BoxShape {     // one block of nx x ny x nz between lo and hi
  Vec3 lo, hi;
  int nx = 1, ny = 1, nz = 1;
};

// Cube-sphere (O-grid). Blocks 0-5 are the outer blocks on the faces +x, -x, +y, -y, +z, -z
// (n x n tangential, n_radial radial); block 6 is the central cube of n x n x n (solid only).
struct SphereShape {
  Vec3 centre;
  double inner_radius = 0.0;     // 0: solid sphere with a central cube
  double outer_radius = 0.0;
  double core_half_size = 0.0;   // half edge of the central cube (solid sphere)
  int n = 1, n_radial = 1;
};

// O-grid cylinder (cone when the radii differ). Blocks 0-3 are the outer blocks on the sides
// +e1, +e2, -e1, -e2 of the square core (n tangential, n_radial radial); block 4 is the core
// (n x n). All blocks have n_axial elements along the axis.
struct CylinderShape {
  Vec3 end1;            // centre of end face 1
  Vec3 axis, e1, e2;    // right-handed unit frame: axis = e1 x e2 points from end 1 to end 2
  double length = 0.0;
  double radius1 = 0.0, radius2 = 0.0;
  double core_fraction = 0.0;  // core half edge / local radius
  int n = 1, n_radial = 1, n_axial = 1;
};

using ComponentShape = std::variant<BoxShape, SphereShape, CylinderShape>;

// The point of `shape` at grid coordinates `grid` of `block` (see HexCell).
Vec3 shape_point(const ComponentShape& shape, std::int32_t block, const Vec3& grid);

// Solid cells of one type other than the 8-node hexahedra (mesh/topology.hpp): connectivity
// (topology(type).nodes node indices per cell, in the type's order), user ids and parts.
struct CellBlock {
  CellType type = CellType::tet4;
  std::vector<std::int32_t> nodes;
  std::vector<std::int64_t> id;
  std::vector<std::int64_t> part;

  std::size_t size() const { return id.size(); }
  std::size_t nodes_per_cell() const { return static_cast<std::size_t>(topology(type).nodes); }
  std::span<const std::int32_t> cell(std::size_t c) const {
    return {nodes.data() + c * nodes_per_cell(), nodes_per_cell()};
  }
};

// One solid element of any type, as the solid numbering of Mesh::solid() gives it.
struct SolidRef {
  CellType type = CellType::hex8;
  std::span<const std::int32_t> nodes;
  std::int64_t id = 0;
  std::int64_t part = 0;
};

struct Mesh {
  Nodes nodes;
  std::vector<Hex8> hexes;
  std::vector<std::int64_t> hex_id;    // user element ids
  std::vector<std::int64_t> hex_part;  // user part id of each hex
  // Index into `shapes` of the generated component a hex came from, or -1 (given by *NODE /
  // *ELEMENT_SOLID). Lets refinement put new boundary nodes on the exact geometry.
  std::vector<std::int32_t> hex_shape;
  // Exact shapes of generated components (indexed by hex_shape) and, parallel to `hexes`, the
  // grid cell each generated hex covers (unused where hex_shape is -1).
  std::vector<ComponentShape> shapes;
  std::vector<HexCell> hex_cell;
  // The user's element each hex belongs to: its own id, or for the p x p x p hexes that
  // *CHANGE_P-ORDER makes of one element, that element's id. May be shorter than `hexes`
  // (hexes appended without it are their own elements): read it through element_of().
  std::vector<std::int64_t> hex_element;
  std::int64_t element_of(std::size_t h) const {
    return h < hex_element.size() ? hex_element[h] : hex_id[h];
  }

  // Shell elements (*ELEMENT_SHELL and the shell generators). Their ids are a namespace of their
  // own, as in LS-DYNA; generators number after the largest hex and shell id so that messages
  // stay unambiguous.
  std::vector<Quad4> shells;
  std::vector<std::int64_t> shell_id;    // user element ids
  std::vector<std::int64_t> shell_part;  // user part id of each shell

  // Solid cells of the other types, one block per type (docs/architecture.md, "Element
  // families": the hexahedra move into blocks once the explicit solver takes them).
  std::vector<CellBlock> cells;

  std::size_t hex_count() const { return hexes.size(); }
  // Every solid element under one numbering: the hexahedra (0 .. hex_count() - 1), then the
  // cells of each block in turn. The static solver, its printout and its output use it.
  std::size_t solid_count() const;
  SolidRef solid(std::size_t e) const;
  // Appends a cell of `type` (not hex8: add_hex) to the block of its type.
  void add_cell(CellType type, std::int64_t id, std::int64_t part,
                std::span<const std::int32_t> nodes_of_cell);
  std::size_t shell_count() const { return shells.size(); }
  // 1 for each node that a solid or a shell uses, 0 for a node of no element.
  std::vector<std::uint8_t> nodes_in_elements() const;
  void add_shell(std::int64_t id, std::int64_t part, const Quad4& nodes_of_shell);
  std::int64_t next_shell_id() const;
  // Appends a hex and keeps all per-hex arrays parallel.
  // `element`: the user element the hex belongs to (default: itself).
  void add_hex(std::int64_t id, std::int64_t part, const Hex8& nodes_of_hex,
               std::int32_t shape = -1, const HexCell& cell = {}, std::int64_t element = 0);
  // Replaces the hexahedra and every per-hex array by those of `from` (a hex list built with
  // add_hex, e.g. by refinement); nodes, shells and cells stay.
  void take_hexes(Mesh&& from);
  std::int64_t next_node_id() const;
  std::int64_t next_hex_id() const;
};

}  // namespace abut
