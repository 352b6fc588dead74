// The 4-node shell alone: quadrature, MacNeal-Harder patch tests, rigid motions of a warped
// element, plane stress of a metal point.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "abut/element/shell4.hpp"
#include "abut/element/shell_block.hpp"
#include "abut/material/point_law.hpp"

namespace abut {
namespace {

TEST(GaussLegendre, IntegratesPolynomialsOfDegreeTwoNMinusOne) {
  for (int n : {1, 3, 5, 7, 9}) {
    std::vector<double> x, w;
    gauss_legendre(n, x, w);
    for (int degree = 0; degree <= 2 * n - 1; ++degree) {
      double sum = 0.0;
      for (int i = 0; i < n; ++i) sum += w[i] * std::pow(x[i], degree);
      const double exact = degree % 2 == 1 ? 0.0 : 2.0 / (degree + 1);
      EXPECT_NEAR(sum, exact, 1e-14) << "n " << n << " degree " << degree;
    }
    EXPECT_EQ(x[static_cast<std::size_t>(n / 2)], 0.0);
  }
}

// MacNeal & Harder (1985, Finite Elements in Analysis and Design 1:3), patch test of fig. 2:
// a 0.24 x 0.12 rectangle of five quads around the interior nodes (0.04, 0.02), (0.18, 0.03),
// (0.16, 0.08), (0.08, 0.08); E = 1e6, nu = 0.25, t = 0.001.
struct Patch {
  Nodes nodes;
  std::vector<Quad4> shells;
  Patch() {
    const double xy[8][2] = {{0, 0},       {0.24, 0},    {0.24, 0.12}, {0, 0.12},
                             {0.04, 0.02}, {0.18, 0.03}, {0.16, 0.08}, {0.08, 0.08}};
    for (int i = 0; i < 8; ++i) nodes.add(i + 1, {xy[i][0], xy[i][1], 0.0});
    shells = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}, {4, 5, 6, 7}};
  }
};

struct Motion {
  std::vector<double> vx, vy, vz, wx, wy, wz;
  explicit Motion(std::size_t n) : vx(n), vy(n), vz(n), wx(n), wy(n), wz(n) {}
  ShellNodalState state(const Nodes& nodes) const {
    return {nodes.x.data(), nodes.y.data(), nodes.z.data(), vx.data(), vy.data(),
            vz.data(),      wx.data(),      wy.data(),      wz.data()};
  }
};

const ElasticParams kPatchMaterial{1.0, 1e6, 0.25};

// Sum of the element forces and moments on each node (6 per node).
std::vector<double> assemble(const ShellBlock& block, std::size_t node_count) {
  std::vector<double> sum(6 * node_count, 0.0);
  const auto& f = block.element_forces();
  for (std::size_t e = 0; e < block.size(); ++e)
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 6; ++i)
        sum[6 * static_cast<std::size_t>(block.shells()[e][a]) + i] += f[24 * e + 6 * a + i];
  return sum;
}

// A 2-D tensor (xx, yy, xy) given in the frame of element `e` (shell4.hpp), in global x, y.
std::array<double, 3> to_global(const Patch& patch, std::size_t e, const double t[3]) {
  std::array<Vec3, 4> p;
  for (int a = 0; a < 4; ++a) p[a] = patch.nodes.position(patch.shells[e][a]);
  const Shell4Geometry g = shell4_geometry(p);
  const double c = g.e1.x, s = g.e1.y;  // e1 = (c, s), e2 = (-s, c)
  return {c * c * t[0] + s * s * t[1] - 2 * c * s * t[2],
          s * s * t[0] + c * c * t[1] + 2 * c * s * t[2],
          c * s * (t[0] - t[1]) + (c * c - s * s) * t[2]};
}

TEST(ShellPatch, MembraneStateIsExactAndInteriorNodesAreInEquilibrium) {
  // u = 1e-3 (x + y/2), v = 1e-3 (y + x/2): sigma_x = sigma_y = 1333.33, tau_xy = 400.
  Patch patch;
  ShellBlock block(1, kPatchMaterial, {0.001, 5, 0.05}, patch.shells, patch.nodes);
  Motion motion(patch.nodes.size());
  for (std::size_t i = 0; i < patch.nodes.size(); ++i) {
    motion.vx[i] = 1e-3 * (patch.nodes.x[i] + patch.nodes.y[i] / 2);
    motion.vy[i] = 1e-3 * (patch.nodes.y[i] + patch.nodes.x[i] / 2);
  }
  block.update(motion.state(patch.nodes), 1.0);  // one step of dt = 1 from zero stress
  const double e = 1e6, nu = 0.25, c = e / (1 - nu * nu);
  const double sx = c * (1e-3 + nu * 1e-3), txy = e / (2 * (1 + nu)) * 1e-3;
  for (std::size_t el = 0; el < block.size(); ++el) {
    double local_n[3], local_m[3], q[2];
    block.resultants(el, local_n, local_m, q);
    const auto n = to_global(patch, el, local_n);
    EXPECT_NEAR(local_m[0], 0.0, 1e-15);
    EXPECT_NEAR(n[0] / 0.001, sx, 1e-9 * sx) << "element " << el;
    EXPECT_NEAR(n[1] / 0.001, sx, 1e-9 * sx);
    EXPECT_NEAR(n[2] / 0.001, txy, 1e-9 * sx);
  }
  const std::vector<double> f = assemble(block, patch.nodes.size());
  for (std::size_t node = 4; node < 8; ++node)  // interior: no resultant force or moment
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(f[6 * node + i], 0.0, 1e-12) << "node " << node;
}

