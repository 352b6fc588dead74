// SolidBlock with *MAT_MOONEY_RIVLIN: uniaxial stretch against closed forms, energy
// conservation of the elastic part, viscous relaxation, stable step, thread independence.
#include <gtest/gtest.h>
#include <omp.h>

#include <array>
#include <cmath>
#include <cstring>

#include "abut/element/solid_block.hpp"
#include "element_fixtures.hpp"

namespace abut {
namespace {

using test::mat_vec;
using test::Motion;

// Drives a block from the reference configuration to x = F X along F(s) = I + s (F_end - I)
// in `steps` steps of dt and returns the last step's result.
BlockStep deform(SolidBlock& block, Motion& motion, const std::array<double, 9>& f_end, int steps,
                 double dt) {
  block.update(motion.state(), 0.0);
  BlockStep step;
  for (int n = 1; n <= steps; ++n) {
    const double s = static_cast<double>(n) / steps;
    std::array<double, 9> f{};
    for (int i = 0; i < 9; ++i)
      f[i] = (i % 4 == 0 ? 1.0 : 0.0) + s * (f_end[i] - (i % 4 == 0 ? 1.0 : 0.0));
    motion.move([&](const Vec3& x) { return mat_vec(f, x); }, dt);
    step = block.update(motion.state(), dt);
  }
  return step;
}

// Uniaxial stress for our compressible form (mooney_rivlin.hpp: Cauchy = tau/J,
// eps_v = J - 1), F = diag(lambda, t, t), J = lambda t^2, l1 = J^(-2/3) lambda^2,
// l2 = l3 = J^(-2/3) t^2. Derived from the IMPETUS principal stresses:
//   sigma_22 = (1/J)[(2C1/3)(l2 - l1) - (2C2/3)(1/l2 - 1/l1)] + K (J - 1) = 0 fixes t, and
//   sigma_11 = sigma_11 - sigma_22 = (2/J)(l1 - l2)(C1 + C2/(l1 l2)).
// For J -> 1 this is Mooney's (1940, J. Appl. Phys. 11:582) and Treloar's (The Physics of
// Rubber Elasticity, 3rd ed., 1975, eq. 10.9) sigma = 2 (C1 + C2/lambda)(lambda^2 - 1/lambda).
struct Uniaxial {
  double lateral_stretch;
  double stress;
};
Uniaxial uniaxial_closed_form(const MooneyRivlinParams& p, double lambda) {
  const auto lateral_stress = [&](double t) {
    const double j = lambda * t * t, iso = std::pow(j, -2.0 / 3.0);
    const double l1 = iso * lambda * lambda, l2 = iso * t * t;
    return (2 * p.c1 / 3 * (l2 - l1) - 2 * p.c2 / 3 * (1 / l2 - 1 / l1)) / j + p.bulk * (j - 1);
  };
  double lo = 0.3, hi = 1.2;  // lateral_stress(lo) < 0 < lateral_stress(hi)
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (lateral_stress(mid) < 0 ? lo : hi) = mid;
  }
  const double t = 0.5 * (lo + hi);
  const double j = lambda * t * t, iso = std::pow(j, -2.0 / 3.0);
  const double l1 = iso * lambda * lambda, l2 = iso * t * t;
  return {t, 2 / j * (l1 - l2) * (p.c1 + p.c2 / (l1 * l2))};
}

std::vector<double> uniaxial_element_stress(const MooneyRivlinParams& p, double lambda,
                                            double lateral) {
  std::vector<Hex8> hexes;
  const Nodes nodes = test::distorted_hex(hexes);
  SolidBlock block(1, p, hexes, nodes);
  Motion motion(nodes);
  deform(block, motion, {lambda, 0, 0, 0, lateral, 0, 0, 0, lateral}, 20, 1e-5);
  std::vector<double> stress;
  block.stress(stress);
  return stress;
}

TEST(SolidBlockRubber, UniaxialStretchMatchesTheCompressibleClosedForm) {
  const MooneyRivlinParams p{1100.0, 2.0e7, 4.0e5, 1.0e5, {}, {}};  // K/G = 20
  const double lambda = 1.5;
  const Uniaxial ref = uniaxial_closed_form(p, lambda);
  const std::vector<double> s = uniaxial_element_stress(p, lambda, ref.lateral_stretch);
  EXPECT_NEAR(s[0], ref.stress, 1e-9 * ref.stress);
  for (int c = 1; c < 6; ++c) EXPECT_NEAR(s[c], 0.0, 1e-9 * ref.stress) << "component " << c;
}

TEST(SolidBlockRubber, NearlyIncompressibleUniaxialStretchMatchesTreloar) {
  const MooneyRivlinParams p{1100.0, 1.0e9, 4.0e5, 1.0e5, {}, {}};  // K/G = 1000
  const double lambda = 1.5;
  const Uniaxial ref = uniaxial_closed_form(p, lambda);
  const std::vector<double> s = uniaxial_element_stress(p, lambda, ref.lateral_stretch);
  const double treloar = 2 * (p.c1 + p.c2 / lambda) * (lambda * lambda - 1 / lambda);
  EXPECT_NEAR(s[0], treloar, 0.02 * treloar);
  EXPECT_NEAR(ref.lateral_stretch, 1 / std::sqrt(lambda), 1e-3);
}

// The elastic part derives from W = C1 (I1_bar - 3) + C2 (I2_bar - 3) + K/2 (J - 1)^2, so the
// stress work along any path equals W(F_end) V0 (Holzapfel 2000, §6.4-6.5).
TEST(SolidBlockRubber, StressWorkEqualsTheStoredEnergyOfThePotential) {
  const MooneyRivlinParams p{1100.0, 2.0e6, 4.0e5, 1.0e5, {}, {}};  // compressible: J changes
  const std::array<double, 9> f{1.4, 0.2, 0.0, 0.0, 1.1, 0.1, 0.05, 0.0, 0.9};
  std::vector<Hex8> hexes;
  const Nodes nodes = test::distorted_hex(hexes);
  SolidBlock block(1, p, hexes, nodes);
  Motion motion(nodes);
  const BlockStep step = deform(block, motion, f, 2000, 1e-5);

  const double j = f[0] * (f[4] * f[8] - f[5] * f[7]) - f[1] * (f[3] * f[8] - f[5] * f[6]) +
                   f[2] * (f[3] * f[7] - f[4] * f[6]);
  double c[3][3];  // C = F^T F
  for (int r = 0; r < 3; ++r)
    for (int s = 0; s < 3; ++s) c[r][s] = f[r] * f[s] + f[3 + r] * f[3 + s] + f[6 + r] * f[6 + s];
  const double i1 = c[0][0] + c[1][1] + c[2][2];
  double trace_c2 = 0.0;
  for (int r = 0; r < 3; ++r)
    for (int s = 0; s < 3; ++s) trace_c2 += c[r][s] * c[s][r];
  const double i2 = 0.5 * (i1 * i1 - trace_c2);
  const double w = p.c1 * (std::pow(j, -2.0 / 3.0) * i1 - 3) +
                   p.c2 * (std::pow(j, -4.0 / 3.0) * i2 - 3) + 0.5 * p.bulk * (j - 1) * (j - 1);
  // Reference volume of the element (the linear map scales it by J).
  std::vector<double> mass(nodes.size(), 0.0);
  block.add_lumped_mass(mass);
  double v0 = 0.0;
  for (double m : mass) v0 += m / p.density;
  EXPECT_NEAR(step.internal_energy, w * v0, 0.01 * w * v0);
}

// Pure shear at constant true strain rate r, x = (X e^{rt}, Y e^{-rt}, Z): D = diag(r, -r, 0)
// is deviatoric and W = 0. The viscous stress is (2 alpha/beta) int_0^t r e^{(tau-t)/beta} dtau
// = 2 alpha r (1 - e^{-t/beta}) (IMPETUS viscous term, impetus-keywords.md §4) and the Newtonian
// term (beta = 0) is 2 alpha r. The elastic part at F = diag(e^{rt}, e^{-rt}, 1) (J = 1) is the
// IMPETUS principal stress with l = (e^{2rt}, e^{-2rt}, 1).
TEST(SolidBlockRubber, ViscousStressFollowsTheRelaxationClosedForm) {
  MooneyRivlinParams p{1100.0, 1.0e8, 1.0e5, 2.0e4, {}, {}};
  p.alpha = {1.0e4, 0.0, 50.0, 0.0};  // second term off
  p.beta = {1.0e-3, 0.0, 0.0, 0.0};   // third term Newtonian
  const double rate = 1.0, dt = 1e-6;
  const int steps = 3000;  // t = 3 beta
  std::vector<Hex8> hexes;
  const Nodes nodes = test::distorted_hex(hexes);
  SolidBlock block(1, p, hexes, nodes);
  Motion motion(nodes);
  block.update(motion.state(), 0.0);
  for (int n = 1; n <= steps; ++n) {
    const double t = n * dt;
    motion.move(
        [&](const Vec3& x) {
          return Vec3{x.x * std::exp(rate * t), x.y * std::exp(-rate * t), x.z};
        },
        dt);
    block.update(motion.state(), dt);
  }
  const double t = steps * dt;
  const double l1 = std::exp(2 * rate * t), l2 = std::exp(-2 * rate * t), l3 = 1.0;
  const double elastic_11 =
      2 * p.c1 / 3 * (2 * l1 - l2 - l3) - 2 * p.c2 / 3 * (2 / l1 - 1 / l2 - 1 / l3);
  const double elastic_22 =
      2 * p.c1 / 3 * (2 * l2 - l3 - l1) - 2 * p.c2 / 3 * (2 / l2 - 1 / l3 - 1 / l1);
  const double viscous =
      2 * p.alpha[0] * rate * (1 - std::exp(-t / p.beta[0])) + 2 * p.alpha[2] * rate;
  std::vector<double> s;
  block.stress(s);
  EXPECT_NEAR(s[0], elastic_11 + viscous, 1e-6 * viscous);
  EXPECT_NEAR(s[1], elastic_22 - viscous, 1e-6 * viscous);
  EXPECT_NEAR(s[3], 0.0, 1e-6 * viscous);
}

// c = sqrt((K + 4/3 G)/rho) with the initial shear modulus G = 2 (C1 + C2) of Mooney-Rivlin
// (Treloar 1975: small-strain shear modulus 2 (C1 + C2)); cube of side h: L = h.
TEST(SolidBlockRubber, StableStepUsesTheInitialModuli) {
  const MooneyRivlinParams p{1100.0, 2.0e8, 4.0e5, 1.0e5, {}, {}};
  std::vector<Hex8> hexes;
  const double h = 0.02;
  const Nodes nodes = test::box_grid(1, 1, 1, {h, h, h}, 0.0, hexes);
  SolidBlock block(1, p, hexes, nodes);
  // Cube: dt = h / sqrt((3 lambda + 2 mu) / rho) with the initial moduli mu = 2 (C1 + C2),
  // lambda = K - 2 mu / 3 (include/abut/element/stable_step.hpp), i.e. h / sqrt(3 K / rho).
  EXPECT_NEAR(block.initial_stable_step(nodes), h / std::sqrt(3.0 * p.bulk / p.density), 1e-12 * h);
}

TEST(SolidBlockRubber, ResultsAreBitwiseIdenticalForOneAndTwoThreads) {
  MooneyRivlinParams p{1100.0, 1.0e8, 1.0e5, 2.0e4, {}, {}};
  p.alpha = {1.0e2, 5.0, 0.0, 0.0};
  p.beta = {1.0e-4, 0.0, 0.0, 0.0};
  std::vector<Hex8> hexes;
  const Nodes nodes = test::box_grid(6, 6, 6, {1.0, 1.0, 1.0}, 0.2, hexes);
  const auto run = [&](int threads, std::vector<double>& forces) {
    const int saved = omp_get_max_threads();
    omp_set_num_threads(threads);
    SolidBlock block(1, p, hexes, nodes);
    Motion motion(nodes);
    block.update(motion.state(), 0.0);
    BlockStep step;
    for (int n = 1; n <= 3; ++n) {
      motion.move(
          [&](const Vec3& x) {
            const double s = 1e-2 * n;
            return Vec3{x.x + s * std::sin(7 * x.y), x.y + s * x.x * x.z, x.z - s * x.y};
          },
          1e-5);
      step = block.update(motion.state(), 1e-5);
    }
    forces = block.element_forces();
    omp_set_num_threads(saved);
    return step;
  };
  std::vector<double> f1, f2;
  const BlockStep a = run(1, f1);
  const BlockStep b = run(2, f2);
  ASSERT_EQ(f1.size(), f2.size());
  EXPECT_EQ(std::memcmp(f1.data(), f2.data(), f1.size() * sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(&a, &b, sizeof(BlockStep)), 0);
}

}  // namespace
}  // namespace abut
