// Single-element uniaxial tension of J2 plasticity with isotropic hardening (*MAT_METAL with a
// *CURVE and with a *FUNCTION of epsp, *MAT_JC at C = 0), loaded, unloaded and reloaded into
// reversed yield.
//
// Reference: the uniaxial response of rate-independent J2 plasticity with isotropic hardening
// (Simo & Hughes, "Computational Inelasticity", 1998, section 1.4 and box 3.2; Lubliner,
// "Plasticity Theory", 1990, section 3.3). Under uniaxial stress sigma the von Mises stress is
// |sigma| and the plastic strain rate is along the load, so with the hypoelastic (Jaumann)
// update of abut the total logarithmic strain eps = ln(L/L0) splits as
//     eps = sigma / E + eps_p,
// and while the element flows |sigma| = sigma_y(epsp) (epsp = |eps_p| accumulated). Hence:
//  - below yield: sigma = E eps (slope E);
//  - loading beyond yield: sigma solves sigma = sigma_y(eps - sigma/E), and epsp = eps - sigma/E;
//  - unloading: elastic, sigma = sigma_u - E (eps_u - eps), epsp constant, until the reversed
//    yield at sigma = -sigma_y(epsp_u) (isotropic hardening: the elastic range is
//    2 sigma_y(epsp_u)), after which |sigma| = sigma_y(epsp) again.
// Tolerance 0.5% of the flow stress throughout (issue 8).
//
// Model: one 10 mm steel cube (E = 210 GPa, nu = 0.3, rho = 7800 kg/m^3) given as *NODE /
// *ELEMENT_SOLID. Symmetry: the faces x = 0, y = 0, z = 0 are held in X, Y, Z by the *NODE bc
// field; the top face z = h is pulled in Z by *BC_MOTION (V, Z, curve) on a node set; the faces
// x = h and y = h are free, so the stress is uniaxial. The top moves at 0.05 m/s (strain rate
// 5 /s) after a 0.2 ms ramp, is reversed over 0.2 ms at eps ~ 0.18 and then moves at -0.05 m/s.
// Quasi-static: the loading takes about 39 ms, 24000 times the element's dilatational wave
// transit h / c = 1.66 us (about 39000 cycles, 0.3 to 0.4 s); the kinetic energy (nearly all of
// it the prescribed motion of the top face) stays below 1e-4 of the internal energy once the
// element flows. Ten times faster (0.5 m/s) the inertia of the free faces leaves a lateral
// stress of 1.4% of the yield stress where the flow sets in (the free faces must speed up from
// the elastic contraction nu eps' to the plastic one eps'/2 within a few cycles).
//
// The reversed yield stress is read at the last elastic cycle, so it is resolved to one cycle's
// stress increment, E eps' dt = 0.96 MPa (0.25% of the flow stress). *MAT_JC at C = 0 and
// *MAT_METAL with the *FUNCTION 200e6 + 300e6 epsp^0.3 describe the same flow curve and give
// the same numbers to the last printed digit.
//
// sigma_zz from the element's von Mises stress q and pressure p: with sigma_xx = sigma_yy = s
// (the element is symmetric in x and y), q = |sigma_zz - s| and -3p = sigma_zz + 2s, so
// sigma_zz = -p + (2/3) q sign(sigma_zz - s) and s = -p - (1/3) q sign(...), the sign taken as
// that of -p (the axial stress dominates). s is the lateral stress left by the inertia of the
// free faces; it is printed and held below 0.5% of the initial yield stress.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "run_to.hpp"

namespace abut {
namespace {

constexpr double kE = 210e9, kH = 0.01;  // the deck's E (kElastic) and the cube's edge
constexpr double kV = 0.05;              // top face speed [m/s]
constexpr double kRamp = 2.0e-4;         // speed ramps (start and reversal) [s]
constexpr double kTurn = 3.94e-2;        // the reversal starts here: eps ~ 0.18 at the turn
constexpr double kEnd = kTurn + kRamp + 2.4e-3;
constexpr double kTol = 0.005;

using FlowCurve = std::function<double(double)>;

// Piecewise-linear flow curve of the *CURVE case: 250 MPa rising to 400 MPa over epsp 0..0.2.
const std::vector<std::pair<double, double>> kTable = {
    {0.0, 250e6}, {0.02, 290e6}, {0.05, 325e6}, {0.1, 362e6}, {0.2, 400e6}};

double table_flow(double epsp) {
  if (epsp <= kTable.front().first) return kTable.front().second;
  for (std::size_t i = 1; i < kTable.size(); ++i) {
    if (epsp <= kTable[i].first) {
      const auto [x0, y0] = kTable[i - 1];
      const auto [x1, y1] = kTable[i];
      return y0 + (y1 - y0) * (epsp - x0) / (x1 - x0);
    }
  }
  return kTable.back().second;
}

// 200 MPa + 300 MPa epsp^0.3: the *FUNCTION case and Johnson-Cook A + B epsp^n at C = 0.
double power_flow(double epsp) { return 200e6 + 300e6 * std::pow(std::max(epsp, 0.0), 0.3); }

// The loading branch: sigma = sigma_y(eps - sigma/E) for eps beyond yield (bisection on sigma).
double expected_loading_stress(const FlowCurve& flow, double eps) {
  if (kE * eps <= flow(0.0)) return kE * eps;
  double lo = flow(0.0), hi = kE * eps;  // g(lo) = lo - flow(eps - lo/E) <= 0 <= g(hi)
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid - flow(eps - mid / kE) > 0.0)
      hi = mid;
    else
      lo = mid;
  }
  return 0.5 * (lo + hi);
}

