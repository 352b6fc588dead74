#pragma once
// The placement of an *INCLUDE'd file: p' = A p + b, composed over nested includes, plus the
// id offsets that keep the included ids apart from the including deck's.
#include <array>
#include <cstdint>
#include <optional>

#include "abut/core/vec3.hpp"

namespace abut::deck {

struct Transform {
  std::array<Vec3, 3> rows{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};  // A by rows
  Vec3 shift;                                                             // b

  Vec3 point(const Vec3& p) const { return linear(p) + shift; }
  Vec3 linear(const Vec3& v) const { return {dot(rows[0], v), dot(rows[1], v), dot(rows[2], v)}; }

  // A is diagonal: axis-aligned boxes stay axis-aligned boxes.
  bool axis_aligned() const;
  // A is diagonal with positive entries: directions (velocities, X/Y/Z) are unchanged.
  bool keeps_directions() const;
  // |s| when A = s Q with Q orthogonal (spheres stay spheres), otherwise nothing.
  std::optional<double> uniform_scale() const;
  double diagonal(int i) const { return rows[i][i]; }
  // det A < 0: the placement mirrors, so hexahedra must be renumbered to stay right-handed.
  bool mirrors() const { return dot(rows[0], cross(rows[1], rows[2])) < 0.0; }

  // The transform that applies `inner` first and then this one.
  Transform after(const Transform& inner) const;
};

// *INCLUDE line 2 to 4: p' = p1 + R (S p - p0) with S = diag(sf_x, sf_y, sf_z) and R the
// rotation whose columns are the new x axis, the new y axis and x × y (negated with mirror).
Transform include_transform(const Vec3& scale, const Vec3& from, const Vec3& to, const Vec3& x_axis,
                            const Vec3& y_axis, bool mirror);

struct IdOffsets {
  std::int64_t node = 0, element = 0, part = 0, material = 0, other = 0;
  IdOffsets operator+(const IdOffsets& o) const {
    return {node + o.node, element + o.element, part + o.part, material + o.material,
            other + o.other};
  }
};

}  // namespace abut::deck
