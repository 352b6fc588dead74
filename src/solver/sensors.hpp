#pragma once
// The *SENSOR conditions of a model during an explicit run (model.hpp Sensor; Radioss /SENSOR
// TIME, DIST and INTER): each is checked once per cycle, at t^n, and once met it stays met, so
// that a contact it switches does not chatter when the watched value crosses back. The time it
// triggered is the whole state (restart files keep it).
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "abut/model/model.hpp"
#include "abut/solver/contact_report.hpp"

namespace abut {

class StateArchive;

class SensorSet {
 public:
  explicit SensorSet(const Model& model);  // node and contact references resolved

  bool empty() const { return sensors_.empty(); }
  // Checks every sensor not yet triggered at time t: positions at t, and the contacts' reports of
  // the last apply (the force a contact carried at the previous cycle). Appends a log line for
  // each one that triggers.
  void update(double t, std::span<const double> x, std::span<const double> y,
              std::span<const double> z, const std::vector<ContactReport>& reports,
              std::vector<std::string>& messages);
  // Is the sensor with this id on at time t (triggered at least its delay ago)?
  bool on(std::int64_t id, double t) const;
  // The time the sensor with this id triggered; infinity while it has not (or no such sensor).
  double triggered_at(std::int64_t id) const;
  void archive(StateArchive& a);

 private:
  struct Watch {
    const Sensor* sensor = nullptr;
    std::int32_t node1 = -1, node2 = -1;                         // Distance
    double triggered = std::numeric_limits<double>::infinity();  // time it triggered
  };
  double value(const Watch& w, double t, std::span<const double> x, std::span<const double> y,
               std::span<const double> z, const std::vector<ContactReport>& reports) const;
  std::vector<Watch> sensors_;
};

}  // namespace abut
