// SolidBlock with *MAT_ELASTIC: patch test, rigid rotation, energy, hourglass, stable step,
// thread-count independence, instability reporting.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <numbers>
#include <optional>

#include "abut/core/error.hpp"
#include "abut/element/hex8.hpp"
#include "abut/element/solid_block.hpp"
#include "element_fixtures.hpp"

namespace abut {
namespace {

using test::mat_vec;
using test::Motion;

const ElasticParams kSteel{7800.0, 210.0e9, 0.3};

// Lame constants from E and nu (Timoshenko and Goodier, Theory of Elasticity, 1970, §6).
double lame_lambda(const ElasticParams& m) {
  return m.young * m.poisson / ((1 + m.poisson) * (1 - 2 * m.poisson));
}
double lame_mu(const ElasticParams& m) { return m.young / (2 * (1 + m.poisson)); }

std::array<double, 9> inverse(const std::array<double, 9>& m) {
  const double det = m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) +
                     m[2] * (m[3] * m[7] - m[4] * m[6]);
  return {(m[4] * m[8] - m[5] * m[7]) / det, (m[2] * m[7] - m[1] * m[8]) / det,
          (m[1] * m[5] - m[2] * m[4]) / det, (m[5] * m[6] - m[3] * m[8]) / det,
          (m[0] * m[8] - m[2] * m[6]) / det, (m[2] * m[3] - m[0] * m[5]) / det,
          (m[3] * m[7] - m[4] * m[6]) / det, (m[1] * m[6] - m[0] * m[7]) / det,
          (m[0] * m[4] - m[1] * m[3]) / det};
}

std::array<double, 9> multiply(const std::array<double, 9>& a, const std::array<double, 9>& b) {
  std::array<double, 9> c{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) c[3 * i + j] += a[3 * i + k] * b[3 * k + j];
  return c;
}

// Rotation by angle about a unit axis (Rodrigues' formula).
std::array<double, 9> rotation(Vec3 axis, double angle) {
  axis = normalized(axis);
  const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
  return {t * axis.x * axis.x + c,          t * axis.x * axis.y - s * axis.z,
          t * axis.x * axis.z + s * axis.y, t * axis.x * axis.y + s * axis.z,
          t * axis.y * axis.y + c,          t * axis.y * axis.z - s * axis.x,
          t * axis.x * axis.z - s * axis.y, t * axis.y * axis.z + s * axis.x,
          t * axis.z * axis.z + c};
}

// Patch test (Irons; Taylor, Simo, Zienkiewicz and Chan 1986, IJNME 22:39): a linear
// displacement field u = A X + c imposed in one step gives in every element, distorted or not,
// the strain increment of the continuum field. With the mid-step configuration
// x_mid = X + (A X + c)/2 the field's velocity gradient times dt is G = A (I + A/2)^-1, so the
// stress must be Hooke's law of sym(G); interior nodes must be in equilibrium and the
// element forces must be the constant-stress forces alone (no hourglass part).
void run_patch_test(const Nodes& nodes, const std::vector<Hex8>& hexes,
                    std::optional<std::size_t> interior_node) {
  const std::array<double, 9> a{1.2e-3, -0.4e-3, 0.7e-3, 0.9e-3, -0.8e-3,
                                0.3e-3, -0.5e-3, 0.6e-3, 1.1e-3};
  const Vec3 shift{0.01, -0.02, 0.005};
  const double dt = 1e-6;
  SolidBlock block(1, kSteel, hexes, nodes);
  Motion motion(nodes);
  block.update(motion.state(), 0.0);
  motion.move([&](const Vec3& x) { return x + mat_vec(a, x) + shift; }, dt);
  const BlockStep step = block.update(motion.state(), dt);

  std::array<double, 9> half{};
  for (int i = 0; i < 9; ++i) half[i] = (i % 4 == 0 ? 1.0 : 0.0) + 0.5 * a[i];
  const std::array<double, 9> g = multiply(a, inverse(half));
  const double eps[6] = {
      g[0], g[4], g[8], 0.5 * (g[1] + g[3]), 0.5 * (g[5] + g[7]), 0.5 * (g[6] + g[2])};
  const double lambda = lame_lambda(kSteel), mu = lame_mu(kSteel);
  const double tr = eps[0] + eps[1] + eps[2];
  double expected[6];
  for (int c = 0; c < 6; ++c) expected[c] = (c < 3 ? lambda * tr : 0.0) + 2 * mu * eps[c];
  const double scale = std::abs(expected[0]);

  std::vector<double> stress;
  block.stress(stress);
  for (std::size_t e = 0; e < hexes.size(); ++e) {
    for (int c = 0; c < 6; ++c) EXPECT_NEAR(stress[6 * e + c], expected[c], 1e-10 * scale);
  }

  // Element forces are exactly -sigma b_a at x^1 (b from the geometry kernel, itself checked
  // against Gauss quadrature in test_hex8.cpp): the hourglass part is zero.
  const std::vector<double>& forces = block.element_forces();
  std::vector<double> node_sum(3 * nodes.size(), 0.0);
  double force_scale = 0.0;
  for (std::size_t e = 0; e < hexes.size(); ++e) {
    Hex8Coords x;
    for (int n = 0; n < 8; ++n) {
      const Vec3 p = motion.position(hexes[e][n]);
      x.x[n] = p.x;
      x.y[n] = p.y;
      x.z[n] = p.z;
    }
    Hex8Gradient geo;
    hex8_gradient(x, geo);
    for (int n = 0; n < 8; ++n) {
      const double f[3] = {
          -(expected[0] * geo.bx[n] + expected[3] * geo.by[n] + expected[5] * geo.bz[n]),
          -(expected[3] * geo.bx[n] + expected[1] * geo.by[n] + expected[4] * geo.bz[n]),
          -(expected[5] * geo.bx[n] + expected[4] * geo.by[n] + expected[2] * geo.bz[n])};
      for (int i = 0; i < 3; ++i) {
        force_scale = std::max(force_scale, std::abs(f[i]));
        EXPECT_NEAR(forces[24 * e + 3 * n + i], f[i],
                    1e-10 * scale * std::cbrt(geo.volume) * std::cbrt(geo.volume));
        node_sum[3 * hexes[e][n] + i] += forces[24 * e + 3 * n + i];
      }
    }
  }
  for (int i = 0; interior_node && i < 3; ++i) {
    EXPECT_NEAR(node_sum[3 * *interior_node + i], 0.0, 1e-10 * force_scale);
  }
  EXPECT_LT(std::abs(step.hourglass_energy), 1e-12 * step.internal_energy);
}

TEST(SolidBlockElastic, PatchTestOnADistortedSingleHex) {
  std::vector<Hex8> hexes;
  const Nodes nodes = test::distorted_hex(hexes);
  run_patch_test(nodes, hexes, std::nullopt);  // one element: no interior node
}

TEST(SolidBlockElastic, PatchTestOnADistorted2x2x2Patch) {
  std::vector<Hex8> hexes;
  const Nodes nodes = test::box_grid(2, 2, 2, {1.0, 1.0, 1.0}, 0.15, hexes);
  run_patch_test(nodes, hexes, 13);  // node 13 is the centre of the 3x3x3 grid
}

// Rigid rotation of a stress-free element by 90 degrees in 2000 steps: an objective update
// gives no stress and no strain energy (issue 3 verification list; Belytschko, Liu and Moran,
// Nonlinear Finite Elements, 2000, §5.6 on objectivity).
TEST(SolidBlockElastic, RigidRotationLeavesAStressFreeElementStressFree) {
  std::vector<Hex8> hexes;
  const Nodes nodes = test::distorted_hex(hexes);
  SolidBlock block(1, kSteel, hexes, nodes);
  Motion motion(nodes);
  block.update(motion.state(), 0.0);
  const Vec3 centre{0.3, -0.2, 0.5};
  const int steps = 2000;
  const double angle = 0.5 * std::numbers::pi, dt = 1e-6;
  BlockStep step;
  for (int n = 1; n <= steps; ++n) {
    const auto r = rotation({1.0, 2.0, 3.0}, angle * n / steps);
    motion.move([&](const Vec3& x) { return centre + mat_vec(r, x - centre); }, dt);
    step = block.update(motion.state(), dt);
  }
  std::vector<double> stress;
  block.stress(stress);
  for (double s : stress) EXPECT_LT(std::abs(s), 1e-6 * kSteel.young * angle);
  // Energy scale: what a strain of 1e-12 would store in the element.
  EXPECT_LT(std::abs(step.internal_energy), 0.5 * kSteel.young * 1e-24);
  EXPECT_LT(std::abs(step.hourglass_energy), 0.5 * kSteel.young * 1e-24);
}

// A pre-stressed element rotated rigidly by 90 degrees about z carries its stress along:
// sigma' = R sigma R^T, so sigma_xx and sigma_yy swap (objectivity).
TEST(SolidBlockElastic, RigidRotationRotatesAnExistingStress) {
  std::vector<Hex8> hexes;
  const Nodes nodes = test::distorted_hex(hexes);
  SolidBlock block(1, kSteel, hexes, nodes);
  Motion motion(nodes);
  block.update(motion.state(), 0.0);
  const double dt = 1e-6, strain = 1e-3;
  const auto stretch = [&](const Vec3& x, double t) {
    return Vec3{x.x * (1 + strain * t), x.y, x.z};
  };
  for (int n = 1; n <= 100; ++n) {
    motion.move([&](const Vec3& x) { return stretch(x, n / 100.0); }, dt);
    block.update(motion.state(), dt);
  }
  std::vector<double> before;
  block.stress(before);
  const int steps = 1000;
  for (int n = 1; n <= steps; ++n) {
    const auto r = rotation({0.0, 0.0, 1.0}, 0.5 * std::numbers::pi * n / steps);
    motion.move([&](const Vec3& x) { return mat_vec(r, stretch(x, 1.0)); }, dt);
    block.update(motion.state(), dt);
  }
  std::vector<double> after;
  block.stress(after);
  const double tol = 1e-10 * std::abs(before[0]);
  EXPECT_NEAR(after[0], before[1], tol);
  EXPECT_NEAR(after[1], before[0], tol);
  EXPECT_NEAR(after[2], before[2], tol);
  EXPECT_NEAR(after[3], -before[3], tol);
}

// Slow uniaxial-strain loading to eps = 1e-3: the accumulated stress work equals the strain
// energy 0.5 sigma:eps V0 = 0.5 (lambda + 2 mu) eps^2 V0 (Timoshenko and Goodier §6.1) to 1%.
TEST(SolidBlockElastic, InternalEnergyEqualsStrainEnergyUnderSlowLoading) {
  std::vector<Hex8> hexes;
  const Nodes nodes = test::box_grid(2, 1, 1, {2.0, 1.0, 1.0}, 0.1, hexes);
  SolidBlock block(1, kSteel, hexes, nodes);
  Motion motion(nodes);
  block.update(motion.state(), 0.0);
  const double strain = 1e-3, dt = 1e-6;
  const int steps = 500;
  BlockStep step;
  for (int n = 1; n <= steps; ++n) {
    const double e = strain * n / steps;
    motion.move([&](const Vec3& x) { return Vec3{x.x * (1 + e), x.y, x.z}; }, dt);
    step = block.update(motion.state(), dt);
  }
  double v0 = 0.0;
  for (const Hex8& h : hexes) {
    Hex8Coords x;
    for (int a = 0; a < 8; ++a) {
      x.x[a] = nodes.x[h[a]];
      x.y[a] = nodes.y[h[a]];
      x.z[a] = nodes.z[h[a]];
    }
    Hex8Gradient g;
    hex8_gradient(x, g);
    v0 += g.volume;
  }
  const double expected = 0.5 * (lame_lambda(kSteel) + 2 * lame_mu(kSteel)) * strain * strain * v0;
  EXPECT_NEAR(step.internal_energy, expected, 0.01 * expected);
  EXPECT_LT(std::abs(step.hourglass_energy), 1e-10 * expected);
}

// A pure hourglass mode u_x = d h1(a) on a cube of side h: no mean strain, so the only
// resistance is the hourglass force. With b_a = (h^2/4)(xi_a, eta_a, zeta_a) for the cube,
// b:b / V = 1.5 h and the documented stiffness k = c 2 G b:b/V = 3 c G h; the generalized
// displacement is q = sum_a u_a gamma_a = d, the nodal force -k d h1(a)/8 and the work k d^2/2.
TEST(SolidBlockElastic, HourglassModeIsResistedWithTheDocumentedStiffness) {
  std::vector<Hex8> hexes;
  const double side = 0.01;
  const Nodes nodes = test::box_grid(1, 1, 1, {side, side, side}, 0.0, hexes);
  SolidBlock block(1, kSteel, hexes, nodes);
  Motion motion(nodes);
  block.update(motion.state(), 0.0);
  const double d = 1e-7 * side, dt = 1e-7;
  const int steps = 50;
  BlockStep step;
  for (int n = 1; n <= steps; ++n) {
    const double amplitude = d * n / steps;
    motion.move(
        [&](const Vec3& x) {
          const double eta = x.y > 0.5 * side ? 1.0 : -1.0, zeta = x.z > 0.5 * side ? 1.0 : -1.0;
          return Vec3{x.x + amplitude * eta * zeta, x.y, x.z};
        },
        dt);
    step = block.update(motion.state(), dt);
  }
  const double k = 3.0 * SolidBlock::kDefaultHourglassCoefficient * lame_mu(kSteel) * side;
  EXPECT_NEAR(step.hourglass_energy, 0.5 * k * d * d, 1e-6 * 0.5 * k * d * d);
  const std::vector<double>& f = block.element_forces();
  for (int a = 0; a < 8; ++a) {
    EXPECT_NEAR(f[3 * a], -k * d * kHex8Hourglass[0][a] / 8.0, 1e-6 * k * d / 8.0);
  }
}

// Stable step of a brick 0.5 x 2 x 3: L = V / A_max = 0.5 (LS-DYNA convention) and the
// dilatational wave speed c = sqrt(E (1 - nu) / ((1 + nu)(1 - 2 nu) rho)) (Kolsky, Stress Waves
// in Solids, 1963, eq. 1.16).
// Critical step of a one-point hex with lumped mass (include/abut/element/stable_step.hpp):
// 2/omega_max with omega_max^2 = 8 (lambda tr G + 2 mu lambda_max G) / (rho V^2). For an
// a x b x c box, b_a = (+-bc, +-ac, +-ab)/4, so G = diag((bc)^2, (ac)^2, (ab)^2) / 2.
TEST(SolidBlockElastic, StableStepIsTheOnePointHexCriticalStep) {
  std::vector<Hex8> hexes;
  const Nodes nodes = test::box_grid(1, 1, 1, {0.5, 2.0, 3.0}, 0.0, hexes);
  SolidBlock block(1, kSteel, hexes, nodes);
  const double nu = kSteel.poisson;
  const double mu = kSteel.young / (2 * (1 + nu));
  const double lambda = kSteel.young * nu / ((1 + nu) * (1 - 2 * nu));
  const double volume = 3.0, trace = (36.0 + 2.25 + 1.0) / 2.0, largest = 36.0 / 2.0;
  const double omega =
      std::sqrt(8.0 * (lambda * trace + 2.0 * mu * largest) / (kSteel.density * volume * volume));
  EXPECT_NEAR(block.initial_stable_step(nodes), 2.0 / omega, 1e-12 * 2.0 / omega);
  Motion motion(nodes);
  EXPECT_NEAR(block.update(motion.state(), 0.0).stable_step, 2.0 / omega, 1e-12 * 2.0 / omega);
  std::vector<double> mass(nodes.size(), 0.0);
  block.add_lumped_mass(mass);
  for (double m : mass) EXPECT_NEAR(m, kSteel.density * 3.0 / 8.0, 1e-12);
}

// For a cube the bound is attained by the checkerboard dilatation mode: dt = h / sqrt(3K/rho),
// the 3D counterpart of the 1D h/c (cf. the CFL limit c dt / h <= 1/sqrt(3) of 3D acoustics).
TEST(SolidBlockElastic, StableStepOfACubeIsHOverRootThreeKOverRho) {
  std::vector<Hex8> hexes;
  const double h = 0.01;
  const Nodes nodes = test::box_grid(1, 1, 1, {h, h, h}, 0.0, hexes);
  SolidBlock block(1, kSteel, hexes, nodes);
  const double bulk = kSteel.young / (3 * (1 - 2 * kSteel.poisson));
  EXPECT_NEAR(block.initial_stable_step(nodes), h / std::sqrt(3 * bulk / kSteel.density),
              1e-12 * h);
}

// Bitwise identical forces, stresses and energies with 1 and 2 threads.
TEST(SolidBlockElastic, ResultsAreBitwiseIdenticalForOneAndTwoThreads) {
  std::vector<Hex8> hexes;
  const Nodes nodes = test::box_grid(10, 10, 10, {1.0, 1.0, 1.0}, 0.2, hexes);
  const auto run = [&](int threads, std::vector<double>& forces, std::vector<double>& stress) {
    const int saved = omp_get_max_threads();
    omp_set_num_threads(threads);
    SolidBlock block(1, kSteel, hexes, nodes);
    Motion motion(nodes);
    block.update(motion.state(), 0.0);
    BlockStep step;
    for (int n = 1; n <= 3; ++n) {
      motion.move(
          [&](const Vec3& x) {
            const double s = 1e-4 * n;
            return Vec3{x.x + s * std::sin(7 * x.y + 3 * x.z), x.y + s * std::cos(5 * x.x * x.z),
                        x.z + s * x.x * x.y};
          },
          1e-6);
      step = block.update(motion.state(), 1e-6);
    }
    forces = block.element_forces();
    block.stress(stress);
    omp_set_num_threads(saved);
    return step;
  };
  std::vector<double> f1, s1, f2, s2;
  const BlockStep a = run(1, f1, s1);
  const BlockStep b = run(2, f2, s2);
  ASSERT_EQ(f1.size(), f2.size());
  EXPECT_EQ(std::memcmp(f1.data(), f2.data(), f1.size() * sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(s1.data(), s2.data(), s1.size() * sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(&a, &b, sizeof(BlockStep)), 0);
  EXPECT_GT(a.internal_energy, 0.0);
  EXPECT_GT(a.hourglass_energy, 0.0);  // the field is not linear: hourglass modes are active
}

// The kernel updates elements in batches of kLanes (solid_block_kernel.cpp): an element's forces,
// stress and step are bitwise the same whichever batch and lane it takes. Here the elements of a
// distorted 3 x 2 x 1 grid (6: one full batch and a part-filled one) are listed in a rotated order.
TEST(SolidBlockElastic, ResultsDoNotDependOnTheElementsBatch) {
  std::vector<Hex8> hexes;
  const Nodes nodes = test::box_grid(3, 2, 1, {1.0, 1.0, 1.0}, 0.2, hexes);
  const auto run = [&](const std::vector<Hex8>& order, std::vector<double>& forces,
                       std::vector<double>& stress) {
    SolidBlock block(1, kSteel, order, nodes);
    Motion motion(nodes);
    block.update(motion.state(), 0.0);
    motion.move(
        [](const Vec3& x) {
          return Vec3{x.x + 1e-4 * std::sin(7 * x.y), x.y, x.z - 1e-4 * x.x * x.y};
        },
        1e-6);
    const BlockStep step = block.update(motion.state(), 1e-6);
    forces = block.element_forces();
    block.stress(stress);
    return step;
  };
  std::vector<Hex8> rotated(hexes.begin() + 3, hexes.end());
  rotated.insert(rotated.end(), hexes.begin(), hexes.begin() + 3);
  std::vector<double> f1, s1, f2, s2;
  const BlockStep a = run(hexes, f1, s1);
  const BlockStep b = run(rotated, f2, s2);
  const std::size_t n = hexes.size();
  for (std::size_t e = 0; e < n; ++e) {
    const std::size_t r = (e + n - 3) % n;  // element e of hexes is element r of rotated
    EXPECT_EQ(std::memcmp(&f1[24 * e], &f2[24 * r], 24 * sizeof(double)), 0) << e;
    EXPECT_EQ(std::memcmp(&s1[6 * e], &s2[6 * r], 6 * sizeof(double)), 0) << e;
  }
  EXPECT_EQ(a.stable_step, b.stable_step);
  EXPECT_GT(a.internal_energy, 0.0);
}

TEST(SolidBlockElastic, InvertedElementThrowsInstabilityErrorNamingElementAndPart) {
  std::vector<Hex8> hexes;
  const Nodes nodes = test::box_grid(1, 1, 1, {1.0, 1.0, 1.0}, 0.0, hexes);
  SolidBlock block(7, kSteel, hexes, nodes);
  block.set_element_ids({42});
  Motion motion(nodes);
  block.update(motion.state(), 0.0);
  // Push the top face through the bottom one.
  motion.move([](const Vec3& x) { return Vec3{x.x, x.y, -x.z}; }, 1e-6);
  try {
    block.update(motion.state(), 1e-6);
    FAIL() << "expected InstabilityError";
  } catch (const InstabilityError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("part 7"), std::string::npos) << what;
    EXPECT_NE(what.find("element 42"), std::string::npos) << what;
  }
}

TEST(SolidBlockElastic, RejectsRigidMaterialAndInvertedInput) {
  std::vector<Hex8> hexes;
  const Nodes nodes = test::box_grid(1, 1, 1, {1.0, 1.0, 1.0}, 0.0, hexes);
  EXPECT_THROW(SolidBlock(1, RigidParams{7800.0}, hexes, nodes), InputError);
  EXPECT_THROW(SolidBlock(1, ElasticParams{7800.0, 210e9, 0.5}, hexes, nodes), InputError);
  std::vector<Hex8> flipped = {Hex8{4, 5, 6, 7, 0, 1, 2, 3}};
  EXPECT_THROW(SolidBlock(1, kSteel, flipped, nodes), InputError);
}

}  // namespace
}  // namespace abut
