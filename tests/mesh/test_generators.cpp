#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "abut/core/error.hpp"
#include "abut/mesh/generators.hpp"
#include "mesh_checks.hpp"

namespace abut {
namespace {

using test::duplicate_nodes;
using test::exterior_nodes;
using test::min_hex_volume;
using test::min_scaled_jacobian;
using test::total_volume;
using test::unused_nodes;

constexpr double kPi = std::numbers::pi;

// Seed 000: *COMPONENT_BOX 2,2,2,2,1 from (-0.03,-0.03,0) to (0.03,0.03,0.01).
BoxComponent seed_box() {
  BoxComponent box;
  box.part_id = 2;
  box.nx = 2;
  box.ny = 2;
  box.nz = 1;
  box.corner1 = {-0.03, -0.03, 0.0};
  box.corner2 = {0.03, 0.03, 0.01};
  return box;
}

// Seed 000: *COMPONENT_SPHERE 1,1,3 / 0,0,0.03,0.01.
SphereComponent seed_sphere(int n = 3) {
  SphereComponent s;
  s.part_id = 1;
  s.density = n;
  s.centre = {0.0, 0.0, 0.03};
  s.outer_radius = 0.01;
  return s;
}

TEST(GenerateBox, SeedBoxCountsVolumeAndNodeMerging) {
  Mesh mesh;
  generate_box(mesh, seed_box());
  EXPECT_EQ(mesh.hex_count(), 4u);
  EXPECT_EQ(mesh.nodes.size(), 18u);  // 3 x 3 x 2 grid points, shared between hexes
  EXPECT_NEAR(total_volume(mesh), 0.06 * 0.06 * 0.01, 1e-18);
  EXPECT_DOUBLE_EQ(min_hex_volume(mesh), 0.03 * 0.03 * 0.01);
  EXPECT_NEAR(min_scaled_jacobian(mesh), 1.0, 1e-12);  // right-handed VTK order, rectangular
  for (std::size_t h = 0; h < mesh.hex_count(); ++h) {
    EXPECT_EQ(mesh.hex_part[h], 2);
    EXPECT_EQ(mesh.hex_id[h], static_cast<std::int64_t>(h + 1));
    EXPECT_EQ(mesh.hex_shape[h], 0);
  }
  ASSERT_EQ(mesh.shapes.size(), 1u);
}

TEST(GenerateBox, CornersInAnyOrderGiveTheSameRightHandedBox) {
  BoxComponent box = seed_box();
  box.corner1 = {0.03, -0.03, 0.01};
  box.corner2 = {-0.03, 0.03, 0.0};
  Mesh mesh;
  generate_box(mesh, box);
  EXPECT_NEAR(total_volume(mesh), 0.06 * 0.06 * 0.01, 1e-18);
  EXPECT_GT(min_hex_volume(mesh), 0.0);
}

TEST(GenerateBox, IdsContinueAfterExistingComponents) {
  Mesh mesh;
  generate_box(mesh, seed_box());
  generate_box(mesh, seed_box());
  EXPECT_EQ(mesh.nodes.size(), 36u);  // components do not share nodes
  EXPECT_EQ(mesh.nodes.id.back(), 36);
  EXPECT_EQ(mesh.hex_id.back(), 8);
  EXPECT_EQ(mesh.hex_shape.back(), 1);
}

TEST(GenerateBox, RejectsZeroExtentAndCounts) {
  Mesh mesh;
  BoxComponent flat = seed_box();
  flat.corner2.z = flat.corner1.z;
  EXPECT_THROW(generate_box(mesh, flat), InputError);
  BoxComponent none = seed_box();
  none.ny = 0;
  EXPECT_THROW(generate_box(mesh, none), InputError);
}

// Number of radial layers chosen by the rule in generators.cpp for a solid sphere of density n:
// core half edge a = R/3, gap R - a, mean tangential edge (2a/n + pi R/(2n))/2.
int solid_sphere_layers(int n) {
  const double a = 1.0 / 3.0, mean_edge = 0.5 * (2.0 * a / n + 0.5 * kPi / n);
  return std::max(1, static_cast<int>(std::lround((1.0 - a) / mean_edge)));
}

TEST(GenerateSphere, SeedSphereTopologyAndQuality) {
  Mesh mesh;
  generate_sphere(mesh, seed_sphere());
  const int m = solid_sphere_layers(3);
  EXPECT_EQ(m, 2);
  // Central cube n^3 plus six outer blocks n x n x m.
  EXPECT_EQ(mesh.hex_count(), static_cast<std::size_t>(27 + 6 * 9 * m));
  // Distinct grid points: cube (n+1)^3 plus, per radial layer, the sphere-like surface of a
  // cube with n elements per edge: 6 n^2 + 2 (the Euler count of a cubed sphere).
  EXPECT_EQ(mesh.nodes.size(), static_cast<std::size_t>(64 + m * (6 * 9 + 2)));
  EXPECT_EQ(duplicate_nodes(mesh, 1e-9), 0u);
  EXPECT_EQ(unused_nodes(mesh), 0u);
  EXPECT_GT(min_hex_volume(mesh), 0.0);
  EXPECT_GT(min_scaled_jacobian(mesh), 0.3);
  for (std::size_t n : exterior_nodes(mesh)) {
    EXPECT_NEAR(norm(mesh.nodes.position(n) - Vec3{0, 0, 0.03}), 0.01, 1e-15);
  }
}

// The faceted sphere is inscribed (boundary nodes on the sphere, flat-ish faces inside), so
// its volume is below 4/3 pi R^3 and the deficit falls as h^2: halving the element arc
// (N 3 -> 6) divides it by about 4 (chordal error of a circle, 1 - cos(h/2) ~ h^2/8).
TEST(GenerateSphere, VolumeConvergesQuadratically) {
  const double exact = 4.0 / 3.0 * kPi * 1e-6;
  double deficit[2];
  for (int i = 0; i < 2; ++i) {
    Mesh mesh;
    generate_sphere(mesh, seed_sphere(3 * (i + 1)));
    deficit[i] = (exact - total_volume(mesh)) / exact;
    EXPECT_GT(deficit[i], 0.0);
    EXPECT_GT(min_scaled_jacobian(mesh), 0.3);
  }
  // Estimate for a quad spanning 2b x 2b radians with corners on the sphere: radial gap b^2 R
  // at its centre, b^2 R/2 at edge midpoints, mean (2/3) b^2 R, so relative volume deficit
  // 3 * (2/3) b^2 = 2 b^2; with b = pi/(4N) that is 13.7 % for N = 3, an upper estimate since
  // equiangular faces near the cube corners are smaller.
  EXPECT_LT(deficit[0], 2.0 * std::pow(kPi / 12.0, 2));
  EXPECT_NEAR(deficit[0] / deficit[1], 4.0, 0.4);
}

TEST(GenerateSphere, HollowSphereHasOnlyShellBlocks) {
  SphereComponent s = seed_sphere(4);
  s.inner_radius = 0.006;
  Mesh mesh;
  generate_sphere(mesh, s);
  // Rule: gap / mean arc edge = 0.004 / (pi/8 * 0.008) = 1.27 -> one layer.
  EXPECT_EQ(mesh.hex_count(), 6u * 16u);
  EXPECT_EQ(mesh.nodes.size(), 2u * (6u * 16u + 2u));
  EXPECT_EQ(duplicate_nodes(mesh, 1e-9), 0u);
  EXPECT_GT(min_scaled_jacobian(mesh), 0.3);
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
    const double r = norm(mesh.nodes.position(n) - s.centre);
    EXPECT_TRUE(std::abs(r - 0.006) < 1e-15 || std::abs(r - 0.01) < 1e-15) << r;
  }
  const double exact = 4.0 / 3.0 * kPi * (1e-6 - 0.216e-6);
  EXPECT_LT(total_volume(mesh), exact);
  EXPECT_GT(total_volume(mesh), 0.9 * exact);  // 2 b^2 = 7.7 % for N = 4 (see above)
}

TEST(GenerateSphere, RejectsBadRadiiAndDensity) {
  Mesh mesh;
  SphereComponent s = seed_sphere();
  s.inner_radius = 0.02;
  EXPECT_THROW(generate_sphere(mesh, s), InputError);
  s = seed_sphere(0);
  EXPECT_THROW(generate_sphere(mesh, s), InputError);
  s = seed_sphere();
  s.outer_radius = 0.0;
  EXPECT_THROW(generate_sphere(mesh, s), InputError);
}

CylinderComponent cone(int n_axial, int n) {
  CylinderComponent c;
  c.part_id = 3;
  c.n_axial = n_axial;
  c.density = n;
  c.end1 = {1.0, 2.0, 3.0};
  c.end2 = {1.0 + 2.0, 2.0 + 1.0, 3.0 + 2.0};  // length 3, oblique axis
  c.radius1 = 1.0;
  c.radius2 = 0.5;
  return c;
}

TEST(GenerateCylinder, ConeCountsQualityAndVolume) {
  Mesh mesh;
  generate_cylinder(mesh, cone(4, 3));
  // Rule as for the sphere in 2D: core n x n, 4 blocks n x m, m = round(gap / mean edge) = 2.
  EXPECT_EQ(mesh.hex_count(), 4u * (9u + 4u * 3u * 2u));
  EXPECT_EQ(duplicate_nodes(mesh, 1e-9), 0u);
  EXPECT_EQ(unused_nodes(mesh), 0u);
  EXPECT_GT(min_hex_volume(mesh), 0.0);
  EXPECT_GT(min_scaled_jacobian(mesh), 0.3);
  // Frustum volume pi L (r1^2 + r1 r2 + r2^2) / 3. The inscribed polygon of 12 sides loses
  // 1 - sin(2 pi/12) 12/(2 pi) = 4.5 % of a circle's area (per cross-section).
  const double exact = kPi * 3.0 * (1.0 + 0.5 + 0.25) / 3.0;
  const double polygon = 12.0 / (2.0 * kPi) * std::sin(2.0 * kPi / 12.0);
  // Equiangular boundary nodes: the mesh cross-section is exactly that regular 12-gon, and
  // the side faces are ruled between similar polygons, so the volume is the polygonal frustum.
  EXPECT_NEAR(total_volume(mesh), exact * polygon, 1e-12 * exact);
}

TEST(GenerateCylinder, SymmetryIsNotSupportedYet) {
  Mesh mesh;
  CylinderComponent c = cone(1, 2);
  c.symmetry = 1;
  EXPECT_THROW(generate_cylinder(mesh, c), InputError);
  c = cone(1, 2);
  c.end2 = c.end1;
  EXPECT_THROW(generate_cylinder(mesh, c), InputError);
}

// Issue 13: the merge tolerance follows the local node spacing and the coordinates' rounding,
// not the size of the component or its distance from the origin.
TEST(GenerateSphere, FarFromTheOriginKeepsItsTopology) {
  SphereComponent far = seed_sphere();
  far.centre = {0.0, 0.0, 1e5};  // a 1 cm sphere 100 km up
  Mesh near_mesh, far_mesh;
  generate_sphere(near_mesh, seed_sphere());
  generate_sphere(far_mesh, far);
  EXPECT_EQ(far_mesh.nodes.size(), near_mesh.nodes.size());
  EXPECT_EQ(far_mesh.hex_count(), near_mesh.hex_count());
  EXPECT_EQ(unused_nodes(far_mesh), 0u);
  EXPECT_GT(min_hex_volume(far_mesh), 0.0);
}

TEST(GenerateBox, SlenderBoxKeepsEveryNode) {
  BoxComponent bar;
  bar.nx = 10;
  bar.ny = 2;
  bar.nz = 2;
  bar.corner1 = {0.0, 0.0, 0.0};
  bar.corner2 = {1e7, 0.01, 0.01};
  Mesh mesh;
  generate_box(mesh, bar);
  EXPECT_EQ(mesh.hex_count(), 40u);
  EXPECT_EQ(mesh.nodes.size(), 11u * 3u * 3u);
  EXPECT_GT(min_hex_volume(mesh), 0.0);
}

// Issue 28: a 1e12 m bar 0.1 m thick, and a metre cube of 20^3 elements 1e12 m from the origin.
// Their nodes lie 0.1 and 0.05 m apart, far above the coordinates' precision there (2.2e-16 *
// 1e12 = 2.2e-4 m): none may merge, whatever the rounding floor of the merge tolerance (1e-13 *
// 1e12 = 0.1 m). Reference: the grid's node count and the box volume.
TEST(GenerateBox, NodesFarFromTheOriginStayDistinctAtTheCoordinatesPrecision) {
  BoxComponent bar;
  bar.nx = 10;
  bar.ny = 1;
  bar.nz = 1;
  bar.corner1 = {0.0, 0.0, 0.0};
  bar.corner2 = {1e12, 0.1, 0.1};
  Mesh bar_mesh;
  generate_box(bar_mesh, bar);
  EXPECT_EQ(bar_mesh.nodes.size(), 11u * 2u * 2u);
  EXPECT_NEAR(total_volume(bar_mesh), 1e10, 1e-9 * 1e10);
  BoxComponent cube;
  cube.nx = cube.ny = cube.nz = 20;
  cube.corner1 = {1e12, 1e12, 1e12};
  cube.corner2 = {1e12 + 1.0, 1e12 + 1.0, 1e12 + 1.0};
  Mesh cube_mesh;
  generate_box(cube_mesh, cube);
  EXPECT_EQ(cube_mesh.nodes.size(), 21u * 21u * 21u);
  EXPECT_EQ(duplicate_nodes(cube_mesh, 0.01), 0u);
  EXPECT_GT(min_hex_volume(cube_mesh), 0.0);
  EXPECT_NEAR(total_volume(cube_mesh), 1.0, 1e-3);  // the corners' rounding at 1e12: 1.2e-4 m
}

TEST(GenerateCylinder, SlenderAndFarCylinderKeepsItsTopology) {
  CylinderComponent c;
  c.n_axial = 4;
  c.density = 2;
  c.end1 = {0.0, 0.0, 0.0};
  c.end2 = {0.0, 0.0, 1e6};
  c.radius1 = 0.01;
  Mesh reference, slender;
  CylinderComponent compact = c;
  compact.end2 = {0.0, 0.0, 0.1};
  generate_cylinder(reference, compact);
  generate_cylinder(slender, c);
  EXPECT_EQ(slender.nodes.size(), reference.nodes.size());
  CylinderComponent far = compact;
  far.end1 = {1e5, 1e5, 1e5};
  far.end2 = {1e5, 1e5, 1e5 + 0.1};
  Mesh far_mesh;
  generate_cylinder(far_mesh, far);
  EXPECT_EQ(far_mesh.nodes.size(), reference.nodes.size());
  EXPECT_GT(min_hex_volume(far_mesh), 0.0);
}

TEST(GeneratorSizes, CountWithoutBuilding) {
  Mesh mesh;
  generate_sphere(mesh, seed_sphere());
  const MeshSize sphere = sphere_size(seed_sphere());
  EXPECT_DOUBLE_EQ(sphere.elements, static_cast<double>(mesh.hex_count()));
  EXPECT_GE(sphere.nodes, static_cast<double>(mesh.nodes.size()));
  const MeshSize box = box_size(seed_box());
  EXPECT_DOUBLE_EQ(box.elements, 4.0);
  EXPECT_DOUBLE_EQ(box.nodes, 18.0);
  // A density the int range allows, a count no integer of the mesh holds.
  SphereComponent huge = seed_sphere(100000);
  EXPECT_GT(sphere_size(huge).elements, 1e15);
}

}  // namespace
}  // namespace abut
