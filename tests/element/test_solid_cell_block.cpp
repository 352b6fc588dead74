// The explicit block of solid cells (element/solid_cell_block.hpp) and what it is built from:
// the HRZ lumped mass (lumped_mass.hpp), the element frequency bound of its stable step
// (element_frequency.hpp), the constant-strain patch test of its update and the stable step of
// an assembled mesh.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "abut/element/element_frequency.hpp"
#include "abut/element/lumped_mass.hpp"
#include "abut/element/solid_cell_block.hpp"
#include "abut/element/solid_full.hpp"
#include "abut/material/elastic.hpp"
#include "abut/material/mooney_rivlin.hpp"
#include "cell_grid.hpp"
#include "dense_checks.hpp"

namespace abut {
namespace {

constexpr CellType kTypes[] = {CellType::hex8,   CellType::hex20, CellType::tet4, CellType::tet10,
                               CellType::wedge6, CellType::hex27, CellType::hex64};
constexpr double kE = 210000.0, kNu = 0.3, kRho = 7.8e-9;  // N, mm, s

// The cells of a grid moved off regular (fixed seed), as a block's connectivity.
test::CellGrid moved_grid(CellType type, int nx, int ny, int nz) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> shift(-0.15, 0.15);
  return test::cell_grid(type, nx, ny, nz, {2.0 * nx, 1.5 * ny, 1.0 * nz},
                         [&](int i, int j, int k, Vec3 p) {
                           if (i > 0 && i < nx) p.x += shift(random);
                           if (j > 0 && j < ny) p.y += shift(random);
                           if (k > 0 && k < nz) p.z += shift(random);
                           return p;
                         });
}

std::vector<std::int32_t> connectivity(const test::CellGrid& g) {
  std::vector<std::int32_t> c;
  for (const auto& cell : g.cells) c.insert(c.end(), cell.begin(), cell.end());
  return c;
}

std::vector<double> coordinates(const test::CellGrid& g, std::size_t cell) {
  std::vector<double> X;
  for (const std::int32_t a : g.cells[cell]) {
    X.push_back(g.nodes.x[a]);
    X.push_back(g.nodes.y[a]);
    X.push_back(g.nodes.z[a]);
  }
  return X;
}

// The largest eigenvalue of a dense symmetric matrix by cyclic Jacobi rotations
// (hex8_fixtures.hpp): an independent check of the Householder reduction and bisection.
double largest_eigenvalue(const std::vector<double>& a, std::size_t n) {
  return test::jacobi_eigenvalues(a, static_cast<int>(n)).back();
}

// ---- Lumped mass -----------------------------------------------------------------------------

TEST(LumpedMass, HrzSharesOfUndistortedCells) {
  // References: the integrals of N_a^2 by hand (lumped_mass.hpp). tet10: corners 1/70 V,
  // midsides 8/105 V, so shares 1/36 and 4/27; hex20 on [-1,1]^3: corners 28/135, midsides
  // 64/135 of the volume 8, so shares 7/248 and 2/31; the linear cells: equal shares.
  struct Case {
    CellType type;
    double corner, midside;
  };
  const Case cases[] = {{CellType::tet10, 1.0 / 36, 4.0 / 27},
                        {CellType::hex20, 7.0 / 248, 2.0 / 31},
                        {CellType::tet4, 0.25, 0.0},
                        {CellType::hex8, 0.125, 0.0},
                        {CellType::wedge6, 1.0 / 6, 0.0}};
  for (const Case& c : cases) {
    SCOPED_TRACE(std::string(topology(c.type).name));
    const CellTopology& t = topology(c.type);
    std::vector<double> X;  // the reference cell scaled by 2, 3, 5 and shifted
    for (const auto& xi : t.natural) {
      X.push_back(2.0 * xi[0] + 1.0);
      X.push_back(3.0 * xi[1] - 2.0);
      X.push_back(5.0 * xi[2] + 0.5);
    }
    std::vector<double> shares(static_cast<std::size_t>(t.nodes));
    const double volume = lumped_volume_shares(c.type, X, shares);
    for (int a = 0; a < t.nodes; ++a)
      EXPECT_NEAR(shares[a] / volume, a < t.corners ? c.corner : c.midside, 1e-14) << "node " << a;
  }
}

// The Lagrange hexahedra: N_a^2 = l_i^2 l_j^2 l_k^2, so the HRZ shares are the products of the
// 1-D shares int l_m^2 / sum: order 2 (nodes -1, 0, 1) 4/15, 16/15, 4/15 of 24/15: 1/6, 2/3, 1/6;
// order 3 (-1, -1/3, 1/3, 1) 16/105, 27/35, 27/35, 16/105: 8/97, 81/194, 81/194, 8/97 (the
// polynomials integrated by hand in fractions).
TEST(LumpedMass, HrzSharesOfLagrangeHexahedra) {
  const std::vector<double> quadratic = {1.0 / 6, 2.0 / 3, 1.0 / 6},
                            cubic = {8.0 / 97, 81.0 / 194, 81.0 / 194, 8.0 / 97};
  for (const auto& [type, w] : {std::pair{CellType::hex27, quadratic}, {CellType::hex64, cubic}}) {
    SCOPED_TRACE(std::string(topology(type).name));
    const CellTopology& t = topology(type);
    std::vector<double> X;
    for (const auto& xi : t.natural) X.insert(X.end(), {2.0 * xi[0], 3.0 * xi[1], 5.0 * xi[2]});
    std::vector<double> shares(static_cast<std::size_t>(t.nodes));
    const double volume = lumped_volume_shares(type, X, shares);
    for (int a = 0; a < t.nodes; ++a) {
      double expected = 1.0;
      for (const double x : t.natural[static_cast<std::size_t>(a)])
        expected *= w[static_cast<std::size_t>(std::lround(0.5 * (x + 1) * t.order))];
      EXPECT_NEAR(shares[a] / volume, expected, 1e-14) << "node " << a;
    }
  }
}

TEST(LumpedMass, PositiveAndWholeOnDistortedCells) {
  for (const CellType type : kTypes) {
    SCOPED_TRACE(std::string(topology(type).name));
    const auto g = moved_grid(type, 3, 2, 2);
    for (std::size_t e = 0; e < g.cells.size(); ++e) {
      const std::vector<double> X = coordinates(g, e);
      std::vector<double> shares(g.cells[e].size());
      const double volume = lumped_volume_shares(type, X, shares);
      EXPECT_NEAR(std::accumulate(shares.begin(), shares.end(), 0.0), volume, 1e-14 * volume);
      EXPECT_NEAR(volume, cell_volume(type, X), 1e-13 * volume);
      for (const double s : shares) EXPECT_GT(s, 0.0);
    }
  }
}

// ---- Stable step -----------------------------------------------------------------------------

// M^-1/2 K M^-1/2 of the assembled elastic cells of g, dense.
std::vector<double> scaled_stiffness(CellType type, const test::CellGrid& g,
                                     std::vector<double> masses) {
  const std::size_t dofs = 3 * g.nodes.size();
  std::vector<double> k(dofs * dofs, 0.0);
  SolidElementResult r;
  for (std::size_t e = 0; e < g.cells.size(); ++e) {
    const std::vector<double> X = coordinates(g, e), u(X.size(), 0.0);
    solid_full_with({type, quadrature(type, Integration::full), X, u, false},
                    IsotropicElastic{kE, kNu}, r);
    const std::size_t n = X.size();
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) {
        const std::size_t gi = 3 * static_cast<std::size_t>(g.cells[e][i / 3]) + i % 3;
        const std::size_t gj = 3 * static_cast<std::size_t>(g.cells[e][j / 3]) + j % 3;
        k[gi * dofs + gj] += r.stiffness[i * n + j];
      }
  }
  for (std::size_t i = 0; i < dofs; ++i)
    for (std::size_t j = 0; j < dofs; ++j)
      k[i * dofs + j] /= std::sqrt(masses[i / 3] * masses[j / 3]);
  return k;
}