std::string tension_deck(const std::string& material) {
  char text[4096];
  std::snprintf(text, sizeof text, R"(
*TIME
%.9g
*NODE
1, 0.0, 0.0, 0.0, XYZ
2, %.9g, 0.0, 0.0, YZ
3, %.9g, %.9g, 0.0, Z
4, 0.0, %.9g, 0.0, ZX
5, 0.0, 0.0, %.9g, XY
6, %.9g, 0.0, %.9g, Y
7, %.9g, %.9g, %.9g, 0
8, 0.0, %.9g, %.9g, X
*ELEMENT_SOLID
1, 1, 1, 2, 3, 4, 5, 6, 7, 8
*SET_NODE
1
5, 6, 7, 8
*PART
"cube"
1, 1
*BC_MOTION
NS, 1
V, Z, 1
*CURVE
1
0.0, 0.0
%.9g, %.9g
%.9g, %.9g
%.9g, %.9g
%.9g, %.9g
)",
                kEnd, kH, kH, kH, kH, kH, kH, kH, kH, kH, kH, kH, kH, kRamp, kV, kTurn, kV,
                kTurn + kRamp, -kV, 1.0, -kV);
  return text + material + "*END\n";
}

struct Sample {
  double t, eps, sigma, lateral, q, epsp, kinetic, internal;
};

std::vector<Sample> run_tension(const std::string& material, const char* name) {
  const Model model = read_deck_string(tension_deck(material), name);
  Simulation sim(model);
  const std::size_t top = verification::node_near(model, kH, kH, kH);
  std::vector<Sample> samples;
  std::vector<double> q, p, ep;
  const auto started = std::chrono::steady_clock::now();
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    s.von_mises_stress(q);
    s.pressure(p);
    s.plastic_strain(ep);
    const double sign = -p[0] >= 0.0 ? 1.0 : -1.0;
    const Energies e = s.energies();
    samples.push_back({s.time(), std::log(s.z()[top] / kH), -p[0] + 2.0 / 3.0 * q[0] * sign,
                       -p[0] - q[0] / 3.0 * sign, q[0], ep[0], e.kinetic, e.internal});
  });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::cout << name << ": " << sim.cycle() << " cycles, step " << sim.initial_time_step() << " s, "
            << seconds << " s wall\n";
  return samples;
}

