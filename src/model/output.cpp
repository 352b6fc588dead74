// The output requests of a run (output.hpp).
#include "abut/model/output.hpp"

#include <algorithm>

namespace abut {

bool is_state_field(std::string_view name) {
  return std::find(std::begin(kStateFields), std::end(kStateFields), name) !=
         std::end(kStateFields);
}

bool OutputRequests::writes(std::string_view field) const {
  return !state_fields || field == "part_id" ||
         std::find(state_fields->begin(), state_fields->end(), field) != state_fields->end();
}

}  // namespace abut