TEST(ShellPatch, BendingStateGivesExactMoments) {
  // w = 1e-3 (x^2 + xy + y^2) / 2, theta_x = dw/dy, theta_y = -dw/dx: M_x = M_y = 1.111e-7 and
  // M_xy = 3.333e-8 in magnitude (MacNeal & Harder 1985, table 2).
  Patch patch;
  ShellBlock block(1, kPatchMaterial, {0.001, 5, 0.05}, patch.shells, patch.nodes);
  Motion motion(patch.nodes.size());
  for (std::size_t i = 0; i < patch.nodes.size(); ++i) {
    const double x = patch.nodes.x[i], y = patch.nodes.y[i];
    motion.vz[i] = 1e-3 * (x * x + x * y + y * y) / 2;
    motion.wx[i] = 1e-3 * (y + x / 2);
    motion.wy[i] = -1e-3 * (x + y / 2);
  }
  block.update(motion.state(patch.nodes), 1.0);
  const double d = 1e6 * 1e-9 / (12 * (1 - 0.0625));
  const double mx = d * (1e-3 + 0.25e-3), mxy = d * (1 - 0.25) / 2 * 1e-3;
  EXPECT_NEAR(mx, 1.111e-7, 1e-10);
  EXPECT_NEAR(mxy, 3.333e-8, 1e-11);
  for (std::size_t el = 0; el < block.size(); ++el) {
    double local_n[3], local_m[3], q[2];
    block.resultants(el, local_n, local_m, q);
    const auto m = to_global(patch, el, local_m);
    EXPECT_NEAR(local_n[0], 0.0, 1e-12);
    EXPECT_NEAR(m[0], -mx, 1e-12 * mx) << "element " << el;
    EXPECT_NEAR(m[1], -mx, 1e-12 * mx);
    EXPECT_NEAR(m[2], -mxy, 1e-12 * mx);
  }
}

// Mindlin plate: a uniform transverse shear strain gamma_xz = dw/dx (rotations zero) gives the
// shear force Q_x = k G h gamma with k = 5/6 (Reissner 1945; Mindlin 1951).
TEST(ShellBlock, TransverseShearForceIsFiveSixthsGhGamma) {
  Nodes nodes;
  nodes.add(1, {0.0, 0.0, 0.0});
  nodes.add(2, {0.2, 0.0, 0.0});
  nodes.add(3, {0.2, 0.1, 0.0});
  nodes.add(4, {0.0, 0.1, 0.0});
  const double e = 2e11, nu = 0.3, h = 0.01, gamma = 1e-4;
  ShellBlock block(1, ElasticParams{7800, e, nu}, {h, 5, 0.05}, {{0, 1, 2, 3}}, nodes);
  Motion motion(4);
  for (std::size_t i = 0; i < 4; ++i) motion.vz[i] = gamma * nodes.x[i];
  block.update(motion.state(nodes), 1.0);
  double n[3], m[3], q[2];
  block.resultants(0, n, m, q);
  const double expected = 5.0 / 6.0 * e / (2.0 * (1.0 + nu)) * h * gamma;
  EXPECT_NEAR(q[0], expected, 1e-12 * expected);
  EXPECT_NEAR(q[1], 0.0, 1e-12 * expected);
  // The nodal forces: -Q A b1_a on each node in z, so the two ends carry -/+ Q b / 2 each.
  const auto& f = block.element_forces();
  EXPECT_NEAR(f[2], expected * 0.1 / 2.0, 1e-9 * expected);
  EXPECT_NEAR(f[6 + 2], -expected * 0.1 / 2.0, 1e-9 * expected);
}

