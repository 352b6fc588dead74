#pragma once
// Consistent unit systems of *UNIT_SYSTEM. abut computes in the deck's own units; the few
// constants that are stated in SI (e.g. the 100 m/s and 1e13 Pa/m of the automatic contact
// penalty, seed 000) are converted with these scales.
#include <optional>
#include <string_view>

namespace abut {

enum class UnitSystem { SI, MMTONS, CMGUS, IPS, MMKGMS, CMGS, MMGMS, MMMGMS };

// Size of one deck unit expressed in SI: metres, kilograms, seconds.
struct UnitScales {
  double length = 1.0;
  double mass = 1.0;
  double time = 1.0;
};

UnitScales unit_scales(UnitSystem system);
std::string_view unit_system_name(UnitSystem system);
// Accepts the names of the keyword reference: SI, MMTONS or MM/TON/S, CMGUS or CM/G/US, IPS,
// MMKGMS or MM/KG/MS, CMGS, MMGMS, MMMGMS (case-insensitive).
std::optional<UnitSystem> parse_unit_system(std::string_view text);

// Converts an SI value of dimension length^L * mass^M * time^T into deck units.
double from_si(UnitSystem system, double value_si, int length_exp, int mass_exp, int time_exp);

}  // namespace abut
