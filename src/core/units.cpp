#include "abut/core/units.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

namespace abut {

UnitScales unit_scales(UnitSystem system) {
  constexpr double inch = 0.0254;
  constexpr double pound_force = 4.4482216152605;  // N
  switch (system) {
    case UnitSystem::SI: return {1.0, 1.0, 1.0};
    case UnitSystem::MMTONS: return {1e-3, 1e3, 1.0};
    case UnitSystem::CMGUS: return {1e-2, 1e-3, 1e-6};
    case UnitSystem::IPS: return {inch, pound_force / inch, 1.0};  // slinch = lbf*s^2/in
    case UnitSystem::MMKGMS: return {1e-3, 1.0, 1e-3};
    case UnitSystem::CMGS: return {1e-2, 1e-3, 1.0};
    case UnitSystem::MMGMS: return {1e-3, 1e-3, 1e-3};
    case UnitSystem::MMMGMS: return {1e-3, 1e-6, 1e-3};
  }
  return {};
}

std::string_view unit_system_name(UnitSystem system) {
  switch (system) {
    case UnitSystem::SI: return "SI [m, kg, s]";
    case UnitSystem::MMTONS: return "MMTONS [mm, ton, s]";
    case UnitSystem::CMGUS: return "CMGUS [cm, g, us]";
    case UnitSystem::IPS: return "IPS [in, slinch, s]";
    case UnitSystem::MMKGMS: return "MMKGMS [mm, kg, ms]";
    case UnitSystem::CMGS: return "CMGS [cm, g, s]";
    case UnitSystem::MMGMS: return "MMGMS [mm, g, ms]";
    case UnitSystem::MMMGMS: return "MMMGMS [mm, mg, ms]";
  }
  return "";
}

std::optional<UnitSystem> parse_unit_system(std::string_view text) {
  std::string s(text);
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::toupper(c); });
  if (s == "SI") return UnitSystem::SI;
  if (s == "MMTONS" || s == "MM/TON/S") return UnitSystem::MMTONS;
  if (s == "CMGUS" || s == "CM/G/US") return UnitSystem::CMGUS;
  if (s == "IPS") return UnitSystem::IPS;
  if (s == "MMKGMS" || s == "MM/KG/MS") return UnitSystem::MMKGMS;
  if (s == "CMGS") return UnitSystem::CMGS;
  if (s == "MMGMS") return UnitSystem::MMGMS;
  if (s == "MMMGMS") return UnitSystem::MMMGMS;
  return std::nullopt;
}

double from_si(UnitSystem system, double value_si, int length_exp, int mass_exp, int time_exp) {
  const UnitScales u = unit_scales(system);
  const double unit_in_si =
      std::pow(u.length, length_exp) * std::pow(u.mass, mass_exp) * std::pow(u.time, time_exp);
  return value_si / unit_in_si;
}

}  // namespace abut
