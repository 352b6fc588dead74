#include "tie_search.hpp"

#include <algorithm>
#include <string>

#include "abut/contact/interface.hpp"
#include "abut/solver/contact_surfaces.hpp"
#include "contact_set.hpp"

namespace abut {

namespace {

std::string node_name(const Model& model, std::int32_t node) {
  return "node " + std::to_string(model.mesh.nodes.id[static_cast<std::size_t>(node)]);
}

// The node ties of one exact tie: the contact library's FREEZE search, node to surface and one
// way, in the reference configuration. Its penalty and masses only bound its springs' step,
// which is not used: any positive value does.
std::vector<ContactInterface::NodeTie> search(const Model& model, const TieSpec& tie) {
  const Nodes& nodes = model.mesh.nodes;
  const auto [secondary, faces1] = secondary_surface(model, tie.surface1, tie.merge, false);
  const std::vector<SkinFace> faces2 = contact_faces(model, tie.surface2, tie.merge);
  const auto unit = [](const SkinFace&) { return 1.0; };
  ContactSettings s;
  s.discretisation = Discretisation::NodeToSurface;
  s.one_way = true;
  s.freeze = true;
  s.detection_depth = tie.detection_depth;
  s.edge_tolerance = tie.edge_tolerance;
  s.edge_angle = tie.edge_angle;
  const std::vector<double> mass(nodes.size(), 1.0), rest(nodes.size(), 0.0);
  const ContactInput initial{nodes.x, nodes.y, nodes.z, rest, rest, rest, 0.0, 0.0, {}};
  try {
    const ContactInterface search(std::move(s), contact_surface(model.mesh, faces1, unit),
                                  contact_surface(model.mesh, faces2, unit), mass, initial,
                                  secondary);
    return search.node_ties();
  } catch (const ContactSetupError& e) {
    const SourceLocation where =
        Sources::has_setting(SourceEntity::Tie, e.setting())
            ? model.sources.of(SourceEntity::Tie, tie.id, e.setting(), tie.where)
            : tie.where;
    throw InputError(where, std::string("exact tie ") + std::to_string(tie.id) + ": " + e.what());
  }
}

}  // namespace

std::vector<TiedNode> find_tied_nodes(const Model& model) {
  std::vector<TiedNode> out;
  const Nodes& nodes = model.mesh.nodes;
  std::vector<std::int32_t> tie_of(nodes.size(), -1);  // the tie that binds a node
  for (std::size_t t = 0; t < model.ties.size(); ++t) {
    const TieSpec& spec = model.ties[t];
    const std::vector<ContactInterface::NodeTie> found = search(model, spec);
    if (found.empty())
      throw InputError(exact_tie_place(model, spec),
                       "exact tie " + std::to_string(spec.id) +
                           " binds no node: no node of surface 1 lies within the detection depth "
                           "of a facet of surface 2 at t = 0 (set " +
                           model.sources.words("detection_depth") + ")");
    for (const ContactInterface::NodeTie& f : found) {
      const auto s = static_cast<std::size_t>(f.node);
      if (tie_of[s] >= 0)
        throw InputError(exact_tie_place(model, spec),
                         node_name(model, f.node) + " is tied by exact tie " +
                             std::to_string(model.ties[tie_of[s]].id) + " already (at line " +
                             std::to_string(model.ties[tie_of[s]].where.line) +
                             "): a node can follow one facet only");
      tie_of[s] = static_cast<std::int32_t>(t);
      TiedNode n;
      n.node = f.node;
      n.tie = static_cast<std::uint32_t>(t);
      Vec3 at;
      for (int a = 0; a < 4; ++a) {
        const std::int32_t m = f.facet[a];
        at += nodes.position(static_cast<std::size_t>(m)) * f.shape[a];
        if (f.shape[a] == 0.0) continue;
        int k = 0;
        while (k < n.count && n.main[k] != m) ++k;
        if (k == n.count) {
          n.main[n.count] = m;
          n.weight[n.count++] = 0.0;
        }
        n.weight[k] += f.shape[a];
      }
      n.offset = nodes.position(s) - at;
      out.push_back(n);
    }
  }
  for (const TiedNode& n : out)
    for (int k = 0; k < n.count; ++k)
      if (const std::int32_t other = tie_of[static_cast<std::size_t>(n.main[k])]; other >= 0) {
        const TieSpec& spec = model.ties[n.tie];
        throw InputError(exact_tie_place(model, spec),
                         node_name(model, n.main[k]) + " of a facet that exact tie " +
                             std::to_string(spec.id) + " binds " + node_name(model, n.node) +
                             " to is itself tied (by exact tie " +
                             std::to_string(model.ties[other].id) +
                             "): chains of ties are not supported; tie to the other surface");
      }
  return out;
}

RemovedNodes tied_node_set(const std::vector<TiedNode>& tied) {
  std::vector<std::int32_t> nodes;
  for (const TiedNode& n : tied) nodes.push_back(n.node);
  return RemovedNodes(std::move(nodes));
}

std::vector<LinearConstraint> tie_constraints(const Model& model,
                                              const std::vector<TiedNode>& tied) {
  std::vector<LinearConstraint> out;
  out.reserve(3 * tied.size());
  for (const TiedNode& n : tied)
    for (int d = 0; d < 3; ++d) {
      LinearConstraint c;
      c.where = exact_tie_place(model, model.ties[n.tie]);
      c.terms.push_back({n.node, d, 1.0});
      for (int k = 0; k < n.count; ++k) c.terms.push_back({n.main[k], d, -n.weight[k]});
      out.push_back(std::move(c));
    }
  return out;
}

}  // namespace abut
