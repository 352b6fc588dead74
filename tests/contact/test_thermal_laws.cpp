// Thermal contact laws (contact/laws/thermal.hpp) against their definitions: Metafor's
// h_c = h_c0 (p/H_v)^w (seed 002), OptiStruct's open/closed conductance (seed 003), a
// distance-dependent conductance (Radioss), IMPETUS's function (seed 000), and the friction heat
// split.
#include <gtest/gtest.h>

#include <cmath>

#include "abut/contact/laws/thermal.hpp"

namespace abut {
namespace {

TEST(ThermalContactLaws, MetaforPressureConductance) {
  const ConductanceLaw law = PressureConductance{2.0e4, 1.0e9, 0.7};
  EXPECT_DOUBLE_EQ(conductance(law, 1.0e9, -1e-6), 2.0e4);
  // Doubling the pressure multiplies the conductance by 2^w (issue 11's verification case).
  EXPECT_NEAR(conductance(law, 2.0e8, 0.0) / conductance(law, 1.0e8, 0.0), std::pow(2.0, 0.7),
              1e-14);
  EXPECT_EQ(conductance(law, 0.0, 1e-3), 0.0);
  EXPECT_EQ(conductance(law, -5.0, 0.0), 0.0);  // tension: no conduction
}

TEST(ThermalContactLaws, OptiStructOpenAndClosed) {
  const ConductanceLaw law = OpenClosedConductance{5000.0, 20.0};
  EXPECT_EQ(conductance(law, 1e6, -1e-5), 5000.0);
  EXPECT_EQ(conductance(law, 0.0, 0.0), 5000.0);  // touching is closed
  EXPECT_EQ(conductance(law, 0.0, 1e-4), 20.0);
}

TEST(ThermalContactLaws, DistanceAndFunctionConductances) {
  const ConductanceLaw distance = DistanceConductance{[](double g) { return 100.0 / (1.0 + g); }};
  EXPECT_EQ(conductance(distance, 0.0, 1.0), 50.0);
  EXPECT_EQ(conductance(distance, 3e6, -0.01), 100.0);  // in contact: f(0)
  const ConductanceLaw function =
      FunctionConductance{[](double p, double g) { return 1.0 + 1e-3 * p - 10.0 * g; }};
  EXPECT_DOUBLE_EQ(conductance(function, 2000.0, 0.01), 2.9);
}

TEST(ThermalContactLaws, FrictionHeatSplit) {
  const FrictionHeatSplit half;
  EXPECT_EQ(half.side1(3.0) + half.side2(3.0), 3.0);
  EXPECT_EQ(half.side1(3.0), 1.5);
  const FrictionHeatSplit biased{0.8};
  EXPECT_DOUBLE_EQ(biased.side1(10.0), 8.0);
  EXPECT_DOUBLE_EQ(biased.side2(10.0), 2.0);
}

}  // namespace
}  // namespace abut
