// Node-to-surface contact at facet edges, borders and concave corners (issue 27, item 4).
//
// 1. Two identical elastic bars, each at v toward the other, node-to-surface (Radioss TYPE25,
//    OptiStruct N2S), one-way and symmetric, on matched end meshes (every end node lands on the
//    other end's facet edges, corners and border) and on end meshes whose inner grid lines are
//    offset by a random fraction of an element (fixed seed). Elementary 1D wave theory (Graff,
//    "Wave Motion in Elastic Solids", 1975, ch. 2; Goldsmith, "Impact", 1960, ch. 4): the contact
//    lasts 2L/c, c = sqrt(E/rho), and the bars' velocities reverse (each bar's momentum changes
//    sign). The bars here are 3D with lateral freedom (Poisson's ratio 0.3): c is the 1D bar
//    speed, the reference for a bar of 5 mm across and 100 mm long (its first lateral mode is far
//    above the pulse: the Pochhammer correction to the speed, (nu pi r / lambda)^2 for the pulse's
//    wavelength lambda ~ 2L, is about 0.02%). The contact is frictionless and undamped, so the
//    total energy is conserved (closed form: E(t) = E(0), checked within 1% at every cycle). The
//    interface spring of a suddenly applied load overshoots its static compression at most
//    twice (dynamic load factor 2, Clough & Penzien, "Dynamics of Structures", 1975, sec. 4-2):
//    2 rho c v / pfac on average over the interface. The check takes the largest penetration of
//    any point, 3 rho c v / pfac: on non-matching meshes single nodes sit deeper than the mean
//    (the 2x bound chosen first was exceeded by 2% in the symmetric offset cell, at one node;
//    what the check is for is the failure mode, 270x). Before issue 27 the border nodes of the
//    matched mesh projected a round-off beyond the other end's sharp border, dropped out and came
//    back deeper (+99.5% energy, 0.26 mm penetration).
// 2. An elastic block pressed by a body force into the 90-degree corner of two fixed shell plates
//    (N2S, frictionless, undamped). The body force is ramped up over 5 ms and held, so the block
//    is pressed in quasi-statically; the energy balance E(t) - E(0) = W(t) (kinetic + internal +
//    contact springs against the body force's work) must hold within 1% at every cycle. Before
//    issue 27 the nodes on the block's corner edge took the closer wall alone and their force
//    flipped between the two walls' normals, which did work at every flip (+12% one-way, +101%
//    symmetric at 20 ms; with a sudden load +58%). The region behind a concave corner is the union
//    of the walls' half-spaces, so the penalty potential is the sum of the walls' (Wriggers,
//    "Computational Contact Mechanics", 2nd ed., 2006, sec. 4.1): every penetrated wall pushes.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "run_to.hpp"

