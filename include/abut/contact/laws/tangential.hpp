#pragma once
// Tangential laws: the tangential force of a contact point from its slip history. Every law is a
// tangential spring (elastic predictor F_trial = F_old - k_t v_t dt) returned to a slip limit, the
// stick/slip rule of seed 004 (F_t = min(mu F_n, |F_old + K V_t dt|)); the laws differ only in
// their limits: the force a sticking point holds before it slips (static) and the force while it
// slides (dynamic).
//   Frictionless      no tangential force
//   Coulomb           mu_s F_n / mu_d F_n (Metafor CoulombContactMaterial, seed 002); mu from a
//                     callback (seed 000's mu = fcn) or a Radioss Ifric law (friction_model.hpp);
//                     mu_s and mu_d may each be times a function of time (Metafor TM)
//   Tresca            m_s k A / m_d k A, independent of the pressure (Metafor
//                     TrescaContactMaterial); m_s, m_d and k may each be times a function of time
//   Sticking          no limit: the tangential spring holds while the contact is closed
//                     (Metafor StickingContactMaterial, OptiStruct STICK)
// A law gives its limits (explicit and static steps) and the slopes of the sliding limit in the
// normal force and in the sliding speed (the consistent tangent of static steps,
// static_contact.hpp): a new law provides all three, or std::visit below does not compile.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <type_traits>
#include <variant>

#include "abut/contact/laws/dependency.hpp"
#include "abut/contact/laws/friction_model.hpp"
#include "abut/core/vec3.hpp"

namespace abut {

// What a law may read at a contact point.
struct SlipState {
  double normal_force = 0.0;  // >= 0
  double area = 0.0;          // the point's area
  double slip_speed = 0.0;    // |v_t|
  double time = 0.0;
  Vec3 position;
};

struct SlipLimits {
  double stick = 0.0;  // largest force held without slip
  double slide = 0.0;  // force while sliding
};

struct TangentialResult {
  Vec3 force;              // tangential force on the point
  double slip_work = 0.0;  // energy dissipated by slip in this step (>= 0)
  bool sliding = false;
};

// The return mapping shared by all laws. `previous`: last step's tangential force (any normal
// component is removed, so the history follows a rotating tangent plane); `was_sliding` selects
// the limit the trial force is checked against. Slip work: slide limit times slip increment.
inline TangentialResult return_to_limit(Vec3 previous, const Vec3& normal,
                                        const Vec3& slip_velocity, double dt, double stiffness,
                                        const SlipLimits& limits, bool was_sliding) {
  previous -= normal * dot(previous, normal);
  const Vec3 trial = previous - slip_velocity * (stiffness * dt);
  const double size = norm(trial);
  const double hold = was_sliding ? limits.slide : limits.stick;
  if (size <= hold) return {trial, 0.0, false};
  const double limit = limits.slide;
  const Vec3 force = limit > 0.0 && size > 0.0 ? trial * (limit / size) : Vec3{};
  return {force, limit * (size - limit) / stiffness, true};
}

struct Frictionless {
  SlipLimits limits(const SlipState&) const { return {}; }
  double slide_slope(const SlipState&) const { return 0.0; }
  double slide_rate_slope(const SlipState&) const { return 0.0; }
};

// mu(pres, vtang, t, x, y, z), seed 000's fcn(fid); must be thread-safe and cheap.
using FrictionFunction =
    std::function<double(double pres, double vtang, double t, double x, double y, double z)>;
using FrictionModel =
    std::variant<std::monostate, ViscousFriction, DarmstadFriction, RenardFriction>;

struct Coulomb {
  double mu_static = 0.0, mu_dynamic = 0.0;
  FrictionFunction function;  // when set: mu_s = mu_d = function(...)
  FrictionModel model;        // when set: mu_s = mu_d = model.mu(p, V)
  // Metafor COEF_FROT_STA / COEF_FROT_DYN (TM): mu_static f_s(t), mu_dynamic f_d(t). Only with
  // constant coefficients (no function, no model). Where mu_d(t) > mu_s(t), mu_s(t) is both.
  TimeFactor static_in_time, dynamic_in_time;

