// Structured hexahedral components: each is a few structured blocks evaluated through the
// component's exact map (shape_point), with the nodes on block interfaces merged.
#include "abut/mesh/generators.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "abut/core/error.hpp"
#include "mesh/node_merger.hpp"

namespace abut {
namespace {

// Half edge of the central cube (square) as a fraction of the radius. With 1/3 the radial
// lines of the outer blocks are at most 1.5 times longer at a face centre (R - a) than at a
// cube corner (R - sqrt(3) a), so the outer layers stay of even thickness; a larger core
// (e.g. R/2) makes the elements over the cube corners three times flatter than elsewhere.
constexpr double kCoreFraction = 1.0 / 3.0;

// Radial layer count of an O-grid outer block: the radial gap divided by the mean tangential
// element edge (average of the edge on the inner and on the outer boundary), rounded, at least
// one. This keeps the outer elements near-cubic on average.
int radial_layers(double gap, double inner_edge, double outer_edge) {
  const double mean_edge = 0.5 * (inner_edge + outer_edge);
  return std::max(1, static_cast<int>(std::lround(gap / mean_edge)));
}

// Radial layers of the outer blocks of a sphere (the radii must be valid).
int sphere_layers(const SphereComponent& c) {
  const double quarter_arc = 0.5 * std::numbers::pi / c.density;  // element arc per unit radius
  if (c.inner_radius > 0.0)
    return radial_layers(c.outer_radius - c.inner_radius, quarter_arc * c.inner_radius,
                         quarter_arc * c.outer_radius);
  const double core_half_size = kCoreFraction * c.outer_radius;
  return radial_layers(c.outer_radius - core_half_size, 2.0 * core_half_size / c.density,
                       quarter_arc * c.outer_radius);
}

// Radial layers of the outer blocks of a cylinder: independent of the radius.
int cylinder_layers(int density) {
  const double mean_radius = 1.0;
  return radial_layers((1.0 - kCoreFraction) * mean_radius,
                       2.0 * kCoreFraction * mean_radius / density,
                       0.5 * std::numbers::pi * mean_radius / density);
}

void require_count(int n, const char* what) {
  if (n < 1) {
    throw InputError(std::string(what) + " must be at least 1 (got " + std::to_string(n) + ")");
  }
}

// Adds one block of n[0] x n[1] x n[2] hexes of shape `shape`, merging its nodes with the nodes
// already in `merger` (the component's other blocks).
void add_block(Mesh& mesh, detail::NodeMerger& merger, std::int32_t shape, std::int32_t block,
               const int n[3], std::int64_t part, std::int64_t& next_node_id,
               std::int64_t& next_hex_id) {
  const ComponentShape& map = mesh.shapes[static_cast<std::size_t>(shape)];
  const int ni = n[0] + 1, nj = n[1] + 1, nk = n[2] + 1;
  std::vector<std::int32_t> grid_node(static_cast<std::size_t>(ni) * nj * nk);
  auto at = [&](int i, int j, int k) -> std::int32_t& {
    return grid_node[(static_cast<std::size_t>(k) * nj + j) * ni + i];
  };
  std::vector<Vec3> point(grid_node.size());
  const auto point_at = [&](int i, int j, int k) -> Vec3& {
    return point[(static_cast<std::size_t>(k) * nj + j) * ni + i];
  };
  for (int k = 0; k < nk; ++k) {
    for (int j = 0; j < nj; ++j) {
      for (int i = 0; i < ni; ++i) {
        const Vec3 g{static_cast<double>(i), static_cast<double>(j), static_cast<double>(k)};
        point_at(i, j, k) = shape_point(map, block, g);
      }
    }
  }
  for (int k = 0; k < nk; ++k) {
    for (int j = 0; j < nj; ++j) {
      for (int i = 0; i < ni; ++i) {
        // The shortest grid edge at the point: the merge tolerance follows the local spacing.
        const Vec3& p = point_at(i, j, k);
        double shortest = std::numeric_limits<double>::infinity();
        const int step[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        for (const auto& d : step) {
          for (const int sign : {-1, 1}) {
            const int a = i + sign * d[0], b = j + sign * d[1], c = k + sign * d[2];
            if (a < 0 || b < 0 || c < 0 || a >= ni || b >= nj || c >= nk) continue;
            const double edge = norm(point_at(a, b, c) - p);
            if (edge > 0.0) shortest = std::min(shortest, edge);
          }
        }
        if (!std::isfinite(shortest)) shortest = 0.0;
        at(i, j, k) = merger.find_or_add(mesh.nodes, p, next_node_id,
                                         detail::merge_tolerance(p, shortest));
      }
    }
  }
  for (int k = 0; k < n[2]; ++k) {
    for (int j = 0; j < n[1]; ++j) {
      for (int i = 0; i < n[0]; ++i) {
        // VTK_HEXAHEDRON: bottom face 0-3 counter-clockwise about block axis 2, then the top.
        const Hex8 hex{
            at(i, j, k),     at(i + 1, j, k),     at(i + 1, j + 1, k),     at(i, j + 1, k),
            at(i, j, k + 1), at(i + 1, j, k + 1), at(i + 1, j + 1, k + 1), at(i, j + 1, k + 1)};
        const HexCell cell{
            block, {static_cast<double>(i), static_cast<double>(j), static_cast<double>(k)}, 1.0};
        mesh.add_hex(next_hex_id++, part, hex, shape, cell);
      }
    }
  }
}

std::int32_t add_shape(Mesh& mesh, ComponentShape shape) {
  mesh.shapes.push_back(std::move(shape));
  return static_cast<std::int32_t>(mesh.shapes.size() - 1);
}

// The merger of a component of this diameter whose points lie within `reach` of the origin;
// each point then merges within a fraction of its own shortest edge (add_block).
detail::NodeMerger component_merger(double reach, double diameter) {
  return detail::NodeMerger(detail::largest_merge_tolerance(reach, diameter));
}

}  // namespace

MeshSize box_size(const BoxComponent& c) {
  if (c.nx < 1 || c.ny < 1 || c.nz < 1) return {};
  const double nx = c.nx, ny = c.ny, nz = c.nz;
  return {nx * ny * nz, (nx + 1) * (ny + 1) * (nz + 1)};
}

MeshSize sphere_size(const SphereComponent& c) {
  if (c.density < 1 || !(c.outer_radius > 0.0) || c.inner_radius < 0.0 ||
      c.inner_radius >= c.outer_radius)
    return {};
  const double n = c.density, layers = sphere_layers(c);
  const double core = c.inner_radius > 0.0 ? 0.0 : n * n * n;
  // Six outer blocks share their edges and faces: about (n+1)^2 (layers+1) nodes each.
  return {6.0 * n * n * layers + core,
          6.0 * (n + 1) * (n + 1) * (layers + 1) + (core > 0.0 ? (n + 1) * (n + 1) * (n + 1) : 0)};
}

MeshSize cylinder_size(const CylinderComponent& c) {
  if (c.n_axial < 1 || c.density < 1) return {};
  const double n = c.density, axial = c.n_axial, layers = cylinder_layers(c.density);
  const double per_section = 4.0 * n * layers + n * n;
  return {axial * per_section, (axial + 1) * (4.0 * (n + 1) * (layers + 1) + (n + 1) * (n + 1))};
}

void generate_box(Mesh& mesh, const BoxComponent& c) {
  require_count(c.nx, "*COMPONENT_BOX N_x");
  require_count(c.ny, "*COMPONENT_BOX N_y");
  require_count(c.nz, "*COMPONENT_BOX N_z");
  BoxShape box;
  box.nx = c.nx;
  box.ny = c.ny;
  box.nz = c.nz;
  for (int a = 0; a < 3; ++a) {
    box.lo[a] = std::min(c.corner1[a], c.corner2[a]);
    box.hi[a] = std::max(c.corner1[a], c.corner2[a]);
    if (!(box.hi[a] > box.lo[a])) {
      throw InputError(std::string("*COMPONENT_BOX corners have zero extent along ") + "xyz"[a] +
                       ": give two opposite corners of a box with volume");
    }
  }
  std::int64_t next_node = mesh.next_node_id(), next_hex = mesh.next_hex_id();
  Vec3 farthest;  // the largest coordinate magnitudes of the box, axis by axis
  for (int a = 0; a < 3; ++a) farthest[a] = std::max(std::fabs(box.lo[a]), std::fabs(box.hi[a]));
  const double reach = norm(farthest);
  detail::NodeMerger merger = component_merger(reach, norm(box.hi - box.lo));
  const std::int32_t shape = add_shape(mesh, box);
  const int n[3] = {c.nx, c.ny, c.nz};
  add_block(mesh, merger, shape, 0, n, c.part_id, next_node, next_hex);
}

void generate_sphere(Mesh& mesh, const SphereComponent& c) {
  require_count(c.density, "*COMPONENT_SPHERE N");
  if (!(c.outer_radius > 0.0) || c.inner_radius < 0.0 || c.inner_radius >= c.outer_radius) {
    throw InputError("*COMPONENT_SPHERE radii must satisfy 0 <= inner < outer (got inner " +
                     std::to_string(c.inner_radius) + ", outer " + std::to_string(c.outer_radius) +
                     ")");
  }
  const int n = c.density;
  SphereShape sphere;
  sphere.centre = c.centre;
  sphere.inner_radius = c.inner_radius;
  sphere.outer_radius = c.outer_radius;
  sphere.n = n;
  if (c.inner_radius == 0.0) sphere.core_half_size = kCoreFraction * c.outer_radius;
  sphere.n_radial = sphere_layers(c);
  std::int64_t next_node = mesh.next_node_id(), next_hex = mesh.next_hex_id();
  detail::NodeMerger merger =
      component_merger(norm(c.centre) + c.outer_radius, 2.0 * c.outer_radius);
  const std::int32_t shape = add_shape(mesh, sphere);
  const int outer[3] = {n, n, sphere.n_radial};
  for (std::int32_t block = 0; block < 6; ++block) {
    add_block(mesh, merger, shape, block, outer, c.part_id, next_node, next_hex);
  }
  if (c.inner_radius == 0.0) {
    const int core[3] = {n, n, n};
    add_block(mesh, merger, shape, 6, core, c.part_id, next_node, next_hex);
  }
}

void generate_cylinder(Mesh& mesh, const CylinderComponent& c) {
  require_count(c.n_axial, "*COMPONENT_CYLINDER N_1");
  require_count(c.density, "*COMPONENT_CYLINDER N_2");
  if (c.symmetry == 1 || c.symmetry == 2) {
    throw InputError("*COMPONENT_CYLINDER symmetry " + std::to_string(c.symmetry) +
                     " (half/quarter cylinder) is not supported yet; use 0 (full cylinder)");
  }
  if (c.symmetry != 0) {
    throw InputError("*COMPONENT_CYLINDER symmetry must be 0 (full), 1 (half) or 2 (quarter)");
  }
  // The manual's default R2 = R1; a radius of zero cannot be meshed, so 0 means "not given".
  const double radius2 = c.radius2 == 0.0 ? c.radius1 : c.radius2;
  if (!(c.radius1 > 0.0) || !(radius2 > 0.0)) {
    throw InputError("*COMPONENT_CYLINDER radii must be positive (got " +
                     std::to_string(c.radius1) + ", " + std::to_string(c.radius2) + ")");
  }
  const Vec3 axis = c.end2 - c.end1;
  const double length = norm(axis);
  if (!(length > 0.0)) {
    throw InputError("*COMPONENT_CYLINDER end centres coincide: the axis needs a length");
  }
  CylinderShape cyl;
  cyl.end1 = c.end1;
  cyl.axis = axis / length;
  // e1: the global axis least aligned with the cylinder axis, made orthogonal to it.
  int least = 0;
  for (int a = 1; a < 3; ++a) {
    if (std::abs(cyl.axis[a]) < std::abs(cyl.axis[least])) least = a;
  }
  Vec3 trial;
  trial[least] = 1.0;
  cyl.e1 = normalized(trial - dot(trial, cyl.axis) * cyl.axis);
  cyl.e2 = cross(cyl.axis, cyl.e1);
  cyl.length = length;
  cyl.radius1 = c.radius1;
  cyl.radius2 = radius2;
  cyl.core_fraction = kCoreFraction;
  cyl.n = c.density;
  cyl.n_axial = c.n_axial;
  cyl.n_radial = cylinder_layers(c.density);
  std::int64_t next_node = mesh.next_node_id(), next_hex = mesh.next_hex_id();
  const double radius = std::max(c.radius1, radius2);
  const double diameter = std::hypot(length, 2.0 * radius);
  detail::NodeMerger merger =
      component_merger(std::max(norm(c.end1), norm(c.end2)) + diameter, diameter);
  const std::int32_t shape = add_shape(mesh, cyl);
  const int outer[3] = {c.density, cyl.n_radial, c.n_axial};
  for (std::int32_t block = 0; block < 4; ++block) {
    add_block(mesh, merger, shape, block, outer, c.part_id, next_node, next_hex);
  }
  const int core[3] = {c.density, c.density, c.n_axial};
  add_block(mesh, merger, shape, 4, core, c.part_id, next_node, next_hex);
}

}  // namespace abut
