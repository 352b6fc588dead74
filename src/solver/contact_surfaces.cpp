#include "abut/solver/contact_surfaces.hpp"

#include <algorithm>
#include <iterator>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "abut/contact/adjust.hpp"
#include "abut/contact/shell_orientation.hpp"
#include "abut/core/error.hpp"

namespace abut {

ContactSurface contact_surface(
    const Mesh& mesh, std::span<const SkinFace> faces,
    const std::function<double(const SkinFace&)>& penalty_of_face,
    const std::function<ElasticModuli(std::int64_t part)>& moduli_of_part,
    ContactSpec::ShellSides shell_sides, std::span<const FacetParent> parents,
    std::span<const std::uint8_t> overlap_reversed) {
  using Sides = ContactSpec::ShellSides;
  if (shell_sides == Sides::Overlap && overlap_reversed.size() != faces.size())
    throw std::invalid_argument("contact_surface: OVERLAP needs one side per face");
  ContactSurface s;
  s.facets.reserve(faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const SkinFace& f = faces[i];
    // The facets a face adds (a shell's sides: plain) have its parent.
    if (!parents.empty()) s.parent.resize(s.size(), FacetParent{});
    const ElasticModuli m = moduli_of_part ? moduli_of_part(f.part) : ElasticModuli{};
    if (f.shell >= 0 && shell_sides != Sides::Both) {
      const bool reverse =
          shell_sides == Sides::Overlap ? overlap_reversed[i] != 0 : shell_sides == Sides::Reverse;
      s.add_shell_side(f.nodes, f.part, penalty_of_face(f), f.thickness, reverse);
      s.element.back() = element_index(mesh, f);
      continue;
    }
    if (f.shell >= 0) {
      const double young = m.bulk > 0.0 ? 9.0 * m.bulk * m.shear / (3.0 * m.bulk + m.shear) : 0.0;
      s.add_shell(f.nodes, f.part, penalty_of_face(f), f.thickness, young);
      s.element.end()[-1] = s.element.end()[-2] = element_index(mesh, f);
      continue;
    }
    const double volume =
        moduli_of_part ? solid_volume(mesh, static_cast<std::size_t>(f.solid)) : 0.0;
    s.add(f.nodes, f.part, penalty_of_face(f), f.thickness, m.bulk, volume);
    s.element.back() = element_index(mesh, f);
    s.exposed_by.back() = f.exposed_by;
    if (!parents.empty()) s.parent.push_back(parents[i]);
  }
  if (!parents.empty()) s.parent.resize(s.size(), FacetParent{});
  return s;
}

std::vector<std::uint8_t> overlap_sides(const Mesh& mesh, std::span<const SkinFace> secondary_faces,
                                        std::span<const std::int32_t> secondary_nodes,
                                        std::span<const SkinFace> main_faces) {
  std::vector<std::int32_t> points(secondary_nodes.begin(), secondary_nodes.end());
  for (const SkinFace& f : secondary_faces)
    points.insert(points.end(), f.nodes.begin(), f.nodes.end());
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  std::vector<std::array<std::int32_t, 4>> shells;
  std::vector<std::size_t> face_of;
  for (std::size_t i = 0; i < main_faces.size(); ++i)
    if (main_faces[i].shell >= 0) {
      shells.push_back(main_faces[i].nodes);
      face_of.push_back(i);
    }
  const std::vector<std::uint8_t> reversed =
      overlap_push_reversed(shells, mesh.nodes.x, mesh.nodes.y, mesh.nodes.z, points);
  std::vector<std::uint8_t> out(main_faces.size(), 0);
  for (std::size_t k = 0; k < shells.size(); ++k) out[face_of[k]] = reversed[k];
  return out;
}

std::int32_t element_index(const Mesh& mesh, const SkinFace& f) {
  return f.shell >= 0 ? static_cast<std::int32_t>(mesh.solid_count()) + f.shell : f.solid;
}

bool part_can_erode(const Model& model, std::int64_t part) {
  const Part* p = model.find_part(part);
  if (p && p->erosion.any()) return true;
  const auto* metal = std::get_if<MetalParams>(&model.material_of_part(part));
  return metal && metal->failure.active;
}

std::vector<SkinFace> contact_faces(const Model& model, const EntityRef& entity, bool merge,
                                    bool exposed_faces) {
  std::vector<SkinFace> faces;
  std::vector<std::int64_t> parts;
  std::vector<std::int32_t> shells;  // of a face set, sorted
  // Interior faces next to solids that can erode, when erosion may expose them.
  std::vector<std::uint8_t> erodible(model.mesh.solid_count(), 0);
  if (exposed_faces)
    for (std::size_t e = 0; e < erodible.size(); ++e)
      erodible[e] = part_can_erode(model, model.mesh.solid(e).part) ? 1 : 0;
  std::function<bool(std::int32_t)> exposable;
  if (std::find(erodible.begin(), erodible.end(), 1) != erodible.end())
    exposable = [&erodible](std::int32_t h) { return erodible[h] != 0; };
  // The skin's own errors (a hex of non-positive volume) have no deck line: give them the
  // surface's.
  const auto located = [&entity](const auto& extract) {
    try {
      return extract();
    } catch (const InputError& e) {
      if (!e.where().file.empty()) throw;
      throw InputError(entity.where, e.message());
    }
  };
  if (entity.type == EntityType::All) {
    faces = located([&] { return exterior_faces(model.mesh, merge, exposable); });
    for (const Part& p : model.parts) parts.push_back(p.id);
  } else if (entity.type == EntityType::Part || entity.type == EntityType::PartSet) {
    parts = model.parts_of(entity);
    faces = located([&] { return exterior_faces(model.mesh, parts, merge, exposable); });
  } else if (entity.type == EntityType::FaceSet) {
    const FaceSet& set = model.face_set(entity);
    located([&] {
      for (const SolidFace& sf : set.faces)
        append_facets(model.mesh, sf.solid, sf.face, 0.0, faces);
      return 0;
    });
    for (const std::int32_t s : set.shells) shells.push_back(s);
  } else {
    throw InputError(entity.where,
                     "a contact surface is a part (P), a part set (PS), ALL or element faces");
  }
  const Mesh& mesh = model.mesh;
  for (std::size_t s = 0; s < mesh.shell_count(); ++s) {
    if (std::find(parts.begin(), parts.end(), mesh.shell_part[s]) == parts.end() &&
        !std::binary_search(shells.begin(), shells.end(), static_cast<std::int32_t>(s)))
      continue;
    SkinFace f;
    f.nodes = mesh.shells[s];
    f.part = mesh.shell_part[s];
    f.thickness = model.find_part(f.part)->thickness;
    f.shell = static_cast<std::int32_t>(s);
    faces.push_back(f);
  }
  if (faces.empty())
    throw InputError(entity.where, "this contact surface has no exterior element faces or shells");
  return faces;
}

double element_penalty(double element_step, double lightest_node, double face_area) {
  const double omega2 = 4.0 / (element_step * element_step);
  return kElementPenaltyFraction * lightest_node * omega2 / (2.0 * face_area);
}

double smallest_element_volume(const Mesh& mesh, std::int64_t part, double shell_thickness) {
  // Per user element: the hexes *CHANGE_P-ORDER made of one order-p element count together, so
  // L_min is the size of the element as defined (seed 000 computes it for its cubic elements).
  std::map<std::int64_t, double> volume_of_element;
  for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
    if (mesh.hex_part[h] == part)
      volume_of_element[mesh.element_of(h)] += hex_volume(mesh.nodes, mesh.hexes[h]);
  for (std::size_t e = mesh.hex_count(); e < mesh.solid_count(); ++e) {
    const SolidRef cell = mesh.solid(e);
    if (cell.part == part) volume_of_element[cell.id] = solid_volume(mesh, e);
  }
  double smallest = std::numeric_limits<double>::infinity();
  for (const auto& [element, volume] : volume_of_element) smallest = std::min(smallest, volume);
  bool shells = false;
  for (std::size_t s = 0; s < mesh.shell_count(); ++s)
    if (mesh.shell_part[s] == part) {
      shells = true;
      smallest = std::min(smallest, quad_area(mesh.nodes, mesh.shells[s]) * shell_thickness);
    }
  if (volume_of_element.empty() && !shells)
    throw InputError("part " + std::to_string(part) +
                     " has no elements, so its automatic contact penalty is undefined");
  return smallest;
}

std::vector<std::string> adjust_contact_nodes(Model& model) {
  std::vector<std::string> notes;
  Nodes& nodes = model.mesh.nodes;
  for (const ContactSpec& spec : model.contacts) {
    if (!spec.adjust_depth) continue;
    std::vector<std::int32_t> secondary;
    if (spec.surface1.type == EntityType::NodeSet) {
      secondary = model.nodes_of(spec.surface1);
    } else {
      for (const SkinFace& f : contact_faces(model, spec.surface1, spec.merge))
        secondary.insert(secondary.end(), f.nodes.begin(), f.nodes.end());
      std::sort(secondary.begin(), secondary.end());
      secondary.erase(std::unique(secondary.begin(), secondary.end()), secondary.end());
    }
    if (spec.adjust_nodes) {  // ADJUST = SET of GRID: those of the secondary nodes in the set
      std::sort(secondary.begin(), secondary.end());
      std::vector<std::int32_t> chosen = model.nodes_of(*spec.adjust_nodes);
      std::sort(chosen.begin(), chosen.end());
      std::vector<std::int32_t> both;
      std::set_intersection(secondary.begin(), secondary.end(), chosen.begin(), chosen.end(),
                            std::back_inserter(both));
      if (both.empty()) {
        throw InputError(spec.adjust_nodes->where,
                         "node set " + std::to_string(spec.adjust_nodes->id) +
                             " has no node on surface 1 of contact " + std::to_string(spec.id) +
                             ": ADJUST would move nothing");
      }
      secondary = std::move(both);
    }
    const std::vector<SkinFace> main_faces = contact_faces(model, spec.surface2, spec.merge);
    const ContactSurface main =
        contact_surface(model.mesh, main_faces, [](const SkinFace&) { return 1.0; });
    // AUTO (stored as a negative depth): 5% of the mean edge of the main surface (seed 003).
    // 0: the search depth, the given detection depth or half the thinnest element of surface 2
    // (the contact's default depth is half the element's thickness).
    double depth = *spec.adjust_depth;
    if (depth < 0.0) {
      depth = 0.05 * mean_edge_length(main, nodes.x, nodes.y, nodes.z);
    } else if (depth == 0.0 && !main.thickness.empty()) {
      depth = spec.detection_depth.value_or(
          0.5 * *std::min_element(main.thickness.begin(), main.thickness.end()));
    }
    const std::size_t moved =
        adjust_onto_surface(main, secondary, nodes.x, nodes.y, nodes.z, depth);
    notes.push_back("contact " + std::to_string(spec.id) + ": ADJUST moved " +
                    std::to_string(moved) + " secondary nodes onto surface 2 (depth " +
                    std::to_string(depth) + ")");
  }
  return notes;
}

CurvePenalty curve_penalty(const Model& model, FunctionRef curve) {
  return CurvePenalty{function_of_one(&model.functions, curve, model.time.end_time)};
}

ScalarFunction function_of_one(const FunctionTable* table, FunctionRef f, double term) {
  if (!f.valid()) return {};
  return [table, f, term](double x) {
    Variables v;
    v.term = term;
    v.t = x;
    return table->value(f, x, v);
  };
}

}  // namespace abut