TEST(ElementFrequency, HouseholderBisectionMatchesJacobiOnOneCell) {
  for (const CellType type : kTypes) {
    SCOPED_TRACE(std::string(topology(type).name));
    const auto g = moved_grid(type, 2, 2, 2);
    const std::size_t e = g.cells.size() / 2;  // an inner, distorted cell
    const std::vector<double> X = coordinates(g, e);
    std::vector<double> shares(g.cells[e].size());
    lumped_volume_shares(type, X, shares);
    for (double& s : shares) s *= kRho;
    const LameConstants lame = lame_constants(ElasticParams{kRho, kE, kNu});
    const double omega = largest_element_frequency(type, X, shares, lame.lambda, lame.mu);
    test::CellGrid one;  // the cell alone
    for (std::size_t a = 0; a < g.cells[e].size(); ++a) {
      one.nodes.add(static_cast<std::int64_t>(a) + 1, {X[3 * a], X[3 * a + 1], X[3 * a + 2]});
      one.cells.resize(1);
      one.cells[0].push_back(static_cast<std::int32_t>(a));
    }
    const double exact =
        std::sqrt(largest_eigenvalue(scaled_stiffness(type, one, shares), X.size()));
    EXPECT_GE(omega, exact * (1.0 - 1e-9));
    EXPECT_LT(omega, exact * (1.0 + 1e-5));
  }
}

