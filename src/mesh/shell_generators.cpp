// Structured shell components: a grid of nodes mapped onto the plate or the tube, and the quads
// between neighbouring grid nodes. The tube's grid wraps around, so it is closed without merging.
#include "abut/mesh/shell_generators.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "abut/core/error.hpp"

namespace abut {
namespace {

void require_count(int n, int least, const std::string& what) {
  if (n < least) {
    throw InputError(what + " must be at least " + std::to_string(least) + " (got " +
                     std::to_string(n) + ")");
  }
}

// Shells continue after every element id, hex or shell, so that an id names one element.
std::int64_t next_element_id(const Mesh& mesh) {
  return std::max(mesh.next_hex_id(), mesh.next_shell_id());
}

// Adds the nodes point(i, j) for i in [0, ni] (i in [0, ni) when `wrap_i`) and j in [0, nj],
// and the ni x nj quads (i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1), counter-clockwise about
// d(point)/di x d(point)/dj. With `wrap_i` node ni is node 0: the grid closes around i.
void add_grid(Mesh& mesh, std::int64_t part, int ni, int nj, bool wrap_i,
              const std::function<Vec3(int, int)>& point) {
  const int rows = wrap_i ? ni : ni + 1;
  std::int64_t node_id = mesh.next_node_id();
  std::int64_t shell_id = next_element_id(mesh);
  std::vector<std::int32_t> grid(static_cast<std::size_t>(rows) * (nj + 1));
  auto at = [&](int i, int j) -> std::int32_t& {
    return grid[static_cast<std::size_t>(j) * rows + static_cast<std::size_t>(i % rows)];
  };
  for (int j = 0; j <= nj; ++j)
    for (int i = 0; i < rows; ++i) at(i, j) = mesh.nodes.add(node_id++, point(i, j));
  for (int j = 0; j < nj; ++j)
    for (int i = 0; i < ni; ++i)
      mesh.add_shell(shell_id++, part, {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
}

// Point j of n_circ around the square of half side 1 in the (e1, e2) plane, counter-clockwise
// from the corner (1, -1): n_circ / 4 segments per side.
std::array<double, 2> square_point(int j, int n_circ) {
  constexpr double corner[5][2] = {{1, -1}, {1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
  const int per_side = n_circ / 4;
  const int side = (j / per_side) % 4;
  const double f = static_cast<double>(j % per_side) / per_side;
  return {corner[side][0] + f * (corner[side + 1][0] - corner[side][0]),
          corner[side][1] + f * (corner[side + 1][1] - corner[side][1])};
}

}  // namespace

Vec3 tube_side_direction(const Vec3& axis, const Vec3& hint) {
  const Vec3 from_hint = hint - dot(hint, axis) * axis;
  if (norm(from_hint) > 1e-9 * norm(hint)) return normalized(from_hint);
  // As *COMPONENT_CYLINDER: the global axis least aligned with the tube axis.
  int least = 0;
  for (int a = 1; a < 3; ++a)
    if (std::abs(axis[a]) < std::abs(axis[least])) least = a;
  Vec3 trial;
  trial[least] = 1.0;
  return normalized(trial - dot(trial, axis) * axis);
}

Vec3 shell_area_vector(const Nodes& nodes, const Quad4& shell) {
  const auto x = [&](int k) { return nodes.position(static_cast<std::size_t>(shell[k])); };
  return 0.5 * cross(x(2) - x(0), x(3) - x(1));
}

void generate_shell_plate(Mesh& mesh, const ShellPlateComponent& c) {
  require_count(c.n1, 1, "*COMPONENT_SHELL_PLATE n1");
  require_count(c.n2, 1, "*COMPONENT_SHELL_PLATE n2");
  const Vec3 a = c.p1 - c.p0, b = c.p2 - c.p0;
  if (!(norm(cross(a, b)) > 1e-12 * norm(a) * norm(b))) {
    throw InputError(
        "*COMPONENT_SHELL_PLATE edges p0 -> p1 and p0 -> p2 must have a length and must not be "
        "parallel: the plate has no area");
  }
  add_grid(mesh, c.part_id, c.n1, c.n2, false, [&](int i, int j) {
    return c.p0 + (static_cast<double>(i) / c.n1) * a + (static_cast<double>(j) / c.n2) * b;
  });
}

void generate_shell_tube(Mesh& mesh, const ShellTubeComponent& c) {
  require_count(c.n_axial, 1, "*COMPONENT_SHELL_TUBE n_axial");
  const bool square = c.section == TubeSection::Square;
  require_count(c.n_circ, square ? 4 : 3, "*COMPONENT_SHELL_TUBE n_circ");
  if (square && c.n_circ % 4 != 0) {
    throw InputError(
        "*COMPONENT_SHELL_TUBE n_circ of a SQUARE tube must be a multiple of 4 (a "
        "node at each corner), got " +
        std::to_string(c.n_circ));
  }
  if (!(c.radius > 0.0)) {
    throw InputError("*COMPONENT_SHELL_TUBE r must be > 0 (got " + std::to_string(c.radius) + ")");
  }
  const Vec3 span = c.end2 - c.end1;
  const double length = norm(span);
  if (!(length > 0.0)) {
    throw InputError("*COMPONENT_SHELL_TUBE end centres coincide: the axis needs a length");
  }
  const Vec3 axis = span / length;
  const Vec3 e1 = tube_side_direction(axis, c.side_direction);
  const Vec3 e2 = cross(axis, e1);
  // Grid i runs counter-clockwise around the axis and j along it: d/di x d/dj = tangent x axis
  // points outward.
  add_grid(mesh, c.part_id, c.n_circ, c.n_axial, true, [&](int i, int j) {
    std::array<double, 2> s;
    if (square) {
      s = square_point(i, c.n_circ);
    } else {
      const double angle = 2.0 * std::numbers::pi * i / c.n_circ;
      s = {std::cos(angle), std::sin(angle)};
    }
    return c.end1 + (static_cast<double>(j) / c.n_axial) * span +
           c.radius * (s[0] * e1 + s[1] * e2);
  });
}

}  // namespace abut
