// The stick-slip law of a contact point (include/abut/contact/laws/stick_slip.hpp) called alone.
// References written out from the formulas, not by calling the code under test:
//   seed 004's return F_t = min(mu F_n, |F_old + K V_t dt|) (../shared/seeds/README.md);
//   the linear slip-weakening law limit(s) = max(S - (S - D) s / D_c, D) (Ida 1972, Palmer & Rice
//   1973), D_c = kWeakeningRange S / k, s the distance slid (|v_t| dt per slipping step); the
//   slip work is the limit times the slip (|trial| - limit) / k;
//   a dashpot c v_t added while the point sticks, never beyond the limit.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "abut/contact/laws/stick_slip.hpp"

namespace abut {
namespace {

constexpr double kK = 1000.0, kDt = 1e-3;  // k dt = 1
constexpr double kStatic = 10.0, kDynamic = 6.0;
const SlipLimits kLimits{kStatic, kDynamic};
const Vec3 kNormal{0.0, 0.0, 1.0};
const double kRange = kWeakeningRange * kStatic / kK;  // D_c
const double kRate = (kStatic - kDynamic) / kRange;    // weakening per unit slip

StickSlipStep step(const Vec3& slip_velocity, double damping = 0.0) {
  return {kNormal, slip_velocity, kDt, kK, damping};
}

TEST(StickSlip, WithinTheStaticLimitThePointSticksWithItsTrialForce) {
  // trial = (4, -3, 0) - (2, 1, 0) k dt = (2, -4, 0); |trial| = 4.47 <= 10; the normal part of the
  // old force (7) is dropped.
  const StickSlipResult r = stick_slip({4.0, -3.0, 7.0}, 0.0, step({2.0, 1.0, 0.0}), kLimits);
  EXPECT_FALSE(r.sliding);
  EXPECT_NEAR(norm(r.force - Vec3{2.0, -4.0, 0.0}), 0.0, 1e-12);
  EXPECT_NEAR(norm(r.spring - r.force), 0.0, 0.0);
  EXPECT_EQ(r.slip, 0.0);
  EXPECT_EQ(r.slip_work, 0.0);
}

TEST(StickSlip, AFirstSlipWeakensTheLimitByTheDistanceSlid) {
  // From rest, v = 12 along -x: trial 12 along x (> 10). The point moved 12 dt = 0.012; the limit
  // is 10 - w 0.012, and the slip (12 - limit) / k.
  const StickSlipResult r = stick_slip({}, 0.0, step({-12.0, 0.0, 0.0}), kLimits);
  const double moved = 12.0 * kDt, limit = kStatic - kRate * moved;
  EXPECT_TRUE(r.sliding);
  EXPECT_NEAR(r.slip, moved, 1e-18);
  EXPECT_NEAR(r.force.x, limit, 1e-12);
  EXPECT_GT(r.force.x, 0.99 * kStatic);  // a short slide keeps nearly the static limit
  EXPECT_NEAR(r.slip_work, limit * (12.0 - limit) / kK, 1e-15);
}

TEST(StickSlip, AHeldPointWhoseNormalForceFallsKeepsItsLimit) {
  // No motion on the partner, the limit halved (the normal force dipped): the spring relaxes to
  // the limit but the point has not slid, so its limit is not weakened.
  const SlipLimits dipped{5.0, 3.0};
  const StickSlipResult r = stick_slip({8.0, 0.0, 0.0}, 0.0, step({}), dipped);
  EXPECT_TRUE(r.sliding);
  EXPECT_EQ(r.slip, 0.0);
  EXPECT_NEAR(r.force.x, 5.0, 1e-12);
}

TEST(StickSlip, BeyondTheWeakeningRangeThePointSlidesOnTheDynamicLimit) {
  // Slid D_c already: the limit is the dynamic one, trial 50 along -y.
  const StickSlipResult r = stick_slip({}, kRange, step({0.0, 50.0, 0.0}), kLimits);
  EXPECT_TRUE(r.sliding);
  EXPECT_NEAR(r.force.y, -kDynamic, 1e-12);
  EXPECT_NEAR(r.slip, kRange + 50.0 * kDt, 1e-15);
  EXPECT_NEAR(r.slip_work, kDynamic * (50.0 - kDynamic) / kK, 1e-14);
}

TEST(StickSlip, ASlidingPointSticksAgainWhenItsSlipReversesAndStartsItsCountAgain) {
  // At the dynamic limit (slip beyond D_c), the slip velocity reverses: trial 6 - 1 = 5 <= 6.
  const StickSlipResult r =
      stick_slip({kDynamic, 0.0, 0.0}, 2.0 * kRange, step({1.0, 0.0, 0.0}), kLimits);
  EXPECT_FALSE(r.sliding);
  EXPECT_EQ(r.slip, 0.0);
  EXPECT_NEAR(r.force.x, 5.0, 1e-12);
  // From there it may hold up to the static limit again: trial 5 + 4.5 = 9.5 <= 10.
  const StickSlipResult again = stick_slip(r.spring, r.slip, step({-4.5, 0.0, 0.0}), kLimits);
  EXPECT_FALSE(again.sliding);
  EXPECT_NEAR(again.force.x, 9.5, 1e-12);
}

TEST(StickSlip, EqualLimitsGiveSeed004sReturn) {
  // mu_s = mu_d: no weakening, the force and work of return_to_limit (tangential.hpp) bit for bit.
  const SlipLimits equal{8.0, 8.0};
  const Vec3 old{3.0, 2.0, 0.5}, v{-9.0, 4.0, 0.0};
  const StickSlipResult r = stick_slip(old, 123.0, step(v), equal);
  const TangentialResult seed = return_to_limit(old, kNormal, v, kDt, kK, equal, false);
  EXPECT_EQ(r.force.x, seed.force.x);
  EXPECT_EQ(r.force.y, seed.force.y);
  EXPECT_EQ(r.force.z, seed.force.z);
  EXPECT_EQ(r.slip_work, seed.slip_work);
}

TEST(StickSlip, WeakeningIsLinearInTheDistanceSlid) {
  // Halfway through D_c the limit is halfway between the static and dynamic ones.
  EXPECT_NEAR(weakened_limit(kLimits, 0.5 * kRange, kK), 0.5 * (kStatic + kDynamic), 1e-12);
  EXPECT_EQ(weakened_limit(kLimits, 0.0, kK), kStatic);
  EXPECT_EQ(weakened_limit(kLimits, 3.0 * kRange, kK), kDynamic);
  // The weakening is slower than the spring unloads, so slip is stable.
  EXPECT_LT(kRate, kK);
}

TEST(StickSlip, DampingActsWhileStickingAndNeverBeyondTheLimit) {
  // c = 0.5: trial (3, 0, 0) from v = (-3, 0, 0); damping force (1.5, 0, 0): 4.5 <= 10.
  const StickSlipResult r = stick_slip({}, 0.0, step({-3.0, 0.0, 0.0}, 0.5), kLimits);
  EXPECT_FALSE(r.sliding);
  EXPECT_NEAR(r.force.x, 4.5, 1e-12);
  EXPECT_NEAR(r.spring.x, 3.0, 1e-12);  // the history holds the spring alone
  EXPECT_NEAR(r.damping_work, 0.5 * 9.0 * kDt, 1e-15);
  // c = 5: the damping would give 3 + 15 = 18 > 10; only 7 of it acts.
  const StickSlipResult capped = stick_slip({}, 0.0, step({-3.0, 0.0, 0.0}, 5.0), kLimits);
  EXPECT_NEAR(capped.force.x, kStatic, 1e-12);
  EXPECT_NEAR(capped.damping_work, (7.0 / 15.0) * 5.0 * 9.0 * kDt, 1e-14);
}

TEST(StickSlip, StickingContactNeverSlips) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const StickSlipResult r = stick_slip({}, 0.0, step({-1e9, 0.0, 0.0}), {kInf, kInf});
  EXPECT_FALSE(r.sliding);
  EXPECT_NEAR(r.force.x, 1e9, 1e-3);
}

}  // namespace
}  // namespace abut