TEST(SolidCellBlock, StableStepBoundsTheAssembledMesh) {
  // The element eigenvalue inequality: the block's step is at most 2 / omega_max of the mesh, and
  // on a mesh of similar cells not far below it.
  for (const CellType type : kTypes) {
    SCOPED_TRACE(std::string(topology(type).name));
    const auto g = moved_grid(type, 2, 2, 1);
    const MaterialParams steel = ElasticParams{kRho, kE, kNu};
    const SolidCellBlock block(1, steel, type, connectivity(g), g.nodes);
    std::vector<double> mass(g.nodes.size(), 0.0);
    block.add_lumped_mass(mass);
    const double omega =
        std::sqrt(largest_eigenvalue(scaled_stiffness(type, g, mass), 3 * g.nodes.size()));
    const double mesh_step = 2.0 / omega;
    std::cout << topology(type).name << ": block step / mesh step "
              << block.initial_stable_step() / mesh_step << "\n";
    EXPECT_LE(block.initial_stable_step(), mesh_step * (1.0 + 1e-9));
    EXPECT_GT(block.initial_stable_step(), 0.5 * mesh_step);
  }
}

// ---- Update ----------------------------------------------------------------------------------

TEST(SolidCellBlock, ConstantStrainRatePatch) {
  // Velocities of a homogeneous deformation v = L x over one step: every point of every
  // (distorted) cell takes sigma = Hooke(D dt) exactly, and the forces on each inner node cancel
  // (a uniform stress is in equilibrium; MacNeal & Harder 1985's patch test in rate form).
  const double l[3][3] = {{1e-3, 2e-4, 0.0}, {-1e-4, -5e-4, 3e-4}, {2e-4, 1e-4, 4e-4}};
  const double dt = 1e-3;
  for (const CellType type : kTypes) {
    SCOPED_TRACE(std::string(topology(type).name));
    const auto g = moved_grid(type, 3, 2, 2);
    const MaterialParams steel = ElasticParams{kRho, kE, kNu};
    SolidCellBlock block(1, steel, type, connectivity(g), g.nodes);
    block.set_bulk_viscosity(0.0, 0.0);
    const std::size_t n = g.nodes.size();
    // x^n such that the mid-step configuration is the reference one.
    std::vector<double> x(n), y(n), z(n), vx(n), vy(n), vz(n);
    for (std::size_t a = 0; a < n; ++a) {
      const double p[3] = {g.nodes.x[a], g.nodes.y[a], g.nodes.z[a]};
      double v[3];
      for (int i = 0; i < 3; ++i) v[i] = l[i][0] * p[0] + l[i][1] * p[1] + l[i][2] * p[2];
      vx[a] = v[0], vy[a] = v[1], vz[a] = v[2];
      x[a] = p[0] + 0.5 * dt * v[0], y[a] = p[1] + 0.5 * dt * v[1], z[a] = p[2] + 0.5 * dt * v[2];
    }
    block.update({x.data(), y.data(), z.data(), vx.data(), vy.data(), vz.data()}, dt);
    // The expected stress: the rotation of the zero stress is zero, so Hooke of D dt.
    const Sym3 d{{l[0][0] * dt, l[1][1] * dt, l[2][2] * dt, 0.5 * (l[0][1] + l[1][0]) * dt,
                  0.5 * (l[1][2] + l[2][1]) * dt, 0.5 * (l[2][0] + l[0][2]) * dt}};
    const Sym3 expected = hooke(lame_constants(std::get<ElasticParams>(steel)), d);
    std::vector<double> s;
    block.stress(s);
    for (std::size_t e = 0; e < block.size(); ++e)
      for (int c = 0; c < 6; ++c) EXPECT_NEAR(s[6 * e + c], expected[c], 1e-10 * 200.0);
    std::vector<double> f(3 * n, 0.0);
    const auto& forces = block.element_forces();
    const auto nn = static_cast<std::size_t>(block.nodes_per_element());
    for (std::size_t e = 0; e < block.size(); ++e)
      for (std::size_t a = 0; a < nn; ++a)
        for (int i = 0; i < 3; ++i)
          f[3 * block.element(e)[a] + i] += forces[3 * nn * e + 3 * a + i];
    double largest = 0.0, inner = 0.0;
    for (std::size_t a = 0; a < n; ++a)
      for (int i = 0; i < 3; ++i) {
        largest = std::max(largest, std::abs(f[3 * a + i]));
        if (!g.on_boundary[a]) inner = std::max(inner, std::abs(f[3 * a + i]));
      }
    EXPECT_GT(largest, 0.0);
    EXPECT_LT(inner, 1e-10 * largest);
  }
}

