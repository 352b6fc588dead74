// Point-in-region tests of the *GEOMETRY_* commands (impetus-keywords.md §7). Boundaries count
// as inside.
#include "abut/mesh/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <type_traits>

#include "abut/core/error.hpp"
#include "abut/mesh/mesh.hpp"
#include "mesh/hex_geometry.hpp"

namespace abut {
namespace {

bool contains(const GeometryBox& g, const Vec3& p) {
  for (int a = 0; a < 3; ++a) {
    const double lo = std::min(g.corner1[a], g.corner2[a]);
    const double hi = std::max(g.corner1[a], g.corner2[a]);
    if (p[a] < lo || p[a] > hi) return false;
  }
  return true;
}

// Solid ball of radius max(R1, R2) when one radius is zero; shell R1 <= r <= R2 when both > 0.
bool contains(const GeometrySphere& g, const Vec3& p) {
  const double r = norm(p - g.centre);
  if (g.radius1 > 0.0 && g.radius2 > 0.0) {
    return r >= std::min(g.radius1, g.radius2) && r <= std::max(g.radius1, g.radius2);
  }
  return r <= std::max(g.radius1, g.radius2);
}

// Frustum shell: the two radii vary linearly from end 1 to end 2; the point's radial distance
// must lie between them. With a sector below 360 degrees, the angle of the point about the axis
// (right-handed about end1 -> end2) measured from `reference` must be at most the sector.
bool contains(const GeometryPipe& g, const Vec3& p) {
  const Vec3 axis = g.end2 - g.end1;
  const double length = norm(axis);
  if (!(length > 0.0)) {
    throw InputError("*GEOMETRY_PIPE end centres coincide: the axis needs a length");
  }
  const Vec3 unit = axis / length;
  const Vec3 d = p - g.end1;
  const double along = dot(d, unit);
  if (along < 0.0 || along > length) return false;
  const double s = along / length;
  const Vec3 radial = d - along * unit;
  const double r = norm(radial);
  const double first = g.radius1 + (g.radius3 - g.radius1) * s;
  const double second = g.radius2 + (g.radius4 - g.radius2) * s;
  if (r < std::min(first, second) || r > std::max(first, second)) return false;
  if (g.sector_angle >= 360.0 || r == 0.0) return true;
  const Vec3 ref = g.reference - dot(g.reference, unit) * unit;
  if (!(norm(ref) > 0.0)) {
    throw InputError("*GEOMETRY_PIPE with a sector needs a reference vector not along the axis");
  }
  const Vec3 e1 = normalized(ref), e2 = cross(unit, e1);
  double angle = std::atan2(dot(radial, e2), dot(radial, e1)) * 180.0 / std::numbers::pi;
  if (angle < 0.0) angle += 360.0;
  return angle <= g.sector_angle;
}

bool contains(const GeometryEllipsoid& g, const Vec3& p) {
  double sum = 0.0;
  for (int a = 0; a < 3; ++a) {
    if (!(g.semi_axes[a] > 0.0)) {
      throw InputError("*GEOMETRY_ELLIPSOID semi-axes must be positive");
    }
    const double t = (p[a] - g.centre[a]) / g.semi_axes[a];
    sum += t * t;
  }
  return sum <= 1.0;
}

// Inside any hex of the part (each hex treated as its trilinear volume). Cost: one bounding-box
// test per hex of the mesh, Newton inversion only for hexes whose box holds the point.
bool contains(const GeometryPart& g, const Vec3& p, const Mesh& mesh) {
  bool part_exists = false;
  for (std::size_t h = 0; h < mesh.hex_count(); ++h) {
    if (mesh.hex_part[h] != g.part_id) continue;
    part_exists = true;
    if (detail::point_in_hex(detail::hex_points(mesh, h), p)) return true;
  }
  if (!part_exists) {
    throw InputError("*GEOMETRY_PART refers to part " + std::to_string(g.part_id) +
                     ", which has no hexahedra");
  }
  return false;
}

}  // namespace

bool geometry_contains(const Geometry& g, const Vec3& p, const Mesh& mesh) {
  return std::visit(
      [&](const auto& region) {
        if constexpr (std::is_same_v<std::decay_t<decltype(region)>, GeometryPart>) {
          return contains(region, p, mesh);
        } else {
          return contains(region, p);
        }
      },
      g);
}

}  // namespace abut
