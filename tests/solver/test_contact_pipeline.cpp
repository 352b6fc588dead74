// From a hex mesh to contact forces: skin -> contact surfaces -> interface.
#include <gtest/gtest.h>

#include "abut/contact/interface.hpp"
#include "abut/contact/penalty.hpp"
#include "abut/mesh/skin.hpp"
#include "abut/solver/contact_surfaces.hpp"
#include "hex_block.hpp"

namespace abut {
namespace {

// Two blocks with non-matching meshes (3x3 and 2x2 elements on the shared 0.6 x 0.6 face),
// the upper one pushed down by d: both passes' points all land inside the other face, so the
// total is exactly pfac * A * d (seed 000 penalty law) with pfac the smaller of the two parts'.
TEST(ContactPipeline, HexBlocksPressedTogether) {
  Mesh mesh;
  testing::add_hex_block(mesh, 1, 3, 3, 2, {0, 0, -0.2}, {0.6, 0.6, 0.0});
  testing::add_hex_block(mesh, 2, 2, 2, 1, {0, 0, 0.05}, {0.6, 0.6, 0.35});
  const std::int64_t lower_part[] = {1}, upper_part[] = {2};
  auto pfac = [](const SkinFace& f) { return f.part == 1 ? 4e9 : 2.5e9; };
  const ContactSurface lower = contact_surface(mesh, exterior_faces(mesh, lower_part, false), pfac);
  const ContactSurface upper = contact_surface(mesh, exterior_faces(mesh, upper_part, false), pfac);
  ASSERT_EQ(lower.size(), 2u * (9 + 6 + 6));  // 2 (nx ny + ny nz + nz nx)
  ASSERT_EQ(upper.size(), 2u * (4 + 2 + 2));

  const std::size_t n = mesh.nodes.size();
  std::vector<double> mass(n, 0.1), vx(n, 0.0), vy(n, 0.0), vz(n, 0.0), fx(n, 0.0), fy(n, 0.0),
      fz(n, 0.0);
  std::vector<double> x = mesh.nodes.x, y = mesh.nodes.y, z = mesh.nodes.z;
  ContactSettings s;
  s.damping = 0.0;
  ContactInterface contact(s, lower, upper, mass, {x, y, z, vx, vy, vz, 0.0, 0.0, {}});
  const double d = 0.002;
  for (std::size_t i = 0; i < n; ++i)
    if (mesh.nodes.z[i] > 0.01) z[i] -= 0.05 + d;
  ContactForces out{fx, fy, fz, {}, {}};
  contact.apply({x, y, z, vx, vy, vz, 0.0, 1e-6, {}}, out);
  const double expected = 2.5e9 * 0.36 * d;
  EXPECT_NEAR(contact.stats().force.z, -expected, 1e-9 * expected);  // surface 1 = lower block
  double upper_fz = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    if (mesh.nodes.z[i] > 0.01) upper_fz += fz[i];
  EXPECT_NEAR(upper_fz, expected, 1e-9 * expected);
  // Side faces meet the top at 90 degrees: nothing beyond the blocks' sharp edges acts.
  EXPECT_EQ(contact.stats().active_points, 9u * 4 + 4u * 4);
}

}  // namespace
}  // namespace abut
