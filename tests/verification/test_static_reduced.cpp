// The one-point hexahedron (C3D8R) with hourglass stiffness in statics (issue 10): the cantilever
// of static_cantilever.hpp against Timoshenko's tip deflection. A one-point element does not lock
// in bending, so, unlike C3D8, it needs no very short elements; its error comes from the
// hourglass stiffness, which resists the bending mode of each element (FB81 stiffness form,
// coefficient 0.05 of 2G, as in the explicit solver) and from the mesh. Both shrink with the
// element size h: the error must fall as the mesh is refined and stay within 3% on the finest.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "abut/mesh/generators.hpp"
#include "abut/solver/static_solver.hpp"
#include "static_cantilever.hpp"

namespace abut {
namespace {

using namespace cantilever;

double reduced_tip(int along, int through) {
  Model m;
  generate_box(m.mesh, {1, along, through, 1, {0, 0, 0}, {kL, kH, kW}});
  m.materials.push_back(elastic());
  m.parts.push_back(part(1, Part::SolidIntegration::Reduced));
  clamp_and_load(m);
  StaticSolver s(m);
  s.run();
  return tip_deflection(m, s);
}

TEST(StaticReduced, CantileverConvergesToTimoshenko) {
  const double reference = timoshenko_deflection();
  double previous = INFINITY;
  for (const int n : {2, 4, 8}) {
    const double tip = reduced_tip(4 * n, n);
    const double error = tip / reference - 1.0;
    std::cout << "C3D8R " << 4 * n << " x " << n << ": tip " << tip << ", Timoshenko " << reference
              << " (" << 100 * error << "%)\n";
    EXPECT_LT(std::abs(error), previous);
    previous = std::abs(error);
  }
  EXPECT_LT(previous, 0.03);
}

}  // namespace
}  // namespace abut