// The checks of the header on one run; `label` names the material in the messages.
void check_tension(const std::vector<Sample>& samples, const FlowCurve& flow, const char* label) {
  ASSERT_GT(samples.size(), 100u);
  const double yield0 = flow(0.0);

  // The turning point: largest strain.
  std::size_t turn = 0;
  for (std::size_t i = 0; i < samples.size(); ++i)
    if (samples[i].eps > samples[turn].eps) turn = i;
  ASSERT_GT(turn, 0u);
  ASSERT_LT(turn + 1, samples.size());
  const Sample u = samples[turn];

  // Loading: elastic, then plastic on the flow curve.
  double worst_elastic = 0.0, worst_flow = 0.0, worst_q = 0.0, worst_expected = 0.0,
         worst_split = 0.0, worst_lateral = 0.0, worst_kinetic = 0.0;
  int elastic_points = 0, plastic_points = 0;
  for (std::size_t i = 0; i <= turn; ++i) {
    const Sample& s = samples[i];
    worst_lateral = std::max(worst_lateral, std::abs(s.lateral) / yield0);
    if (s.epsp == 0.0) {
      if (s.sigma < 0.1 * yield0) continue;  // the first cycles of the ramp
      ++elastic_points;
      worst_elastic = std::max(worst_elastic, std::abs(s.sigma - kE * s.eps) / (kE * s.eps));
      continue;
    }
    ++plastic_points;
    const double fy = flow(s.epsp);
    worst_flow = std::max(worst_flow, std::abs(s.sigma - fy) / fy);
    worst_q = std::max(worst_q, std::abs(s.q - fy) / fy);
    const double expected = expected_loading_stress(flow, s.eps);
    worst_expected = std::max(worst_expected, std::abs(s.sigma - expected) / expected);
    worst_split = std::max(worst_split, std::abs(s.epsp - (s.eps - s.sigma / kE)));
    if (s.epsp > 0.01) worst_kinetic = std::max(worst_kinetic, s.kinetic / s.internal);
  }

  // Unloading: elastic with slope E and constant plastic strain until the reversed yield.
  std::size_t reversed = 0;
  double worst_unload = 0.0, epsp_drift = 0.0;
  for (std::size_t i = turn + 1; i < samples.size(); ++i) {
    const Sample& s = samples[i];
    if (s.epsp > u.epsp + 1e-9) {
      reversed = i;
      break;
    }
    epsp_drift = std::max(epsp_drift, std::abs(s.epsp - u.epsp));
    worst_unload =
        std::max(worst_unload, std::abs(s.sigma - (u.sigma - kE * (u.eps - s.eps))) / u.sigma);
  }
  ASSERT_GT(reversed, turn + 10) << "no elastic unloading";
  const Sample r = samples[reversed - 1];  // last elastic state: the reversed yield stress
  const double fu = flow(u.epsp);
  // Reversed plastic flow: compression on the flow curve at the current plastic strain.
  double worst_reversed = 0.0;
  for (std::size_t i = reversed; i < samples.size(); ++i) {
    const double fy = flow(samples[i].epsp);
    worst_reversed = std::max(worst_reversed, std::abs(-samples[i].sigma - fy) / fy);
  }
  const Sample last = samples.back();

  std::printf(
      "%s: %d elastic and %d plastic loading points; elastic slope error %.3g%% (worst); "
      "sigma_zz vs sigma_y(epsp) %.3g%%, von Mises vs sigma_y(epsp) %.3g%%, sigma_zz vs the "
      "solution of sigma = sigma_y(eps - sigma/E) %.3g%%; |epsp - (eps - sigma/E)| %.3g; "
      "largest lateral stress %.3g%% of the yield stress; kinetic/internal energy %.3g\n",
      label, elastic_points, plastic_points, 100 * worst_elastic, 100 * worst_flow, 100 * worst_q,
      100 * worst_expected, worst_split, 100 * worst_lateral, worst_kinetic);
  std::printf(
      "%s: turn at eps %.5f, epsp %.5f, sigma %.2f MPa (sigma_y %.2f MPa); unloading slope "
      "error %.3g%% of sigma_u, epsp drift %.3g; reversed yield at %.2f MPa vs -sigma_y(epsp_u) "
      "%.2f MPa (%.3g%%), elastic range %.5f vs 2 sigma_y/E %.5f; reversed flow %.3g%% (worst), "
      "final epsp %.5f\n",
      label, u.eps, u.epsp, u.sigma / 1e6, fu / 1e6, 100 * worst_unload, epsp_drift, r.sigma / 1e6,
      -fu / 1e6, 100 * (r.sigma + fu) / fu, u.eps - r.eps, 2 * fu / kE, 100 * worst_reversed,
      last.epsp);

  EXPECT_GT(elastic_points, 10) << label;
  EXPECT_GT(u.epsp, 0.15) << label;
  EXPECT_LT(worst_elastic, kTol) << label;
  EXPECT_LT(worst_flow, kTol) << label;
  EXPECT_LT(worst_q, kTol) << label;
  EXPECT_LT(worst_expected, kTol) << label;
  EXPECT_LT(worst_split, kTol * u.epsp) << label;  // 0.5% of the plastic strain at the turn
  EXPECT_LT(worst_lateral, kTol) << label;
  EXPECT_LT(worst_kinetic, 1e-4) << label;
  EXPECT_LT(worst_unload, kTol) << label;
  EXPECT_LT(epsp_drift, 1e-12) << label;
  EXPECT_NEAR(r.sigma, -fu, kTol * fu) << label;
  EXPECT_NEAR(u.eps - r.eps, 2 * fu / kE, kTol * 2 * fu / kE) << label;
  EXPECT_LT(worst_reversed, kTol) << label;
  EXPECT_GT(last.epsp, u.epsp + 1e-3) << label << ": too little reversed flow to check";
}

constexpr const char* kElastic = "1, 7800.0, 210.0e9, 0.3\n";

TEST(MetalTension, CurveFlowStressLoadUnloadReverse) {
  std::string material = std::string("*MAT_METAL\n") + kElastic + "2\n*CURVE\n2\n";
  char line[64];
  for (const auto& [x, y] : kTable) {
    std::snprintf(line, sizeof line, "%.9g, %.9g\n", x, y);
    material += line;
  }
  check_tension(run_tension(material, "metal_curve.k"), table_flow, "*MAT_METAL, *CURVE");
}

TEST(MetalTension, FunctionFlowStressLoadUnloadReverse) {
  const std::string material =
      std::string("*MAT_METAL\n") + kElastic + "2\n*FUNCTION\n2\n200.0e6 + 300.0e6*epsp^0.3\n";
  check_tension(run_tension(material, "metal_function.k"), power_flow, "*MAT_METAL, *FUNCTION");
}

TEST(MetalTension, JohnsonCookWithoutRateLoadUnloadReverse) {
  const std::string material = std::string("*MAT_JC\n") + kElastic + "200.0e6, 300.0e6, 0.3, 0.0\n";
  check_tension(run_tension(material, "metal_jc.k"), power_flow, "*MAT_JC, C = 0");
}

}  // namespace
}  // namespace abut
