#include "sensors.hpp"

#include <fmt/format.h>

#include <cmath>

#include "abut/core/state_archive.hpp"

namespace abut {

SensorSet::SensorSet(const Model& model) {
  for (const Sensor& s : model.sensors) {
    Watch w;
    w.sensor = &s;
    if (s.kind == Sensor::Kind::Distance) {  // the deck reader checked that both nodes exist
      w.node1 = model.nodes_of(s.node1).front();
      w.node2 = model.nodes_of(s.node2).front();
    }
    sensors_.push_back(w);
  }
}

double SensorSet::value(const Watch& w, double t, std::span<const double> x,
                        std::span<const double> y, std::span<const double> z,
                        const std::vector<ContactReport>& reports) const {
  switch (w.sensor->kind) {
    case Sensor::Kind::Time:
      return t;
    case Sensor::Kind::Distance: {
      const auto a = static_cast<std::size_t>(w.node1), b = static_cast<std::size_t>(w.node2);
      const double dx = x[a] - x[b], dy = y[a] - y[b], dz = z[a] - z[b];
      return std::sqrt(dx * dx + dy * dy + dz * dz);
    }
    case Sensor::Kind::ContactForce:
      for (const ContactReport& r : reports)
        if (r.id == w.sensor->contact) return std::abs(r.stats.normal_force);
      return 0.0;  // not reached: the deck reader checked the contact exists
  }
  return 0.0;
}

void SensorSet::update(double t, std::span<const double> x, std::span<const double> y,
                       std::span<const double> z, const std::vector<ContactReport>& reports,
                       std::vector<std::string>& messages) {
  static constexpr const char* kKind[] = {"TIME", "DISTANCE", "CONTACT_FORCE"};
  for (Watch& w : sensors_) {
    if (std::isfinite(w.triggered)) continue;  // once triggered, it stays so
    const Sensor& s = *w.sensor;
    const double v = value(w, t, x, y, z, reports);
    const bool met = s.kind == Sensor::Kind::Time ? v >= s.threshold
                     : s.below                    ? v < s.threshold
                                                  : v > s.threshold;
    if (!met) continue;
    w.triggered = t;
    std::string line = fmt::format("abut: sensor {} ({}) triggered at t = {:.6g}", s.id,
                                   kKind[static_cast<int>(s.kind)], t);
    if (s.kind != Sensor::Kind::Time)
      line += fmt::format(": value {:.6g} {} {:.6g}", v, s.below ? "below" : "above", s.threshold);
    if (s.delay > 0.0) line += fmt::format("; on from t = {:.6g} (delay)", t + s.delay);
    messages.push_back(std::move(line));
  }
}

bool SensorSet::on(std::int64_t id, double t) const {
  for (const Watch& w : sensors_)
    if (w.sensor->id == id) return std::isfinite(w.triggered) && t >= w.triggered + w.sensor->delay;
  return false;
}

double SensorSet::triggered_at(std::int64_t id) const {
  for (const Watch& w : sensors_)
    if (w.sensor->id == id) return w.triggered;
  return std::numeric_limits<double>::infinity();
}

void SensorSet::archive(StateArchive& a) {
  a.mark("sensors");
  a.expect(static_cast<std::uint64_t>(sensors_.size()), "the number of sensors");
  for (Watch& w : sensors_) a.value(w.triggered);
}

}  // namespace abut
