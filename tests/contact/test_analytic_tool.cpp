// The analytic tools' geometry (analytic_tool.hpp): the derivative of the push direction that the
// static tangent takes for a curved tool, against central differences of project().
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "abut/contact/analytic_tool.hpp"

namespace abut {
namespace {

TEST(AnalyticTool, NormalGradientIsTheDerivativeOfThePush) {
  const Vec3 x{0.7, -1.9, 0.4};  // off every axis and centre
  for (const ToolShape shape : {ToolShape::Plane, ToolShape::Cylinder, ToolShape::Sphere})
    for (const ToolSide side : {ToolSide::Outside, ToolSide::Inside}) {
      AnalyticTool tool;
      tool.shape = shape;
      tool.side = side;
      tool.point = {0.1, 0.2, -0.3};
      tool.axis = normalized(Vec3{0.3, 0.1, 1.0});
      tool.radius = 1.5;
      ToolPose pose;
      pose.displacement = {0.05, -0.02, 0.01};
      const std::array<double, 9> g = normal_gradient(tool, pose, x);
      const double step = 1e-6;
      for (int j = 0; j < 3; ++j) {
        Vec3 up = x, down = x;
        up[j] += step, down[j] -= step;
        const Vec3 d =
            (project(tool, pose, up).normal - project(tool, pose, down).normal) / (2.0 * step);
        for (int i = 0; i < 3; ++i)
          EXPECT_NEAR(g[3 * i + j], d[i], 1e-7)
              << static_cast<int>(shape) << " " << static_cast<int>(side) << " " << i << j;
      }
    }
}

// Metafor's matrix segments: a plane strip between two lines and a cylinder's arc between two
// angles; beyond their ends nothing touches (open ends, as a finite cylinder's).
TEST(AnalyticTool, SegmentsEndWhereTheySay) {
  AnalyticTool strip;  // the plane z = 0 for 0 <= x <= 2
  strip.axis = {0.0, 0.0, 1.0};
  strip.start = {1.0, 0.0, 0.0};
  strip.span = 2.0;
  const ToolPose still;
  EXPECT_TRUE(project(strip, still, {0.0, 5.0, 0.1}).found);
  EXPECT_TRUE(project(strip, still, {2.0, -5.0, -0.1}).found);
  EXPECT_FALSE(project(strip, still, {-1e-9, 0.0, 0.1}).found);
  EXPECT_FALSE(project(strip, still, {2.0 + 1e-9, 0.0, 0.1}).found);
  ToolPose moved;
  moved.displacement = {1.0, 0.0, 0.0};  // the strip moves with the tool
  EXPECT_TRUE(project(strip, moved, {2.5, 0.0, 0.1}).found);
  EXPECT_FALSE(project(strip, moved, {0.5, 0.0, 0.1}).found);

  AnalyticTool arc;  // the lower half of a cylinder of radius 1 about z: from -x through -y to +x
  arc.shape = ToolShape::Cylinder;
  arc.side = ToolSide::Inside;
  arc.radius = 1.0;
  arc.start = {-1.0, 0.0, 0.0};
  arc.span = 3.14159265358979323846;
  const ToolProjection below = project(arc, still, {0.0, -0.9, 3.0});
  ASSERT_TRUE(below.found);
  EXPECT_NEAR(below.gap, 0.1, 1e-15);  // inside the pipe, 0.1 from its wall
  EXPECT_TRUE(project(arc, still, {-0.5, -1e-9, 0.0}).found);
  EXPECT_TRUE(project(arc, still, {0.5, -1e-9, 0.0}).found);
  EXPECT_FALSE(project(arc, still, {0.0, 0.9, 0.0}).found);  // the upper half
  EXPECT_FALSE(project(arc, still, {0.5, 1e-9, 0.0}).found);
}

}  // namespace
}  // namespace abut