namespace abut {
namespace {

constexpr double kRho = 7800.0, kE = 210e9, kV = 4.0, kL = 0.1, kB = 0.005;
// 160 x 4 x 4 elements, 0.625 mm along and 1.25 mm across: with 80 along the contact lasted 2.1%
// longer than 2L/c in one cell, the release front smeared by the bulk viscosity over ~sqrt(h L)
// (test_contact_bars.cpp).
constexpr int kAlong = 160, kAcross = 4;
constexpr double kH = kL / kAlong;
constexpr double kPfac = kE / kH;  // the axial stiffness of one element per unit area

// Two bars along x with a 4 x 4 cross-section; the right bar's inner grid lines across are
// shifted by fractions (sy, sz) of an element (0: the matched mesh).
std::string bars_deck(bool symmetric, double sy, double sz) {
  std::ostringstream d;
  d.precision(17);
  d << "*UNIT_SYSTEM\nSI\n*TIME\n6.0e-5\n*NODE\n";
  const double h = kB / kAcross;
  int id = 0;
  std::ostringstream elements;
  int eid = 0;
  for (int part = 1; part <= 2; ++part) {
    const double x0 = part == 1 ? -kL - 5e-5 : 5e-5;
    const double shift_y = part == 1 ? 0.0 : sy, shift_z = part == 1 ? 0.0 : sz;
    const auto line = [&](int i, double s) { return i == 0 || i == kAcross ? i * h : (i + s) * h; };
    const int base = id;
    const auto node = [&](int i, int j, int k) {
      return base + 1 + i + (kAlong + 1) * (j + (kAcross + 1) * k);
    };
    for (int k = 0; k <= kAcross; ++k)
      for (int j = 0; j <= kAcross; ++j)
        for (int i = 0; i <= kAlong; ++i)
          d << ++id << ", " << x0 + kL * i / kAlong << ", " << line(j, shift_y) << ", "
            << line(k, shift_z) << "\n";
    for (int k = 0; k < kAcross; ++k)
      for (int j = 0; j < kAcross; ++j)
        for (int i = 0; i < kAlong; ++i)
          elements << ++eid << ", " << part << ", " << node(i, j, k) << ", " << node(i + 1, j, k)
                   << ", " << node(i + 1, j + 1, k) << ", " << node(i, j + 1, k) << ", "
                   << node(i, j, k + 1) << ", " << node(i + 1, j, k + 1) << ", "
                   << node(i + 1, j + 1, k + 1) << ", " << node(i, j + 1, k + 1) << "\n";
  }
  d << "*ELEMENT_SOLID\n" << elements.str();
  d << "*MAT_ELASTIC\n1, " << kRho << ", " << kE << ", 0.3\n"
    << "*PART\n\"left bar\"\n1, 1\n\"right bar\"\n2, 1\n"
    << "*INITIAL_VELOCITY\nP, 1, " << kV << ", 0.0, 0.0\n"
    << "*INITIAL_VELOCITY\nP, 2, " << -kV << ", 0.0, 0.0\n"
    << "*CONTACT\n\"bar ends\"\n1\nP, 1, P, 2, 0.0, " << kPfac << "\n0, 0.0\n"
    << "*CONTACT_DISCRETIZATION\n1, N2S, " << (symmetric ? 1 : 0) << "\n*END\n";
  return d.str();
}

struct Impact : verification::ContactSpans {
  double worst_energy = 0.0;  // largest |E(t) - E(0)| / E(0) over the cycles
  double penetration = 0.0;   // largest over the cycles
  double v_left = 0.0, v_right = 0.0;
};

Impact collide(bool symmetric, double sy, double sz) {
  const Model model = read_deck_string(bars_deck(symmetric, sy, sz), "n2s_bars.k");
  Simulation sim(model);
  Impact r;
  const double e0 = sim.energies().total();
  r.start(sim);
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    r.record(s);
    const ContactStats& stats = s.contact_reports()[0].stats;
    r.worst_energy = std::max(r.worst_energy, std::abs(s.energies().total() - e0) / e0);
    r.penetration = std::max(r.penetration, stats.max_penetration);
  });
  const auto parts = sim.part_states();
  r.v_left = parts.at(0).velocity.x;
  r.v_right = parts.at(1).velocity.x;
  return r;
}

struct Cell {
  bool symmetric;
  bool offset;
};

class NodeToSurfaceBars : public ::testing::TestWithParam<Cell> {};

TEST_P(NodeToSurfaceBars, ConserveEnergyAndTouchForTwoLOverC) {
  const Cell cell = GetParam();
  double sy = 0.0, sz = 0.0;
  if (cell.offset) {  // a random fraction of an element, the same in every run
    std::mt19937 random(27);
    std::uniform_real_distribution<double> fraction(0.1, 0.9);
    sy = fraction(random);
    sz = fraction(random);
  }
  const Impact r = collide(cell.symmetric, sy, sz);
  const double c = std::sqrt(kE / kRho);
  const double expected = 2.0 * kL / c;
  const double duration = r.end - r.begin;
  const double static_penetration = kRho * c * kV / kPfac;
  std::cout << (cell.symmetric ? "symmetric" : "one-way") << " N2S, "
            << (cell.offset ? "offset" : "matched") << " mesh (shift " << sy << ", " << sz
            << " of an element): energy error " << 100.0 * r.worst_energy
            << "% (largest over the cycles), contact " << duration << " s, 2L/c = " << expected
            << " s, error " << 100.0 * (duration - expected) / expected << "%; penetration "
            << r.penetration << " m (rho c v / pfac = " << static_penetration
            << " m); velocities after " << r.v_left << ", " << r.v_right << " m/s\n";
  EXPECT_EQ(r.periods, 1);  // one uninterrupted contact
  ASSERT_GT(r.end, r.begin);
  EXPECT_LT(r.worst_energy, 0.01);
  EXPECT_NEAR(duration, expected, 0.02 * expected);
  EXPECT_LT(r.penetration, 3.0 * static_penetration);
  // The velocities reverse; the 3D bars keep a few percent of the energy ringing afterwards.
  EXPECT_NEAR(r.v_left, -kV, 0.05 * kV);
  EXPECT_NEAR(r.v_right, kV, 0.05 * kV);
}

