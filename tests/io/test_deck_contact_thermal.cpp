// Thermal contact input: fid_thermal and fric_heat of *CONTACT (seed 000) and *CONTACT_THERMAL
// (abut's own: Metafor's pressure law, OptiStruct's open/closed conductance, Radioss's distance
// law), each read into ContactSpec, and each mistake a file:line error at its field.
#include <gmock/gmock.h>

#include "abut/solver/simulation.hpp"
#include "test_deck_helpers.hpp"

namespace abut {
namespace {

using testing::error_of;
using ::testing::HasSubstr;
using testing::kBoxModel;
using testing::model_of;
using testing::with_contact;

TEST(DeckContactThermal, FidThermalAndFricHeatOfContact) {
  const Model m = model_of(std::string(kBoxModel) +
                           "*FUNCTION\n7\n100 + 1e-3 * pres - 1e4 * gap\n"
                           "*CONTACT\n5\nP, 1, P, 1\n0\n0, 0, 7, 20, 0, 0, , 1\n");
  const ContactSpec& c = m.contacts.at(0);
  ASSERT_TRUE(c.thermal.valid());
  Variables v;
  v.pres = 2e6;
  v.gap = 1e-3;
  EXPECT_DOUBLE_EQ(m.functions.value(c.thermal, v), 100.0 + 2e3 - 10.0);
  EXPECT_TRUE(c.friction_heat);
  EXPECT_EQ(c.friction_heat_to_surface1, 0.5);
  EXPECT_FALSE(c.conductance.has_value());
}

TEST(DeckContactThermal, EachLawOfContactThermal) {
  using Law = ContactSpec::Conductance::Law;
  {
    const Model m = model_of(with_contact("*CONTACT_THERMAL\n5, PRESSURE, 1e4, 2e9, 0.8\n"));
    const ContactSpec& c = m.contacts.at(0);
    ASSERT_TRUE(c.conductance.has_value());
    EXPECT_EQ(c.conductance->law, Law::Pressure);
    EXPECT_EQ(c.conductance->nominal, 1e4);
    EXPECT_EQ(c.conductance->hardness, 2e9);
    EXPECT_EQ(c.conductance->exponent, 0.8);
    // The row of *CONTACT_THERMAL.
    EXPECT_EQ(m.sources.of(SourceEntity::Contact, c.id, "conductance").line, 17u);
  }
  {
    const Model m = model_of(with_contact("*CONTACT_THERMAL\n5, OPEN_CLOSED, 500, 5, , 0.25\n"));
    const ContactSpec& c = m.contacts.at(0);
    EXPECT_EQ(c.conductance->law, Law::OpenClosed);
    EXPECT_EQ(c.conductance->closed, 500.0);
    EXPECT_EQ(c.conductance->open, 5.0);
    EXPECT_EQ(c.friction_heat_to_surface1, 0.25);
  }
  {
    const Model m =
        model_of(with_contact("*CURVE\n3\n0, 100\n0.001, 0\n*CONTACT_THERMAL\n5, DISTANCE, 3\n"));
    const ContactSpec& c = m.contacts.at(0);
    EXPECT_EQ(c.conductance->law, Law::Distance);
    ASSERT_TRUE(c.distance_conductance.valid());
    EXPECT_DOUBLE_EQ(m.functions.value(c.distance_conductance, 5e-4, {}), 50.0);
  }
  {  // only the share of the friction heat
    const Model m = model_of(with_contact("*CONTACT_THERMAL\n5, , , , , 1.0\n"));
    EXPECT_FALSE(m.contacts.at(0).conductance.has_value());
    EXPECT_EQ(m.contacts.at(0).friction_heat_to_surface1, 1.0);
  }
}

TEST(DeckContactThermal, MistakesNameTheirField) {
  const auto field = [](const std::string& row) {
    return error_of(with_contact("*CONTACT_THERMAL\n" + row + "\n")).where().field;
  };
  EXPECT_EQ(field("5, WARM, 1"), "law");
  EXPECT_EQ(field("5, PRESSURE, -1, 2e9"), "h_1");
  EXPECT_EQ(field("5, PRESSURE, 1e4, 0"), "h_2");
  EXPECT_EQ(field("5, PRESSURE, 1e4"), "h_2");  // H_v is required
  EXPECT_EQ(field("5, PRESSURE, 1e4, 2e9, -1"), "h_3");
  EXPECT_EQ(field("5, OPEN_CLOSED, 100, 1, 3"), "h_3");
  EXPECT_EQ(field("5, DISTANCE"), "h_1");
  EXPECT_EQ(field("5, DISTANCE, 99"), "h_1");  // no *CURVE 99
  EXPECT_EQ(field("5, , 100"), "law");
  EXPECT_EQ(field("5, OPEN_CLOSED, 100, 0, , 1.5"), "f_heat");
  EXPECT_EQ(field("6, OPEN_CLOSED, 100"), "coid");  // no *CONTACT 6
}

// A thermal contact without a temperature field is refused when the run is set up, at the
// *CONTACT, rather than run without heat.
TEST(DeckContactThermal, NeedsThermalPropertiesToRun) {
  const Model m = model_of(with_contact("*CONTACT_THERMAL\n5, OPEN_CLOSED, 100\n"));
  try {
    Simulation sim(m);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 17u);  // the row of *CONTACT_THERMAL
    EXPECT_EQ(e.where().field, "law");
    EXPECT_THAT(e.message(),
                HasSubstr("thermal properties (thpid of the material and its *PROP_THERMAL)"));
  }
  const Model both = model_of(std::string(kBoxModel) +
                              "*FUNCTION\n7\n100\n*CONTACT\n5\nP, 1, P, 1\n0\n0, 0, 7\n"
                              "*CONTACT_THERMAL\n5, OPEN_CLOSED, 100\n");
  try {
    Simulation sim(both);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 22u);  // the row of *CONTACT_THERMAL
    EXPECT_THAT(e.message(), HasSubstr("fid_thermal"));
  }
}

}  // namespace
}  // namespace abut
