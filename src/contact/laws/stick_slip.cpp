#include "abut/contact/laws/stick_slip.hpp"

#include <algorithm>
#include <cmath>

namespace abut {
namespace {

// (static - dynamic) / D_c: how fast the limit falls with slip [force / length].
double weakening_rate(const SlipLimits& limits, double stiffness) {
  if (!(limits.stick > limits.slide) || !std::isfinite(limits.stick)) return 0.0;
  return (limits.stick - limits.slide) * stiffness / (kWeakeningRange * limits.stick);
}

// The largest s in [0, 1] with |spring + s d| <= limit, given |spring| <= limit.
double damping_within(const Vec3& spring, const Vec3& d, double limit) {
  const double dd = dot(d, d);
  if (!(dd > 0.0) || !std::isfinite(limit) || norm(spring + d) <= limit) return 1.0;
  const double b = dot(spring, d), c = dot(spring, spring) - limit * limit;
  return std::clamp((-b + std::sqrt(std::max(b * b - dd * c, 0.0))) / dd, 0.0, 1.0);
}

}  // namespace

double weakened_limit(const SlipLimits& limits, double slip, double stiffness) {
  const double w = weakening_rate(limits, stiffness);
  return w > 0.0 ? std::max(limits.stick - w * slip, limits.slide) : limits.stick;
}

StickSlipResult stick_slip(const Vec3& spring, double slip, const StickSlipStep& now,
                           const SlipLimits& limits) {
  const double k = now.stiffness;
  // Seed 004's return, held by the limit weakened by the slip so far, and should it slip, by the
  // limit weakened further by the distance the point moved on its partner in this step (not by
  // the spring's relaxation when the normal force falls: a block whose pressure dips while it is
  // held has not slid).
  const double hold = weakened_limit(limits, slip, k);
  const double moved = norm(now.slip_velocity) * now.dt;
  const TangentialResult t =
      return_to_limit(spring, now.normal, now.slip_velocity, now.dt, k,
                      {hold, weakened_limit(limits, slip + moved, k)}, /*was_sliding=*/false);
  StickSlipResult r;
  r.spring = r.force = t.force;
  r.slip_work = t.slip_work;
  r.sliding = t.sliding;
  if (t.sliding) {
    r.slip = slip + moved;
  } else if (now.damping > 0.0) {  // sticks: the slip count starts again, the spring is damped
    const Vec3 d = now.slip_velocity * (-now.damping);
    const double s = damping_within(t.force, d, hold);
    r.force = t.force + d * s;
    r.damping_work = s * now.damping * dot(now.slip_velocity, now.slip_velocity) * now.dt;
  }
  return r;
}

}  // namespace abut
