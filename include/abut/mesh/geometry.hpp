#pragma once
// Regions of space from *GEOMETRY_* (used by gid fields: contact, p-order change, smoothing).
#include <cstdint>
#include <variant>

#include "abut/core/vec3.hpp"

namespace abut {

struct Mesh;

struct GeometryBox {        // *GEOMETRY_BOX: two opposite corners
  Vec3 corner1, corner2;
};
struct GeometrySphere {     // *GEOMETRY_SPHERE: centre, R1, R2 (shell R1 <= r <= R2 when both > 0)
  Vec3 centre;
  double radius1 = 0.0, radius2 = 0.0;
};
struct GeometryPipe {       // *GEOMETRY_PIPE: end centres, radii at both ends, sector
  Vec3 end1, end2;
  double radius1 = 0.0, radius2 = 0.0;  // first and second radius at end 1
  double radius3 = 0.0, radius4 = 0.0;  // first and second radius at end 2 (the deck reader
                                        // applies the defaults R3 = R1, R4 = R2)
  Vec3 reference;                       // radial reference direction of the sector
  double sector_angle = 360.0;          // degrees
};
struct GeometryEllipsoid {  // *GEOMETRY_ELLIPSOID: centre and semi-axes
  Vec3 centre, semi_axes;
};
struct GeometryPart {       // *GEOMETRY_PART: the region the part occupies at time 0
  std::int64_t part_id = 0;
};

using Geometry = std::variant<GeometryBox, GeometrySphere, GeometryPipe, GeometryEllipsoid, GeometryPart>;

// Is point p inside (or on the boundary of) the geometry? `mesh` is needed for GeometryPart:
// a point is inside a part when it is inside (the trilinear volume of) one of its hexes.
// Throws InputError for a degenerate geometry or a part without hexes.
bool geometry_contains(const Geometry& g, const Vec3& p, const Mesh& mesh);

}  // namespace abut
