// The materials the static solver takes (solver/static/static_elements.cpp): what it cannot
// honour is an error naming the part, never a law quietly run without one of its terms.
#include <gtest/gtest.h>

#include <string>

#include "abut/mesh/generators.hpp"
#include "abut/solver/static_solver.hpp"

namespace abut {
namespace {

Model block_of(const MetalParams& metal) {
  Model m;
  generate_box(m.mesh, {1, 2, 2, 1, {0, 0, 0}, {1, 1, 1}});
  Material mat;
  mat.id = 1;
  mat.params = metal;
  m.materials.push_back(mat);
  Part p;
  p.id = 1;
  p.material_id = 1;
  p.title = "disc";
  m.parts.push_back(p);
  m.static_steps.push_back(StaticStep{});
  return m;
}

std::string error_of(const Model& m) {
  try {
    const StaticSolver s(m);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(StaticMaterials, ThermalSofteningAndDuctileFailureAreErrors) {
  MetalParams steel;
  steel.density = 7.8e-9, steel.young = 2.1e5, steel.poisson = 0.3, steel.johnson_cook = true;
  steel.a = 300.0;
  EXPECT_EQ(error_of(block_of(steel)), "");
  MetalParams softening = steel;
  softening.softening_m = 1.0, softening.room_temperature = 20.0;
  softening.melting_temperature = 1500.0;
  EXPECT_NE(error_of(block_of(softening))
                .find("part 1 (disc): thermal softening (m > 0) is not "
                      "supported in static steps yet"),
            std::string::npos);
  MetalParams failing = steel;
  failing.failure.active = true, failing.failure.d1 = 0.1;
  // A model made in code: the message in the model's words (a deck names its keyword).
  EXPECT_NE(error_of(block_of(failing)).find("ductile failure is not supported in static steps"),
            std::string::npos);
}

}  // namespace
}  // namespace abut
