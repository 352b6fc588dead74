#pragma once
// What a setting of the model applies to: a node, a part, a set of them, the whole model, the
// region of a geometry, a face set or an analytic tool (the deck's `entype, enid` pair; the
// .inp's set names resolve to the same). Model::nodes_of, parts_of and entity_name read them.
#include <cstdint>

#include "abut/core/error.hpp"

namespace abut {

enum class EntityType {
  Node,
  NodeSet,
  Part,
  PartSet,
  All,
  GeometryRegion,  // the nodes or facets inside a *GEOMETRY (entype G)
  FaceSet,         // element faces (Abaqus *SURFACE, IMPETUS FS; model_static.hpp)
  Tool             // an analytic rigid tool of *CONTACT_TOOL (entype TOOL), surface 2 of a contact
};

struct EntityRef {
  EntityType type = EntityType::All;
  std::int64_t id = 0;
  SourceLocation where;
};

}  // namespace abut
