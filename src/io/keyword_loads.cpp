// *INITIAL_VELOCITY, *BC_MOTION, *LOAD_GRAVITY, *LOAD_PRESSURE.
#include <cctype>

#include "deck_reader.hpp"

namespace abut::deck {
namespace {

bool starts_with_number(const std::vector<std::string>& fields) {
  return !fields.empty() && !fields[0].empty() &&
         std::isalpha(static_cast<unsigned char>(fields[0][0])) == 0;
}

}  // namespace

void read_initial_velocity(DeckReader& d, Block& b) {
  if (b.done())
    throw InputError(b.where(), "missing data line: expected entype, enid, v_x0, v_y0, v_z0, ...");
  while (!b.done()) {
    const Row r =
        b.row({"entype", "enid", "v_x0", "v_y0", "v_z0", "omega_x", "omega_y", "omega_z"});
    PendingVelocity v;
    v.entity = d.entity(r, 0, 1,
                        {EntityType::Node, EntityType::NodeSet, EntityType::Part,
                         EntityType::PartSet, EntityType::All, EntityType::GeometryRegion});
    bool directional = false;
    for (std::size_t k = 0; k < 3; ++k) {
      v.velocity[k] = r.number_or_function(2 + k, 0.0);
      if (v.velocity[k].function_id)
        v.velocity[k].function_id = d.function_id(r, 2 + k, v.velocity[k]);
      v.velocity_where[k] = r.where(2 + k);
      v.angular_velocity[static_cast<int>(k)] = r.number_or(5 + k, 0.0);
      directional = directional || v.velocity[k].value != 0.0 || v.velocity[k].function_id ||
                    v.angular_velocity[static_cast<int>(k)] != 0.0;
    }
    if (directional) d.require_unrotated(r.where(), "an initial velocity");
    // Optional line 2 starts with a number (x0); a new line 1 starts with an entity type.
    if (starts_with_number(b.peek_fields())) {
      const Row r2 = b.row({"x0", "y0", "z0", "dv_x", "dv_y", "dv_z", "csysid"});
      v.centre = d.frame().transform.point(
          {r2.number_or(0, 0.0), r2.number_or(1, 0.0), r2.number_or(2, 0.0)});
      for (std::size_t k = 3; k < 6; ++k) r2.unsupported_unless(k, 0.0, "a velocity gradient (dv)");
      r2.global_coordinates_only(6);
    } else {
      v.centre = d.frame().transform.point({0, 0, 0});
    }
    d.velocities.push_back(v);
    d.entity_references.push_back(v.entity);
  }
}

void read_bc_motion(DeckReader& d, Block& b) {
  std::int64_t next_id = 0;  // from a bcid line, until its entype line (ids are > 0)
  bool open = false;         // a boundary condition has been started in this block
  const auto check_complete = [&]() {
    const MotionBoundary& m = d.model.motions.back();
    if (m.fixed_translation == 0 && m.fixed_rotation == 0 && m.motions.empty()) {
      throw InputError(
          m.where,
          "the boundary condition neither constrains (bc_tr, bc_rot) nor prescribes a motion");
    }
  };
  if (b.done())
    throw InputError(b.where(), "missing data line: expected entype, enid, bc_tr, bc_rot, ...");
  while (!b.done()) {
    const auto fields = b.peek_fields();
    if (fields.size() == 1 && starts_with_number(fields)) {  // the optional bcid line
      const Row r = b.row({"bcid"});
      if (next_id != 0) r.fail(0, "expected the entype, enid line after the bcid line");
      next_id = d.other_id(r, 0);
      d.claim_id("boundary condition", next_id, r.where(0));
      continue;
    }
    const std::string first = upper(fields.empty() ? "" : fields[0]);
    if (first == "A" || first == "V" || first == "D") {
      const Row r = b.row({"pmeth", "direc", "cid", "sf", "fid"});
      if (!open || next_id != 0) r.fail(0, "a motion line must follow an entype, enid line");
      const std::size_t i = d.model.motions.size() - 1;
      MotionBoundary& m = d.model.motions[i];
      PrescribedMotion p;
      p.kind = first == "A"   ? PrescribedMotion::Kind::Acceleration
               : first == "V" ? PrescribedMotion::Kind::Velocity
                              : PrescribedMotion::Kind::Displacement;
      p.direction = parse_direction(r, 1, true);
      d.require_unrotated(r.where(1), "a prescribed motion");
      const std::uint8_t bit = static_cast<std::uint8_t>(1u << (p.direction % 3));
      const std::uint8_t fixed = p.direction < 3 ? m.fixed_translation : m.fixed_rotation;
      if ((fixed & bit) != 0) r.fail(1, "this direction is already constrained by bc_tr or bc_rot");
      for (const auto& other : m.motions) {
        if (other.direction == p.direction)
          r.fail(1, "this direction already has a prescribed motion");
      }
      p.scale = r.number_or(3, 1.0);
      p.where = r.where();
      const std::size_t k = m.motions.size();
      d.bind_function(d.other_id(r, 2), r.where(2), [i, k](Model& model, FunctionRef f) {
        model.motions[i].motions[k].curve = f;
      });
      if (const auto fid = d.optional_other_id(r, 4)) {
        d.bind_function(*fid, r.where(4), [i, k](Model& model, FunctionRef f) {
          model.motions[i].motions[k].activation = f;
        });
      }
      m.motions.push_back(p);
      continue;
    }
    if (open) check_complete();
    const Row r =
        b.row({"entype", "enid", "bc_tr", "bc_rot", "csysid_tr", "csysid_rot", "t_beg", "t_end"});
    MotionBoundary m;
    m.id = next_id;
    next_id = 0;
    m.entity = d.entity(r, 0, 1,
                        {EntityType::Node, EntityType::NodeSet, EntityType::Part,
                         EntityType::PartSet, EntityType::All, EntityType::GeometryRegion});
    m.fixed_translation = parse_dof_mask(r, 2);
    m.fixed_rotation = parse_dof_mask(r, 3);
    if (m.fixed_translation != 0) d.require_unrotated(r.where(2), "a constraint");
    if (m.fixed_rotation != 0) d.require_unrotated(r.where(3), "a constraint");
    r.global_coordinates_only(4);
    r.unsupported_unless(
        5, 0.0, "rotation about a coordinate system other than the centre of gravity (csysid_rot)");
    m.begin_time = r.number_or(6, 0.0);
    m.end_time = r.number_or(7, 1e10);
    r.require(m.end_time > m.begin_time, 7, "expected t_end > t_beg");
    m.where = r.where();
    d.model.motions.push_back(m);
    d.entity_references.push_back(m.entity);
    open = true;
  }
  if (next_id != 0)
    throw InputError(b.where(), "the bcid line must be followed by an entype, enid line");
  check_complete();
}

void read_load_gravity(DeckReader& d, Block& b) {
  if (b.done())
    throw InputError(b.where(), "missing data line: expected direc, cid, addmass, csysid, sf");
  while (!b.done()) {
    const Row r = b.row({"direc", "cid", "addmass", "csysid", "sf"});
    Gravity g;
    g.direction = parse_direction(r, 0, false);
    d.require_unrotated(r.where(0), "gravity");
    r.unsupported_unless(2, 0.0, "added mass (addmass)");
    r.global_coordinates_only(3);
    g.scale = r.number_or(4, 1.0);
    g.where = r.where();
    const std::size_t i = d.model.gravity.size();
    d.bind_function(d.other_id(r, 1), r.where(1),
                    [i](Model& model, FunctionRef f) { model.gravity[i].curve = f; });
    d.model.gravity.push_back(g);
  }
}

void read_load_pressure(DeckReader& d, Block& b) {
  if (b.done()) throw InputError(b.where(), "missing data line: expected entype, enid, cid, sf");
  while (!b.done()) {
    const Row r = b.row({"entype", "enid", "cid", "sf"});
    PressureLoad p;
    p.entity = d.entity(r, 0, 1,
                        {EntityType::Part, EntityType::PartSet, EntityType::All,
                         EntityType::GeometryRegion, EntityType::FaceSet});
    p.scale = r.number_or(3, 1.0);
    p.where = r.where();
    const std::size_t i = d.model.pressures.size();
    d.bind_function(d.other_id(r, 2), r.where(2),
                    [i](Model& model, FunctionRef f) { model.pressures[i].curve = f; });
    d.model.pressures.push_back(p);
    // The faces are resolved (and an entity without any is an error) once the mesh is final.
    d.entity_references.push_back(p.entity);
  }
}

}  // namespace abut::deck
