#pragma once
// Static and dynamic friction at one contact point over one step: seed 004's elastic stick
// predictor F_t = min(mu F_n, |F_old + K V_t dt|) (return_to_limit, tangential.hpp) returned to a
// limit that is the static one (seed 002's COEF_FROT_STA, Tresca's m_s) for a point that sticks
// and falls to the dynamic one (COEF_FROT_DYN, m_d) as the point slides.
//
// A sharp switch, which drops a point to the dynamic limit at its first slip however small, lets
// a body that static friction should hold slide away:
//  - partial slip: where a block on a slope carries less pressure (its uphill edge, by the
//    tilting moment of the load) its points reach mu_s N first and slip a little while the rest
//    hold the block. Dropped to mu_d N they pass their load to the neighbours, which slip in turn,
//    and the whole interface ends at mu_d;
//  - the stick spring's swing: a point that sticks again after sliding starts at mu_d N against
//    its old slip; undamped, its spring swings past the holding force, on a slope to
//    (2 tan(theta) + mu_d) N > mu_s N, and slips again.
// So the limit falls from static to dynamic linearly with the distance s the point has slid on
// its partner since it last stuck (the linear slip-weakening law of friction: Ida 1972; Palmer &
// Rice 1973):
//     limit(s) = max(static - (static - dynamic) s / D_c, dynamic),
// with D_c = kWeakeningRange times the stick spring's elastic range, static / k (for a linear
// normal law and k_t = k_n: mu_s times the penetration). The distance is what the point moved on
// its partner while it slipped (|v_t| dt per step), not the spring's relaxation when the normal
// force falls: a block whose pressure dips while it is held has not slid. A point that creeps a
// little while the body is held (partial slip, a spring's swing, the bounce of a block set down
// on a penalty spring) keeps nearly the static limit and sticks again; a point that slides is at
// the dynamic limit after a slip of D_c (mu_s times 100 penetrations), which shrinks as the
// penalty grows: the law tends to the sharp switch. The weakening is slower than the spring
// ((static - dynamic) / D_c < k), so slip is stable.
//
// A point sticks whenever its trial force is within its current limit: it touched anew (its
// spring and slip start at zero), or its slip velocity reversed or vanished; its slip count then
// starts again. While it sticks its spring is damped by the same fraction of critical as the
// normal one (c = 2 xi sqrt(k m), given by the caller), so tangential swings settle as normal ones
// do; the damping never lifts the force above the limit.
#include "abut/contact/laws/tangential.hpp"
#include "abut/core/vec3.hpp"

namespace abut {

// D_c in elastic ranges of the stick spring. What sets it: a block set down on a slope under its
// full weight bounces on its penalty springs for some ten of their periods (10% damping), and
// creeps meanwhile by a distance that scales like the penetration. In the static-friction matrix
// (tests/verification/test_static_friction.cpp) 30 held most of those blocks, 100 held all the
// surface-to-surface ones. The cost: a block that starts to slide from rest reaches the dynamic
// limit a few milliseconds later (docs/verification.md).
inline constexpr double kWeakeningRange = 100.0;

struct StickSlipStep {
  Vec3 normal;             // unit normal of the contact
  Vec3 slip_velocity;      // relative tangential velocity of the point on its partner
  double dt = 0.0;         // the step
  double stiffness = 0.0;  // tangential spring k [force / length]
  double damping = 0.0;    // c [force time / length], applied while sticking
};

struct StickSlipResult {
  Vec3 force;                 // tangential force on the point: spring plus damping
  Vec3 spring;                // the new elastic tangential force (history)
  double slip = 0.0;          // distance slid since the point last stuck (history) [length]
  double slip_work = 0.0;     // dissipated by slip (>= 0): the limit times the slip
  double damping_work = 0.0;  // dissipated by the damping (>= 0)
  bool sliding = false;
};

// limit(s) above.
double weakened_limit(const SlipLimits& limits, double slip, double stiffness);

// `spring`, `slip`: the point's history from the step before (zero for a point that touches anew).
StickSlipResult stick_slip(const Vec3& spring, double slip, const StickSlipStep& now,
                           const SlipLimits& limits);

}  // namespace abut
