// Closest point, normal and gap of a point to an analytic tool (analytic_tool.hpp): the plane's
// signed distance, the radial distance to a cylinder's axis or a sphere's centre less the radius.
#include "abut/contact/analytic_tool.hpp"

#include <cmath>

namespace abut {

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

ToolProjection project(const AnalyticTool& tool, const ToolPose& pose, const Vec3& x) {
  ToolProjection r;
  const Vec3 origin = tool.point + pose.displacement;
  const double sign = tool.side == ToolSide::Outside ? 1.0 : -1.0;
  Vec3 radial = x - origin;  // from the axis (cylinder) or centre (sphere) to the point
  if (tool.shape == ToolShape::Plane) {
    if (std::isfinite(tool.span)) {  // a strip between two lines
      const double along = dot(radial, tool.start);
      if (along < 0.0 || along > tool.span) return r;
    }
    const double distance = dot(radial, tool.axis);
    r.gap = sign * distance;
    r.normal = tool.axis * sign;
    r.closest = x - tool.axis * distance;
    r.found = true;
    return r;
  }
  if (tool.shape == ToolShape::Cylinder) {
    const double along = dot(radial, tool.axis);
    if (along < 0.0 || along > tool.length) return r;  // beyond an open end
    radial -= tool.axis * along;
    if (std::isfinite(tool.span)) {  // an arc: its angle from `start`, in [0, 2 pi)
      double angle = std::atan2(dot(tool.axis, cross(tool.start, radial)), dot(tool.start, radial));
      if (angle < 0.0) angle += 2.0 * kPi;
      if (angle > tool.span) return r;
    }
  }
  const double distance = norm(radial);
  if (!(distance > 0.0)) return r;  // on the axis or at the centre: no direction to push
  const Vec3 out = radial / distance;
  r.gap = sign * (distance - tool.radius);
  r.normal = out * sign;
  r.closest = x - out * (distance - tool.radius);
  r.found = true;
  return r;
}

std::array<double, 9> normal_gradient(const AnalyticTool& tool, const ToolPose& pose,
                                      const Vec3& x) {
  std::array<double, 9> g{};
  if (tool.shape == ToolShape::Plane) return g;
  Vec3 radial = x - (tool.point + pose.displacement);
  if (tool.shape == ToolShape::Cylinder) radial -= tool.axis * dot(radial, tool.axis);
  const double distance = norm(radial);
  if (!(distance > 0.0)) return g;
  const Vec3 n = radial / distance;
  const double scale = (tool.side == ToolSide::Outside ? 1.0 : -1.0) / distance;
  const bool cylinder = tool.shape == ToolShape::Cylinder;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      g[3 * i + j] =
          scale * ((i == j) - n[i] * n[j] - (cylinder ? tool.axis[i] * tool.axis[j] : 0.0));
  return g;
}

Vec3 tool_velocity(const AnalyticTool& tool, const ToolPose& pose, const Vec3& x) {
  if (pose.spin == 0.0) return pose.velocity;
  return pose.velocity + cross(tool.axis * pose.spin, x - (tool.point + pose.displacement));
}

Vec3 tool_increment(const AnalyticTool& tool, const ToolPose& from, const ToolPose& to,
                    const Vec3& x) {
  const Vec3 translation = to.displacement - from.displacement;
  const double turn = to.angle - from.angle;
  if (turn == 0.0) return translation;
  return translation + cross(tool.axis * turn, x - (tool.point + to.displacement));
}

}  // namespace abut
