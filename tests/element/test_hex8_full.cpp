// The fully integrated hexahedron (C3D8) for the implicit solver: stiffness properties, patch
// test, CalculiX 2.20 reference results, the consistent tangent against finite differences,
// objectivity and the St Venant-Kirchhoff closed form.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "abut/core/mat3.hpp"
#include "abut/core/vec3.hpp"
#include "abut/element/hex8.hpp"
#include "abut/element/hex8_full.hpp"
#include "hex8_fixtures.hpp"

namespace abut {
namespace {

using namespace hex8_test;

constexpr IsotropicElastic kSteel{210000.0, 0.3};

// Hex8FullResult is 5 kB: keep it off the test's stack.
std::unique_ptr<Hex8FullResult> run(const Hex8FullInput& in, const IsotropicElastic& m = kSteel) {
  auto r = std::make_unique<Hex8FullResult>();
  hex8_full(in, m, *r);
  return r;
}

// ---- Material point ------------------------------------------------------------------------

// Hooke's law with engineering shear strains: D = lambda 1 (x) 1 + mu diag(2, 2, 2, 1, 1, 1),
// lambda = E nu / ((1 + nu)(1 - 2 nu)), mu = E / (2 (1 + nu)) (e.g. Hughes, The Finite Element
// Method, 2000, section 2.7).
TEST(IsotropicElastic, HookeTangentAndEnergy) {
  const double lambda = 210000.0 * 0.3 / (1.3 * 0.4), mu = 210000.0 / 2.6;
  double d[36];
  kSteel.tangent(d);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      double expect = 0.0;
      if (i < 3 && j < 3) expect = lambda + (i == j ? 2.0 * mu : 0.0);
      if (i >= 3 && i == j) expect = mu;
      EXPECT_NEAR(d[6 * i + j], expect, 1e-10 * mu) << i << "," << j;
    }
  const double strain[6] = {1e-3, -2e-4, 3e-4, 5e-4, -1e-4, 2e-4};
  double s[6], s2[6], d2[36];
  kSteel.stress(strain, s);
  const double w = kSteel.evaluate(3, strain, s2, d2);
  double w_expect = 0.0;
  for (int i = 0; i < 6; ++i) {
    double ds = 0.0;
    for (int j = 0; j < 6; ++j) ds += d[6 * i + j] * strain[j];
    EXPECT_NEAR(s[i], ds, 1e-12 * mu);
    EXPECT_EQ(s[i], s2[i]);
    w_expect += 0.5 * s[i] * strain[i];
  }
  EXPECT_DOUBLE_EQ(w, w_expect);
  static_assert(Hex8MaterialPoint<IsotropicElastic>);
}

// ---- Stiffness -----------------------------------------------------------------------------

// A free element has exactly six zero-energy modes, the rigid body modes; the fully integrated
// hexahedron has no spurious (hourglass) modes (Hughes, The Finite Element Method, 2000,
// section 4.6; Bathe, Finite Element Procedures, 1996, section 5.5.6).
TEST(Hex8Full, StiffnessIsSymmetricWithExactlySixRigidModes) {
  const Nodes zero{};
  for (bool nlgeom : {false, true}) {
    const auto r = run(make_input(kDistorted, zero, nlgeom));
    const double kmax = max_abs(r->stiffness, 576);
    for (int m = 0; m < 24; ++m)
      for (int n = 0; n < 24; ++n)
        ASSERT_LE(std::abs(r->stiffness[24 * m + n] - r->stiffness[24 * n + m]), 1e-12 * kmax);
    const std::vector<double> ev =
        jacobi_eigenvalues(std::vector<double>(r->stiffness, r->stiffness + 576), 24);
    for (int i = 0; i < 6; ++i) EXPECT_LT(std::abs(ev[i]), 1e-10 * ev[23]) << ev[i];
    // The smallest deformation mode is far from zero: no hourglass mode.
    EXPECT_GT(ev[6], 1e-3 * ev[23]) << ev[6] << " / " << ev[23];
    // At u = 0 NLGEOM is the small-strain element (B_NL = B, S = 0).
    EXPECT_LT(max_abs(r->force, 24), 1e-300);
  }
  // Same tangent with and without NLGEOM at the undeformed state.
  const auto lin = run(make_input(kDistorted, zero, false));
  const auto nl = run(make_input(kDistorted, zero, true));
  for (int i = 0; i < 576; ++i)
    EXPECT_NEAR(nl->stiffness[i], lin->stiffness[i], 1e-13 * max_abs(lin->stiffness, 576));
}

// K times each rigid mode (three translations, three infinitesimal rotations) is zero, and K is
// positive on deformation vectors.
TEST(Hex8Full, RigidModesCarryNoForce) {
  const auto r = run(make_input(kDistorted, Nodes{}, false));
  const double kmax = max_abs(r->stiffness, 576);
  for (int mode = 0; mode < 6; ++mode) {
    const Nodes v = field_at_nodes(kDistorted, [&](Vec3 x) {
      if (mode < 3)
        return Vec3{mode == 0 ? 1.0 : 0.0, mode == 1 ? 1.0 : 0.0, mode == 2 ? 1.0 : 0.0};
      const Vec3 axis{mode == 3 ? 1.0 : 0.0, mode == 4 ? 1.0 : 0.0, mode == 5 ? 1.0 : 0.0};
      return cross(axis, x);
    });
    for (int m = 0; m < 24; ++m) {
      double kv = 0.0;
      for (int n = 0; n < 24; ++n) kv += r->stiffness[24 * m + n] * v[n / 3][n % 3];
      EXPECT_LT(std::abs(kv), 1e-12 * kmax * 3.0) << "mode " << mode << " row " << m;
    }
  }
  for (unsigned seed = 1; seed < 20; ++seed) {
    const Nodes v = random_displacements(1.0, seed);
    double vkv = 0.0;
    for (int m = 0; m < 24; ++m)
      for (int n = 0; n < 24; ++n)
        vkv += v[m / 3][m % 3] * r->stiffness[24 * m + n] * v[n / 3][n % 3];
    EXPECT_GT(vkv, 0.0);
  }
}

// ---- Patch test ----------------------------------------------------------------------------

// A linear displacement field u = A X + c is reproduced exactly by the trilinear element on any
// shape (the patch test; Zienkiewicz & Taylor, The Finite Element Method, vol. 1, 5th ed.,
// chapter 10): the strain is sym(A) and the stress D sym(A) at every Gauss point, and the nodal
// forces are f_a = sigma b_a with b_a = int grad N_a dV, here the closed form of Flanagan and
// Belytschko (1981) from hex8.hpp, an independent computation.
TEST(Hex8Full, PatchTestSmallStrain) {
  const double A[3][3] = {
      {1.0e-3, 4.0e-4, -2.0e-4}, {-3.0e-4, -5.0e-4, 6.0e-4}, {2.5e-4, 1.0e-4, 8.0e-4}};
  const Vec3 c{0.3, -0.2, 0.1};
  const Nodes u = field_at_nodes(kDistorted, [&](Vec3 x) {
    return Vec3{A[0][0] * x.x + A[0][1] * x.y + A[0][2] * x.z,
                A[1][0] * x.x + A[1][1] * x.y + A[1][2] * x.z,
                A[2][0] * x.x + A[2][1] * x.y + A[2][2] * x.z} +
           c;
  });
  const auto r = run(make_input(kDistorted, u, false));
  const double eps[6] = {A[0][0],           A[1][1],           A[2][2],
                         A[0][1] + A[1][0], A[1][2] + A[2][1], A[2][0] + A[0][2]};
  double sigma[6];
  kSteel.stress(eps, sigma);
  for (int p = 0; p < 8; ++p)
    for (int k = 0; k < 6; ++k) {
      EXPECT_NEAR(r->strain[p][k], eps[k], 1e-15) << p << "," << k;
      EXPECT_NEAR(r->stress[p][k], sigma[k], 1e-10) << p << "," << k;
    }
  Hex8Coords xc;
  for (int a = 0; a < 8; ++a) {
    xc.x[a] = kDistorted[a][0];
    xc.y[a] = kDistorted[a][1];
    xc.z[a] = kDistorted[a][2];
  }
  Hex8Gradient g;
  hex8_gradient(xc, g);
  const Mat3 s = from_voigt(sigma);
  for (int a = 0; a < 8; ++a) {
    const Vec3 fa = s * Vec3{g.bx[a], g.by[a], g.bz[a]};
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(r->force[3 * a + i], fa[i], 1e-10) << a << "," << i;
  }
  // Energy: W V with W = sigma . eps / 2 constant.
  double w = 0.0;
  for (int k = 0; k < 6; ++k) w += 0.5 * sigma[k] * eps[k];
  EXPECT_NEAR(r->strain_energy, w * g.volume, 1e-12 * w * g.volume);
}

// The same with NLGEOM and a homogeneous deformation x = F X + c with large stretch and shear:
// E = (F^T F - I)/2 and the St Venant-Kirchhoff S are constant, sigma = F S F^T / det F, and the
// nodal forces are f_a = P b_a with the first Piola-Kirchhoff stress P = F S and b_a of the
// reference configuration (Belytschko, Liu & Moran 2000, section 4.9: f = int B0^T P dV0).
TEST(Hex8Full, PatchTestNonlinearGeometry) {
  const Mat3 F{{1.3, 0.2, -0.1, 0.15, 0.8, 0.3, -0.2, 0.1, 1.1}};
  const Vec3 c{0.3, -0.2, 0.1};
  const Nodes u = field_at_nodes(kDistorted, [&](Vec3 x) { return F * x + c - x; });
  const auto r = run(make_input(kDistorted, u, true));
  const Mat3 C = transpose(F) * F;
  const double E[6] = {
      0.5 * (C(0, 0) - 1), 0.5 * (C(1, 1) - 1), 0.5 * (C(2, 2) - 1), C(0, 1), C(1, 2), C(2, 0)};
  double S[6];
  kSteel.stress(E, S);
  const Mat3 sigma = F * from_voigt(S) * transpose(F);
  const double J = determinant(F);
  const double smax = max_abs(S, 6);
  for (int p = 0; p < 8; ++p) {
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(r->strain[p][k], E[k], 1e-14) << p << "," << k;
    const double expect[6] = {sigma(0, 0), sigma(1, 1), sigma(2, 2),
                              sigma(0, 1), sigma(1, 2), sigma(2, 0)};
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(r->stress[p][k], expect[k] / J, 1e-13 * smax);
  }
  Hex8Coords xc;
  for (int a = 0; a < 8; ++a) {
    xc.x[a] = kDistorted[a][0];
    xc.y[a] = kDistorted[a][1];
    xc.z[a] = kDistorted[a][2];
  }
  Hex8Gradient g;
  hex8_gradient(xc, g);
  const Mat3 P = F * from_voigt(S);
  for (int a = 0; a < 8; ++a) {
    const Vec3 fa = P * Vec3{g.bx[a], g.by[a], g.bz[a]};
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(r->force[3 * a + i], fa[i], 1e-12 * smax * g.volume);
  }
  // det(dx/dxi) = det F det J0 at every point: the smallest is det F times the reference one.
  const auto r0 = run(make_input(kDistorted, Nodes{}, false));
  EXPECT_NEAR(r->min_jacobian, J * r0->min_jacobian, 1e-14);
}

// ---- Gauss point order -----------------------------------------------------------------------

// CalculiX numbers the 2x2x2 points xi fastest, then eta, then zeta (gauss.f, gauss3d2; User's
// Manual figure "2x2x2 integration point scheme in hexahedral elements"). On the unit cube,
// X = (1 + xi)/2 etc.; the trilinear field u = k (Z X, X Y, Y Z) has strains eps_xx = k Z,
// eps_yy = k X, eps_zz = k Y, which reads the coordinates of each point back.
TEST(Hex8Full, GaussPointsInCalculiXOrder) {
  const double k = 1e-3;
  const Nodes u = field_at_nodes(kUnitCube, [&](Vec3 x) {
    return Vec3{x.z * x.x, x.x * x.y, x.y * x.z} * k;
  });
  const auto r = run(make_input(kUnitCube, u, false));
  const double lo = 0.5 * (1.0 - 1.0 / std::sqrt(3.0)), hi = 0.5 * (1.0 + 1.0 / std::sqrt(3.0));
  for (int p = 0; p < 8; ++p) {
    const double x = (p % 2) ? hi : lo, y = ((p / 2) % 2) ? hi : lo, z = (p / 4) ? hi : lo;
    EXPECT_NEAR(r->strain[p][0], k * z, 1e-15) << p;
    EXPECT_NEAR(r->strain[p][1], k * x, 1e-15) << p;
    EXPECT_NEAR(r->strain[p][2], k * y, 1e-15) << p;
  }
  EXPECT_NEAR(r->min_jacobian, 0.125, 1e-15);  // det J of the unit cube: 1/8
}

// ---- CalculiX reference runs -----------------------------------------------------------------

// Both decks: one C3D8 with the nodes of kDistorted (CalculiX nodes 1..8 in our order),
// *ELASTIC 210000., 0.3, every degree of freedom prescribed by *BOUNDARY to the displacements
// below, *NODE PRINT U, RF, *EL PRINT S, E and *EL PRINT TOTALS=ONLY ELSE; run with ccx 2.20
// (Debian package calculix-ccx 2.20-1). The reaction forces RF are the internal forces. ccx
// prints stresses sxx syy szz sxy sxz syz and tensorial strains exx eyy ezz exy exz eyz, with
// 7 significant digits.
void expect_matches_calculix(const Hex8FullResult& r, const double force[8][3],
                             const double stress[8][6], const double strain[8][6], double energy) {
  constexpr int kFromCcx[6] = {0, 1, 2, 3, 5, 4};  // our Voigt k <- ccx column kFromCcx[k]
  double fmax = 0.0, smax = 0.0, emax = 0.0;
  for (int a = 0; a < 8; ++a) {
    fmax = std::max(fmax, max_abs(force[a], 3));
    smax = std::max(smax, max_abs(stress[a], 6));
    emax = std::max(emax, max_abs(strain[a], 6));
  }
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(r.force[3 * a + i], force[a][i], 1e-6 * fmax) << a << "," << i;
  for (int p = 0; p < 8; ++p)
    for (int k = 0; k < 6; ++k) {
      const int c = kFromCcx[k];
      EXPECT_NEAR(r.stress[p][k], stress[p][c], 1e-6 * smax) << "point " << p + 1 << " comp " << k;
      const double engineering = (k < 3 ? 1.0 : 2.0) * strain[p][c];
      EXPECT_NEAR(r.strain[p][k], engineering, 2e-6 * emax) << "point " << p + 1 << " comp " << k;
    }
  EXPECT_NEAR(r.strain_energy, energy, 1e-6 * energy);
}

// *STEP, *STATIC (small strain).
TEST(Hex8Full, MatchesCalculiXSmallStrain) {
  constexpr Nodes u{{{-0.000352, -0.000698, 0.000302},
                     {-0.000855, 7.2e-05, -0.000269},
                     {-0.000884, 1.5e-05, -0.000925},
                     {-0.000133, -0.00086, -0.000819},
                     {-0.000151, 0.000654, -0.000752},
                     {-0.000554, 0.000255, 0.000895},
                     {0.000154, -0.000207, 0.000953},
                     {-0.000907, 0.000717, -0.000421}}};
  constexpr double kForce[8][3] = {
      {-1.391280e+01, -1.759568e+01, -1.468450e+01}, {-7.016060e+01, -9.037776e+00, -4.661596e+01},
      {-1.331678e+01, 1.701582e+01, -1.533557e+02},  {-1.612630e+01, -5.930823e+01, -7.151457e+01},
      {4.816809e+01, 4.188883e+01, -8.163465e+01},   {3.033323e+01, -2.380279e+01, 1.226266e+02},
      {7.447152e+01, 1.376245e+01, 1.876724e+02},    {-3.945635e+01, 3.707738e+01, 5.750630e+01},
  };
  constexpr double kStress[8][6] = {
      {-1.037207e+02, -8.533924e+01, -9.924857e+01, 2.232751e+01, 7.929282e+00, 2.154591e+01},
      {-1.825690e+01, -7.794672e-02, 1.033541e+02, 2.605832e+01, 1.695027e+01, -1.254038e+01},
      {-2.681953e+01, -1.784651e+01, 5.327805e+01, 1.999601e+01, -4.149919e+00, 2.447212e+01},
      {4.140492e+01, 5.515783e+01, 2.207043e+02, 2.199485e+01, 3.578130e+01, -2.229550e+01},
      {-6.425600e+01, -6.165302e+01, -9.148237e+01, -3.016018e+01, 5.821935e+01, 6.120330e+01},
      {1.619455e+00, 1.130514e+00, 1.097043e+02, 4.597814e+00, 6.327813e+01, 1.064709e+01},
      {9.126038e+01, 3.829599e+01, 8.932498e+01, -3.495950e+01, 2.800092e+01, 6.517472e+01},
      {1.425362e+02, 8.955182e+01, 2.583767e+02, -4.967034e+00, 6.920966e+01, 5.076828e+00},
  };
  constexpr double kStrain[8][6] = {
      {-2.302111e-04, -1.164213e-04, -2.025267e-04, 1.382179e-04, 4.908603e-05, 1.333795e-04},
      {-2.344750e-04, -1.219386e-04, 5.183551e-04, 1.613134e-04, 1.049302e-04, -7.763095e-05},
      {-1.783285e-04, -1.227813e-04, 3.175136e-04, 1.237848e-04, -2.568998e-05, 1.514941e-04},
      {-1.969224e-04, -1.117854e-04, 9.130260e-04, 1.361586e-04, 2.215033e-04, -1.380198e-04},
      {-8.721612e-05, -7.110243e-05, -2.557603e-04, -1.867059e-04, 3.604055e-04, 3.788776e-04},
      {-1.506237e-04, -1.536505e-04, 5.184727e-04, 2.846266e-05, 3.917218e-04, 6.591055e-05},
      {2.522575e-04, -7.561721e-05, 2.402765e-04, -2.164159e-04, 1.733391e-04, 4.034626e-04},
      {1.817031e-04, -1.462955e-04, 8.988109e-04, -3.074831e-05, 4.284407e-04, 3.142798e-05},
  };
  const auto r = run(make_input(kDistorted, u, false));
  expect_matches_calculix(*r, kForce, kStress, kStrain, 3.721214e-01);
}

// *STEP, NLGEOM, *STATIC 0.1, 1. (the values at step time 1): Cauchy stress, Lagrangian strain.
TEST(Hex8Full, MatchesCalculiXNonlinearGeometry) {
  constexpr Nodes u{{{-0.2134, -0.2293, -0.1149},
                     {0.1897, -0.1916, 0.049},
                     {0.0833, -0.0766, 0.0286},
                     {-0.2623, -0.2642, -0.1764},
                     {0.1082, -0.0434, -0.1115},
                     {0.0513, -0.0281, -0.1201},
                     {0.1766, 0.1194, -0.1535},
                     {0.0447, 0.0151, 0.2251}}};
  constexpr double kForce[8][3] = {
      {-4.250721e+04, -3.901858e+04, -4.000595e+04}, {3.481287e+04, -3.108772e+04, -8.677929e+03},
      {2.532272e+04, 1.172896e+04, -4.384345e+03},   {-5.659252e+04, 3.414919e+03, -4.637725e+04},
      {-4.800105e+03, -8.544612e+03, 1.032337e+04},  {2.526251e+04, -9.295870e+03, 2.280399e+03},
      {3.275383e+04, 3.290785e+04, 2.678952e+04},    {-1.425210e+04, 3.989505e+04, 6.005218e+04},
  };
  constexpr double kStress[8][6] = {
      {6.455570e+04, 2.375949e+04, 2.847129e+04, 3.520915e+03, 2.401945e+04, 1.290495e+04},
      {5.508751e+04, 2.582127e+04, 7.711453e+03, -1.227817e+03, 7.402380e+03, 7.703407e+03},
      {6.963490e+04, 3.446075e+04, 6.777816e+04, 8.511008e+03, 2.982716e+04, 2.079052e+04},
      {5.248702e+04, 2.639134e+04, 1.165094e+04, 3.543673e+03, 1.258904e+04, 1.077323e+04},
      {1.952992e+04, 2.261835e+04, 2.247666e+04, 2.077397e+03, 1.090979e+04, 2.289040e+04},
      {1.150595e+04, 1.979783e+04, -3.591949e+03, 2.747827e+03, -9.184793e+02, 9.378960e+03},
      {4.484374e+04, 4.039638e+04, 6.971401e+04, 5.552070e+03, 7.994290e+03, 3.241715e+04},
      {2.577517e+04, 2.735383e+04, 5.769434e+03, 6.865548e+03, -3.099109e+03, 1.262075e+04},
  };
  constexpr double kStrain[8][6] = {
      {1.691835e-01, 4.561110e-04, 3.270005e-02, -6.472803e-03, 1.091404e-01, 6.328708e-02},
      {1.704685e-01, 4.127726e-02, -5.825317e-02, -1.158347e-02, 3.108454e-02, 4.983506e-02},
      {1.498682e-01, -1.218700e-03, 1.707354e-01, 6.974453e-03, 1.160005e-01, 7.377129e-02},
      {1.547812e-01, 3.603673e-02, -3.410552e-02, 2.917122e-04, 6.529869e-02, 6.212502e-02},
      {2.666972e-02, 3.388429e-02, 4.327880e-02, -1.048937e-02, 5.766524e-02, 1.162498e-01},
      {3.556597e-02, 6.768617e-02, -6.068165e-02, 1.395733e-02, -6.862678e-03, 6.088484e-02},
      {7.635538e-02, 3.262813e-02, 1.778184e-01, 1.415561e-03, 2.273809e-02, 1.334879e-01},
      {7.533719e-02, 6.506234e-02, -3.996435e-02, 2.862411e-02, -9.570390e-03, 7.926686e-02},
  };
  const auto r = run(make_input(kDistorted, u, true));
  expect_matches_calculix(*r, kForce, kStress, kStrain, 3.457305e+04);
}

// CalculiX test deck contactenergy.inp (calculix-ccx-test, examples/test): element 1 is a unit
// cube, E = 210000, nu = 0, its bottom nodes 1, 2, 5, 6 fixed in x, y, z (NSET Nfix, *BOUNDARY
// Nfix,1,3), loaded on top through contact by the small block above; by symmetry the contact
// load is four nodal forces -1 on the top nodes 3, 4, 7, 8. contactenergy.dat.ref: u_z of the top
// nodes -1.904762E-05, internal energy of element 1 3.809524E-05. We solve K u = f for the one
// element with the deck's coordinates.
TEST(Hex8Full, CalculiXContactEnergyCube) {
  constexpr Nodes x{{{1.0, 1.0, -1.49012e-08},
                     {1.0, 0.0, -1.49012e-08},
                     {1.0, 0.0, 1.0},
                     {1.0, 1.0, 1.0},
                     {-7.45058e-09, 1.0, -1.49012e-08},
                     {-7.45058e-09, 0.0, -1.49012e-08},
                     {-7.45058e-09, 0.0, 1.0},
                     {-7.45058e-09, 1.0, 1.0}}};
  const IsotropicElastic material{210000.0, 0.0};
  const auto r0 = run(make_input(x, Nodes{}, false), material);
  ASSERT_GT(r0->min_jacobian, 0.0);
  const int top[4] = {2, 3, 6, 7};
  std::vector<int> free_dofs;
  for (int a : top)
    for (int i = 0; i < 3; ++i) free_dofs.push_back(3 * a + i);
  const int n = static_cast<int>(free_dofs.size());
  std::vector<double> k(n * n), f(n, 0.0);
  for (int m = 0; m < n; ++m) {
    for (int q = 0; q < n; ++q) k[n * m + q] = r0->stiffness[24 * free_dofs[m] + free_dofs[q]];
    if (free_dofs[m] % 3 == 2) f[m] = -1.0;
  }
  const std::vector<double> sol = solve_dense(k, f);
  Nodes u{};
  for (int m = 0; m < n; ++m) u[free_dofs[m] / 3][free_dofs[m] % 3] = sol[m];
  for (int a : top) EXPECT_NEAR(u[a][2], -1.904762e-05, 1e-6 * 1.904762e-05) << a;
  const auto r = run(make_input(x, u, false), material);
  EXPECT_NEAR(r->strain_energy, 3.809524e-05, 1e-6 * 3.809524e-05);
  double work = 0.0;  // Clapeyron: W = f . u / 2
  for (int m = 0; m < n; ++m) work += 0.5 * f[m] * sol[m];
  EXPECT_NEAR(r->strain_energy, work, 1e-12 * work);
  for (int p = 0; p < 8; ++p) EXPECT_NEAR(r->stress[p][2], -4.0, 1e-6 * 4.0);  // sigma_zz = F / A
}

// ---- Consistency of force and tangent --------------------------------------------------------

// The tangent is the derivative of the internal force and the force the derivative of the strain
// energy (hyperelastic element); both checked by central differences on a distorted element under
// large strain and rotation (and the small-strain element likewise).
TEST(Hex8Full, TangentAndForceMatchFiniteDifferences) {
  for (bool nlgeom : {true, false}) {
    // Large strain (up to ~20%) plus a 40 degree rotation.
    const Mat3 R = rotation_from_vector(Vec3{0.3, -0.5, 0.4} * (0.698 / std::sqrt(0.5)));
    const Nodes du = random_displacements(0.25, 99);
    Nodes u{};
    for (int a = 0; a < 8; ++a) {
      const Vec3 xa{kDistorted[a][0], kDistorted[a][1], kDistorted[a][2]};
      const Vec3 y = R * (xa + Vec3{du[a][0], du[a][1], du[a][2]}) - xa;
      u[a] = {y.x, y.y, y.z};
    }
    Hex8FullInput in = make_input(kDistorted, u, nlgeom);
    const auto r = run(in);
    ASSERT_GT(r->min_jacobian, 0.0);
    const double kmax = max_abs(r->stiffness, 576), fmax = max_abs(r->force, 24);
    const double h = 1e-6;
    double worst_k = 0.0, worst_f = 0.0;
    for (int n = 0; n < 24; ++n) {
      Hex8FullInput plus = in, minus = in;
      plus.u[n / 3][n % 3] += h;
      minus.u[n / 3][n % 3] -= h;
      const auto rp = run(plus), rm = run(minus);
      for (int m = 0; m < 24; ++m) {
        const double fd = (rp->force[m] - rm->force[m]) / (2 * h);
        worst_k = std::max(worst_k, std::abs(fd - r->stiffness[24 * m + n]));
      }
      const double dw = (rp->strain_energy - rm->strain_energy) / (2 * h);
      worst_f = std::max(worst_f, std::abs(dw - r->force[n]));
    }
    EXPECT_LT(worst_k, 1e-6 * kmax) << "nlgeom " << nlgeom << ": " << worst_k / kmax;
    EXPECT_LT(worst_f, 1e-6 * fmax) << "nlgeom " << nlgeom << ": " << worst_f / fmax;
  }
}

// For small displacements NLGEOM tends to the small-strain element: the difference in force is of
// second order in the displacement.
TEST(Hex8Full, NonlinearGeometryTendsToSmallStrain) {
  double previous = 0.0;
  for (double amp : {1e-3, 1e-4}) {
    const Nodes u = random_displacements(amp, 5);
    const auto lin = run(make_input(kDistorted, u, false));
    const auto nl = run(make_input(kDistorted, u, true));
    double diff = 0.0;
    for (int m = 0; m < 24; ++m) diff = std::max(diff, std::abs(nl->force[m] - lin->force[m]));
    const double rel = diff / max_abs(lin->force, 24);
    EXPECT_LT(rel, 10.0 * amp);
    if (previous > 0.0) {
      EXPECT_NEAR(rel / previous, 0.1, 0.02);  // linear in amp: O(u^2) / O(u)
    }
    previous = rel;
  }
}

// ---- Objectivity -----------------------------------------------------------------------------

// A rigid rotation by 90 degrees of the undeformed element: F = R, E = 0, no force and no stress
// (total Lagrangian strains are invariant under rigid motion; Belytschko, Liu & Moran 2000,
// section 3.3).
TEST(Hex8Full, RigidRotationGivesNoStrainNoForce) {
  const double quarter = 2.0 * std::atan(1.0);
  for (const Vec3 axis :
       {Vec3{0, 0, 1}, normalized(Vec3{1, 1, 1}), normalized(Vec3{-0.3, 0.8, 0.5})}) {
    const Mat3 R = rotation_from_vector(axis * quarter);
    const Nodes u = field_at_nodes(kDistorted, [&](Vec3 x) {
      return R * x + Vec3{0.5, -1.0, 2.0} - x;
    });
    const auto r = run(make_input(kDistorted, u, true));
    // Round-off against the scales E L^2 ~ 1e6 of the force and E ~ 2e5 of the stress.
    EXPECT_LT(max_abs(r->force, 24), 1e-8) << max_abs(r->force, 24);
    for (int p = 0; p < 8; ++p) {
      EXPECT_LT(max_abs(r->strain[p], 6), 1e-14);
      EXPECT_LT(max_abs(r->stress[p], 6), 1e-8);
    }
    EXPECT_LT(std::abs(r->strain_energy), 1e-20);
    // The current Jacobian is the reference one: a rotation keeps volume.
    const auto r0 = run(make_input(kDistorted, Nodes{}, false));
    EXPECT_NEAR(r->min_jacobian, r0->min_jacobian, 1e-14);
  }
}

// A stretched element rotated rigidly afterwards: same Green-Lagrange strain and strain energy,
// Cauchy stress rotated (sigma' = R sigma R^T), forces rotated (f'_a = R f_a), tangent rotated.
TEST(Hex8Full, RotatedStretchedElementIsObjective) {
  const Nodes stretch = random_displacements(0.2, 17);
  const Mat3 R = rotation_from_vector(Vec3{0.4, 1.1, -0.7});
  Nodes rotated{};
  for (int a = 0; a < 8; ++a) {
    const Vec3 xa{kDistorted[a][0], kDistorted[a][1], kDistorted[a][2]};
    const Vec3 y = R * (xa + Vec3{stretch[a][0], stretch[a][1], stretch[a][2]}) - xa;
    rotated[a] = {y.x, y.y, y.z};
  }
  const auto r1 = run(make_input(kDistorted, stretch, true));
  const auto r2 = run(make_input(kDistorted, rotated, true));
  EXPECT_NEAR(r2->strain_energy, r1->strain_energy, 1e-12 * r1->strain_energy);
  double smax = 0.0;
  for (int p = 0; p < 8; ++p) smax = std::max(smax, max_abs(r1->stress[p], 6));
  for (int p = 0; p < 8; ++p) {
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(r2->strain[p][k], r1->strain[p][k], 1e-13);
    const Mat3 s = R * from_voigt(r1->stress[p]) * transpose(R);
    const double expect[6] = {s(0, 0), s(1, 1), s(2, 2), s(0, 1), s(1, 2), s(2, 0)};
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(r2->stress[p][k], expect[k], 1e-12 * smax);
  }
  const double fmax = max_abs(r1->force, 24);
  for (int a = 0; a < 8; ++a) {
    const Vec3 f = R * Vec3{r1->force[3 * a], r1->force[3 * a + 1], r1->force[3 * a + 2]};
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(r2->force[3 * a + i], f[i], 1e-12 * fmax);
  }
  // K' = (I (x) R) K (I (x) R)^T, block by block.
  const double kmax = max_abs(r1->stiffness, 576);
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 8; ++b) {
      Mat3 k;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) k(i, j) = r1->stiffness[24 * (3 * a + i) + 3 * b + j];
      const Mat3 kr = R * k * transpose(R);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          EXPECT_NEAR(r2->stiffness[24 * (3 * a + i) + 3 * b + j], kr(i, j), 1e-11 * kmax);
    }
}

