#include "contact_set.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <utility>

#include "abut/contact/penalty.hpp"
#include "abut/core/memory.hpp"
#include "abut/element/element_frequency.hpp"
#include "abut/element/shell4.hpp"
#include "abut/element/stable_step.hpp"
#include "abut/mesh/skin.hpp"
#include "abut/solver/contact_surfaces.hpp"
#include "contact_checks.hpp"
#include "contact_settings_of.hpp"

namespace abut {

namespace {

double max_initial_speed(std::span<const double> vx, std::span<const double> vy,
                         std::span<const double> vz) {
  double v2 = 0.0;
  for (std::size_t i = 0; i < vx.size(); ++i)
    v2 = std::max(v2, vx[i] * vx[i] + vy[i] * vy[i] + vz[i] * vz[i]);
  return std::sqrt(v2);
}

// Penalty of each part of the interface: pfac as given, or automatic (seed 000).
std::map<std::int64_t, PartPenalty> part_penalties(const Model& model, const ContactSpec& spec,
                                                   const std::vector<SkinFace>& s1,
                                                   const std::vector<SkinFace>& s2, double v_max) {
  std::map<std::int64_t, PartPenalty> out;
  for (const auto* faces : {&s1, &s2})
    for (const SkinFace& f : *faces) out[f.part].part_id = f.part;
  for (auto& [part_id, p] : out) {
    if (spec.penalty) {
      p.penalty = *spec.penalty;
      continue;
    }
    const MaterialParams& material = model.material_of_part(part_id);
    p.automatic = true;
    if (spec.element_penalty && !is_rigid(material))
      continue;  // per facet, filled in by the caller
    if (!model.units)
      throw InputError(model.place_of(spec, "penalty"),
                       "neither " + model.sources.words("penalty") + " nor " +
                           model.sources.words("unit_system") +
                           " is given: the automatic penalty stiffness is defined in SI units "
                           "(seed 000), so state the unit system or give the penalty");
    p.penalty =
        is_rigid(material)
            ? rigid_penalty(v_max, *model.units)
            : automatic_penalty(
                  initial_moduli(material).bulk,
                  smallest_element_volume(model.mesh, part_id, model.find_part(part_id)->thickness),
                  v_max, *model.units);
  }
  return out;
}

// The contact faces holding at least one of `nodes`; InputError at `entity` if a node is on none.
std::vector<SkinFace> faces_touching(const std::vector<SkinFace>& faces,
                                     const std::vector<std::int32_t>& nodes, std::size_t node_count,
                                     const EntityRef& entity) {
  std::vector<std::uint8_t> wanted(node_count, 0), found(node_count, 0);
  for (auto n : nodes) wanted[static_cast<std::size_t>(n)] = 1;
  std::vector<SkinFace> out;
  for (const SkinFace& f : faces) {
    bool hit = false;
    for (auto n : f.nodes) hit = hit || wanted[static_cast<std::size_t>(n)];
    if (!hit) continue;
    out.push_back(f);
    for (auto n : f.nodes) found[static_cast<std::size_t>(n)] = 1;
  }
  for (auto n : nodes)
    if (!found[static_cast<std::size_t>(n)])
      throw InputError(entity.where,
                       "node set " + std::to_string(entity.id) +
                           " holds a node that is neither on the model's exterior surface nor on a "
                           "shell; node-to-surface contact of free nodes is not supported yet");
  return out;
}

}  // namespace

SecondarySurface secondary_surface(const Model& model, const EntityRef& surface1, bool merge,
                                   bool exposed_faces) {
  SecondarySurface s;
  if (surface1.type != EntityType::NodeSet) {
    s.faces = contact_faces(model, surface1, merge, exposed_faces);
    return s;
  }
  s.nodes = model.nodes_of(surface1);
  s.faces =
      faces_touching(contact_faces(model, EntityRef{EntityType::All, 0, surface1.where}, merge),
                     s.nodes, model.mesh.nodes.size(), surface1);
  return s;
}

namespace {

// Critical step of a face's hex (stable_step.hpp), its material's P-wave speed and density, or
// of a shell (shell4.hpp) with the plate wave speed.
double element_step(const Model& model, const SkinFace& f) {
  const MaterialParams& material = model.material_of_part(f.part);
  const ElasticModuli m = initial_moduli(material);
  const double lambda = m.bulk - 2.0 * m.shear / 3.0;
  if (f.shell >= 0) {
    std::array<Vec3, 4> p;
    for (int a = 0; a < 4; ++a)
      p[a] = model.mesh.nodes.position(static_cast<std::size_t>(f.nodes[a]));
    const double young = 9.0 * m.bulk * m.shear / (3.0 * m.bulk + m.shear);
    const double nu = lambda / (2.0 * (lambda + m.shear));
    const double length = shell4_critical_length(shell4_geometry(p), f.nodes[2] == f.nodes[3]);
    return length / std::sqrt(young / (density_of(material) * (1.0 - nu * nu)));
  }
  const auto solid = static_cast<std::size_t>(f.solid);
  if (solid >= model.mesh.hex_count()) {  // a cell of another type: its frequency bound
    const SolidRef cell = model.mesh.solid(solid);
    std::vector<double> X;
    for (const std::int32_t a : cell.nodes) {
      const Vec3 p = model.mesh.nodes.position(static_cast<std::size_t>(a));
      X.insert(X.end(), {p.x, p.y, p.z});
    }
    return cell_critical_step(cell.type, X, density_of(material), lambda, m.shear);
  }
  const Hex8& hex = model.mesh.hexes[solid];
  const double length =
      hex8_critical_length(hex8_modal_gradient_at(hex, model.mesh.nodes), lambda, m.shear);
  return length / std::sqrt((lambda + 2.0 * m.shear) / density_of(material));
}

double lightest_node(const SkinFace& f, std::span<const double> node_mass) {
  double m = std::numeric_limits<double>::infinity();
  for (auto n : f.nodes) m = std::min(m, node_mass[static_cast<std::size_t>(n)]);
  return m;
}

double face_area(const Nodes& nodes, const SkinFace& f) {
  auto at = [&](int a) {
    const auto i = static_cast<std::size_t>(f.nodes[a]);
    return Vec3{nodes.x[i], nodes.y[i], nodes.z[i]};
  };
  return 0.5 * norm(cross(at(2) - at(0), at(3) - at(1)));
}

// Moduli for the Radioss stiffness rules. A rigid part has none: it gets the bulk modulus that
// gives seed 000's rigid penalty over its smallest element, B = pfac_rigid * L_min, and the shear
// modulus 1.5 B of a material with nu = 0 (E = 3 B for shells).
ElasticModuli radioss_moduli(const Model& model, std::int64_t part, const PartPenalty& p) {
  const MaterialParams& material = model.material_of_part(part);
  if (!is_rigid(material)) return initial_moduli(material);
  const double bulk = p.penalty * std::cbrt(smallest_element_volume(
                                      model.mesh, part, model.find_part(part)->thickness));
  return {bulk, 1.5 * bulk};
}

}  // namespace

ContactSet::ContactSet(const Model& model, std::span<const double> node_mass,
                       std::span<const double> vx0, std::span<const double> vy0,
                       std::span<const double> vz0, const RemovedNodes& tied_nodes)
    : model_(model) {
  const double v_max = max_initial_speed(vx0, vy0, vz0);
  const Nodes& nodes = model.mesh.nodes;
  const ContactInput initial{nodes.x, nodes.y, nodes.z, vx0, vy0, vz0, model.time.start_time,
                             0.0,     {}};
  for (const ContactSpec& spec : model.contacts) {
    if (spec.small_sliding)
      throw InputError(
          model.place_of(spec, "small_sliding"),
          "small sliding is an option of static steps: the explicit solver searches partners "
          "as the bodies move (ask for finite sliding)");
    if (spec.smoothing)
      throw InputError(spec.smoothing->where,
                       "surface smoothing acts in static steps only (OptiStruct's S2S smoothing "
                       "belongs to its implicit analyses, seed 003): explicit contact meets the "
                       "facets as they are");
    if (spec.stabilization)
      throw InputError(spec.stabilization->where,
                       "contact stabilization acts in static steps only (OptiStruct CNTSTB): the "
                       "explicit solver's parts have their mass to hold them");
    // Node-to-surface of a node group: its nodes on the model's exterior faces that hold them.
    const auto [secondary_nodes, faces1] =
        secondary_surface(model, spec.surface1, spec.merge, !spec.no_internal);
    if (spec.surface2.type == EntityType::Tool) {
      add_tool_contact(spec, faces1, secondary_nodes, node_mass, initial, v_max);
      continue;
    }
    const std::vector<SkinFace> faces2 =
        contact_faces(model, spec.surface2, spec.merge, !spec.no_internal);
    const std::map<std::int64_t, PartPenalty> penalties =
        part_penalties(model, spec, faces1, faces2, v_max);
    std::function<double(const SkinFace&)> penalty_of = [&penalties](const SkinFace& f) {
      return penalties.at(f.part).penalty;
    };
    if (spec.element_penalty)
      penalty_of = [&](const SkinFace& f) {
        const MaterialParams& material = model.material_of_part(f.part);
        if (is_rigid(material)) return penalties.at(f.part).penalty;
        return element_penalty(element_step(model, f), lightest_node(f, node_mass),
                               face_area(model.mesh.nodes, f));
      };
    std::function<ElasticModuli(std::int64_t)> moduli_of;
    if (spec.stiffness.rule != StiffnessRule::FacetPenalty)
      moduli_of = [&model, &penalties](std::int64_t part) {
        return radioss_moduli(model, part, penalties.at(part));
      };

    ContactReport report;
    report.id = spec.id;
    report.title = spec.title;
    for (const auto& [part, p] : penalties) report.parts.push_back(p);
    ContactSettings settings = settings_of(model, spec);
    if (spec.remove_tied_nodes) settings.removed_nodes = tied_nodes;
    report.laws = describe(spec, settings);
    const std::vector<std::uint8_t> overlap_reversed =
        spec.main_shell_sides == ContactSpec::ShellSides::Overlap
            ? overlap_sides(model.mesh, faces1, secondary_nodes, faces2)
            : std::vector<std::uint8_t>{};
    // What the contact points may take: the memory still available (a model that would not fit
    // is refused at its *CONTACT line before its points are made).
    settings.memory_limit = available_memory().value_or(settings.memory_limit);
    try {
      interfaces_.emplace_back(std::move(settings),
                               contact_surface(model.mesh, faces1, penalty_of, moduli_of),
                               contact_surface(model.mesh, faces2, penalty_of, moduli_of,
                                               spec.main_shell_sides, {}, overlap_reversed),
                               node_mass, initial, secondary_nodes);
    } catch (const ContactSetupError& e) {
      throw InputError(location_of(model, spec, e.setting()), e.what());
    }
    if (spec.element_penalty)  // the softest facet of each part
      for (PartPenalty& part : report.parts)
        if (part.penalty == 0.0) {
          part.penalty = std::numeric_limits<double>::infinity();
          for (const std::vector<SkinFace>* faces : {&std::as_const(faces1), &faces2})
            for (const SkinFace& f : *faces)
              if (f.part == part.part_id) part.penalty = std::min(part.penalty, penalty_of(f));
        }
    report.pairs = interfaces_.back().pair_stiffness();
    report.points = interfaces_.back().point_count();
    report.released_points = interfaces_.back().released_points();
    report.warnings = penalty_warnings(model, report);
    for (std::string& w :
         deep_start_warnings(model, spec.id, interfaces_.back().deep_initial_points(initial)))
      report.warnings.push_back(std::move(w));
    reports_.push_back(std::move(report));
    slots_.push_back({false, interfaces_.size() - 1});
  }
  cfx_.assign(nodes.size(), 0.0);
  cfy_.assign(nodes.size(), 0.0);
  cfz_.assign(nodes.size(), 0.0);
  for (const ContactInterface& c : interfaces_)
    surface_nodes_.insert(surface_nodes_.end(), c.surface_nodes().begin(), c.surface_nodes().end());
  for (const ToolContact& c : tools_)
    surface_nodes_.insert(surface_nodes_.end(), c.surface_nodes().begin(), c.surface_nodes().end());
  std::sort(surface_nodes_.begin(), surface_nodes_.end());
  surface_nodes_.erase(std::unique(surface_nodes_.begin(), surface_nodes_.end()),
                       surface_nodes_.end());
  for (const ContactSpec& spec : model.contacts)
    if (spec.exchanges_heat()) thermal_ = true;
  if (thermal_) {
    heat_.assign(nodes.size(), 0.0);
    conductance_.assign(nodes.size(), 0.0);
  }
}

void ContactSet::add_tool_contact(const ContactSpec& spec, const std::vector<SkinFace>& faces1,
                                  const std::vector<std::int32_t>& secondary_nodes,
                                  std::span<const double> node_mass, const ContactInput& initial,
                                  double v_max) {
  const Model& model = model_;
  const RigidTool& tool = model.tool(spec.surface2);
  for (const SkinFace& f : faces1)
    if (model.find_part(f.part)->erosion.any())
      throw InputError(spec.surface1.where,
                       "part " + std::to_string(f.part) +
                           " may erode: eroding elements against an analytic tool (surface 2 "
                           "TOOL) are not supported yet");
  // The tool has no elements: each node's spring is pfac of its own facets (given, or the
  // automatic penalty of its part, seed 000).
  const std::map<std::int64_t, PartPenalty> penalties =
      part_penalties(model, spec, faces1, {}, v_max);
  ContactReport report;
  report.id = spec.id;
  report.title = spec.title;
  for (const auto& [part, p] : penalties) report.parts.push_back(p);
  ContactSettings settings = settings_of(model, spec);
  report.laws = describe(spec, settings);
  report.laws.discretisation = "node-to-surface, one-way, against tool " + std::to_string(tool.id);
  try {
    tools_.emplace_back(
        std::move(settings), tool.tool,
        contact_surface(model.mesh, faces1,
                        [&penalties](const SkinFace& f) { return penalties.at(f.part).penalty; }),
        node_mass, initial, secondary_nodes);
  } catch (const ContactSetupError& e) {
    throw InputError(e.setting() == "tool" ? tool.where : location_of(model, spec, e.setting()),
                     e.what());
  }
  motions_.emplace_back(model, tool);
  report.points = tools_.back().point_count();
  reports_.push_back(std::move(report));
  slots_.push_back({true, tools_.size() - 1});
}

void ContactSet::apply(const ContactInput& in, std::span<double> fx, std::span<double> fy,
                       std::span<double> fz) {
  if (slots_.empty()) return;
  for (const std::int32_t i : surface_nodes_) cfx_[i] = cfy_[i] = cfz_[i] = 0.0;
  ContactForces forces{cfx_, cfy_, cfz_, {}, {}};
  if (thermal_) {
    for (const std::int32_t i : surface_nodes_) heat_[i] = conductance_[i] = 0.0;
    forces.heat = heat_;
    forces.conductance = conductance_;
  }
  for (std::size_t c = 0; c < slots_.size(); ++c) {
    const std::size_t k = slots_[c].index;
    if (slots_[c].tool) {
      // The nodes' velocities are those of the half step before t (v^{n-1/2}).
      const ToolPose pose = motions_[k].advance(in.time, in.time - 0.5 * in.dt);
      tools_[k].apply(in, pose, forces);
      reports_[c].stats = tools_[k].stats();
    } else {
      interfaces_[k].apply(in, forces);
      reports_[c].stats = interfaces_[k].stats();
    }
  }
  for (const std::int32_t i : surface_nodes_) {
    fx[i] += cfx_[i];
    fy[i] += cfy_[i];
    fz[i] += cfz_[i];
  }
}

void ContactSet::conduct_heat(std::span<const double> temperature, std::span<double> heat) {
  for (std::size_t c = 0; c < slots_.size(); ++c) {
    if (slots_[c].tool) continue;  // tools exchange no heat (refused at setup)
    ContactInterface& interface = interfaces_[slots_[c].index];
    interface.conduct_heat(temperature, 0.0, heat);
    reports_[c].stats = interface.stats();
  }
}

void ContactSet::book_conducted_heat(double duration) {
  for (std::size_t c = 0; c < slots_.size(); ++c) {
    if (slots_[c].tool) continue;
    ContactInterface& interface = interfaces_[slots_[c].index];
    interface.book_conducted_heat(duration);
    reports_[c].stats.conducted_heat = interface.stats().conducted_heat;
  }
}

void ContactSet::erode(std::span<const std::uint8_t> eroded) {
  for (ContactInterface& c : interfaces_) c.erode(eroded);
}

double ContactSet::stable_step(std::int64_t* limiting_contact, double* springs) const {
  double step = std::numeric_limits<double>::infinity();
  if (springs) *springs = step;
  for (std::size_t c = 0; c < slots_.size(); ++c) {
    const ContactStats& stats =
        slots_[c].tool ? tools_[slots_[c].index].stats() : interfaces_[slots_[c].index].stats();
    const double bound = std::min(stats.stable_step, stats.approach_step);
    if (springs) *springs = std::min(*springs, bound);
    const double s = stats.step_bound();
    if (s < step) {
      step = s;
      if (limiting_contact) *limiting_contact = reports_[c].id;
    }
  }
  return step;
}

double ContactSet::elastic_and_damping_energy() const {
  double e = 0.0;
  for (const ContactInterface& c : interfaces_)
    e += c.stats().elastic_energy + c.stats().damping_energy;
  for (const ToolContact& c : tools_) e += c.stats().elastic_energy + c.stats().damping_energy;
  return e;
}

double ContactSet::released_energy() const {
  double e = 0.0;
  for (const ContactInterface& c : interfaces_) e += c.stats().released_energy;
  for (const ToolContact& c : tools_) e += c.stats().released_energy;
  return e;
}

double ContactSet::friction_energy() const {
  double e = 0.0;
  for (const ContactInterface& c : interfaces_) e += c.stats().friction_energy;
  for (const ToolContact& c : tools_) e += c.stats().friction_energy;
  return e;
}

double ContactSet::tool_work() const {
  double e = 0.0;
  for (const ToolContact& c : tools_) e += c.stats().tool_work;
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
  for (const ToolContact& c : tools_) {
    const auto p = c.nodal_pressure();
    for (std::size_t i = 0; i < n && i < p.size(); ++i) pressure[i] += p[i];
  }
}

void ContactSet::archive(StateArchive& a) {
  a.mark("contacts");
  a.expect(static_cast<std::uint64_t>(interfaces_.size()), "the number of contacts");
  a.expect(static_cast<std::uint64_t>(tools_.size()), "the number of tool contacts");
  a.values(interfaces_, tools_, motions_, cfx_, cfy_, cfz_, heat_, conductance_);
  for (std::size_t c = 0; c < slots_.size(); ++c)
    reports_[c].stats =
        slots_[c].tool ? tools_[slots_[c].index].stats() : interfaces_[slots_[c].index].stats();
}

}  // namespace abut
