// *MAT_METAL and *MAT_JC: fields into MetalParams, the flow curve bound, unsupported options as
// errors at their field.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "test_deck_helpers.hpp"

namespace abut {
namespace {

using testing::error_of;
using testing::model_of;

const std::string kMesh = R"(*UNIT_SYSTEM
SI
*TIME
1.0e-3
*COMPONENT_BOX
1, 1, 1, 1, 1
0.0, 0.0, 0.0, 0.01, 0.01, 0.01
*PART
"bar"
1, 1
)";

TEST(DeckMetals, MetalReadsItsFlowCurve) {
  const Model m = model_of(
      kMesh + "*MAT_METAL\n1, 7800.0, 210.0e9, 0.3\n7\n*FUNCTION\n7\n167e6 + 415e6*epsp^0.3\n");
  const auto& p = std::get<MetalParams>(m.materials.at(0).params);
  EXPECT_DOUBLE_EQ(p.young, 210e9);
  EXPECT_DOUBLE_EQ(p.poisson, 0.3);
  EXPECT_FALSE(p.johnson_cook);
  ASSERT_TRUE(p.flow_curve.valid());
  Variables v;
  v.epsp = 0.1;
  EXPECT_NEAR(m.functions.value(p.flow_curve, 0.1, v), 167e6 + 415e6 * std::pow(0.1, 0.3), 1e-3);
}

// m, T0, Tm of both keywords (thermal softening, metal.hpp; the Simulation checks that the
// material has a temperature field).
TEST(DeckMetals, ThermalSofteningFields) {
  const Model jc = model_of(
      kMesh + "*MAT_JC\n1, 8960.0, 124.0e9, 0.34\n90e6, 292e6, 0.31, 0.025, 1.09, 298, 1356\n");
  const auto& p = std::get<MetalParams>(jc.materials.at(0).params);
  EXPECT_DOUBLE_EQ(p.softening_m, 1.09);
  EXPECT_DOUBLE_EQ(p.room_temperature, 298.0);
  EXPECT_DOUBLE_EQ(p.melting_temperature, 1356.0);
  const Model metal = model_of(kMesh +
                               "*MAT_METAL\n1, 7800.0, 210.0e9, 0.3\n7, 0, 0, 0, 1, 0.5, 20, 1500\n"
                               "*CURVE\n7\n0, 1e8\n1, 2e8\n");
  const auto& q = std::get<MetalParams>(metal.materials.at(0).params);
  EXPECT_DOUBLE_EQ(q.softening_m, 0.5);
  EXPECT_DOUBLE_EQ(q.room_temperature, 20.0);
  EXPECT_DOUBLE_EQ(q.melting_temperature, 1500.0);
}

TEST(DeckMetals, JohnsonCookFieldsAndDefaults) {
  const Model m = model_of(kMesh + "*MAT_JC\n1, 8960.0, 124.0e9, 0.34\n90e6, 292e6, 0.31, 0.025\n");
  const auto& p = std::get<MetalParams>(m.materials.at(0).params);
  EXPECT_TRUE(p.johnson_cook);
  EXPECT_DOUBLE_EQ(p.a, 90e6);
  EXPECT_DOUBLE_EQ(p.b, 292e6);
  EXPECT_DOUBLE_EQ(p.n, 0.31);
  EXPECT_DOUBLE_EQ(p.c, 0.025);
  EXPECT_DOUBLE_EQ(p.rate0, 1.0);
}

TEST(DeckMetals, UnsupportedOptionsAreErrorsAtTheirField) {
  EXPECT_EQ(
      error_of(kMesh + "*MAT_METAL\n1, 7800.0, 210.0e9, 0.3\n7, 0.5\n*CURVE\n7\n0, 1e8\n1, 2e8\n")
          .where()
          .field,
      "xi");
  EXPECT_EQ(
      error_of(kMesh + "*MAT_METAL\n1, 7800.0, 210.0e9, 0.3\n7, 0, 1\n*CURVE\n7\n0, 1e8\n1, 2e8\n")
          .where()
          .field,
      "yield");
  EXPECT_EQ(
      error_of(kMesh +
               "*MAT_METAL\n1, 7800.0, 210.0e9, 0.3\n7, 0, 0, 0.1\n*CURVE\n7\n0, 1e8\n1, 2e8\n")
          .where()
          .field,
      "c");
  // Thermal softening with m > 0 needs Tm above T0.
  const InputError thermal =
      error_of(kMesh + "*MAT_JC\n1, 8960.0, 124.0e9, 0.34\n90e6, 292e6, 0.31, 0.025, 1.09\n");
  EXPECT_EQ(thermal.where().field, "Tm");
  EXPECT_EQ(thermal.where().line, 13u);
  EXPECT_EQ(error_of(kMesh + "*MAT_JC\n1, 8960.0, 124.0e9, 0.34\n90e6, 292e6, 0.31, 0, -1\n")
                .where()
                .field,
            "m");
  EXPECT_EQ(error_of(kMesh + "*MAT_JC\n1, 8960.0, 124.0e9, 0.34\n0, 292e6\n").where().field, "A");
  EXPECT_EQ(error_of(kMesh + "*MAT_METAL\n1, 7800.0, 210.0e9, 0.3\n9\n").where().field,
            "cid");  // no curve 9
}

TEST(DeckMetals, DamagePropertyBindsToTheMetalsDid) {
  const Model m = model_of(kMesh +
                           "*MAT_JC\n1, 7800.0, 210.0e9, 0.3, 4\n300e6, 500e6, 0.5\n"
                           "*PROP_DAMAGE_JC\n4, 0.05, 3.44, -2.12, 0.002, 0, 2.0\n");
  const auto& f = std::get<MetalParams>(m.materials.at(0).params).failure;
  EXPECT_TRUE(f.active);
  EXPECT_DOUBLE_EQ(f.d1, 0.05);
  EXPECT_DOUBLE_EQ(f.d2, 3.44);
  EXPECT_DOUBLE_EQ(f.d3, -2.12);
  EXPECT_DOUBLE_EQ(f.d4, 0.002);
  EXPECT_DOUBLE_EQ(f.rate0, 2.0);
  const std::string jc = "*MAT_JC\n1, 7800.0, 210.0e9, 0.3, 4\n300e6, 500e6, 0.5\n";
  const InputError missing = error_of(kMesh + jc);
  EXPECT_EQ(missing.where().field, "did");
  EXPECT_EQ(missing.where().line, 12u);
  // The thermal factor d5 needs the metal's Tm above T0 (line 2 of *MAT_JC).
  const InputError no_tm = error_of(kMesh + jc + "*PROP_DAMAGE_JC\n4, 0.05, 0, 0, 0, 1.0\n");
  EXPECT_EQ(no_tm.where().field, "did");
  EXPECT_NE(no_tm.message().find("melting temperature Tm above T0"), std::string::npos);
  const Model hot = model_of(kMesh +
                             "*MAT_JC\n1, 7800.0, 210.0e9, 0.3, 4\n300e6, 500e6, 0.5, 0, 0, "
                             "20, 1520\n*PROP_DAMAGE_JC\n4, 0.05, 0, 0, 0, 1.5\n");
  EXPECT_DOUBLE_EQ(std::get<MetalParams>(hot.materials.at(0).params).failure.d5, 1.5);
  EXPECT_EQ(error_of(kMesh + jc + "*PROP_DAMAGE_JC\n4, 0.0\n").where().field, "d1");
  EXPECT_EQ(error_of(kMesh + "*MAT_ELASTIC\n1, 7800.0, 210.0e9, 0.3, 4\n").where().field, "did");
}

}  // namespace
}  // namespace abut