// Every law of a solid through every cell type (the material-point seam): a homogeneous
// deformation with the velocity v = l x at the mid-step (l symmetric, so no spin), 30 steps, on the
// distorted grid. Each point of each cell must hold the stress of the homogeneous state:
//  - *MAT_JC with n = 1, c = 0 (linear hardening, sigma_y = A + B epsp): on this radial path
//    (a fixed direction of D) the equivalent strain e = sqrt(2/3 dev(eps):dev(eps)) gives in
//    closed form q = 3 G e below yield, else epsp = (e - A/3G) / (1 + B/3G) and q = A + B epsp
//    (the radial return is exact for radial loading with linear hardening: Simo & Hughes 1998,
//    3.3), the deviator along dev(D), the pressure K tr(eps); eps the sum of the increments;
//  - *MAT_MOONEY_RIVLIN (no viscous terms): its stress at the homogeneous F of the positions the
//    step starts from, F = (I + dt A)^n with v = A x^n (the law alone, test_mooney_rivlin.cpp).
TEST(SolidCellBlock, EveryLawOfASolidInEveryCellHoldsTheHomogeneousState) {
  constexpr double dt = 1e-3;
  constexpr int steps = 30;
  const double l[3][3] = {{0.12, 0.03, 0.0}, {0.03, -0.05, 0.04}, {0.0, 0.04, -0.06}};
  // The block takes the rates at x^{n-1/2} = x^n - dt/2 v (the mid-step of the velocities it is
  // given): v = A x^n with A = (I + dt/2 l)^-1 l puts v = l x there.
  double m[3][3], a[3][3] = {};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[i][j] = (i == j ? 1.0 : 0.0) + 0.5 * dt * l[i][j];
  const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                     m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                     m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  double inv[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
      inv[i][j] = (m[i1][j1] * m[i2][j2] - m[i1][j2] * m[i2][j1]) / det;
    }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) a[i][j] += inv[i][k] * l[k][j];

  MetalParams metal;
  metal.density = kRho;
  metal.young = kE;
  metal.poisson = kNu;
  metal.johnson_cook = true;
  metal.a = 200.0;
  metal.b = 1000.0;
  metal.n = 1.0;
  MooneyRivlinParams rubber;
  rubber.density = 1.5e-9;
  rubber.bulk = 2000.0;
  rubber.c1 = 0.8;
  rubber.c2 = 0.2;

  // The metal's closed form after `steps` increments of sym(l) dt.
  const double g = kE / (2.0 * (1.0 + kNu)), k = kE / (3.0 * (1.0 - 2.0 * kNu));
  const Sym3 eps{{l[0][0] * dt * steps, l[1][1] * dt * steps, l[2][2] * dt * steps,
                  l[0][1] * dt * steps, l[1][2] * dt * steps, l[2][0] * dt * steps}};
  const Sym3 dev = deviator(eps);
  const double e = std::sqrt(2.0 / 3.0 * double_dot(dev, dev));
  const double yield_e = metal.a / (3.0 * g);
  ASSERT_GT(e, 2.0 * yield_e);  // well into the plastic range
  const double epsp = (e - yield_e) / (1.0 + metal.b / (3.0 * g));
  const double q = metal.a + metal.b * epsp;
  Sym3 metal_stress;
  for (int c = 0; c < 6; ++c) metal_stress[c] = 2.0 / 3.0 * q / e * dev[c];
  for (int c = 0; c < 3; ++c) metal_stress[c] += k * (eps[0] + eps[1] + eps[2]);

  for (const CellType type : kTypes) {
    for (const bool is_metal : {true, false}) {
      SCOPED_TRACE(std::string(topology(type).name) + (is_metal ? " metal" : " rubber"));
      const auto grid = moved_grid(type, 3, 2, 2);
      const MaterialParams material = is_metal ? MaterialParams{metal} : MaterialParams{rubber};
      SolidCellBlock block(1, material, type, connectivity(grid), grid.nodes);
      block.set_bulk_viscosity(0.0, 0.0);
      const std::size_t n = grid.nodes.size();
      std::vector<double> x(grid.nodes.x), y(grid.nodes.y), z(grid.nodes.z), vx(n), vy(n), vz(n);
      double f[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};  // F at x^n
      double f_last[3][3];
      for (int step = 0; step < steps; ++step) {
        for (std::size_t p = 0; p < n; ++p) {
          const double r[3] = {x[p], y[p], z[p]};
          vx[p] = a[0][0] * r[0] + a[0][1] * r[1] + a[0][2] * r[2];
          vy[p] = a[1][0] * r[0] + a[1][1] * r[1] + a[1][2] * r[2];
          vz[p] = a[2][0] * r[0] + a[2][1] * r[1] + a[2][2] * r[2];
        }
        block.update({x.data(), y.data(), z.data(), vx.data(), vy.data(), vz.data()}, dt);
        std::copy(&f[0][0], &f[0][0] + 9, &f_last[0][0]);
        double next[3][3] = {};
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            for (int c = 0; c < 3; ++c)
              next[i][j] += ((i == c ? 1.0 : 0.0) + dt * a[i][c]) * f[c][j];
        std::copy(&next[0][0], &next[0][0] + 9, &f[0][0]);
        for (std::size_t p = 0; p < n; ++p)
          x[p] += dt * vx[p], y[p] += dt * vy[p], z[p] += dt * vz[p];
      }
      Sym3 expected = metal_stress;
      if (!is_metal) {
        Mat3 fm;
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) fm[static_cast<std::size_t>(3 * i + j)] = f_last[i][j];
        expected = mooney_rivlin_stress(rubber, fm);
      }
      double scale = 0.0;
      for (int c = 0; c < 6; ++c) scale = std::max(scale, std::abs(expected[c]));
      std::vector<double> s;
      block.stress(s);  // the element means: a homogeneous state makes every point the same
      for (std::size_t el = 0; el < block.size(); ++el)
        for (int c = 0; c < 6; ++c) ASSERT_NEAR(s[6 * el + c], expected[c], 1e-9 * scale);
    }
  }
}

