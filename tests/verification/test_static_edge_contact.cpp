// A beam pried between two plates (CalculiX's beamcontact, test suite of ccx 2.20, with its beam's
// C3D20R elements divided twice in each direction and its penalty x 100): a cantilever 1 x 1.5 x 8
// clamped at z = 0, pushed along x at mid-height, whose tip sits between two fixed plates that
// start exactly touching its faces. It pivots on one plate's lower edge and swings its tip into
// the other: surface-to-surface contact on a sharp edge, with points at a gap of zero at the start.
// With K = 1e10 (about 2.5e4 E/h) abut stopped: first its cells' tangent k n (x) n missed the turn
// of their push (docs/contact.md), then the points at zero gap opened and closed for 14 iterations
// before the contact settled, and the increment was cut back at 16 until it was too small.
// Reference (statics, closed form): the reactions of the clamp and the plates balance the load,
// force and moment, in the deformed configuration; the contact passes the moment from the beam to
// the plates, so a contact force at the wrong place or out of balance shows here.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <sstream>
#include <string>

#include "abut/io/deck.hpp"
#include "abut/solver/static_solver.hpp"

namespace abut {
namespace {

constexpr double kLoad = 1000.0;  // N along x at (0, 0.75, 4)

// The deck: r divisions of the original 2 x 2 x 8 C3D20R beam per element edge.
std::string pried_beam_deck(int r, double penalty) {
  const int nx = 2 * r, ny = 2 * r, nz = 8 * r;
  const double lx = 1.0, ly = 1.5, lz = 8.0;
  std::ostringstream d;
  std::map<std::array<int, 3>, int> id;
  d << "*NODE, NSET=Nall\n";
  int n = 0;
  for (int k = 0; k <= 2 * nz; ++k)
    for (int j = 0; j <= 2 * ny; ++j)
      for (int i = 0; i <= 2 * nx; ++i) {
        if (i % 2 + j % 2 + k % 2 > 1) continue;  // serendipity: no face or body centres
        id[{i, j, k}] = ++n;
        d << n << "," << lx * i / (2 * nx) << "," << ly * j / (2 * ny) << "," << lz * k / (2 * nz)
          << "\n";
      }
  const int plates = n + 1;
  const double plate[16][3] = {{1, 2, 8.5},   {1, -.5, 8.5},   {1, -.5, 7.5},   {1, 2, 7.5},
                               {1.1, 2, 8.5}, {1.1, -.5, 8.5}, {1.1, -.5, 7.5}, {1.1, 2, 7.5},
                               {-.1, 2, 8.5}, {-.1, -.5, 8.5}, {-.1, -.5, 7.5}, {-.1, 2, 7.5},
                               {0, 2, 8.5},   {0, -.5, 8.5},   {0, -.5, 7.5},   {0, 2, 7.5}};
  for (const auto& p : plate) d << ++n << "," << p[0] << "," << p[1] << "," << p[2] << "\n";
  d << "*ELEMENT, TYPE=C3D20R, ELSET=Eall\n";
  int e = 0;
  std::ostringstream minus, plus;  // the beam's faces beside the plates: x = 0 (S6), x = 1 (S4)
  for (int c = 0; c < nz; ++c)
    for (int b = 0; b < ny; ++b)
      for (int a = 0; a < nx; ++a) {
        const int i = 2 * a, j = 2 * b, k = 2 * c;
        const int at[20][3] = {
            {i, j, k},         {i + 2, j, k},         {i + 2, j + 2, k},     {i, j + 2, k},
            {i, j, k + 2},     {i + 2, j, k + 2},     {i + 2, j + 2, k + 2}, {i, j + 2, k + 2},
            {i + 1, j, k},     {i + 2, j + 1, k},     {i + 1, j + 2, k},     {i, j + 1, k},
            {i + 1, j, k + 2}, {i + 2, j + 1, k + 2}, {i + 1, j + 2, k + 2}, {i, j + 1, k + 2},
            {i, j, k + 1},     {i + 2, j, k + 1},     {i + 2, j + 2, k + 1}, {i, j + 2, k + 1}};
        d << ++e;
        for (int q = 0; q < 20; ++q)  // 15 nodes on the first line, as CalculiX writes them
          d << (q == 15 ? ",\n" : ",") << id[{at[q][0], at[q][1], at[q][2]}];
        d << "\n";
        if (lz * (c + 1) / nz > 7.0 + 1e-9) {
          if (a == 0) minus << e << ", S6\n";
          if (a == nx - 1) plus << e << ", S4\n";
        }
      }
  d << "*ELEMENT, TYPE=C3D8, ELSET=Eall\n" << e + 1;
  for (int q = 0; q < 8; ++q) d << "," << plates + q;
  d << "\n" << e + 2;
  for (int q = 8; q < 16; ++q) d << "," << plates + q;
  d << "\n*NSET, NSET=Nfix\n";
  for (const auto& [ijk, node] : id)
    if (ijk[2] == 0) d << node << ",\n";
  for (int q = 0; q < 16; ++q) d << plates + q << ",\n";
  d << "*BOUNDARY\nNfix, 1, 3\n*MATERIAL, NAME=EL\n*ELASTIC\n210000., .3\n"
    << "*SOLID SECTION, ELSET=Eall, MATERIAL=EL\n"
    << "*SURFACE, NAME=Smast1\n"
    << e + 2 << ", S2\n*SURFACE, NAME=Smast2\n"
    << e + 1 << ", S1\n"
    << "*SURFACE, NAME=Sslav1\n"
    << minus.str() << "*SURFACE, NAME=Sslav2\n"
    << plus.str() << "*CONTACT PAIR, INTERACTION=SI1, TYPE=SURFACE TO SURFACE\nSslav1, Smast1\n"
    << "*CONTACT PAIR, INTERACTION=SI1, TYPE=SURFACE TO SURFACE\nSslav2, Smast2\n"
    << "*SURFACE INTERACTION, NAME=SI1\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n"
    << penalty << "\n*STEP, NLGEOM\n*STATIC\n0.999, 1.\n*CLOAD\n"
    << id[{0, ny, nz}] << ", 1, " << kLoad << "\n*END STEP\n";
  return d.str();
}

TEST(StaticEdgeContact, ABeamPriedBetweenPlatesBalancesItsLoad) {
  const Model m = read_inp_string_with_notes(pried_beam_deck(2, 1e10), "pried_beam.inp").model;
  // Tight tolerances, so that the balance below is the solution's, not Newton's tolerance.
  StaticControls tight;
  tight.force_tolerance = 1e-6;
  tight.displacement_tolerance = 1e-6;
  StaticSolver solver(m, tight);
  ASSERT_NO_THROW(solver.run());
  const std::span<const double> u = solver.displacement(), rf = solver.reaction();
  const Nodes& x0 = m.mesh.nodes;
  std::size_t loaded = 0;
  for (std::size_t i = 0; i < x0.size(); ++i)
    if (x0.x[i] == 0.0 && x0.y[i] == 0.75 && x0.z[i] == 4.0) loaded = i;
  // Forces along x and z, and moments about y through the origin, of the reactions and the load.
  double fx = kLoad, fz = 0.0;
  double my = (x0.z[loaded] + u[3 * loaded + 2]) * kLoad;
  double plates_fx = 0.0;
  for (std::size_t i = 0; i < x0.size(); ++i) {
    const double x = x0.x[i] + u[3 * i], z = x0.z[i] + u[3 * i + 2];
    fx += rf[3 * i], fz += rf[3 * i + 2];
    my += z * rf[3 * i] - x * rf[3 * i + 2];
    if (x0.z[i] > 7.0) plates_fx += std::abs(rf[3 * i]);
  }
  std::cout << "pried beam: plates' |Fx| " << plates_fx << " N; balance Fx " << fx << " N, Fz "
            << fz << " N, My " << my << " N mm\n";
  EXPECT_GT(plates_fx, 0.5 * kLoad);  // the plates do hold the tip
  EXPECT_NEAR(fx, 0.0, 1e-4 * kLoad);
  EXPECT_NEAR(fz, 0.0, 1e-4 * kLoad);
  EXPECT_NEAR(my, 0.0, 1e-4 * kLoad * 4.0);
}

}  // namespace
}  // namespace abut
