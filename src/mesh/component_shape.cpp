// Maps from structured-grid coordinates to points for the generated components.
//
// Sphere and cylinder use an O-grid: a central cube (square) surrounded by outer blocks, one
// per cube face. This layout is our inference (impetus-keywords.md §3: the manual shows the
// topology only in a figure). In an outer block, a point is the linear blend
//     x = (1 - rho) * (point on the cube face) + rho * (point on the sphere/circle),
// where the cube face point is spaced uniformly and the sphere point is spaced equiangularly
// (direction = normalize(tan(pi/4 s) e1 + tan(pi/4 t) e2 + n), the "equiangular cubed sphere"
// of Ronchi, Iacono & Paolucci, J. Comput. Phys. 124 (1996)). Equal angles keep the outer
// elements of similar size; the blend is smooth, so no element folds.
#include <cmath>
#include <numbers>

#include "abut/mesh/mesh.hpp"

namespace abut {
namespace {

struct Frame {
  Vec3 e1, e2, n;  // e1 x e2 = n (outward face normal), so outer blocks are right-handed
};

// Frames of the six outer sphere blocks: +x, -x, +y, -y, +z, -z.
constexpr Frame kSphereFrames[6] = {
    {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}}, {{0, 0, 1}, {0, 1, 0}, {-1, 0, 0}},
    {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}, {{1, 0, 0}, {0, 0, 1}, {0, -1, 0}},
    {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}},
};

// Grid coordinate g in [0, n] -> cube-face coordinate in [-1, 1].
double centred(double g, int n) { return -1.0 + 2.0 * g / n; }

// Equiangular direction parameter: tan(pi/4 s), exactly +-1 at the block edges so that
// neighbouring blocks produce the same shared points.
double equiangular(double s) {
  if (s == 1.0 || s == -1.0) return s;
  return std::tan(0.25 * std::numbers::pi * s);
}

Vec3 box_point(const BoxShape& b, std::int32_t, const Vec3& g) {
  return {b.lo.x + (b.hi.x - b.lo.x) * (g.x / b.nx), b.lo.y + (b.hi.y - b.lo.y) * (g.y / b.ny),
          b.lo.z + (b.hi.z - b.lo.z) * (g.z / b.nz)};
}

Vec3 sphere_point(const SphereShape& s, std::int32_t block, const Vec3& g) {
  if (block == 6) {  // central cube
    return s.centre +
           s.core_half_size * Vec3{centred(g.x, s.n), centred(g.y, s.n), centred(g.z, s.n)};
  }
  const Frame& f = kSphereFrames[block];
  const double a = centred(g.x, s.n), b = centred(g.y, s.n);
  const double rho = g.z / s.n_radial;
  const Vec3 direction = normalized(equiangular(a) * f.e1 + equiangular(b) * f.e2 + f.n);
  if (s.inner_radius > 0.0) {  // hollow: concentric spherical layers
    return s.centre + (s.inner_radius + rho * (s.outer_radius - s.inner_radius)) * direction;
  }
  const Vec3 on_cube = s.core_half_size * (a * f.e1 + b * f.e2 + f.n);
  return s.centre + (1.0 - rho) * on_cube + rho * s.outer_radius * direction;
}

Vec3 cylinder_point(const CylinderShape& c, std::int32_t block, const Vec3& g) {
  const double zeta = g.z / c.n_axial;
  const double radius = c.radius1 + (c.radius2 - c.radius1) * zeta;
  const double half = c.core_fraction * radius;
  const Vec3 on_axis = c.end1 + (zeta * c.length) * c.axis;
  if (block == 4) {  // square core
    return on_axis + half * (centred(g.x, c.n) * c.e1 + centred(g.y, c.n) * c.e2);
  }
  // Outer block on side n2 of the core; tangent t2 = n2 x axis so that t2 x n2 = axis.
  const Vec3 sides[4] = {c.e1, c.e2, -c.e1, -c.e2};
  const Vec3 n2 = sides[block];
  const Vec3 t2 = cross(n2, c.axis);
  const double s = centred(g.x, c.n);
  const double rho = g.y / c.n_radial;
  const Vec3 direction = normalized(equiangular(s) * t2 + n2);
  return on_axis + (1.0 - rho) * half * (s * t2 + n2) + rho * radius * direction;
}

}  // namespace

Vec3 shape_point(const ComponentShape& shape, std::int32_t block, const Vec3& grid) {
  if (const auto* b = std::get_if<BoxShape>(&shape)) return box_point(*b, block, grid);
  if (const auto* s = std::get_if<SphereShape>(&shape)) return sphere_point(*s, block, grid);
  return cylinder_point(std::get<CylinderShape>(shape), block, grid);
}

}  // namespace abut