// ---- Average nodal pressure (C3D4) ----------------------------------------------------------

// The strain energy a block of C3D4 takes in one step to the pure-bending field of a bar
// 10 x 1 x 1 (Timoshenko & Goodier, Theory of Elasticity, 1970, section 102): curvature kappa in
// the x-z plane, u_x = kappa x z, u_y = -nu kappa y z, u_z = -kappa (x^2 + nu (z^2 - y^2)) / 2,
// stress sigma_xx = E kappa z only, energy E I kappa^2 L / 2 whatever nu (I = 1/12).
double bending_energy_ratio(const MaterialParams& material, double nu, bool nodal_pressure,
                            int across) {
  constexpr double kappa = 1e-4, dt = 1e-3;
  auto g = test::cell_grid(CellType::tet4, 5 * across, across, across, {10.0, 1.0, 1.0});
  for (std::size_t a = 0; a < g.nodes.size(); ++a) g.nodes.y[a] -= 0.5, g.nodes.z[a] -= 0.5;
  SolidCellBlock block(1, material, CellType::tet4, connectivity(g), g.nodes);
  block.set_bulk_viscosity(0.0, 0.0);
  block.set_nodal_pressure(nodal_pressure);
  const std::size_t n = g.nodes.size();
  std::vector<double> x(n), y(n), z(n), vx(n), vy(n), vz(n);
  for (std::size_t a = 0; a < n; ++a) {
    const double X = g.nodes.x[a], Y = g.nodes.y[a], Z = g.nodes.z[a];
    const double u[3] = {kappa * X * Z, -nu * kappa * Y * Z,
                         -0.5 * kappa * (X * X + nu * (Z * Z - Y * Y))};
    x[a] = X + u[0], y[a] = Y + u[1], z[a] = Z + u[2];
    vx[a] = u[0] / dt, vy[a] = u[1] / dt, vz[a] = u[2] / dt;
  }
  const BlockStep step =
      block.update({x.data(), y.data(), z.data(), vx.data(), vy.data(), vz.data()}, dt);
  const double young = 1e7;
  return step.internal_energy / (0.5 * young * kappa * kappa * 10.0 / 12.0);
}