TEST(ShellBlock, RigidRotationOfAWarpedElementStrainsNothing) {
  Nodes nodes;
  nodes.add(1, {0.0, 0.0, 0.01});
  nodes.add(2, {1.1, 0.1, -0.02});
  nodes.add(3, {1.0, 0.9, 0.015});
  nodes.add(4, {-0.1, 1.2, -0.01});
  ShellBlock block(1, ElasticParams{7800, 2e11, 0.3}, {0.01, 3, 0.05}, {{0, 1, 2, 3}}, nodes);
  Motion motion(4);
  const Vec3 omega{0.3, -0.7, 0.5}, v0{1.0, 2.0, -3.0};
  for (std::size_t i = 0; i < 4; ++i) {
    const Vec3 v = v0 + cross(omega, nodes.position(i));
    motion.vx[i] = v.x, motion.vy[i] = v.y, motion.vz[i] = v.z;
    motion.wx[i] = omega.x, motion.wy[i] = omega.y, motion.wz[i] = omega.z;
  }
  block.update(motion.state(nodes), 1e-3);
  for (double f : block.element_forces()) EXPECT_NEAR(f, 0.0, 1e-3);  // vs forces ~1e9 * strain
  for (double s : block.point_stress()) EXPECT_NEAR(s, 0.0, 1e-2);    // Pa, vs E ~ 2e11
}

TEST(ShellBlock, ForcesAreSelfEquilibratedOnAWarpedElement) {
  Nodes nodes;
  nodes.add(1, {0.0, 0.0, 0.05});
  nodes.add(2, {1.0, 0.0, -0.05});
  nodes.add(3, {1.2, 1.0, 0.05});
  nodes.add(4, {0.1, 0.8, -0.05});
  ShellBlock block(1, ElasticParams{7800, 2e11, 0.3}, {0.01, 5, 0.05}, {{0, 1, 2, 3}}, nodes);
  Motion motion(4);
  const double v[4][6] = {{0.1, -0.2, 0.3, 1, 2, 0.5},
                          {-0.3, 0.2, 0.1, -1, 0.5, 0.2},
                          {0.2, 0.1, -0.4, 0.3, -2, 1},
                          {0.0, 0.3, 0.2, 2, 1, -1}};
  for (std::size_t i = 0; i < 4; ++i) {
    motion.vx[i] = v[i][0], motion.vy[i] = v[i][1], motion.vz[i] = v[i][2];
    motion.wx[i] = v[i][3], motion.wy[i] = v[i][4], motion.wz[i] = v[i][5];
  }
  block.update(motion.state(nodes), 1e-4);
  const auto& f = block.element_forces();
  Vec3 force, moment;
  double scale = 0.0;
  for (std::size_t a = 0; a < 4; ++a) {
    const Vec3 fa{f[6 * a], f[6 * a + 1], f[6 * a + 2]};
    force += fa;
    moment += cross(nodes.position(a), fa) + Vec3{f[6 * a + 3], f[6 * a + 4], f[6 * a + 5]};
    scale = std::max(scale, norm(fa));
  }
  EXPECT_GT(scale, 1e3);
  EXPECT_NEAR(norm(force), 0.0, 1e-10 * scale);
  EXPECT_NEAR(norm(moment), 0.0, 1e-10 * scale);
}

TEST(PlaneStress, MetalPointKeepsZeroNormalStressOnTheFlowSurface) {
  // Equibiaxial stretch of a perfectly plastic point: sigma_1 = sigma_2 = sigma_y, sigma_3 = 0.
  FunctionTable table;
  MetalParams params;
  params.density = 7800, params.young = 2e11, params.poisson = 0.3;
  params.johnson_cook = true, params.a = 3e8, params.b = 0.0;
  const LameConstants lame{2e11 * 0.3 / (1.3 * 0.4), 2e11 / 2.6};
  const MetalPoint law{lame, FlowStress(params, &table), {}};
  Sym3 stress;
  PointHistory history;
  for (int step = 0; step < 40; ++step) {
    Sym3 increment{{1e-4, 1e-4, 0, 0, 0, 0}};
    stress = plane_stress_update(law, stress, increment, 0.0, history);
  }
  EXPECT_NEAR(stress[0], 3e8, 1e-6 * 3e8);
  EXPECT_NEAR(stress[1], 3e8, 1e-6 * 3e8);
  EXPECT_EQ(stress[2], 0.0);
  // Total strain 4e-3 in each direction, elastic part sigma_y (1 - nu) / E = 1.05e-3; the
  // equivalent plastic strain of equibiaxial flow is 2 x the in-plane plastic strain.
  EXPECT_NEAR(history.plastic_strain, 2.0 * (4e-3 - 3e8 * 0.7 / 2e11), 1e-6);
}

}  // namespace
}  // namespace abut