  double mu(const SlipState& s, bool dynamic) const {
    const double p = s.area > 0.0 ? s.normal_force / s.area : 0.0;
    if (function)
      return function(p, s.slip_speed, s.time, s.position.x, s.position.y, s.position.z);
    const double constant =
        dynamic ? mu_dynamic * dynamic_in_time.at(s.time) : mu_static * static_in_time.at(s.time);
    return of_model(constant, [&](const auto& m) { return m.mu(p, s.slip_speed); });
  }
  bool varies() const { return function || !std::holds_alternative<std::monostate>(model); }
  // The sliding coefficient: mu(s, true), at most the static one (constant coefficients).
  double mu_slide(const SlipState& s) const {
    if (varies()) return mu(s, true);
    return std::min(std::max(mu(s, true), 0.0), std::max(mu(s, false), 0.0));
  }
  // `value(m)` of the model m that is set, `none` without one. Every alternative answers here: a
  // model added to FrictionModel without mu, dmu_dp and dmu_dv does not compile (issue 31),
  // rather than falling back to mu_s.
  template <class Value>
  double of_model(double none, Value&& value) const {
    return std::visit(
        [&](const auto& m) {
          if constexpr (std::is_same_v<std::decay_t<decltype(m)>, std::monostate>)
            return none;
          else
            return value(m);
        },
        model);
  }
  SlipLimits limits(const SlipState& s) const {
    const double mu_s = std::max(mu(s, false), 0.0);
    const double mu_d = varies() ? mu_s : mu_slide(s);
    return {mu_s * s.normal_force, mu_d * s.normal_force};
  }
  // d(mu p A)/d(p A) = mu + p dmu/dp at the sliding speed.
  double slide_slope(const SlipState& s) const {
    const double p = s.area > 0.0 ? s.normal_force / s.area : 0.0;
    const double dmu_dp =
        function ? function_slope(p, s,
                                  [&](double q) {
                                    return std::array{q, s.slip_speed};
                                  })
                 : of_model(0.0, [&](const auto& m) { return m.dmu_dp(p, s.slip_speed); });
    const double slide = mu_slide(s);
    return slide > 0.0 ? slide + p * dmu_dp : 0.0;
  }
  // d(mu p A)/dV = p A dmu/dV.
  double slide_rate_slope(const SlipState& s) const {
    if (!(mu_slide(s) > 0.0)) return 0.0;
    const double p = s.area > 0.0 ? s.normal_force / s.area : 0.0;
    const double dmu_dv =
        function ? function_slope(s.slip_speed, s,
                                  [&](double v) {
                                    return std::array{p, v};
                                  })
                 : of_model(0.0, [&](const auto& m) { return m.dmu_dv(p, s.slip_speed); });
    return s.normal_force * dmu_dv;
  }
  // The friction function's slope in one argument at `at`, by a central difference of 1e-6 of
  // it (or of 1 near 0, in the deck's units); `args(v)` gives (p, V) with that argument set to v.
  template <class Args>
  double function_slope(double at, const SlipState& s, Args&& args) const {
    const double h = 1e-6 * std::max(std::abs(at), 1.0);
    auto mu_at = [&](double v) {
      const auto [p, speed] = args(v);
      return function(p, speed, s.time, s.position.x, s.position.y, s.position.z);
    };
    return (mu_at(at + h) - mu_at(at - h)) / (2.0 * h);
  }
};

// Shear limit m k (seed 002: usually m sigma_0 / sqrt(3), k the shear yield stress), times area.
// Each of m_s, m_d and k may be times a function of time (Metafor TM; seed 002 gives TRESCA_K
// none, abut allows it); where m_d(t) > m_s(t), m_s(t) is both.
struct Tresca {
  double factor_static = 0.0, factor_dynamic = 0.0;  // TRESCA_STA_M, TRESCA_DYN_M
  double shear_yield = 0.0;                          // TRESCA_K
  TimeFactor static_in_time, dynamic_in_time, yield_in_time;
  SlipLimits limits(const SlipState& s) const {
    const double k = std::max(shear_yield * yield_in_time.at(s.time), 0.0) * s.area;
    const double m_s = std::max(factor_static * static_in_time.at(s.time), 0.0);
    const double m_d = std::clamp(factor_dynamic * dynamic_in_time.at(s.time), 0.0, m_s);
    return {m_s * k, m_d * k};
  }
  double slide_slope(const SlipState&) const { return 0.0; }
  double slide_rate_slope(const SlipState&) const { return 0.0; }
};

struct Sticking {
  SlipLimits limits(const SlipState&) const {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    return {kInf, kInf};
  }
  double slide_slope(const SlipState&) const { return 0.0; }
  double slide_rate_slope(const SlipState&) const { return 0.0; }
};

using TangentialLaw = std::variant<Frictionless, Coulomb, Tresca, Sticking>;

inline SlipLimits slip_limits(const TangentialLaw& law, const SlipState& s) {
  return std::visit([&](const auto& l) { return l.limits(s); }, law);
}
inline double slide_slope(const TangentialLaw& law, const SlipState& s) {
  return std::visit([&](const auto& l) { return l.slide_slope(s); }, law);
}
inline double slide_rate_slope(const TangentialLaw& law, const SlipState& s) {
  return std::visit([&](const auto& l) { return l.slide_rate_slope(s); }, law);
}

// Radioss Ifiltr (seed 004, comment 8): F_t = a F_t + (1 - a) F_t,prev with a = Xfreq (1),
// 2 pi dt / T with Xfreq = T the period (2), 2 pi Xfreq dt with Xfreq the cut-off frequency (3).
struct FrictionFilter {
  enum class Kind { None, Simple, Period, Frequency } kind = Kind::None;
  double xfreq = 1.0;
  double alpha(double dt) const;
};

}  // namespace abut
