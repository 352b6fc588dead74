#include <gtest/gtest.h>

#include <cmath>

#include "abut/core/error.hpp"
#include "abut/mesh/generators.hpp"
#include "abut/mesh/geometry.hpp"
#include "abut/mesh/mesh.hpp"

namespace abut {
namespace {

const Mesh kNoMesh;

TEST(GeometryContains, BoxWithCornersInAnyOrder) {
  const Geometry box = GeometryBox{{1, 2, 3}, {-1, 0, 1}};
  EXPECT_TRUE(geometry_contains(box, {0, 1, 2}, kNoMesh));
  EXPECT_TRUE(geometry_contains(box, {1, 2, 3}, kNoMesh));  // corner: boundary is inside
  EXPECT_FALSE(geometry_contains(box, {0, 1, 3.001}, kNoMesh));
  EXPECT_FALSE(geometry_contains(box, {-1.5, 1, 2}, kNoMesh));
}

TEST(GeometryContains, SolidSphereAndShell) {
  const Geometry ball = GeometrySphere{{1, 1, 1}, 2.0, 0.0};
  EXPECT_TRUE(geometry_contains(ball, {1, 1, 1}, kNoMesh));
  EXPECT_TRUE(geometry_contains(ball, {2.9, 1, 1}, kNoMesh));
  EXPECT_FALSE(geometry_contains(ball, {2.5, 2.5, 1}, kNoMesh));  // r = 2.12
  const Geometry shell = GeometrySphere{{1, 1, 1}, 1.0, 2.0};
  EXPECT_FALSE(geometry_contains(shell, {1.5, 1, 1}, kNoMesh));
  EXPECT_TRUE(geometry_contains(shell, {1, 2.5, 1}, kNoMesh));
  EXPECT_FALSE(geometry_contains(shell, {1, 1, 3.5}, kNoMesh));
}

GeometryPipe pipe_along_z() {
  GeometryPipe p;
  p.end1 = {0, 0, 0};
  p.end2 = {0, 0, 2};
  p.radius1 = 0.0;
  p.radius2 = 1.0;
  p.radius3 = 0.0;
  p.radius4 = 1.0;
  p.reference = {1, 0, 0};
  return p;
}

TEST(GeometryContains, PipeFrustumShellAndSector) {
  GeometryPipe p = pipe_along_z();
  EXPECT_TRUE(geometry_contains(p, {0.5, 0, 1}, kNoMesh));
  EXPECT_TRUE(geometry_contains(p, {0, 0, 0}, kNoMesh));
  EXPECT_FALSE(geometry_contains(p, {0.5, 0, 2.1}, kNoMesh));  // beyond end 2
  EXPECT_FALSE(geometry_contains(p, {0.8, 0.8, 1}, kNoMesh));  // r = 1.13
  // Shell from radius 0.5 to 1 at end 1, narrowing to 0.25 .. 0.5 at end 2.
  p.radius1 = 0.5;
  p.radius3 = 0.25;
  p.radius4 = 0.5;
  EXPECT_FALSE(geometry_contains(p, {0.3, 0, 0}, kNoMesh));
  EXPECT_TRUE(geometry_contains(p, {0.3, 0, 2}, kNoMesh));
  EXPECT_TRUE(geometry_contains(p, {0, 0.7, 1}, kNoMesh));  // radii 0.375 .. 0.75 at middle
  EXPECT_FALSE(geometry_contains(p, {0, 0.8, 1}, kNoMesh));
  // Quarter sector from +x, counter-clockwise about the axis end1 -> end2 (+z).
  p = pipe_along_z();
  p.sector_angle = 90.0;
  EXPECT_TRUE(geometry_contains(p, {0.5, 0.5, 1}, kNoMesh));    // 45 degrees
  EXPECT_TRUE(geometry_contains(p, {0.0, 0.5, 1}, kNoMesh));    // 90 degrees: boundary
  EXPECT_FALSE(geometry_contains(p, {-0.5, 0.5, 1}, kNoMesh));  // 135 degrees
  EXPECT_FALSE(geometry_contains(p, {0.5, -0.1, 1}, kNoMesh));  // 349 degrees
  p.reference = {0, 0, 5};
  EXPECT_THROW(geometry_contains(p, {0.5, 0.5, 1}, kNoMesh), InputError);
}

TEST(GeometryContains, Ellipsoid) {
  const Geometry e = GeometryEllipsoid{{0, 0, 0}, {2, 1, 0.5}};
  EXPECT_TRUE(geometry_contains(e, {1.9, 0, 0}, kNoMesh));
  EXPECT_FALSE(geometry_contains(e, {0, 1.1, 0}, kNoMesh));
  EXPECT_FALSE(geometry_contains(e, {1.5, 0.5, 0.25}, kNoMesh));  // 0.5625+0.25+0.25 > 1
  EXPECT_TRUE(geometry_contains(e, {1.0, 0.5, 0.25}, kNoMesh));   // 0.25+0.25+0.25
}

TEST(GeometryContains, PartIsTheVolumeOfItsHexes) {
  Mesh mesh;
  SphereComponent s;
  s.part_id = 5;
  s.density = 3;
  s.outer_radius = 1.0;
  generate_sphere(mesh, s);
  BoxComponent b;
  b.part_id = 6;
  b.corner1 = {3, 0, 0};
  b.corner2 = {4, 1, 1};
  generate_box(mesh, b);
  const Geometry part = GeometryPart{5};
  EXPECT_TRUE(geometry_contains(part, {0, 0, 0}, mesh));
  EXPECT_TRUE(geometry_contains(part, {0.3, -0.4, 0.5}, mesh));
  const Vec3 corner_node = normalized(Vec3{1, 1, 1});  // a cube-sphere block corner
  EXPECT_TRUE(geometry_contains(part, corner_node, mesh));
  EXPECT_FALSE(geometry_contains(part, 1.01 * corner_node, mesh));
  // Faceted: the +z face on the axis is flat with corners at s = t = +-1/3, i.e. directions
  // (tan 15 deg, tan 15 deg, 1), so it lies at z = 1/sqrt(1 + 2 tan^2 15 deg) = 0.9351.
  EXPECT_TRUE(geometry_contains(part, {0, 0, 0.934}, mesh));
  EXPECT_FALSE(geometry_contains(part, {0, 0, 0.936}, mesh));
  EXPECT_FALSE(geometry_contains(part, {3.5, 0.5, 0.5}, mesh));  // inside part 6 only
  EXPECT_TRUE(geometry_contains(GeometryPart{6}, {3.5, 0.5, 0.5}, mesh));
  EXPECT_THROW(geometry_contains(GeometryPart{9}, {0, 0, 0}, mesh), InputError);
}

}  // namespace
}  // namespace abut
