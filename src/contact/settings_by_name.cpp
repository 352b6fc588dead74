// The contact settings by name (settings_by_name.hpp).
#include "abut/contact/settings_by_name.hpp"

#include <cmath>
#include <functional>
#include <map>

namespace abut {
namespace {

bool flag(double value) { return value != 0.0; }

Coulomb& coulomb(ContactSettings& s) {
  if (!std::holds_alternative<Coulomb>(s.tangential_law)) s.tangential_law = Coulomb{};
  return std::get<Coulomb>(s.tangential_law);
}

using Setter = std::function<void(ContactSettings&, double)>;
const std::map<std::string, Setter, std::less<>>& setters() {
  static const std::map<std::string, Setter, std::less<>> table = {
      {"node_to_surface",
       [](ContactSettings& s, double v) {
         s.discretisation =
             flag(v) ? Discretisation::NodeToSurface : Discretisation::SurfaceToSurface;
       }},
      {"one_way", [](ContactSettings& s, double v) { s.one_way = flag(v); }},
      {"accuracy_level",
       [](ContactSettings& s, double v) { s.accuracy_level = static_cast<int>(v); }},
      {"friction",
       [](ContactSettings& s, double v) {
         if (v == 0.0) {
           s.tangential_law = Frictionless{};
           return;
         }
         coulomb(s).mu_static = v;
         coulomb(s).mu_dynamic = v;
       }},
      {"friction_static", [](ContactSettings& s, double v) { coulomb(s).mu_static = v; }},
      {"friction_sliding", [](ContactSettings& s, double v) { coulomb(s).mu_dynamic = v; }},
      {"damping", [](ContactSettings& s, double v) { s.damping = v; }},
      {"detection_depth", [](ContactSettings& s, double v) { s.detection_depth = v; }},
      {"search_margin", [](ContactSettings& s, double v) { s.search_margin = v; }},
      {"begin_time", [](ContactSettings& s, double v) { s.begin_time = v; }},
      {"end_time", [](ContactSettings& s, double v) { s.end_time = v; }},
      {"initial_offset", [](ContactSettings& s, double v) { s.initial_offset = v; }},
      {"initial_max", [](ContactSettings& s, double v) { s.initial_max = v; }},
      {"edge_angle", [](ContactSettings& s, double v) { s.edge_angle = v; }},
      {"tangential_penalty", [](ContactSettings& s, double v) { s.tangential_penalty = v; }},
      {"stick_stress", [](ContactSettings& s, double v) { s.stick_stress = v; }},
  };
  return table;
}

}  // namespace

void set_by_name(ContactSettings& s, std::string_view name, double value) {
  const auto it = setters().find(name);
  if (it == setters().end()) {
    std::string known;
    for (const std::string& n : setting_names()) known += (known.empty() ? "" : ", ") + n;
    throw ContactSetupError(std::string(name),
                            "unknown setting '" + std::string(name) + "' (known: " + known + ")");
  }
  if (!std::isfinite(value))
    throw ContactSetupError(std::string(name), std::string(name) + " is not finite");
  it->second(s, value);
}

std::vector<std::string> setting_names() {
  std::vector<std::string> names;
  for (const auto& entry : setters()) names.push_back(entry.first);
  return names;
}

}  // namespace abut