TEST(SolidCellBlock, NodalPressureKeepsNearlyIncompressibleBendingUnlocked) {
  // E = 10 MPa, nu = 0.499 (K / G = 250), a 40 x 8 x 8 grid of cubes, 6 tetrahedra each. The
  // exact energy does not depend on nu. Plain constant-strain tetrahedra are off it by their
  // discretisation error at nu = 0.3 and lock at 0.499 (their energy grows with K); with the
  // averaged nodal pressure the error at 0.499 stays within twice the plain tetrahedra's own
  // error at 0.3. The same with Mooney-Rivlin of K / G = 250 (C1 + C2 = G / 2), whose
  // small-strain energy is that of the elastic law.
  const auto elastic = [](double nu) { return MaterialParams{ElasticParams{1000.0, 1e7, nu}}; };
  const auto rubber = [](double nu) {
    const double shear = 1e7 / (2.0 * (1.0 + nu)), bulk = 1e7 / (3.0 * (1.0 - 2.0 * nu));
    MooneyRivlinParams p;
    p.density = 1000.0;
    p.c1 = 0.3 * shear, p.c2 = 0.2 * shear, p.bulk = bulk;
    return MaterialParams{p};
  };
  for (const bool hyperelastic : {false, true}) {
    const auto law = [&](double nu) { return hyperelastic ? rubber(nu) : elastic(nu); };
    const double plain = bending_energy_ratio(law(0.3), 0.3, false, 8);
    const double plain_incompressible = bending_energy_ratio(law(0.499), 0.499, false, 8);
    const double averaged = bending_energy_ratio(law(0.3), 0.3, true, 8);
    const double averaged_incompressible = bending_energy_ratio(law(0.499), 0.499, true, 8);
    std::cout << (hyperelastic ? "Mooney-Rivlin" : "elastic")
              << ": energy / exact at nu = 0.3 and 0.499: plain " << plain << ", "
              << plain_incompressible << "; averaged nodal pressure " << averaged << ", "
              << averaged_incompressible << "\n";
    EXPECT_LT(std::abs(averaged_incompressible - 1.0), 2.0 * std::abs(plain - 1.0));
    EXPECT_GT(plain_incompressible, 5.0);  // the locking the averaging removes
  }
}

}  // namespace
}  // namespace abut
