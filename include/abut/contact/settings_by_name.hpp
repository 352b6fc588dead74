#pragma once
// The common contact settings by name and value, for hosts that pass settings as text and numbers
// (the C interface abut_contact.h, Python's abut.contact): one table, one set of names, documented
// in abut_contact.h. A flag is 0 or 1.
#include <string>
#include <string_view>
#include <vector>

#include "abut/contact/settings.hpp"

namespace abut {

// Sets the setting `name` of `s` to `value`; ContactSetupError (naming `name`) for an unknown name
// or a value that is not finite. The interface checks the values themselves when it is made.
void set_by_name(ContactSettings& s, std::string_view name, double value);
// The names set_by_name knows, sorted.
std::vector<std::string> setting_names();

}  // namespace abut
