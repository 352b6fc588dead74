#pragma once
// The material-point seam of hypoelastic laws: an element hands a point its old stress (already
// rotated to the current frame), the strain increment of the step, the step and the point's
// history (plastic strain, damage); the law returns the new stress and advances the history.
// Hexahedra call `update` as it is (3-D); shells call plane_stress_update, which finds the
// thickness strain that makes the normal stress vanish. A new hypoelastic law is one value type
// with `update` and `at_temperature` (the law at an element temperature, for the coupling to heat).
#include <cmath>

#include "abut/material/elastic.hpp"
#include "abut/material/metal.hpp"
#include "abut/material/sym_tensor.hpp"

namespace abut {

struct PointHistory {
  double plastic_strain = 0.0;  // equivalent plastic strain
  double damage = 0.0;          // ductile damage (metals with a did); >= 1: the point has failed
  double plastic_strain_rate = 0.0;  // of the last step
  bool failed() const { return damage >= 1.0; }
};

// Johnson-Cook failure strain at a stress state and plastic strain rate (material.hpp).
double failure_strain(const DuctileFailure& f, const Sym3& stress, double plastic_strain_rate);

// *MAT_ELASTIC: Hooke's law on the increment.
struct ElasticPoint {
  LameConstants lame;
  Sym3 update(const Sym3& rotated, const Sym3& increment, double /*dt*/,
              PointHistory& /*history*/) const {
    return add(rotated, hooke(lame, increment));
  }
  // The same on several points at once (T = Lanes, lanes.hpp; arrays in Sym3 order): a law
  // without history may offer this form, which the hexahedron kernel then uses.
  template <class T>
  void update_lanes(const T rotated[6], const T increment[6], T out[6]) const {
    T h[6];
    hooke_of(lame, increment, h);
    for (int i = 0; i < 6; ++i) out[i] = rotated[i] + h[i];
  }
  // The law at an element temperature (issue 11): Hooke's law does not depend on it.
  ElasticPoint at_temperature(double /*temperature*/) const { return *this; }
};

// *MAT_METAL, *MAT_JC: elastic trial and radial return (metal.hpp), then the damage.
struct MetalPoint {
  LameConstants lame;
  FlowStress flow;
  DuctileFailure failure;
  Sym3 update(const Sym3& rotated, const Sym3& increment, double dt, PointHistory& h) const {
    if (h.failed()) {
      h.plastic_strain_rate = 0.0;
      return Sym3{};
    }
    const PlasticUpdate u =
        radial_return(add(rotated, hooke(lame, increment)), lame.mu, h.plastic_strain, dt, flow);
    const double dp = u.plastic_strain_increment;
    h.plastic_strain += dp;
    h.plastic_strain_rate = dt > 0.0 ? dp / dt : 0.0;
    if (failure.active && dp > 0.0) {
      const double eps_f = failure_strain(failure, u.stress, dt > 0.0 ? dp / dt : 0.0);
      h.damage = eps_f > 0.0 ? h.damage + dp / eps_f : 1.0;
      if (h.failed()) return Sym3{};
    }
    return u.stress;
  }
  // The law at an element temperature (issue 11): the thermally softened flow stress and the
  // failure strain's factor 1 + d5 T* (Johnson & Cook 1985).
  MetalPoint at_temperature(double temperature) const {
    MetalPoint p = *this;
    p.flow = flow.at_temperature(temperature);
    p.failure.thermal_factor =
        1.0 + failure.d5 * homologous_temperature(flow.params(), temperature);
    return p;
  }
};

// Plane stress (sigma_zz = 0, z the normal) for any law above: the thickness strain increment
// d_zz is the root of sigma_zz(d_zz), found by Newton steps with the elastic slope lambda + 2 mu
// first and secants after (Hallquist, LS-DYNA Theory Manual, "iterative plane stress" for
// materials without a plane-stress return). Elastic points converge in one step; a plastic
// point in a few, because sigma_zz is monotonic in d_zz with a slope between the elastic and the
// tangent modulus. `increment[2]` is ignored; on return it holds the d_zz found.
//
// `ratio` (optional, in and out) is the point's last d_zz / (d_xx + d_yy): a flowing point keeps
// nearly the same ratio from step to step (about -1 in fully plastic, isochoric flow, against the
// elastic -nu / (1 - nu)), so starting from it saves most iterations.
template <class Law>
Sym3 plane_stress_update(const Law& law, const Sym3& rotated, Sym3& increment, double dt,
                         PointHistory& history, double* ratio = nullptr) {
  const double slope0 = law.lame.lambda + 2.0 * law.lame.mu;
  const double in_plane = increment[0] + increment[1];
  double dzz = ratio != nullptr && rotated[2] == 0.0
                   ? *ratio * in_plane
                   : -(rotated[2] + law.lame.lambda * in_plane) / slope0;
  PointHistory trial = history;
  increment[2] = dzz;
  Sym3 stress = law.update(rotated, increment, dt, trial);
  const double scale = std::abs(stress[0]) + std::abs(stress[1]) + std::abs(stress[3]) +
                       std::abs(stress[4]) + std::abs(stress[5]) + 1e-300;
  double previous_dzz = dzz, previous_szz = stress[2], slope = slope0;
  for (int iteration = 0; iteration < 30 && std::abs(stress[2]) > 1e-12 * scale; ++iteration) {
    dzz -= stress[2] / slope;
    trial = history;
    increment[2] = dzz;
    stress = law.update(rotated, increment, dt, trial);
    if (dzz != previous_dzz) {
      const double secant = (stress[2] - previous_szz) / (dzz - previous_dzz);
      if (secant > 0.0) slope = secant;
    }
    previous_dzz = dzz;
    previous_szz = stress[2];
  }
  history = trial;
  if (ratio != nullptr && in_plane != 0.0) *ratio = dzz / in_plane;
  stress[2] = 0.0;
  return stress;
}

}  // namespace abut
