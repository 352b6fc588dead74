#include "contact_set.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "abut/contact/penalty.hpp"
#include "abut/contact/surface.hpp"
#include "abut/mesh/skin.hpp"

namespace abut {

namespace {

std::vector<SkinFace> faces_of(const Model& model, const EntityRef& entity, bool merge) {
  std::vector<SkinFace> faces;
  if (entity.type == EntityType::All) {
    faces = exterior_faces(model.mesh, merge);
  } else if (entity.type == EntityType::Part || entity.type == EntityType::PartSet) {
    const std::vector<std::int64_t> parts = model.parts_of(entity);
    faces = exterior_faces(model.mesh, parts, merge);
  } else {
    throw InputError(entity.where, "a contact surface is a part (P), a part set (PS) or ALL");
  }
  if (faces.empty())
    throw InputError(entity.where, "this contact surface has no exterior element faces");
  return faces;
}

double max_initial_speed(std::span<const double> vx, std::span<const double> vy, std::span<const double> vz) {
  double v2 = 0.0;
  for (std::size_t i = 0; i < vx.size(); ++i) v2 = std::max(v2, vx[i] * vx[i] + vy[i] * vy[i] + vz[i] * vz[i]);
  return std::sqrt(v2);
}

// Penalty of each part of the interface: pfac as given, or automatic (seed 000).
std::map<std::int64_t, PartPenalty> part_penalties(const Model& model, const ContactSpec& spec,
                                                   const std::vector<SkinFace>& s1,
                                                   const std::vector<SkinFace>& s2, double v_max) {
  std::map<std::int64_t, PartPenalty> out;
  for (const auto* faces : {&s1, &s2})
    for (const SkinFace& f : *faces) out[f.part].part_id = f.part;
  if (!spec.penalty && !model.units)
    throw InputError(spec.where, "neither pfac nor *UNIT_SYSTEM is given: the automatic penalty "
                                 "stiffness is defined in SI units (seed 000), so state the unit "
                                 "system with *UNIT_SYSTEM or give pfac on line 2");
  for (auto& [part_id, p] : out) {
    if (spec.penalty) {
      p.penalty = *spec.penalty;
      continue;
    }
    const MaterialParams& material = model.material_of_part(part_id);
    p.automatic = true;
    p.penalty = is_rigid(material)
                    ? rigid_penalty(v_max, *model.units)
                    : automatic_penalty(initial_moduli(material).bulk, smallest_element_volume(model.mesh, part_id),
                                        v_max, *model.units);
  }
  return out;
}

ContactSettings settings_of(const Model& model, const ContactSpec& spec) {
  if (spec.thermal.valid())
    throw InputError(spec.where, "fid_thermal (contact heat conduction) is not supported yet: abut has "
                                 "no thermal solution yet");
  if (spec.friction_heat)
    throw InputError(spec.where, "fric_heat = 1 (friction work to heat) is not supported yet: abut has "
                                 "no thermal solution yet");
  ContactSettings s;
  s.accuracy_level = spec.accuracy_level;
  s.accuracy_edge = spec.accuracy_edge;
  s.friction = spec.friction;
  const FunctionTable* table = &model.functions;
  const double term = model.time.end_time;
  if (spec.friction_function.valid()) {
    const FunctionRef mu = spec.friction_function;
    s.friction_function = [table, mu, term](double pres, double vtang, double t, double x, double y, double z) {
      Variables v;
      v.pres = pres;
      v.vtang = vtang;
      v.t = t;
      v.term = term;
      v.x = x;
      v.y = y;
      v.z = z;
      return table->value(mu, v);
    };
  }
  const auto wear_rate = [table, term](FunctionRef f) -> WearRateFunction {
    if (!f.valid()) return {};
    return [table, f, term](double pres, double vtang) {
      Variables v;
      v.pres = pres;
      v.vtang = vtang;
      v.term = term;
      return table->value(f, v);
    };
  };
  s.wear_rate1 = wear_rate(spec.wear1);
  s.wear_rate2 = wear_rate(spec.wear2);
  const auto region = [&model, &spec](const std::optional<std::int64_t>& gid) -> RegionPredicate {
    if (!gid) return {};
    const GeometryEntry* g = model.find_geometry(*gid);
    if (!g) throw InputError(spec.where, "geometry " + std::to_string(*gid) + " does not exist");
    const Geometry* geometry = &g->geometry;
    const Mesh* mesh = &model.mesh;
    return [geometry, mesh](double x, double y, double z) { return geometry_contains(*geometry, {x, y, z}, *mesh); };
  };
  s.initial_region = region(spec.initial_geometry);
  s.moving_region = region(spec.moving_geometry);
  s.begin_time = spec.begin_time;
  s.end_time = spec.end_time;
  s.damping = spec.damping;
  s.initial_offset = spec.initial_offset;
  s.initial_max = spec.initial_max;
  s.edge_tolerance = spec.edge_tolerance;
  s.edge_angle = spec.edge_angle;
  s.one_way = spec.one_way;
  s.stick_stress = spec.stick_stress;
  s.where = spec.where;
  return s;
}

}  // namespace

ContactSet::ContactSet(const Model& model, std::span<const double> node_mass, std::span<const double> vx0,
                       std::span<const double> vy0, std::span<const double> vz0)
    : model_(model) {
  const double v_max = max_initial_speed(vx0, vy0, vz0);
  const Nodes& nodes = model.mesh.nodes;
  const ContactInput initial{nodes.x, nodes.y, nodes.z, vx0, vy0, vz0, model.time.start_time, 0.0};
  for (const ContactSpec& spec : model.contacts) {
    const std::vector<SkinFace> faces1 = faces_of(model, spec.surface1, spec.merge);
    const std::vector<SkinFace> faces2 = faces_of(model, spec.surface2, spec.merge);
    const std::map<std::int64_t, PartPenalty> penalties = part_penalties(model, spec, faces1, faces2, v_max);
    const auto penalty_of = [&penalties](std::int64_t part) { return penalties.at(part).penalty; };

    ContactReport report;
    report.id = spec.id;
    report.title = spec.title;
    for (const auto& [part, p] : penalties) report.parts.push_back(p);
    std::vector<std::int64_t> parts1, parts2;
    for (const SkinFace& f : faces1) parts1.push_back(f.part);
    for (const SkinFace& f : faces2) parts2.push_back(f.part);
    for (auto* parts : {&parts1, &parts2}) {
      std::sort(parts->begin(), parts->end());
      parts->erase(std::unique(parts->begin(), parts->end()), parts->end());
    }
    for (const std::int64_t a : parts1)
      for (const std::int64_t b : parts2) report.pairs.push_back({a, b, pair_penalty(penalty_of(a), penalty_of(b))});

    interfaces_.emplace_back(settings_of(model, spec), make_contact_surface(faces1, penalty_of),
                             make_contact_surface(faces2, penalty_of), node_mass, initial);
    report.points = interfaces_.back().point_count();
    report.released_points = interfaces_.back().released_points();
    reports_.push_back(std::move(report));
  }
  cfx_.assign(nodes.size(), 0.0);
  cfy_.assign(nodes.size(), 0.0);
  cfz_.assign(nodes.size(), 0.0);
}

void ContactSet::apply(const ContactInput& in, std::span<double> fx, std::span<double> fy, std::span<double> fz) {
  if (interfaces_.empty()) return;
  std::fill(cfx_.begin(), cfx_.end(), 0.0);
  std::fill(cfy_.begin(), cfy_.end(), 0.0);
  std::fill(cfz_.begin(), cfz_.end(), 0.0);
  ContactForces forces{cfx_, cfy_, cfz_};
  for (std::size_t c = 0; c < interfaces_.size(); ++c) {
    interfaces_[c].apply(in, forces);
    reports_[c].stats = interfaces_[c].stats();
  }
  for (std::size_t i = 0; i < cfx_.size(); ++i) {
    fx[i] += cfx_[i];
    fy[i] += cfy_[i];
    fz[i] += cfz_[i];
  }
}

double ContactSet::stable_step(std::int64_t* limiting_contact) const {
  double step = std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < interfaces_.size(); ++c) {
    const double s = std::min(interfaces_[c].initial_stable_step(), interfaces_[c].stats().stable_step);
    if (s < step) {
      step = s;
      if (limiting_contact) *limiting_contact = reports_[c].id;
    }
  }
  return step;
}

double ContactSet::elastic_and_damping_energy() const {
  double e = 0.0;
  for (const ContactInterface& c : interfaces_) e += c.stats().elastic_energy + c.stats().damping_energy;
  return e;
}

double ContactSet::friction_energy() const {
  double e = 0.0;
  for (const ContactInterface& c : interfaces_) e += c.stats().friction_energy;
  return e;
}

void ContactSet::nodal_fields(std::vector<double>& force, std::vector<double>& pressure,
                              std::vector<double>& wear) const {
  const std::size_t n = cfx_.size();
  force.assign(3 * n, 0.0);
  pressure.assign(n, 0.0);
  wear.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    force[3 * i] = cfx_[i];
    force[3 * i + 1] = cfy_[i];
    force[3 * i + 2] = cfz_[i];
  }
  for (const ContactInterface& c : interfaces_) {
    const auto p = c.nodal_pressure();
    const auto w = c.wear();
    for (std::size_t i = 0; i < n && i < p.size(); ++i) pressure[i] += p[i];
    for (std::size_t i = 0; i < n && i < w.size(); ++i) wear[i] += w[i];
  }
}

}  // namespace abut
