// Explicit runs of every solid cell type (element/solid_cell_block.hpp; hexahedra through the
// one-point SolidBlock as the baseline), from element cards in the .k dialect
// (verification/cell_deck.hpp): the 1-D wave problems of test_elastic_wave_bar.cpp and
// test_contact_bars.cpp, whose references are elementary 1-D wave theory (Graff, "Wave Motion in
// Elastic Solids", 1975, ch. 2): with Poisson's ratio 0 a bar is exactly 1-D, a front carries the
// stress rho c v at c = sqrt(E / rho), and two equal bars meeting at +-v stay in contact for 2L/c
// and leave with their velocities swapped. The energy balance is checked at every cycle.
//
// Meshes: boxes of n x 1 x 1 hexahedra, each kept (C3D8, C3D20), split into 6 tetrahedra (C3D4,
// C3D10) or 2 wedges (C3D6): the tetrahedra and wedges lie askew to the bar, so a front crosses
// cells of several shapes and orientations at once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include "abut/mesh/skin.hpp"
#include "cell_deck.hpp"
#include "run_to.hpp"

namespace abut {
namespace {

constexpr double kRho = 7800.0, kE = 210e9, kV = 10.0;
constexpr CellType kTypes[] = {CellType::hex8, CellType::hex20, CellType::tet4, CellType::tet10,
                               CellType::wedge6};

constexpr double kSideOfBars = 0.001;  // the bars' cross-section: 1 mm x 1 mm
const char* kMaterial = "*MAT_ELASTIC\n1, 7800.0, 210.0e9, 0.0\n";

// The largest |energy balance error| over the cycles once the energies exceed 1e-3 of `scale`.
struct Balance {
  double worst = 0.0;
  void record(const Simulation& s, double scale) {
    const Energies e = s.energies();
    if (std::max(std::abs(e.total()), std::abs(e.external_work)) > 1e-3 * scale)
      worst = std::max(worst, std::abs(s.energy_balance_error()));
  }
};

double centroid_x(const Model& model, std::size_t e) {
  const SolidRef cell = model.mesh.solid(e);
  double x = 0.0;
  const int corners = topology(cell.type).corners;
  for (int a = 0; a < corners; ++a)
    x += model.mesh.nodes.x[static_cast<std::size_t>(cell.nodes[static_cast<std::size_t>(a)])];
  return x / corners;
}

// The stress behind and ahead of a front at `front` (a fraction of the bar's length) in a bar of
// `slabs` equal slabs along x: 1-D theory speaks of a cross-section, so each slab's stress is the
// volume-weighted mean of its cells' (one grid cell long: one hexahedron, or its 6 tetrahedra or
// 2 wedges). Checked from 15% of the bar behind the front on and 10% ahead of it (the front is
// spread by the bulk viscosity and rings behind: test_elastic_wave_bar.cpp).
struct Plateau {
  double mean_error = 0.0, worst_behind = 0.0, worst_ahead = 0.0;
  int behind = 0, ahead = 0;
};
Plateau plateau(const Model& model, const Simulation& sim, int slabs, double expected, double front,
                double length = 1.0) {
  std::vector<double> mises;
  sim.von_mises_stress(mises);
  const auto n = static_cast<std::size_t>(slabs);
  std::vector<double> slab_sum(n, 0.0), slab_volume(n, 0.0);
  for (std::size_t e = 0; e < mises.size(); ++e) {
    const auto slab =
        std::min(n - 1, static_cast<std::size_t>(centroid_x(model, e) / length * slabs));
    const double v = solid_volume(model.mesh, e);
    slab_sum[slab] += mises[e] * v;
    slab_volume[slab] += v;
  }
  Plateau p;
  double sum = 0.0, volume = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double x = (static_cast<double>(k) + 0.5) / slabs, stress = slab_sum[k] / slab_volume[k];
    if (x > front + 0.15 && x < 0.95) {
      p.worst_behind = std::max(p.worst_behind, std::abs(stress - expected) / expected);
      sum += slab_sum[k];
      volume += slab_volume[k];
      ++p.behind;
    } else if (x < front - 0.1) {
      p.worst_ahead = std::max(p.worst_ahead, stress / expected);
      ++p.ahead;
    }
  }
  p.mean_error = (sum / volume - expected) / expected;
  return p;
}

// Runs a bar of `slabs` slabs over `length`, its end at x = length held, until the front is
// halfway back, and checks the plateau: its mean is what momentum conservation fixes (0.5%); the
// slabs ring about it with the dispersion of each discretisation (1.1-1.9% for C3D8, C3D10, C3D6,
// 2.9% for C3D20, whose midside nodes are spaced h/2, 4.5% for C3D4 with the average nodal
// pressure, 2.6% without; 3.2 and 3.8% for hex27 and hex64), bounded at 5% to catch a gross error;
// at least `checked` slabs behind the front and ahead of it; the energy balance at every cycle.
void check_wave_bar(const Model& model, const std::string& name, int slabs, double length,
                    double side, int checked) {
  const double c = std::sqrt(kE / kRho), expected = kRho * c * kV;
  const double kinetic = 0.5 * kRho * length * side * side * kV * kV;
  Simulation sim(model);
  Balance balance;
  verification::run_to(sim, 0.5 * length / c,
                       [&](const Simulation& s) { balance.record(s, kinetic); });
  const Plateau p = plateau(model, sim, slabs, expected, 1.0 - c * sim.time() / length, length);
  std::cout << name << ": plateau stress error: mean " << 100.0 * p.mean_error
            << "%, largest over the slabs " << 100.0 * p.worst_behind << "%, ahead "
            << 100.0 * p.worst_ahead << "% of rho c v; energy balance " << 100.0 * balance.worst
            << "%; " << sim.cycle() << " cycles\n";
  EXPECT_LT(std::abs(p.mean_error), 0.005);
  EXPECT_LT(p.worst_behind, 0.05);
  EXPECT_LT(p.worst_ahead, 0.02);
  EXPECT_GT(p.behind, checked);
  EXPECT_GT(p.ahead, checked);
  EXPECT_LT(balance.worst, 0.01);
}

// Runs two bars of `length` meeting at +-10 m/s to the deck's end time: contact for 2L/c once,
// velocities swapped (2%), the energy balance at every cycle.
void check_two_bars(const Model& model, const std::string& name, double length, double side) {
  const double c = std::sqrt(kE / kRho), expected = 2.0 * length / c;
  const double kinetic = 2.0 * 0.5 * kRho * length * side * side * kV * kV;
  Simulation sim(model);
  verification::ContactSpans spans;
  Balance balance;
  spans.start(sim);
  verification::run_to(sim, sim.end_time(), [&](const Simulation& s) {
    spans.record(s);
    balance.record(s, kinetic);
  });
  const auto parts = sim.part_states();
  const double duration = spans.end - spans.begin;
  std::cout << name << ": contact " << duration << " s, 2L/c " << expected << " s ("
            << 100.0 * (duration - expected) / expected << "%); velocities after "
            << parts.at(0).velocity.x << ", " << parts.at(1).velocity.x << " m/s; energy balance "
            << 100.0 * balance.worst << "%; " << sim.cycle() << " cycles\n";
  EXPECT_EQ(spans.periods, 1);
  EXPECT_NEAR(duration, expected, 0.02 * expected);
  EXPECT_NEAR(parts.at(0).velocity.x, -kV, 0.02 * kV);
  EXPECT_NEAR(parts.at(1).velocity.x, kV, 0.02 * kV);
  EXPECT_LT(balance.worst, 0.01);
}

// A bar 1 m x 10 mm x 10 mm of 100 cells along x at 10 m/s against a wall at x = 1 m (its end
// held): the front runs back at c with sigma = rho c v behind it.
TEST(ExplicitCells, WaveBarStressBehindTheFrontIsRhoCV) {
  for (const CellType type : kTypes) {
    SCOPED_TRACE(std::string(topology(type).abaqus));
    const auto g = test::cell_grid(type, 100, 1, 1, {1.0, 0.01, 0.01});
    const std::string deck = "*UNIT_SYSTEM\nSI\n*TIME\n2.5e-4\n" +
                             verification::cell_cards(type, g, 1, 1, 1) + kMaterial +
                             "*PART\n\"bar\"\n1, 1\n*INITIAL_VELOCITY\nP, 1, 10.0, 0.0, 0.0\n"
                             "*GEOMETRY_BOX\n1\n0.999, -1.0, -1.0, 1.001, 1.0, 1.0\n"
                             "*BC_MOTION\nG, 1, XYZ\n*END\n";
    const Model model = read_deck_string(deck, "wave_bar.k");
    ASSERT_EQ(model.mesh.solid_count(), g.cells.size());
    check_wave_bar(model, std::string(topology(type).abaqus), 100, 1.0, 0.01, 20);
  }
}

// The same bar as generated hexahedra raised to order 2 and 3 by *CHANGE_P-ORDER, as Lagrange
// hexahedra (*CONTROL_P-ORDER LAGRANGE: hex27, hex64) with the same node spacing of 10 mm
// (50 x 1 x 1 hex27, 33 x 1 x 1 hex64 over 0.99 m); the slabs are the elements.
TEST(ExplicitCells, LagrangeHexahedraWaveBarStressBehindTheFrontIsRhoCV) {
  for (const int order : {2, 3}) {
    SCOPED_TRACE(order);
    const int cells = order == 2 ? 50 : 33;
    const double length = 0.01 * order * cells;
    const std::string deck =
        "*UNIT_SYSTEM\nSI\n*TIME\n2.5e-4\n*COMPONENT_BOX\n1, 1, " + std::to_string(cells) +
        ", 1, 1\n0.0, 0.0, 0.0, " + std::to_string(length) + ", " + std::to_string(0.01 * order) +
        ", " + std::to_string(0.01 * order) +
        "\n*CONTROL_P-ORDER\nLAGRANGE\n*CHANGE_P-ORDER\nP, 1, " + std::to_string(order) + "\n" +
        kMaterial + "*PART\n\"bar\"\n1, 1\n*INITIAL_VELOCITY\nP, 1, 10.0, 0.0, 0.0\n" +
        "*GEOMETRY_BOX\n1\n" + std::to_string(length - 0.001) + ", -1.0, -1.0, " +
        std::to_string(length + 0.001) + ", 1.0, 1.0\n*BC_MOTION\nG, 1, XYZ\n*END\n";
    const Model model = read_deck_string(deck, "wave_bar.k");
    ASSERT_EQ(model.mesh.solid_count(), static_cast<std::size_t>(cells));
    ASSERT_EQ(model.mesh.cells.size(), 1u);
    EXPECT_EQ(model.mesh.cells[0].type, order == 2 ? CellType::hex27 : CellType::hex64);
    check_wave_bar(model, std::string(topology(model.mesh.cells[0].type).name), cells, length,
                   0.01 * order, 6);
  }
}

// Two bars 0.1 m x 1 mm x 1 mm of 100 cells each, 0.1 mm apart, meeting at +-10 m/s with
// surface-to-surface contact (pfac = E / h, test_contact_bars.cpp).
TEST(ExplicitCells, TwoBarsTouchForTwoLOverCAndSwapVelocities) {
  constexpr double kL = 0.1, kSide = 0.001;
  constexpr int kCells = 100;
  for (const CellType type : kTypes) {
    SCOPED_TRACE(std::string(topology(type).abaqus));
    const auto g = test::cell_grid(type, kCells, 1, 1, {kL, kSide, kSide});
    const auto nodes = static_cast<std::int64_t>(g.nodes.size());
    const auto cells = static_cast<std::int64_t>(g.cells.size());
    const std::string deck =
        "*UNIT_SYSTEM\nSI\n*TIME\n6e-5\n" +
        verification::cell_cards(type, g, 1, 1, 1, {-kL - 0.00005, 0.0, 0.0}) +
        verification::cell_cards(type, g, 2, nodes + 1, cells + 1, {0.00005, 0.0, 0.0}) +
        kMaterial +
        "*PART\n\"left bar\"\n1, 1\n\"right bar\"\n2, 1\n*INITIAL_VELOCITY\nP, 1, 10.0, 0.0, "
        "0.0\n*INITIAL_VELOCITY\nP, 2, -10.0, 0.0, 0.0\n*CONTACT\n\"bar ends\"\n1\nP, 1, P, 2, "
        "0.0, " +
        fmt::format("{:.17g}", kE * kCells / kL) + "\n*END\n";
    check_two_bars(read_deck_string(deck, "bars.k"), std::string(topology(type).abaqus), kL, kSide);
  }
}

// The same two bars as generated hexahedra raised to Lagrange hexahedra (hex27: 50 per bar,
// hex64: 33 per bar, so that nodes stay 1 mm apart along the bar; 0.1 and 0.099 m long), the
// contact on their lattice facets.
TEST(ExplicitCells, LagrangeHexahedraTwoBarsTouchForTwoLOverC) {
  for (const int order : {2, 3}) {
    SCOPED_TRACE(order);
    const int cells = order == 2 ? 50 : 33;
    const double length = 0.001 * order * cells;
    const auto box = [&](int id, double x0) {
      return fmt::format(
          "*COMPONENT_BOX\n{0}, {0}, {1}, 1, 1\n{2:.17g}, 0.0, 0.0, {3:.17g}, {4}, {4}\n", id,
          cells, x0, x0 + length, kSideOfBars);
    };
    const std::string deck =
        "*UNIT_SYSTEM\nSI\n*TIME\n6e-5\n" + box(1, -length - 0.00005) + box(2, 0.00005) +
        "*CONTROL_P-ORDER\nLAGRANGE\n*CHANGE_P-ORDER\nALL, 0, " + std::to_string(order) + "\n" +
        kMaterial +
        "*PART\n\"left bar\"\n1, 1\n\"right bar\"\n2, 1\n*INITIAL_VELOCITY\nP, 1, 10.0, 0.0, "
        "0.0\n*INITIAL_VELOCITY\nP, 2, -10.0, 0.0, 0.0\n*CONTACT\n\"bar ends\"\n1\nP, 1, P, 2, "
        "0.0, " +
        fmt::format("{:.17g}", kE / 0.001) + "\n*END\n";
    const Model model = read_deck_string(deck, "bars.k");
    ASSERT_EQ(model.mesh.hex_count(), 0u);
    check_two_bars(model, std::string(topology(model.mesh.cells[0].type).name), length,
                   kSideOfBars);
  }
}

// The wave bar and the two bars again, as generated boxes cut into tetrahedra by
// *CHANGE_TO_TETRAHEDRA (5 or 6 per hex, each cut by its own node numbers, so the tetrahedra
// are not the regular 6-per-cube pattern of the card meshes above, and the bars' end faces are
// triangulated independently of each other).
TEST(ExplicitCells, GeneratedTetrahedraWaveBarAndTwoBars) {
  for (const int nodes : {4, 10}) {
    SCOPED_TRACE(nodes);
    const std::string name = nodes == 4 ? "generated C3D4" : "generated C3D10";
    const std::string cut = "*CHANGE_TO_TETRAHEDRA\nALL, 0, " + std::to_string(nodes) + "\n";
    const std::string bar =
        "*UNIT_SYSTEM\nSI\n*TIME\n2.5e-4\n*COMPONENT_BOX\n1, 1, 100, 1, 1\n0.0, 0.0, 0.0, 1.0, "
        "0.01, 0.01\n" +
        cut + kMaterial +
        "*PART\n\"bar\"\n1, 1\n*INITIAL_VELOCITY\nP, 1, 10.0, 0.0, 0.0\n"
        "*GEOMETRY_BOX\n1\n0.999, -1.0, -1.0, 1.001, 1.0, 1.0\n*BC_MOTION\nG, 1, XYZ\n*END\n";
    check_wave_bar(read_deck_string(bar, "wave_bar.k"), name, 100, 1.0, 0.01, 20);

    constexpr double kL = 0.1;
    const auto box = [&](int id, double x0) {
      return fmt::format(
          "*COMPONENT_BOX\n{0}, {0}, 100, 1, 1\n{1:.17g}, 0.0, 0.0, {2:.17g}, {3}, {3}\n", id, x0,
          x0 + kL, kSideOfBars);
    };
    const std::string bars =
        "*UNIT_SYSTEM\nSI\n*TIME\n6e-5\n" + box(1, -kL - 0.00005) + box(2, 0.00005) + cut +
        kMaterial +
        "*PART\n\"left bar\"\n1, 1\n\"right bar\"\n2, 1\n*INITIAL_VELOCITY\nP, 1, 10.0, 0.0, "
        "0.0\n*INITIAL_VELOCITY\nP, 2, -10.0, 0.0, 0.0\n*CONTACT\n\"bar ends\"\n1\nP, 1, P, 2, "
        "0.0, " +
        fmt::format("{:.17g}", kE * 100 / kL) + "\n*END\n";
    const Model model = read_deck_string(bars, "bars.k");
    ASSERT_EQ(model.mesh.hex_count(), 0u);
    check_two_bars(model, name, kL, kSideOfBars);
  }
}

}  // namespace
}  // namespace abut