// ---- St Venant-Kirchhoff closed form ---------------------------------------------------------

// Uniaxial stretch lambda of a bar with nu = 0 (lateral faces free, lateral displacements zero
// because the Lame lambda is 0): F = diag(lambda, 1, 1), E11 = (lambda^2 - 1)/2,
// S11 = E (lambda^2 - 1)/2, Cauchy sigma11 = F11 S11 F11 / det F = lambda S11, and the force on the
// end face is P11 A0 = lambda S11 A0 (e.g. Belytschko, Liu & Moran 2000, section 5.4.3 on the
// St Venant-Kirchhoff material in uniaxial strain: it softens in compression).
TEST(Hex8Full, UniaxialStretchStVenantKirchhoff) {
  const double L = 3.0, W = 0.5, H = 0.8;  // bar along x
  constexpr double E = 1000.0;
  const Nodes bar{
      {{0, 0, 0}, {L, 0, 0}, {L, W, 0}, {0, W, 0}, {0, 0, H}, {L, 0, H}, {L, W, H}, {0, W, H}}};
  for (double lambda : {1.5, 0.7, 1.001}) {
    const Nodes u = field_at_nodes(bar, [&](Vec3 x) { return Vec3{(lambda - 1.0) * x.x, 0, 0}; });
    const auto r = run(make_input(bar, u, true), IsotropicElastic{E, 0.0});
    const double s11 = E * (lambda * lambda - 1.0) / 2.0;
    for (int p = 0; p < 8; ++p) {
      EXPECT_NEAR(r->strain[p][0], (lambda * lambda - 1.0) / 2.0, 1e-14);
      EXPECT_NEAR(r->stress[p][0], lambda * s11, 1e-12 * E);
      for (int k = 1; k < 6; ++k) EXPECT_NEAR(r->stress[p][k], 0.0, 1e-12 * E);
    }
    double end_force = 0.0;  // nodes 1, 2, 5, 6 at x = L
    for (int a : {1, 2, 5, 6}) end_force += r->force[3 * a];
    EXPECT_NEAR(end_force, lambda * s11 * W * H, 1e-12 * E);
    EXPECT_NEAR(r->strain_energy, 0.5 * s11 * (lambda * lambda - 1.0) / 2.0 * L * W * H, 1e-12 * E);
  }
}

// ---- Jacobian ----------------------------------------------------------------------------------

// min_jacobian: positive for a valid element, <= 0 for an inverted one (a node pushed through
// the opposite face), in the reference (small strain) or current (NLGEOM) configuration.
TEST(Hex8Full, MinJacobianFlagsInvertedElements) {
  const auto ok = run(make_input(kUnitCube, Nodes{}, false));
  EXPECT_NEAR(ok->min_jacobian, 0.125, 1e-15);
  Nodes inverted_x = kUnitCube;
  inverted_x[6] = {-0.5, -0.5, -0.5};
  EXPECT_LE(run(make_input(inverted_x, Nodes{}, false))->min_jacobian, 0.0);
  Nodes u{};
  u[6] = {-1.5, -1.5, -1.5};
  EXPECT_LE(run(make_input(kUnitCube, u, true))->min_jacobian, 0.0);
  EXPECT_GT(run(make_input(kUnitCube, u, false))->min_jacobian, 0.0);  // small strain: reference
}

}  // namespace
}  // namespace abut
