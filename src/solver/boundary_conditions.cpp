#include "boundary_conditions.hpp"

#include <algorithm>
#include <string>

namespace abut {

namespace {
bool is_part_entity(const EntityRef& e) {
  return e.type == EntityType::Part || e.type == EntityType::PartSet || e.type == EntityType::All;
}
}  // namespace

BoundaryConditions resolve_boundary_conditions(
    const Model& model, const std::vector<std::int32_t>& rigid_body_of_node,
    const std::vector<std::pair<std::int64_t, std::size_t>>& rigid_body_of_part,
    const std::vector<double>& rotary_inertia) {
  BoundaryConditions bc;
  for (const MotionBoundary& m : model.motions) {
    const bool rotates = m.fixed_rotation != 0 ||
                         std::any_of(m.motions.begin(), m.motions.end(),
                                     [](const PrescribedMotion& p) { return p.direction >= 3; });
    std::vector<std::int32_t> deformable_nodes;
    if (is_part_entity(m.entity)) {
      for (const std::int64_t pid : model.parts_of(m.entity)) {
        const auto body = std::find_if(rigid_body_of_part.begin(), rigid_body_of_part.end(),
                                       [pid](const auto& pb) { return pb.first == pid; });
        if (body != rigid_body_of_part.end()) {
          bc.rigid.push_back({&m, body->second});
          continue;
        }
        EntityRef one{EntityType::Part, pid, m.entity.where};
        for (const std::int32_t n : model.nodes_of(one))
          if (rigid_body_of_node[n] < 0) deformable_nodes.push_back(n);
      }
    } else {
      for (const std::int32_t n : model.nodes_of(m.entity)) {
        if (rigid_body_of_node[n] >= 0)
          throw InputError(m.where, "node " + std::to_string(model.mesh.nodes.id[n]) +
                                        " belongs to a rigid part; constrain or move a rigid part "
                                        "as a whole (" +
                                        model.sources.words("rigid_motion") + ")");
        deformable_nodes.push_back(n);
      }
    }
    std::sort(deformable_nodes.begin(), deformable_nodes.end());
    deformable_nodes.erase(std::unique(deformable_nodes.begin(), deformable_nodes.end()),
                           deformable_nodes.end());
    if (!deformable_nodes.empty()) {
      std::vector<std::int32_t> rotating;  // nodes with rotational degrees of freedom (shells)
      if (!rotary_inertia.empty())
        for (const std::int32_t n : deformable_nodes)
          if (rotary_inertia[n] > 0.0) rotating.push_back(n);
      if (rotates && rotating.empty())
        throw InputError(m.where,
                         "rotational constraints and RX/RY/RZ motions act on shell nodes and "
                         "rigid parts; solid nodes have no rotational degrees of freedom");
      bc.nodal.push_back({&m, std::move(deformable_nodes), std::move(rotating)});
    }
  }
  return bc;
}

bool prescription_active(const Model& model, const PrescribedMotion& p, double t) {
  if (!p.activation.valid()) return true;
  Variables v;
  v.t = t;
  return model.functions.value(p.activation, v) > 0.0;
}

bool motion_active(const Model&, const MotionBoundary& m, double t) {
  return t >= m.begin_time && t <= m.end_time;
}

}  // namespace abut
