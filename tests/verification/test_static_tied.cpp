// A tied (FREEZE / TIED) interface between non-matching meshes carries bending as one body would
// (issue 10). A cantilever of C3D8 hexes, clamped at x = 0 and loaded by a tip shear, is cut at
// mid-span into two parts with different meshes (4 and 3 elements through the depth) tied by
// surface-to-surface contact. Reference: Timoshenko's tip deflection (static_cantilever.hpp).
// The fully integrated hex is too stiff in bending by about (1 - nu)/2 (a/b)^2 for elements of
// length a and depth b (parasitic shear; Cook et al., Concepts and Applications of FEA, 4th ed.,
// section 6.13): the elements here are 8 to 16 times deeper than long, so that share stays below
// 1%, and the same cantilever meshed as one body is printed beside the tied one.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "abut/mesh/generators.hpp"
#include "abut/solver/static_solver.hpp"
#include "static_cantilever.hpp"

namespace abut {
namespace {

using namespace cantilever;

FaceSet faces_at_x(const Model& m, std::int64_t id, std::int64_t part, int face, double x) {
  FaceSet s;
  s.id = id;
  for (std::size_t h = 0; h < m.mesh.hex_count(); ++h) {
    if (m.mesh.hex_part[h] != part) continue;
    bool all = true;
    for (const int a : kHexFaces[face])
      all = all && std::abs(m.mesh.nodes.x[m.mesh.hexes[h][a]] - x) < 1e-12;
    if (all) s.faces.push_back({static_cast<std::int32_t>(h), static_cast<std::int8_t>(face)});
  }
  return s;
}

// Far below the default 0.005, but above the round-off of the stiff tie springs (the gap x - q is
// computed to ~1e-16 of the coordinates, which the penalty turns into ~1e-7 of the average force).
StaticControls tight() {
  StaticControls c;
  c.force_tolerance = 1e-6;
  c.displacement_tolerance = 1e-6;
  return c;
}

TEST(StaticTied, NonMatchingMeshesCarryBendingAsOneBody) {
  const double reference = timoshenko_deflection();
  // One body: 128 x 4 x 1 hexes.
  Model one;
  generate_box(one.mesh, {1, 128, 4, 1, {0, 0, 0}, {kL, kH, kW}});
  one.materials.push_back(elastic());
  one.parts.push_back(full_part(1));
  clamp_and_load(one);
  StaticSolver s1(one, tight());
  s1.run();
  const double one_body = tip_deflection(one, s1);
  // Tied: [0, L/2] with 64 x 4 x 1 hexes, [L/2, L] with 50 x 3 x 1, tied at x = L/2.
  Model tied;
  generate_box(tied.mesh, {1, 64, 4, 1, {0, 0, 0}, {kL / 2, kH, kW}});
  generate_box(tied.mesh, {2, 50, 3, 1, {kL / 2, 0, 0}, {kL, kH, kW}});
  tied.materials.push_back(elastic());
  tied.parts.push_back(full_part(1));
  tied.parts.push_back(full_part(2));
  clamp_and_load(tied);
  tied.face_sets.push_back(faces_at_x(tied, 1, 2, 5, kL / 2));  // part 2's x-min faces (S6)
  tied.face_sets.push_back(faces_at_x(tied, 2, 1, 3, kL / 2));  // part 1's x-max faces (S4)
  ASSERT_EQ(tied.face_sets[0].faces.size(), 3u);
  ASSERT_EQ(tied.face_sets[1].faces.size(), 4u);
  ContactSpec c;
  c.id = 1;
  c.surface1 = {EntityType::FaceSet, 1, {}};
  c.surface2 = {EntityType::FaceSet, 2, {}};
  c.one_way = true;
  c.damping = 0.0;
  c.friction_law = ContactSpec::FrictionLaw::Freeze;
  c.penalty = 1000.0 * kE / (kL / 128);  // stiff against the elements: the tie adds < 0.1%
  tied.contacts.push_back(c);
  StaticSolver s2(tied, tight());
  s2.run();
  const double tied_tip = tip_deflection(tied, s2);
  std::cout << "tip deflection: Timoshenko " << reference << ", one body " << one_body << " ("
            << 100 * (one_body / reference - 1) << "%), tied " << tied_tip << " ("
            << 100 * (tied_tip / reference - 1) << "%)\n";
  EXPECT_NEAR(one_body / reference, 1.0, 0.02);
  EXPECT_NEAR(tied_tip / reference, 1.0, 0.02);
  EXPECT_NEAR(tied_tip / one_body, 1.0, 0.02);
}

}  // namespace
}  // namespace abut
