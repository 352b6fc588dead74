#pragma once
// Friction coefficients that depend on the contact pressure p and the sliding speed V: the
// Radioss /INTER/TYPE25 laws (seed 004, comment 7; decoded in seeds/README.md). Units as in the
// seed's table: C1..C6 carry the units that make mu dimensionless in the deck's unit system.
#include <array>
#include <cmath>
#include <variant>

namespace abut {

// Ifric = 1, generalised viscous: mu = Fric + C1 p + C2 V + C3 p V + C4 p^2 + C5 V^2.
struct ViscousFriction {
  double fric = 0.0;
  std::array<double, 6> c{};
  double mu(double p, double v) const {
    return fric + c[0] * p + c[1] * v + c[2] * p * v + c[3] * p * p + c[4] * v * v;
  }
  double dmu_dp(double p, double v) const { return c[0] + c[2] * v + 2.0 * c[3] * p; }
  double dmu_dv(double p, double v) const { return c[1] + c[2] * p + 2.0 * c[4] * v; }
};

// Ifric = 2, modified Darmstad: mu = Fric + C1 exp(C2 V) p^2 + C3 exp(C4 V) p + C5 exp(C6 V).
struct DarmstadFriction {
  double fric = 0.0;
  std::array<double, 6> c{};
  double mu(double p, double v) const {
    return fric + c[0] * std::exp(c[1] * v) * p * p + c[2] * std::exp(c[3] * v) * p +
           c[4] * std::exp(c[5] * v);
  }
  double dmu_dp(double p, double v) const {
    return 2.0 * c[0] * std::exp(c[1] * v) * p + c[2] * std::exp(c[3] * v);
  }
  double dmu_dv(double p, double v) const {
    return c[0] * c[1] * std::exp(c[1] * v) * p * p + c[2] * c[3] * std::exp(c[3] * v) * p +
           c[4] * c[5] * std::exp(c[5] * v);
  }
};

// Ifric = 3, Renard: C1 = mu_s, C2 = mu_d, C3 = mu_max, C4 = mu_min, C5 = Vcr1, C6 = Vcr2.
// Rises from mu_s to mu_max on [0, Vcr1], falls to mu_min on [Vcr1, Vcr2] (smooth step), then
// tends to mu_d from below.
struct RenardFriction {
  std::array<double, 6> c{};
  double mu(double, double v) const {
    const double mu_s = c[0], mu_d = c[1], mu_max = c[2], mu_min = c[3], v1 = c[4], v2 = c[5];
    if (v <= v1) {
      const double r = v / v1;
      return mu_s + (mu_max - mu_s) * r * (2.0 - r);
    }
    if (v <= v2) {
      const double s = (v - v1) / (v2 - v1);
      return mu_max - (mu_max - mu_min) * s * s * (3.0 - 2.0 * s);
    }
    return mu_d - 1.0 / (1.0 / (mu_d - mu_min) + (v - v2) * (v - v2));
  }
  double dmu_dp(double, double) const { return 0.0; }
  double dmu_dv(double, double v) const {
    const double mu_d = c[1], mu_max = c[2], mu_min = c[3], v1 = c[4], v2 = c[5];
    if (v <= v1) return (mu_max - c[0]) * (2.0 - 2.0 * v / v1) / v1;
    if (v <= v2) {
      const double s = (v - v1) / (v2 - v1);
      return -(mu_max - mu_min) * 6.0 * s * (1.0 - s) / (v2 - v1);
    }
    const double q = 1.0 / (mu_d - mu_min) + (v - v2) * (v - v2);
    return 2.0 * (v - v2) / (q * q);
  }
};

}  // namespace abut
