#pragma once
// How messages name an entity of a deck (the entype/enid pair of a load or a condition):
// "part 3", "node set 12", "the region of geometry 5", "the model" for ALL.
#include <string>

#include "abut/model/model.hpp"

namespace abut {

std::string entity_name(const EntityRef& e);

}  // namespace abut
