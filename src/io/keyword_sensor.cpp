// *SENSOR (abut's own, after Radioss /SENSOR TIME, DIST and INTER), *CONTACT_SENSOR (Radioss
// /INTER/TYPE25 sens_ID) and *CONTACT_RELEASE_BC (Radioss IBCX, IBCY, IBCZ). Seed 004: a sensor
// given to an interface switches it, and its Tstart, Tstop are then not used (comment 10); the
// flagged boundary conditions of the secondary nodes are released at impact. The solver side is
// src/solver/sensors.cpp and src/solver/simulation_sensors.cpp.
#include <set>

#include "deck_reader.hpp"

namespace abut::deck {

void read_sensor(DeckReader& d, Block& b) {
  using Kind = Sensor::Kind;
  while (!b.done()) {
    const Row r = b.row({"sid", "type", "value", "sense", "delay", "id_1", "id_2"});
    Sensor s;
    s.id = d.other_id(r, 0);
    d.claim_id("sensor", s.id, r.where(0));
    s.kind = word_choice(r, 1, Kind::Time,
                         {{"TIME", Kind::Time},
                          {"DISTANCE", Kind::Distance},
                          {"DIST", Kind::Distance},
                          {"CONTACT_FORCE", Kind::ContactForce},
                          {"INTER", Kind::ContactForce}},
                         "TIME, DISTANCE (between two nodes) or CONTACT_FORCE (total normal force "
                         "of a *CONTACT)");
    if (!r.given(1)) r.fail(1, "expected the sensor type TIME, DISTANCE or CONTACT_FORCE");
    s.threshold = r.number(2);
    s.delay = r.number_or(4, 0.0);
    r.require(s.delay >= 0.0, 4, "expected a delay >= 0 [time]");
    s.where = r.where();
    switch (s.kind) {
      case Kind::Time:
        r.require(s.threshold >= 0.0, 2, "expected the time at which the sensor triggers, >= 0");
        if (r.given(3)) r.fail(3, "a TIME sensor triggers once t >= value: leave sense empty");
        if (r.given(5) || r.given(6))
          r.fail(r.given(5) ? 5 : 6, "a TIME sensor takes no ids: leave id_1 and id_2 empty");
        break;
      case Kind::Distance:
        r.require(s.threshold > 0.0, 2, "expected a distance > 0 [length]");
        s.node1 = EntityRef{EntityType::Node, d.node_id(r, 5), r.where(5)};
        s.node2 = EntityRef{EntityType::Node, d.node_id(r, 6), r.where(6)};
        if (s.node1.id == s.node2.id)
          r.fail(6, "expected two different nodes (their distance is always 0)");
        d.entity_references.push_back(s.node1);
        d.entity_references.push_back(s.node2);
        break;
      case Kind::ContactForce:
        r.require(s.threshold >= 0.0, 2, "expected a force >= 0 [force]");
        s.contact = d.other_id(r, 5);
        if (r.given(6)) r.fail(6, "a CONTACT_FORCE sensor watches one *CONTACT: give id_1 only");
        break;
    }
    if (s.kind != Kind::Time) {
      if (!r.given(3))
        r.fail(3, "expected ABOVE (triggers when the value exceeds the threshold) or BELOW");
      s.below = word_choice(r, 3, false, {{"ABOVE", false}, {"BELOW", true}},
                            "ABOVE (triggers when the value exceeds the threshold) or BELOW");
    }
    d.model.sensors.push_back(std::move(s));
  }
}

void read_contact_sensor(DeckReader& d, Block& b) {
  const Row r = b.row({"coid", "sid", "action"});
  const std::int64_t sid = d.other_id(r, 1);
  const bool off = word_choice(r, 2, false, {{"ON", false}, {"OFF", true}},
                               "ON (the contact acts from the time the sensor is on; Radioss) or "
                               "OFF (the contact acts until then)");
  contact_place(d, r, "sensor", 1);
  refine_contact(d, r, [sid, off](ContactSpec& c) {
    c.sensor = sid;
    c.sensor_switches_off = off;
  });
}

void read_contact_release_bc(DeckReader& d, Block& b) {
  const Row r = b.row({"coid", "ibcx", "ibcy", "ibcz"});
  const std::uint8_t mask = static_cast<std::uint8_t>(
      (r.flag(1) ? kFixX : 0) | (r.flag(2) ? kFixY : 0) | (r.flag(3) ? kFixZ : 0));
  if (mask == 0) r.fail(1, "expected at least one of ibcx, ibcy, ibcz to be 1");
  // The row as a whole: any of the three asks for the release.
  d.model.sources.set(SourceEntity::Contact, d.other_id(r, 0), "release_bc", r.where());
  refine_contact(d, r, [mask](ContactSpec& c) { c.release_bc = mask; });
}

// Once every *CONTACT is merged: the contact of each CONTACT_FORCE sensor and the sensor of each
// *CONTACT_SENSOR must exist.
void check_sensors(const Model& model) {
  std::set<std::int64_t> contact_ids, sensor_ids;
  for (const ContactSpec& c : model.contacts) contact_ids.insert(c.id);
  for (const Sensor& s : model.sensors) sensor_ids.insert(s.id);
  for (const Sensor& s : model.sensors)
    if (s.kind == Sensor::Kind::ContactForce && !contact_ids.count(s.contact))
      throw InputError(with_field(s.where, "id_1"),
                       "contact " + std::to_string(s.contact) +
                           " does not exist: id_1 of a CONTACT_FORCE sensor must be the ctid of "
                           "a *CONTACT (defined contacts: " +
                           joined(contact_ids) + ")");
  for (const ContactSpec& c : model.contacts)
    if (c.sensor && !sensor_ids.count(*c.sensor))
      throw InputError(model.place_of(c, "sensor"),
                       "sensor " + std::to_string(*c.sensor) +
                           " does not exist (defined sensors: " + joined(sensor_ids) + ")");
}

}  // namespace abut::deck
