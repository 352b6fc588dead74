// Every solid element type from an .inp deck through the static solver: a bar under a uniform
// pressure on its end faces (*DLOAD Pn on whichever faces S1..Sn lie there), supported without
// restraining its lateral contraction. The exact solution is uniaxial stress sigma_xx = -p, a
// linear displacement field u = (-p x, nu p y, nu p z) / E, which every element represents
// exactly: nodal displacements to round-off check the reader (node orders, face numbers), the
// element and the consistent pressure loads of each face type together.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../element/cell_grid.hpp"
#include "abut/io/deck.hpp"
#include "abut/solver/static_solver.hpp"

namespace abut {
namespace {

constexpr double kE = 200000.0, kNu = 0.3, kP = 50.0;
constexpr double kL = 4.0;

std::string bar_deck(CellType type, bool reduced) {
  // 4 x 2 x 2 cells on a 4 x 1 x 1 bar, the inner nodes moved so that no element is regular.
  const auto g = test::cell_grid(type, 4, 2, 2, {kL, 1.0, 1.0}, [](int i, int j, int k, Vec3 p) {
    if (i > 0 && i < 4 && j == 1 && k == 1) p += Vec3{0.11 * (i - 2), 0.07, -0.05};
    return p;
  });
  std::string deck = "*NODE, NSET=NALL\n";
  for (std::size_t a = 0; a < g.nodes.size(); ++a) {
    const Vec3 x = g.nodes.position(a);
    deck += std::to_string(a + 1) + ", " + std::to_string(x.x) + ", " + std::to_string(x.y) + ", " +
            std::to_string(x.z) + "\n";
  }
  const CellTopology& t = topology(type);
  deck += "*ELEMENT, TYPE=" + std::string(t.abaqus) + (reduced ? "R" : "") + ", ELSET=EALL\n";
  std::string loads;
  for (std::size_t e = 0; e < g.cells.size(); ++e) {
    std::string line = std::to_string(e + 1);
    for (const std::int32_t n : g.cells[e]) line += ", " + std::to_string(n + 1);
    // CalculiX's layout: 16 entries on the first line, the rest on the next.
    std::size_t cut = 0;
    for (int commas = 0; cut < line.size() && commas < 16; ++cut) commas += line[cut] == ',';
    if (cut < line.size()) line = line.substr(0, cut) + "\n" + line.substr(cut + 1);
    deck += line + "\n";
    for (std::size_t f = 0; f < t.faces.size(); ++f) {
      bool at_end = true;
      for (int k = 0; k < t.faces[f].size(); ++k)
        at_end = at_end && g.nodes.position(g.cells[e][t.faces[f].nodes[k]]).x == kL;
      if (at_end) loads += std::to_string(e + 1) + ", P" + std::to_string(f + 1) + ", 50.\n";
    }
  }
  // Supports: x = 0 held along x; the origin also along y and z, (0,1,0) along z, (0,0,1) along y.
  std::string support = "*BOUNDARY\n";
  for (std::size_t a = 0; a < g.nodes.size(); ++a) {
    const Vec3 x = g.nodes.position(a);
    if (x.x != 0.0) continue;
    const std::string id = std::to_string(a + 1);
    support += id + ", 1, 1\n";
    if (x.y == 0.0 && x.z == 0.0) support += id + ", 2, 3\n";
    if (x.y == 1.0 && x.z == 0.0) support += id + ", 3, 3\n";
    if (x.y == 0.0 && x.z == 1.0) support += id + ", 2, 2\n";
  }
  deck += "*MATERIAL, NAME=STEEL\n*ELASTIC\n200000., 0.3\n";
  deck += "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n" + support;
  deck += "*STEP\n*STATIC\n*DLOAD\n" + loads + "*END STEP\n";
  return deck;
}

TEST(StaticElements, BarUnderEndPressureIsExactForEveryType) {
  struct Case {
    CellType type;
    bool reduced;
  };
  for (const Case c :
       {Case{CellType::hex8, false}, Case{CellType::hex20, false}, Case{CellType::hex20, true},
        Case{CellType::tet4, false}, Case{CellType::tet10, false}, Case{CellType::wedge6, false}}) {
    SCOPED_TRACE(std::string(topology(c.type).abaqus) + (c.reduced ? "R" : ""));
    const DeckResult deck = read_inp_string_with_notes(bar_deck(c.type, c.reduced), "bar.inp");
    const Model& model = deck.model;
    StaticSolver solver(model);
    solver.run();
    const auto u = solver.displacement();
    const Nodes& nodes = model.mesh.nodes;
    for (std::size_t a = 0; a < nodes.size(); ++a) {
      const Vec3 x = nodes.position(a);
      EXPECT_NEAR(u[3 * a], -kP * x.x / kE, 1e-12);
      EXPECT_NEAR(u[3 * a + 1], kNu * kP * x.y / kE, 1e-12);
      EXPECT_NEAR(u[3 * a + 2], kNu * kP * x.z / kE, 1e-12);
    }
  }
}

}  // namespace
}  // namespace abut
