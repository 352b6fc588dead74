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

}  // namespace
}  // namespace abut
