#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

#include "abut/core/error.hpp"
#include "abut/mesh/generators.hpp"
#include "abut/mesh/refine.hpp"
#include "abut/mesh/skin.hpp"
#include "mesh_checks.hpp"

namespace abut {
namespace {

using test::duplicate_nodes;
using test::exterior_nodes;
using test::min_hex_volume;
using test::min_scaled_jacobian;
using test::total_volume;
using test::unused_nodes;
using ::testing::HasSubstr;

constexpr double kPi = std::numbers::pi;

// Seed 000 box: *COMPONENT_BOX 2,2,2,2,1, (-0.03,-0.03,0) to (0.03,0.03,0.01).
Mesh seed_box(std::int64_t part = 2) {
  BoxComponent box;
  box.part_id = part;
  box.nx = 2;
  box.ny = 2;
  box.nz = 1;
  box.corner1 = {-0.03, -0.03, 0.0};
  box.corner2 = {0.03, 0.03, 0.01};
  Mesh mesh;
  generate_box(mesh, box);
  return mesh;
}

// Seed 000 sphere: *COMPONENT_SPHERE 1,1,N / 0,0,0.03,0.01.
Mesh seed_sphere(int n) {
  SphereComponent s;
  s.part_id = 1;
  s.density = n;
  s.centre = {0.0, 0.0, 0.03};
  s.outer_radius = 0.01;
  Mesh mesh;
  generate_sphere(mesh, s);
  return mesh;
}

OrderChange change(std::int64_t part, int order) {
  OrderChange c;
  c.parts = {part};
  c.order = order;
  return c;
}

void forget_exact_shapes(Mesh& mesh) {  // as if the hexes came from *NODE / *ELEMENT_SOLID
  for (auto& s : mesh.hex_shape) s = -1;
}

TEST(Refine, SeedBoxOrder3SplitsConformingly) {
  Mesh mesh = seed_box();
  const auto notes = refine_and_smooth(mesh, {change(2, 3)}, {});
  EXPECT_EQ(mesh.hex_count(), 4u * 27u);
  EXPECT_EQ(mesh.nodes.size(), 7u * 7u * 4u);  // 196: the 6 x 6 x 3 grid, nodes shared
  EXPECT_EQ(duplicate_nodes(mesh, 1e-9), 0u);
  EXPECT_NEAR(total_volume(mesh), 0.06 * 0.06 * 0.01, 1e-18);
  EXPECT_NEAR(min_scaled_jacobian(mesh), 1.0, 1e-12);
  // Ids continue after the largest existing ones; every child keeps the part.
  EXPECT_EQ(mesh.hex_id.front(), 5);
  EXPECT_EQ(mesh.hex_id.back(), 4 + 108);
  EXPECT_EQ(mesh.nodes.id.back(), 196);
  for (std::int64_t p : mesh.hex_part) EXPECT_EQ(p, 2);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_THAT(notes[0], HasSubstr("4 hexes split 3x3x3 into 108"));
}

TEST(Refine, HighestOrderWinsAndOrder2Splits2x2x2) {
  Mesh mesh = seed_box();
  refine_and_smooth(mesh, {change(2, 2)}, {});
  EXPECT_EQ(mesh.hex_count(), 32u);
  EXPECT_EQ(mesh.nodes.size(), 5u * 5u * 3u);
  Mesh both = seed_box();
  refine_and_smooth(both, {change(2, 2), change(2, 3)}, {});
  EXPECT_EQ(both.hex_count(), 108u);
}

TEST(Refine, HexesWithoutShapeRefineTrilinearly) {
  Mesh mesh = seed_box();
  forget_exact_shapes(mesh);
  // Skew the box: a trilinear split reproduces the parent map, so the volume is unchanged.
  mesh.nodes.x[0] -= 0.004;
  mesh.nodes.z[17] += 0.003;
  const double before = total_volume(mesh);
  refine_and_smooth(mesh, {change(2, 3)}, {});
  EXPECT_EQ(mesh.nodes.size(), 196u);
  EXPECT_NEAR(total_volume(mesh), before, 1e-15 * before);
  EXPECT_GT(min_hex_volume(mesh), 0.0);
}

// Refined order 3 of density 3 has exactly the boundary nodes of density 9 (equiangular
// spacing at s = -1 + 2i/9 in both cases), and a hex mesh's volume is the volume inside its
// bilinear boundary faces, so both volumes agree. The deficit drops ninefold (h^2 law).
TEST(Refine, SphereOrder3PutsNewNodesOnTheSphere) {
  Mesh mesh = seed_sphere(3);
  const double exact = 4.0 / 3.0 * kPi * 1e-6;
  const double coarse_deficit = exact - total_volume(mesh);
  refine_and_smooth(mesh, {change(1, 3)}, {});
  EXPECT_EQ(mesh.hex_count(), 135u * 27u);
  EXPECT_EQ(duplicate_nodes(mesh, 1e-9), 0u);
  EXPECT_EQ(unused_nodes(mesh), 0u);
  EXPECT_GT(min_scaled_jacobian(mesh), 0.3);
  for (std::size_t n : exterior_nodes(mesh)) {
    EXPECT_NEAR(norm(mesh.nodes.position(n) - Vec3{0, 0, 0.03}), 0.01, 1e-12);
  }
  const double fine_volume = total_volume(seed_sphere(9));
  EXPECT_NEAR(total_volume(mesh), fine_volume, 1e-12 * exact);
  EXPECT_NEAR(coarse_deficit / (exact - total_volume(mesh)), 9.0, 0.9);
}

// The Lagrange form takes the same lattice nodes as the split and makes one hex27 / hex64 of each
// hex, with its id and part. Its volume interpolates the sphere with polynomials of order p
// through the nodes (an error of O(h^(p+1)) against the O(h^2) of the split's flat facets on the
// same nodes): closer to 4/3 pi r^3 than the split by a factor above 2 (order 2) and 10 (order 3).
TEST(Refine, LagrangeFormMakesOneHexahedronOfOrderPOnTheSameNodes) {
  const double exact = 4.0 / 3.0 * kPi * 1e-6;
  for (const int order : {2, 3}) {
    SCOPED_TRACE(order);
    Mesh split = seed_sphere(3), lagrange = seed_sphere(3);
    refine_and_smooth(split, {change(1, order)}, {});
    const auto notes =
        refine_and_smooth(lagrange, {change(1, order)}, {}, {}, POrderForm::lagrange);
    EXPECT_EQ(lagrange.hex_count(), 0u);
    ASSERT_EQ(lagrange.cells.size(), 1u);
    const CellBlock& block = lagrange.cells[0];
    EXPECT_EQ(block.type, order == 2 ? CellType::hex27 : CellType::hex64);
    ASSERT_EQ(block.size(), 135u);
    EXPECT_EQ(block.id.front(), 1);
    EXPECT_EQ(block.id.back(), 135);
    for (std::int64_t p : block.part) EXPECT_EQ(p, 1);
    EXPECT_EQ(lagrange.nodes.size(), split.nodes.size());
    for (std::size_t n = 0; n < split.nodes.size(); ++n)
      EXPECT_EQ(norm(lagrange.nodes.position(n) - split.nodes.position(n)), 0.0);
    double volume = 0.0;
    for (std::size_t e = 0; e < lagrange.solid_count(); ++e) volume += solid_volume(lagrange, e);
    const double split_error = std::abs(exact - total_volume(split));
    std::cout << "order " << order << ": volume error, split " << split_error / exact
              << ", Lagrange " << (exact - volume) / exact << "\n";
    EXPECT_GT(split_error / std::abs(exact - volume), order == 2 ? 2.0 : 10.0);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_THAT(notes[0], HasSubstr("135 hexes made " +
                                    std::to_string((order + 1) * (order + 1) * (order + 1)) +
                                    "-node Lagrange hexahedra"));
  }
}

// Two generated boxes that touch along a face without sharing nodes (a punch standing on a base,
// examples/static_block_press.k) stay two bodies: their new nodes on the touching faces coincide
// in position but not in the corners they lie between. (Merging them by position made the node
// count disagree with a conforming mesh and refused the deck.)
TEST(Refine, TouchingBodiesStayApart) {
  Mesh mesh = seed_box(1);  // 2 x 2 x 1 hexes, z in [0, 0.01]
  BoxComponent top;
  top.part_id = 2;
  top.nx = 2, top.ny = 2, top.nz = 1;
  top.corner1 = {-0.03, -0.03, 0.01};
  top.corner2 = {0.03, 0.03, 0.02};
  generate_box(mesh, top);
  ASSERT_EQ(mesh.nodes.size(), 2u * 18u);
  for (const POrderForm form : {POrderForm::split, POrderForm::lagrange}) {
    Mesh refined = mesh;
    OrderChange both;
    both.parts = {1, 2};
    both.order = 3;
    refine_and_smooth(refined, {both}, {}, {}, form);
    EXPECT_EQ(refined.nodes.size(), 2u * 7u * 7u * 4u);  // two 6 x 6 x 3 lattices, none shared
  }
}

TEST(Refine, RegionSelectsHexesByCentroid) {
  Mesh a = seed_box(1), b = seed_box(2);
  for (double& x : b.nodes.x) x += 1.0;  // two separate boxes, no shared nodes
  Mesh mesh = a;
  const auto offset = static_cast<std::int32_t>(mesh.nodes.size());
  for (std::size_t n = 0; n < b.nodes.size(); ++n) {
    mesh.nodes.add(b.nodes.id[n] + 18, b.nodes.position(n));
  }
  for (std::size_t h = 0; h < b.hex_count(); ++h) {
    Hex8 hex = b.hexes[h];
    for (auto& n : hex) n += offset;
    mesh.add_hex(b.hex_id[h] + 4, 2, hex);
  }
  OrderChange only_second = change(1, 3);
  only_second.parts = {1, 2};
  only_second.region = GeometryBox{{0.5, -1, -1}, {2, 1, 1}};  // contains box 2 only
  const auto notes = refine_and_smooth(mesh, {only_second}, {});
  EXPECT_EQ(mesh.hex_count(), 4u + 108u);
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_THAT(notes[0], HasSubstr("no hex centroid inside"));
  EXPECT_THAT(notes[1], HasSubstr("4 hexes split 3x3x3"));
}

// Two hexes of different parts sharing a face: refining one alone would leave hanging nodes.
Mesh two_glued_hexes() {
  Mesh mesh;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i)
        mesh.nodes.add(mesh.next_node_id(),
                       {static_cast<double>(i), static_cast<double>(j), static_cast<double>(k)});
  auto n = [](int i, int j, int k) { return static_cast<std::int32_t>((k * 2 + j) * 3 + i); };
  for (int i = 0; i < 2; ++i) {
    mesh.add_hex(i + 1, i + 1,
                 {n(i, 0, 0), n(i + 1, 0, 0), n(i + 1, 1, 0), n(i, 1, 0), n(i, 0, 1),
                  n(i + 1, 0, 1), n(i + 1, 1, 1), n(i, 1, 1)});
  }
  return mesh;
}

TEST(Refine, SharedFaceWithUnrefinedPartIsAnError) {
  Mesh mesh = two_glued_hexes();
  try {
    refine_and_smooth(mesh, {change(1, 3)}, {});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_THAT(e.message(), HasSubstr("parts 1 and 2 share nodes; refine both or neither"));
  }
  Mesh different = two_glued_hexes();
  EXPECT_THROW(refine_and_smooth(different, {change(1, 3), change(2, 2)}, {}), InputError);
  Mesh both = two_glued_hexes();
  OrderChange all = change(1, 3);
  all.parts = {1, 2};
  refine_and_smooth(both, {all}, {});
  EXPECT_EQ(both.nodes.size(), 7u * 4u * 4u);
  EXPECT_NEAR(total_volume(both), 2.0, 1e-13);
}

TEST(Refine, RegionCuttingAPartIsAnError) {
  Mesh mesh = seed_box();
  OrderChange half = change(2, 2);
  half.region = GeometryBox{{0.0, -1, -1}, {1, 1, 1}};  // centroids with x > 0
  EXPECT_THROW(refine_and_smooth(mesh, {half}, {}), InputError);
}

TEST(Refine, RejectsBadOrderAndUnknownPart) {
  Mesh mesh = seed_box();
  EXPECT_THROW(refine_and_smooth(mesh, {change(2, 4)}, {}), InputError);
  EXPECT_THROW(refine_and_smooth(mesh, {change(7, 2)}, {}), InputError);
}

SurfaceSmoothing smooth(std::int64_t part, double angle) {
  SurfaceSmoothing s;
  s.parts = {part};
  s.max_angle = angle;
  return s;
}

TEST(Smooth, WithoutRefinementMovesNothingAndSaysSo) {
  Mesh mesh = seed_sphere(3);
  forget_exact_shapes(mesh);
  const std::vector<double> x = mesh.nodes.x;
  const auto notes = refine_and_smooth(mesh, {}, {smooth(1, 45.0)});
  EXPECT_EQ(mesh.nodes.x, x);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_THAT(notes[0], HasSubstr("moves no nodes"));
}

TEST(Smooth, ExactShapeWinsAndSaysSo) {
  Mesh mesh = seed_sphere(3);
  const auto notes = refine_and_smooth(mesh, {change(1, 3)}, {smooth(1, 45.0)});
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_THAT(notes[0], HasSubstr("exact component shape"));
  for (std::size_t n : exterior_nodes(mesh)) {
    EXPECT_NEAR(norm(mesh.nodes.position(n) - Vec3{0, 0, 0.03}), 0.01, 1e-12);
  }
}

TEST(Smooth, InternalInterfacesAreNotSupportedYet) {
  Mesh mesh = seed_box();
  SurfaceSmoothing s = smooth(2, 45.0);
  s.internal = true;
  EXPECT_THROW(refine_and_smooth(mesh, {change(2, 2)}, {s}), InputError);
}

// Box edges are 90 degree features (>= 45): they stay straight, flat faces stay flat, so the
// smoothed refinement keeps the exact box.
TEST(Smooth, FeatureEdgesOfABoxStayStraight) {
  Mesh mesh = seed_box();
  forget_exact_shapes(mesh);
  refine_and_smooth(mesh, {change(2, 3)}, {smooth(2, 45.0)});
  EXPECT_EQ(mesh.nodes.size(), 196u);
  EXPECT_NEAR(total_volume(mesh), 0.06 * 0.06 * 0.01, 1e-18);
  EXPECT_NEAR(min_scaled_jacobian(mesh), 1.0, 1e-12);
}

// A faceted sphere (no exact shape) refined to order 3: trilinear placement leaves the new
// surface nodes on the flat facets; smoothing at 45 degrees (seed 000: *SMOOTH_MESH P,1,45.0)
// places them on Nagata patches through the original surface nodes, which approximate the
// sphere to higher order (Nagata 2005, section 4), so the worst radial error shrinks.
TEST(Smooth, FacetedSphereBecomesRound) {
  const Vec3 centre{0, 0, 0.03};
  auto worst_radial_error = [&](const Mesh& m) {
    double worst = 0.0;
    for (std::size_t n : exterior_nodes(m))
      worst = std::max(worst, std::abs(norm(m.nodes.position(n) - centre) - 0.01));
    return worst / 0.01;
  };
  Mesh flat = seed_sphere(3), round = seed_sphere(3);
  forget_exact_shapes(flat);
  forget_exact_shapes(round);
  refine_and_smooth(flat, {change(1, 3)}, {});
  const auto notes = refine_and_smooth(round, {change(1, 3)}, {smooth(1, 45.0)});
  EXPECT_THAT(notes[0], HasSubstr("Nagata"));
  EXPECT_EQ(round.nodes.size(), flat.nodes.size());
  EXPECT_EQ(duplicate_nodes(round, 1e-9), 0u);
  EXPECT_GT(min_scaled_jacobian(round), 0.3);
  const double flat_error = worst_radial_error(flat), round_error = worst_radial_error(round);
  // Flat facets: the face centre of a 30 x 30 degree quad sits ~(1 - cos 21 deg) = 6.8 % in.
  EXPECT_GT(flat_error, 0.03);
  EXPECT_LT(round_error, flat_error / 5.0);
  const double exact = 4.0 / 3.0 * kPi * 1e-6;
  EXPECT_LT(std::abs(total_volume(round) - exact), std::abs(total_volume(flat) - exact) / 5.0);
}

}  // namespace
}  // namespace abut
