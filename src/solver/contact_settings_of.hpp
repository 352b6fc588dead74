#pragma once
// A *CONTACT card in the contact library's terms (contact_settings_of.cpp).
#include <string>
#include <vector>

#include "abut/contact/describe.hpp"
#include "abut/contact/settings.hpp"
#include "abut/model/model.hpp"
#include "abut/solver/contact_report.hpp"

namespace abut {

// The thermal contact of a *CONTACT (laws/thermal.hpp): the conductance of fid_thermal (h of pres
// and gap; a *CURVE: of pres) or of *CONTACT_THERMAL, and the friction heat split of fric_heat.
ThermalContactSettings thermal_of(const Model& model, const ContactSpec& spec);

// The tangential law of a *CONTACT (laws/tangential.hpp), for explicit and static steps:
// *CONTACT_FRICTION, or seed 000's Coulomb mu (constant, or a *FUNCTION of the model's `table`
// evaluated with term = `term`).
TangentialLaw tangential_law_of(const ContactSpec& spec, const FunctionTable* table, double term);

// The per-part-pair laws of *CONTACT_FRICTION_PAIR (Radioss /FRICTION), in deck order.
std::vector<PairFriction> pair_frictions_of(const Model& model, const ContactSpec& spec);

// The contact library's settings of a *CONTACT with its companion cards (all but the surfaces and
// the penalties, which ContactSet builds from the mesh).
ContactSettings settings_of(const Model& model, const ContactSpec& spec);

// Whether the contact is one-way (*CONTACT one_way, *CONTACT_DISCRETIZATION, a node group).
bool one_way_of(const ContactSpec& spec);

// Where the input gave a contact-library setting (the setting() of its error; Sources), for
// errors: the contact's own place when the input did not give it.
SourceLocation location_of(const Model& model, const ContactSpec& spec, const std::string& setting);

// The laws of a contact in the model's words (the contact library's describe(), contact/
// describe.hpp, and what the model adds), for the log and summary.json.
ContactDescription describe(const ContactSpec& spec, const ContactSettings& settings);

}  // namespace abut
