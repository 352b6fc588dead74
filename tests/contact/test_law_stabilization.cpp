// The contact stabilization law (laws/stabilization.hpp, OptiStruct CNTSTB): its stiffness over an
// increment, c factor s_gap(g) / dt, and its projector n n + f_t (I - n n), by hand.
#include <gtest/gtest.h>

#include "abut/contact/laws/stabilization.hpp"

namespace abut {
namespace {

TEST(LawStabilization, StiffnessFollowsTheIncrementTheRampAndTheOpening) {
  const ContactStabilization s{2.0, 0.5, 0.25};
  // Closed (any penetration) and touching: the full c factor / dt.
  EXPECT_DOUBLE_EQ(s.stiffness(-1.0, 3.0, 0.1), 2.0 * 3.0 / 0.1);
  EXPECT_DOUBLE_EQ(s.stiffness(0.0, 3.0, 0.1), 60.0);
  // Open: linear to nothing at the range.
  EXPECT_DOUBLE_EQ(s.stiffness(0.125, 3.0, 0.1), 60.0 * 0.75);
  EXPECT_DOUBLE_EQ(s.stiffness(0.5, 3.0, 0.1), 0.0);
  EXPECT_DOUBLE_EQ(s.stiffness(2.0, 3.0, 0.1), 0.0);
  // Off: a ramp at 0, or no increment.
  EXPECT_DOUBLE_EQ(s.stiffness(-1.0, 0.0, 0.1), 0.0);
  EXPECT_DOUBLE_EQ(s.stiffness(-1.0, 3.0, 0.0), 0.0);
}

TEST(LawStabilization, ProjectorDampsTheTangentialMotionByItsFraction) {
  const ContactStabilization s{1.0, 1.0, 0.25};
  const Vec3 n{0.0, 0.6, 0.8};
  const Vec3 du{1.0, 2.0, -1.0};
  const Vec3 held = s.project(du, n);
  // Normal part n (du . n) = 0.4 n; tangential part du - 0.4 n, a quarter of it.
  const Vec3 normal_part = n * 0.4;
  const Vec3 expected = normal_part + (du - normal_part) * 0.25;
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(held[i], expected[i], 1e-15);
    double row = 0.0;  // P du from the projector's entries
    for (int j = 0; j < 3; ++j) row += s.projector(n, i, j) * du[j];
    EXPECT_NEAR(row, expected[i], 1e-15);
  }
}

}  // namespace
}  // namespace abut
