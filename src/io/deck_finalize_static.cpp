// The static procedure of a .k deck (*STATIC, abut's own). Once the deck is read and the mesh is
// final, the commands that only an explicit run has are refused, and the boundary conditions and
// loads become the lists of each StaticStep (model_static.hpp). Values that vary in time keep
// their *CURVE or *FUNCTION as an amplitude of the total time, so a curve means in a static step
// what it means in an explicit run:
//   *NODE bc, *BC_MOTION bc_tr  -> StepDisplacement 0, in the steps in which they act
//   *BC_MOTION D lines          -> StepDisplacement sf x curve(t)
//   *LOAD_PRESSURE              -> StepPressure sf x curve(t) on each exterior hex face
//   *LOAD_GRAVITY               -> StepForce m x sf x curve(t) on each node (lumped mass m)
// Then Model::motions, pressures and gravity are emptied: the static solver reads the steps.
#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "abut/element/lumped_mass.hpp"
#include "abut/element/solid_block.hpp"
#include "abut/solver/pressure_loads.hpp"
#include "deck_reader.hpp"

namespace abut::deck {
namespace {

std::string at(const SourceLocation& w) { return w.file + ":" + std::to_string(w.line); }

// One value of a step for one key (a dof, 3 node + direction, or a face, 6 hex + local face):
// value x curve(t), or the constant value without a curve.
struct Entry {
  double value = 0.0;
  FunctionRef curve;
  SourceLocation where;  // empty file: the bc field of *NODE
};

std::string origin(const Entry& e) {
  return e.where.file.empty() ? std::string("the bc field of *NODE")
                              : e.where.keyword + " at " + at(e.where);
}

using StepEntries = std::map<std::int64_t, Entry>;

// The steps a boundary condition acts in: each step wholly or not at all (a condition that
// starts or stops inside a step has no static meaning: the step has one set of supports).
std::vector<bool> active_steps(const MotionBoundary& m, const std::vector<double>& ends,
                               const std::vector<StaticStep>& steps) {
  const double eps = 1e-9 * ends.back();
  std::vector<bool> active(ends.size(), false);
  for (std::size_t s = 0; s < ends.size(); ++s) {
    const double t0 = s == 0 ? 0.0 : ends[s - 1], t1 = ends[s];
    const bool whole = m.begin_time <= t0 + eps && m.end_time >= t1 - eps;
    const bool none = m.end_time <= t0 + eps || m.begin_time >= t1 - eps;
    if (whole) {
      active[s] = true;
    } else if (!none) {
      throw InputError(
          with_field(m.where, m.begin_time > t0 + eps ? "t_beg" : "t_end"),
          "the boundary condition acts from t_beg = " + format_number(m.begin_time) +
              " to t_end = " + format_number(m.end_time) +
              ", which covers only part of static step " + std::to_string(s + 1) +
              " (t = " + format_number(t0) + " to " + format_number(t1) + ", *STATIC at " +
              at(steps[s].where) +
              "): in static steps a boundary condition acts during whole steps; give t_beg and "
              "t_end at step ends");
    }
  }
  return active;
}

}  // namespace

void DeckReader::finish_static_steps() {
  const Mesh& mesh = model.mesh;
  std::set<std::int64_t> part_ids;
  for (const Part& p : model.parts) part_ids.insert(p.id);
  for (const PendingPartSolid& s : part_solids) {
    const auto part = std::find_if(model.parts.begin(), model.parts.end(),
                                   [&s](const Part& p) { return p.id == s.part; });
    if (part == model.parts.end()) {
      throw InputError(s.where, "part " + std::to_string(s.part) +
                                    " does not exist (defined parts: " + joined(part_ids) + ")");
    }
    if (s.integration == Part::SolidIntegration::Full && static_step_ends.empty()) {
      throw InputError(s.integration_where,
                       "fully integrated hexahedra (FULL) are for static steps (*STATIC) only; the "
                       "explicit solver's hexahedra have one point (REDUCED)");
    }
    part->solid_integration = s.integration;
    if (std::find(mesh.hex_part.begin(), mesh.hex_part.end(), s.part) == mesh.hex_part.end())
      notes.push_back("*PART_SOLID of part " + std::to_string(s.part) +
                      ": the part has no hexahedra");
  }
  if (static_step_ends.empty()) return;

  // What only an explicit run has.
  const std::string static_at =
      " (the deck has *STATIC at " + at(model.static_steps.front().where) + ")";
  if (time_where) {
    throw InputError(*time_where,
                     "*TIME sets the end time and the time step of an explicit run; a deck with "
                     "*STATIC ends at the t_end of its last step: remove *TIME" +
                         static_at);
  }
  if (output_where) {
    throw InputError(*output_where,
                     "*OUTPUT sets the output intervals of an explicit run; static steps write a "
                     "state at every converged increment: remove *OUTPUT" +
                         static_at);
  }
  if (bulk_viscosity_where) {
    throw InputError(*bulk_viscosity_where,
                     "*CONTROL_BULK_VISCOSITY damps the shock fronts of an explicit run; static "
                     "steps have no velocities for it to act on: remove *CONTROL_BULK_VISCOSITY" +
                         static_at);
  }
  if (!velocities.empty()) {
    throw InputError(velocities.front().entity.where,
                     "initial velocities are for explicit runs (static steps start at rest): "
                     "remove *INITIAL_VELOCITY" +
                         static_at);
  }
  if (!model.sensors.empty()) {
    throw InputError(model.sensors.front().where,
                     "sensors (*SENSOR) are not supported in static steps: they watch an explicit "
                     "run in time" +
                         static_at);
  }
  for (const ContactSpec& c : model.contacts) {
    if (c.sensor)
      throw InputError(model.place_of(c, "sensor"),
                       "a contact switched by a sensor (*CONTACT_SENSOR) is not supported in "
                       "static steps" +
                           static_at);
    if (c.release_bc)
      throw InputError(model.place_of(c, "release_bc"),
                       "releasing boundary conditions at impact (*CONTACT_RELEASE_BC) is not "
                       "supported in static steps" +
                           static_at);
  }
  for (const Part& p : model.parts) {
    if (p.erosion.any())
      throw InputError(p.where, "element erosion (dt_erode, eps_geo_erode, eps_v_erode of part " +
                                    std::to_string(p.id) +
                                    ") is not supported in static steps yet" + static_at);
  }
  model.time.end_time = static_step_ends.back();
  model.time.start_time = 0.0;

  const std::size_t n_steps = model.static_steps.size();
  const auto describe_dof = [&](std::int64_t key) {
    return "node " + std::to_string(mesh.nodes.id[static_cast<std::size_t>(key / 3)]) +
           ", direction " + "xyz"[key % 3];
  };
  // A prescribed displacement: one per dof and step (the same one twice is harmless).
  std::vector<StepEntries> displacements(n_steps), forces(n_steps), pressures(n_steps);
  const auto prescribe = [&](std::size_t s, std::int64_t key, const Entry& e) {
    const auto [it, inserted] = displacements[s].emplace(key, e);
    if (inserted) return;
    const Entry& old = it->second;
    if (old.value == e.value && old.curve.index == e.curve.index) return;
    throw InputError(e.where, describe_dof(key) + " already has a condition in static step " +
                                  std::to_string(s + 1) + " from " + origin(old) +
                                  ": a degree of freedom takes one condition per step");
  };
  // Loads of one curve on the same key add up; loads of different curves cannot be one load of
  // the step.
  const auto add_load = [&](StepEntries& into, std::int64_t key, const Entry& e,
                            const std::string& what) {
    const auto [it, inserted] = into.emplace(key, e);
    if (inserted) return;
    if (it->second.curve.index != e.curve.index)
      throw InputError(e.where, what + " already carries a load of another curve from " +
                                    origin(it->second) +
                                    ": loads of different curves on one degree of freedom or "
                                    "face are not supported in static steps yet");
    it->second.value += e.value;
  };

  // *NODE constraints hold in every step.
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (mesh.nodes.fixed[i] & (1u << k))
        for (std::size_t s = 0; s < n_steps; ++s)
          prescribe(s, 3 * static_cast<std::int64_t>(i) + k, Entry{});

  // *BC_MOTION
  for (const MotionBoundary& m : model.motions) {
    if (m.fixed_rotation != 0)
      throw InputError(with_field(m.where, "bc_rot"),
                       "fixed rotations (bc_rot) are not supported in static steps yet");
    for (const PrescribedMotion& p : m.motions) {
      if (p.direction >= 3)
        throw InputError(with_field(p.where, "direc"),
                         "prescribed rotations (RX, RY, RZ) are not supported in static steps yet");
      if (p.kind != PrescribedMotion::Kind::Displacement)
        throw InputError(
            with_field(p.where, "pmeth"),
            std::string("a prescribed ") +
                (p.kind == PrescribedMotion::Kind::Velocity ? "velocity (V)" : "acceleration (A)") +
                " has no meaning in a static step: give the displacement (pmeth D, with a curve "
                "of the displacement against time)");
      if (p.activation.valid())
        throw InputError(with_field(p.where, "fid"),
                         "an activation function (fid) is not supported in static steps yet: let "
                         "t_beg and t_end of the boundary condition fall on step ends");
    }
    if (m.entity.type == EntityType::Part || m.entity.type == EntityType::PartSet) {
      for (const std::int64_t pid : model.parts_of(m.entity))
        if (is_rigid(model.material_of_part(pid)))
          throw InputError(m.entity.where, "part " + std::to_string(pid) +
                                               " is rigid: rigid parts are not supported in "
                                               "static steps yet");
    }
    const std::vector<bool> active = active_steps(m, static_step_ends, model.static_steps);
    if (std::find(active.begin(), active.end(), true) == active.end()) {
      notes.push_back("*BC_MOTION at " + at(m.where) + " acts in no static step");
      continue;
    }
    const std::vector<std::int32_t> nodes = model.nodes_of(m.entity);
    for (std::size_t s = 0; s < n_steps; ++s) {
      if (!active[s]) continue;
      for (const std::int32_t i : nodes) {
        const std::int64_t base = 3 * static_cast<std::int64_t>(i);
        for (int k = 0; k < 3; ++k)
          if (m.fixed_translation & (1u << k)) prescribe(s, base + k, Entry{0.0, {}, m.where});
        for (const PrescribedMotion& p : m.motions)
          prescribe(s, base + p.direction, Entry{p.scale, p.curve, p.where});
      }
    }
  }

  // *LOAD_PRESSURE on the exterior hex faces, in every step.
  for (const PressureLoad& p : model.pressures) {
    const PressureSolidFaces faces = pressure_solid_faces(model, p);
    if (!faces.shells.empty())
      throw InputError(
          p.entity.where,
          "a pressure on shells (part " +
              std::to_string(mesh.shell_part[static_cast<std::size_t>(faces.shells.front())]) +
              ") is not supported in static steps yet");
    for (const SolidFace& f : faces.faces)
      for (std::size_t s = 0; s < n_steps; ++s)
        add_load(pressures[s], 6 * static_cast<std::int64_t>(f.solid) + f.face,
                 Entry{p.scale, p.curve, p.where},
                 "face " + std::to_string(f.face + 1) + " of element " +
                     std::to_string(mesh.solid(static_cast<std::size_t>(f.solid)).id));
  }

  // *LOAD_GRAVITY: the weight of each node's lumped mass (the explicit solver's, rho V / 8 per
  // hex corner), in every step.
  if (!model.gravity.empty()) {
    const SourceLocation& where = model.gravity.front().where;
    std::map<std::int64_t, std::vector<Hex8>> hexes_of_part;
    for (std::size_t h = 0; h < mesh.hex_count(); ++h)
      hexes_of_part[mesh.hex_part[h]].push_back(mesh.hexes[h]);
    std::vector<double> mass(mesh.nodes.size(), 0.0);
    for (const Part& part : model.parts) {
      if (std::find(mesh.shell_part.begin(), mesh.shell_part.end(), part.id) !=
          mesh.shell_part.end())
        throw InputError(where, "gravity on shells (part " + std::to_string(part.id) +
                                    ") is not supported in static steps yet");
      const auto it = hexes_of_part.find(part.id);
      const MaterialParams& material = model.material_of_part(part.id);
      // The other cells: their HRZ lumped masses (lumped_mass.hpp), as the explicit solver's.
      for (std::size_t e = mesh.hex_count(); e < mesh.solid_count(); ++e) {
        const SolidRef cell = mesh.solid(e);
        if (cell.part != part.id) continue;
        if (is_rigid(material))
          throw InputError(where, "gravity on a rigid part (part " + std::to_string(part.id) +
                                      ") is not supported in static steps yet");
        std::vector<double> X, shares(cell.nodes.size());
        for (const std::int32_t n : cell.nodes) {
          const Vec3 p = mesh.nodes.position(static_cast<std::size_t>(n));
          X.insert(X.end(), {p.x, p.y, p.z});
        }
        lumped_volume_shares(cell.type, X, shares);
        for (std::size_t a = 0; a < shares.size(); ++a)
          mass[static_cast<std::size_t>(cell.nodes[a])] += density_of(material) * shares[a];
      }
      if (it == hexes_of_part.end()) continue;
      if (is_rigid(material))
        throw InputError(where, "gravity on a rigid part (part " + std::to_string(part.id) +
                                    ") is not supported in static steps yet");
      try {
        SolidBlock(part.id, material, it->second, mesh.nodes, &model.functions)
            .add_lumped_mass(mass);
      } catch (const InputError& e) {
        throw InputError(part.where, e.what());
      }
    }
    for (const Gravity& g : model.gravity)
      for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
        if (mass[i] == 0.0) continue;
        const std::int64_t key = 3 * static_cast<std::int64_t>(i) + g.direction;
        for (std::size_t s = 0; s < n_steps; ++s)
          add_load(forces[s], key, Entry{mass[i] * g.scale, g.curve, g.where}, describe_dof(key));
      }
  }

  for (std::size_t s = 0; s < n_steps; ++s) {
    StaticStep& step = model.static_steps[s];
    for (const auto& [key, e] : displacements[s])
      step.displacements.push_back({static_cast<std::int32_t>(key / 3),
                                    static_cast<int>(key % 3),
                                    e.value,
                                    {e.curve, true},
                                    e.where});
    for (const auto& [key, e] : forces[s])
      step.forces.push_back({static_cast<std::int32_t>(key / 3),
                             static_cast<int>(key % 3),
                             e.value,
                             {e.curve, true},
                             e.where});
    for (const auto& [key, e] : pressures[s])
      step.pressures.push_back(
          {{static_cast<std::int32_t>(key / 6), static_cast<std::int8_t>(key % 6)},
           e.value,
           {e.curve, true},
           e.where});
  }
  model.motions.clear();
  model.pressures.clear();
  model.gravity.clear();
}

}  // namespace abut::deck
