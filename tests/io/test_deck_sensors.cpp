// *SENSOR, *CONTACT_SENSOR and *CONTACT_RELEASE_BC (abut's own; Radioss /SENSOR, /INTER/TYPE25
// sens_ID and IBC, seed 004): read into Model::sensors and ContactSpec, and each mistake a
// file:line error at its field; static steps refuse them at their line.
#include <gmock/gmock.h>

#include "test_deck_helpers.hpp"

namespace abut {
namespace {

using testing::error_of;
using ::testing::HasSubstr;
using testing::kBoxModel;
using testing::model_of;
using testing::with_contact;

// The line of `text` on which the last occurrence of `needle` is (1-based).
std::size_t line_of(const std::string& text, const std::string& needle) {
  const std::size_t at = text.rfind(needle);
  EXPECT_NE(at, std::string::npos) << needle;
  std::size_t line = 1;
  for (std::size_t i = 0; i < at && i < text.size(); ++i) line += text[i] == '\n';
  return line;
}

// The error of `deck`: in t.k, on the line of the last `needle`, at `field`, with `message`.
void expect_error(const std::string& deck, const std::string& needle, const std::string& field,
                  const std::string& message) {
  const InputError e = error_of(deck);
  EXPECT_EQ(e.where().file, "t.k") << e.what();
  EXPECT_EQ(e.where().line, line_of(deck, needle)) << e.what();
  EXPECT_EQ(e.where().field, field) << e.what();
  EXPECT_THAT(e.what(), HasSubstr(message));
}

TEST(DeckSensors, EveryKindAndTheContactKeywords) {
  const Model m =
      model_of(with_contact("*SENSOR\n1, TIME, 0.002, , 1e-4\n2, DISTANCE, 0.5, BELOW, , 1, 2\n"
                            "3, CONTACT_FORCE, 100, ABOVE, , 5\n*CONTACT_SENSOR\n5, 2, OFF\n"
                            "*CONTACT_RELEASE_BC\n5, 1, 0, 1\n"));
  ASSERT_EQ(m.sensors.size(), 3u);
  EXPECT_EQ(m.sensors[0].kind, Sensor::Kind::Time);
  EXPECT_EQ(m.sensors[0].threshold, 0.002);
  EXPECT_EQ(m.sensors[0].delay, 1e-4);
  EXPECT_EQ(m.sensors[1].kind, Sensor::Kind::Distance);
  EXPECT_TRUE(m.sensors[1].below);
  EXPECT_EQ(m.sensors[1].node1.id, 1);
  EXPECT_EQ(m.sensors[1].node2.id, 2);
  EXPECT_EQ(m.sensors[2].kind, Sensor::Kind::ContactForce);
  EXPECT_FALSE(m.sensors[2].below);
  EXPECT_EQ(m.sensors[2].contact, 5);
  const ContactSpec& c = m.contacts.at(0);
  ASSERT_TRUE(c.sensor.has_value());
  EXPECT_EQ(*c.sensor, 2);
  EXPECT_TRUE(c.sensor_switches_off);
  EXPECT_EQ(c.release_bc, kFixX | kFixZ);
  // Radioss's words for the types are synonyms; the action defaults to ON.
  const Model r =
      model_of(with_contact("*SENSOR\n4, DIST, 0.5, ABOVE, , 1, 2\n6, INTER, 1, BELOW, , 5\n"
                            "*CONTACT_SENSOR\n5, 4\n"));
  EXPECT_EQ(r.sensors[0].kind, Sensor::Kind::Distance);
  EXPECT_EQ(r.sensors[1].kind, Sensor::Kind::ContactForce);
  EXPECT_FALSE(r.contacts.at(0).sensor_switches_off);
}

TEST(DeckSensors, MistakesNameTheirFileLineAndField) {
  const auto sensor = [](const std::string& row) { return with_contact("*SENSOR\n" + row + "\n"); };
  expect_error(sensor("1, CLOCK, 1"), "1, CLOCK", "type", "TIME, DISTANCE");
  expect_error(sensor("1, , 1"), "1, , 1", "type", "expected the sensor type");
  expect_error(sensor("1, TIME, -1"), "1, TIME", "value", "time at which the sensor triggers");
  expect_error(sensor("1, TIME, 1, , -2"), "1, TIME", "delay", "delay >= 0");
  expect_error(sensor("1, TIME, 1, ABOVE"), "1, TIME", "sense", "leave sense empty");
  expect_error(sensor("1, DISTANCE, 0, BELOW, , 1, 2"), "1, DISTANCE", "value", "distance > 0");
  expect_error(sensor("1, DISTANCE, 1, , , 1, 2"), "1, DISTANCE", "sense", "ABOVE");
  expect_error(sensor("1, DISTANCE, 1, UP, , 1, 2"), "1, DISTANCE", "sense", "ABOVE");
  expect_error(sensor("1, DISTANCE, 1, BELOW, , 1, 1"), "1, DISTANCE", "id_2", "two different");
  expect_error(sensor("1, DISTANCE, 1, BELOW, , 1, 999"), "1, DISTANCE", "id_2", "999");
  expect_error(sensor("1, CONTACT_FORCE, 1, ABOVE, , 8"), "1, CONTACT_FORCE", "id_1",
               "contact 8 does not exist");
  expect_error(sensor("1, CONTACT_FORCE, -1, ABOVE, , 5"), "1, CONTACT_FORCE", "value",
               "force >= 0");
  expect_error(sensor("1, TIME, 1\n1, TIME, 2"), "1, TIME, 2", "sid", "sensor");
  expect_error(with_contact("*CONTACT_SENSOR\n5, 9\n"), "5, 9", "sid", "sensor 9 does not exist");
  expect_error(with_contact("*SENSOR\n1, TIME, 1\n*CONTACT_SENSOR\n5, 1, LATER\n"), "5, 1, LATER",
               "action", "ON");
  expect_error(with_contact("*SENSOR\n1, TIME, 1\n*CONTACT_SENSOR\n7, 1\n"), "7, 1", "coid",
               "contact 7 does not exist");
  expect_error(with_contact("*CONTACT_RELEASE_BC\n5, 0, 0, 0\n"), "5, 0, 0, 0", "ibcx",
               "at least one");
  expect_error(with_contact("*CONTACT_RELEASE_BC\n5, 0, 2, 0\n"), "5, 0, 2, 0", "ibcy", "");
}

TEST(DeckSensors, StaticStepsRefuseThem) {
  std::string deck = std::string(kBoxModel);
  deck.erase(deck.find("*TIME\n1.0e-3\n"), std::string("*TIME\n1.0e-3\n").size());
  deck += "*CONTACT\n5\nP, 1, P, 1\n*STATIC\n1.0\n";
  expect_error(deck + "*SENSOR\n1, TIME, 0.5\n", "1, TIME", "",
               "sensors (*SENSOR) are not supported in static steps");
  expect_error(deck + "*CONTACT_RELEASE_BC\n5, 0, 0, 1\n", "5, 0, 0, 1", "",
               "releasing boundary conditions at impact (*CONTACT_RELEASE_BC) is not supported "
               "in static steps");
}

}  // namespace
}  // namespace abut
