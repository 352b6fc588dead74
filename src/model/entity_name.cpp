#include "abut/model/entity_name.hpp"

namespace abut {

std::string entity_name(const EntityRef& e) {
  const std::string id = std::to_string(e.id);
  switch (e.type) {
    case EntityType::Node:
      return "node " + id;
    case EntityType::NodeSet:
      return "node set " + id;
    case EntityType::Part:
      return "part " + id;
    case EntityType::PartSet:
      return "part set " + id;
    case EntityType::GeometryRegion:
      return "the region of geometry " + id;
    case EntityType::FaceSet:
      return "face set " + id;
    case EntityType::Tool:
      return "tool " + id;
    case EntityType::All:
      break;
  }
  return "the model";
}

}  // namespace abut