INSTANTIATE_TEST_SUITE_P(Matrix, NodeToSurfaceBars,
                         ::testing::Values(Cell{false, false}, Cell{true, false}, Cell{false, true},
                                           Cell{true, true}),
                         [](const ::testing::TestParamInfo<Cell>& cell) {
                           return std::string(cell.param.symmetric ? "Symmetric" : "OneWay") +
                                  (cell.param.offset ? "OffsetMesh" : "MatchedMesh");
                         });

// An aluminium block of 2 x 2 x 2 elements (20 mm) in the corner of two fixed steel shell plates
// 2 mm thick (floor z = 0, wall y = 0, both with their contact surfaces at 1 mm), pressed in by a
// body force along (0, -1, -1) ramped to 1000 m/s^2 per component over 5 ms, for 20 ms.
std::string corner_deck(bool symmetric) {
  return R"(
*UNIT_SYSTEM
SI
*TIME
0.02
*COMPONENT_BOX
1, 1, 2, 2, 2
0.0, 0.001, 0.001, 0.02, 0.021, 0.021
*COMPONENT_SHELL_PLATE
2, 2, 4, 4
-0.01, 0.0, 0.0, 0.03, 0.0, 0.0
-0.01, 0.04, 0.0
*COMPONENT_SHELL_PLATE
3, 3, 4, 4
-0.01, 0.0, 0.0, -0.01, 0.0, 0.04
0.03, 0.0, 0.0
*MAT_ELASTIC
1, 2700.0, 70.0e9, 0.3
*MAT_ELASTIC
2, 7800.0, 210.0e9, 0.3
*PART
"block"
1, 1
"floor"
2, 2, , 0.002
"wall"
3, 2, , 0.002
*SET_PART
9
2, 3
*BC_MOTION
P, 2, XYZ, XYZ
*BC_MOTION
P, 3, XYZ, XYZ
*CURVE
1
0.0, 0.0
0.005, -1000.0
1.0, -1000.0
*LOAD_GRAVITY
Y, 1
Z, 1
*CONTACT
"block in the corner"
1
P, 1, PS, 9, 0.0
0, 0.0
*CONTACT_DISCRETIZATION
1, N2S, )" +
         std::string(symmetric ? "1" : "0") +
         R"(
*END
)";
}

class NodeToSurfaceCorner : public ::testing::TestWithParam<bool> {};

TEST_P(NodeToSurfaceCorner, EnergyBalanceHoldsAtEveryCycle) {
  const bool symmetric = GetParam();
  const Model model = read_deck_string(corner_deck(symmetric), "n2s_corner.k");
  Simulation sim(model);
  std::vector<double> time, work, error;
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    time.push_back(s.time());
    work.push_back(s.energies().external_work);
    error.push_back(std::abs(s.energy_balance_error()));
  });
  const Energies e = sim.energies();
  // Every cycle once the work done is above 1e-3 of its final value (in the first cycles the
  // energies are round-off, 1e-20 J, and their ratio means nothing).
  double worst = 0.0, worst_time = 0.0;
  for (std::size_t k = 0; k < time.size(); ++k)
    if (work[k] > 1e-3 * e.external_work && error[k] > worst)
      worst = error[k], worst_time = time[k];
  std::cout << (symmetric ? "symmetric" : "one-way") << " N2S in a concave corner: work "
            << e.external_work << " J, largest balance error " << 100.0 * worst << "% (at "
            << worst_time << " s), at the end " << 100.0 * sim.energy_balance_error()
            << "%, kinetic energy at the end " << e.kinetic << " J\n";
  ASSERT_GT(e.external_work, 0.0);
  EXPECT_LT(worst, 0.01);
  // Settled: the block rests in the corner (its kinetic energy a small part of the work).
  EXPECT_LT(e.kinetic, 0.01 * e.external_work);
}

INSTANTIATE_TEST_SUITE_P(Corner, NodeToSurfaceCorner, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& side) {
                           return std::string(side.param ? "Symmetric" : "OneWay");
                         });

}  // namespace
}  // namespace abut
