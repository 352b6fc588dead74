#pragma once
// An analytic rigid tool: a plane, a cylinder or a sphere given by parameters (Metafor's rigid
// contact matrices of analytic lines and arcs, seed 002, and their 3D counterparts), moved
// rigidly by a translation and, for a cylinder, spun about its own axis. The tool is a solid
// region (a half-space, a solid cylinder, a ball) or, with side Inside, the complement of one
// (a pipe, a spherical cup): a point inside the region is pushed out along the normal of the
// closest point of its surface. Plain values; the contact with it is tool_contact.hpp.
#include <array>
#include <limits>

#include "abut/core/vec3.hpp"

namespace abut {

enum class ToolShape { Plane, Cylinder, Sphere };
// Which side of the tool's surface the body lies on: Outside (a block on a plane, a roller, a
// ball) or Inside (the other half-space, a part inside a pipe, a ball inside a spherical cup).
enum class ToolSide { Outside, Inside };

struct AnalyticTool {
  ToolShape shape = ToolShape::Plane;
  ToolSide side = ToolSide::Outside;
  // Plane: a point of it; cylinder: a point of its axis (where it starts when its length is
  // finite); sphere: its centre. At zero displacement.
  Vec3 point;
  // Plane: its outward normal (towards the body with side Outside); cylinder: its axis. Unit.
  Vec3 axis{0.0, 0.0, 1.0};
  double radius = 0.0;  // cylinder, sphere
  // Cylinder: it spans [0, length] along the axis from `point`; beyond, nothing touches it (its
  // ends are open, without caps). Infinite: the whole axis.
  double length = std::numeric_limits<double>::infinity();
  // Ends across the extrusion (Metafor's matrix segments: a line between two points, an arc
  // between two angles). Plane: it spans [0, span] along `start` (a unit direction in the plane)
  // from `point`; cylinder: the angles [0, span] (radians, right-handed about the axis) from the
  // unit radial direction `start`. Beyond, nothing touches it (open ends). Infinite: no ends.
  Vec3 start;
  double span = std::numeric_limits<double>::infinity();
};

// Where the tool is: its rigid displacement from its definition, and its velocity (translation
// and spin rate about its axis [rad / time], a cylinder's only) at the time the contact looks.
struct ToolPose {
  Vec3 displacement;
  double angle = 0.0;  // turned about the axis so far [rad] (work of the spin)
  Vec3 velocity;
  double spin = 0.0;
};

// A point's closest point on the tool's surface. `gap` > 0 on the body's side (open), < 0
// inside the tool (penetration); `normal` is the unit direction the tool pushes the point.
// `found` is false where the projection is undefined (on a cylinder's axis or a sphere's
// centre) or the point lies beyond a finite cylinder's ends.
struct ToolProjection {
  Vec3 closest, normal;
  double gap = 0.0;
  bool found = false;
};

ToolProjection project(const AnalyticTool& tool, const ToolPose& pose, const Vec3& x);

// The derivative of the push direction with respect to the point, d normal / d x (row-major 3 x
// 3): zero for a plane; (I - n n) / rho for a sphere and (I - n n - a a) / rho for a cylinder,
// rho the distance from the centre or axis, negated inside (the normal turns the other way).
// Zero where the projection is undefined.
std::array<double, 9> normal_gradient(const AnalyticTool& tool, const ToolPose& pose,
                                      const Vec3& x);

// The velocity of the tool's material at x: v + spin axis x (x - axis point).
Vec3 tool_velocity(const AnalyticTool& tool, const ToolPose& pose, const Vec3& x);

// The displacement of the tool's material at x from pose `from` to pose `to` (the spin turns
// x about the axis of `to` by the angle between them, to first order).
Vec3 tool_increment(const AnalyticTool& tool, const ToolPose& from, const ToolPose& to,
                    const Vec3& x);

}  // namespace abut
