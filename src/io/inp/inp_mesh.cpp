// *HEADING, *NODE, *ELEMENT, *NSET, *ELSET and *SURFACE: the mesh, its sets and surfaces, kept
// with user ids and names until finish_mesh (inp_finish.cpp) resolves them.
#include <optional>
#include <utility>

#include "../deck_text.hpp"
#include "abut/mesh/shape_functions.hpp"
#include "inp_reader.hpp"

namespace abut::inp {
namespace {

constexpr std::string_view kSupportedTypes =
    "abut reads the solid elements C3D8 (8-node hexahedron, 2x2x2 points), C3D8R (one point with "
    "hourglass control), C3D20 (20-node hexahedron, 3x3x3 points), C3D20R (2x2x2 points), C3D4 "
    "(4-node tetrahedron), C3D10 (10-node tetrahedron, 4 points) and C3D6 (6-node wedge)";

// The cell type and rule of an element name: each type's full-integration name (C3D20) and, for
// a type with a reduced rule, the name with R (C3D20R).
std::optional<std::pair<CellType, bool>> element_type(const std::string& name) {
  for (const CellType type : kCellTypes) {
    const std::string full(topology(type).abaqus);
    if (full.empty()) continue;  // no Abaqus name (the Lagrange hexahedra)
    if (name == full) return std::make_pair(type, false);
    if (name == full + "R" && !quadrature(type, Integration::reduced).empty())
      return std::make_pair(type, true);
  }
  return std::nullopt;
}

// The ids and set names of the data lines of a *NSET / *ELSET (or its GENERATE ranges), added
// to sets[target]. The sets named on a line are copied as they are now (CalculiX).
void read_set_lines(Reader& r, const Card& c, std::vector<IdSet>& sets,
                    const std::unordered_map<std::string, std::size_t>& names, std::size_t target,
                    const std::string& what) {
  const bool generate = has_parameter(c, "GENERATE");
  IdSet& set = sets[target];
  for (const DataLine& l : c.data) {
    const Fields f(r, c, l);
    if (generate) {
      f.at_most(3, "first, last, increment");
      const std::int64_t first = f.integer(0, "first");
      const std::int64_t last = f.integer(1, "last");
      const std::int64_t step = f.given(2) ? f.integer(2, "increment") : 1;
      if (first <= 0) f.fail("first", "expected a positive " + what + " number");
      if (last < first) f.fail("last", "expected last >= first");
      if (step <= 0) f.fail("increment", "expected an increment > 0");
      for (std::int64_t id = first; id <= last; id += step) {
        set.ids.push_back(id);
        set.where.push_back(f.loc());
      }
      continue;
    }
    for (std::size_t i = 0; i < f.size(); ++i) {
      if (!f.given(i)) continue;  // `1,` and `1,,2`
      const Item item = f.item(i, what);
      if (item.name.empty()) {
        set.ids.push_back(item.id);
        set.where.push_back(item.where);
        continue;
      }
      const auto it = names.find(upper_name(item.name));
      if (it == names.end()) {
        f.fail(what, what + " set " + item.name +
                         " is not defined before this line (the sets named in a set are "
                         "copied when it is read, so define them first)");
      }
      if (it->second == target) continue;  // a set named in itself adds nothing
      const IdSet& other = sets[it->second];
      set.ids.insert(set.ids.end(), other.ids.begin(), other.ids.end());
      set.where.insert(set.where.end(), other.where.begin(), other.where.end());
    }
  }
}

}  // namespace

void read_heading(Reader& r, const Card& c) {
  check_parameters(r, c, {});
  for (const DataLine& l : c.data) r.title_lines.push_back(l.text);
}

void read_node(Reader& r, const Card& c) {
  check_parameters(r, c,
                   {{"NSET"},
                    {"SYSTEM", ParameterRule::Kind::Unsupported, "local coordinate systems"},
                    {"INPUT", ParameterRule::Kind::Unsupported, "use *INCLUDE"}});
  IdSet* set = nullptr;
  if (const auto name = parameter_value(c, "NSET")) set = &r.node_set(*name, r.loc(c));
  Nodes& nodes = r.model.mesh.nodes;
  for (const DataLine& l : c.data) {
    const Fields f(r, c, l);
    f.at_most(4, "node number, x, y, z");
    const std::int64_t id = f.integer(0, "node");
    if (id <= 0) f.fail("node", "expected a node number > 0, got " + std::to_string(id));
    const Vec3 p{f.number(1, "x"), f.number_or(2, "y", 0.0), f.number_or(3, "z", 0.0)};
    const auto index = static_cast<std::int32_t>(nodes.size());
    const auto [it, inserted] = r.node_index.emplace(id, index);
    if (!inserted) {
      f.fail("node", "node " + std::to_string(id) + " is already defined at " +
                         r.at(r.node_where[static_cast<std::size_t>(it->second)]));
    }
    nodes.add(id, p);
    r.node_where.push_back(f.loc());
    if (set) {
      set->ids.push_back(id);
      set->where.push_back(f.loc());
    }
  }
}

void read_element(Reader& r, const Card& c) {
  check_parameters(
      r, c, {{"TYPE"}, {"ELSET"}, {"INPUT", ParameterRule::Kind::Unsupported, "use *INCLUDE"}});
  const std::string type = deck::upper(required_parameter(r, c, "TYPE"));
  const auto cell = element_type(type);
  if (!cell) {
    throw InputError(r.where(c, "TYPE"), "element type " + type + " is not supported yet: " +
                                             std::string(kSupportedTypes));
  }
  const std::size_t count = static_cast<std::size_t>(topology(cell->first).nodes) + 1;
  IdSet* set = nullptr;
  if (const auto name = parameter_value(c, "ELSET")) set = &r.element_set(*name, r.loc(c));
  for (std::size_t i = 0; i < c.data.size(); ++i) {
    const DataLine& first = c.data[i];
    const SourceLocation where = r.where(Reader::loc(first), c.keyword);
    // A line ending with a comma continues on the next line (CalculiX's C3D20 takes 16 entries
    // on its first line and the rest on the next, with or without the comma).
    std::vector<std::string> fields;
    const DataLine* line = &first;
    while (true) {
      std::vector<std::string> more = deck::split_fields(line->text);
      const bool continues = line->text.back() == ',';
      if (continues) more.pop_back();
      fields.insert(fields.end(), more.begin(), more.end());
      if (fields.size() >= count || i + 1 >= c.data.size()) break;
      if (!continues && fields.size() < 16) break;
      line = &c.data[++i];
    }
    const auto field_where = [&](const std::string& name) {
      SourceLocation w = r.where(Reader::loc(*line), c.keyword, name);
      return w;
    };
    if (fields.size() != count) {
      throw InputError(where, "expected the element number and " + std::to_string(count - 1) +
                                  " node numbers (" + type + "), got " +
                                  std::to_string(fields.size()) +
                                  " fields; a line ending with a comma continues on the next");
    }
    ElementRecord e;
    e.type = cell->first;
    e.reduced = cell->second;
    e.where = Reader::loc(first);
    for (std::size_t k = 0; k < count; ++k) {
      const std::string name = k == 0 ? "element" : "n" + std::to_string(k);
      const auto v = deck::parse_integer(fields[k]);
      if (!v || *v <= 0) {
        throw InputError(field_where(name), "expected a positive integer, got '" + fields[k] + "'");
      }
      if (k == 0) {
        e.id = *v;
      } else {
        e.nodes[k - 1] = *v;
      }
    }
    const auto [it, inserted] = r.element_index.emplace(e.id, r.elements.size());
    if (!inserted) {
      throw InputError(r.where(e.where, c.keyword, "element"),
                       "element " + std::to_string(e.id) + " is already defined at " +
                           r.at(r.elements[it->second].where));
    }
    r.elements.push_back(e);
    if (set) {
      set->ids.push_back(e.id);
      set->where.push_back(e.where);
    }
  }
}

void read_nset(Reader& r, const Card& c) {
  check_parameters(
      r, c,
      {{"NSET"},
       {"GENERATE", ParameterRule::Kind::Flag},
       {"ELSET", ParameterRule::Kind::Unsupported, "list the nodes (or node sets) instead"},
       {"INSTANCE", ParameterRule::Kind::Unsupported, "abut reads flat input files"},
       {"UNSORTED", ParameterRule::Kind::Ignored, "has no effect in abut (sets are sorted)"},
       {"INTERNAL", ParameterRule::Kind::Ignored, "has no effect in abut"},
       {"FREQUENCY", ParameterRule::Kind::Ignored,
        "has no meaning for a node set: ignored (CalculiX ignores it too)"}});
  const std::string name = required_parameter(r, c, "NSET");
  r.node_set(name, r.loc(c));
  read_set_lines(r, c, r.node_sets, r.node_set_names, r.node_set_names.at(upper_name(name)),
                 "node");
}

void read_elset(Reader& r, const Card& c) {
  check_parameters(
      r, c,
      {{"ELSET"},
       {"GENERATE", ParameterRule::Kind::Flag},
       {"INSTANCE", ParameterRule::Kind::Unsupported, "abut reads flat input files"},
       {"UNSORTED", ParameterRule::Kind::Ignored, "has no effect in abut (sets are sorted)"},
       {"INTERNAL", ParameterRule::Kind::Ignored, "has no effect in abut"},
       {"FREQUENCY", ParameterRule::Kind::Ignored,
        "has no meaning for an element set: ignored (CalculiX ignores it too)"}});
  const std::string name = required_parameter(r, c, "ELSET");
  r.element_set(name, r.loc(c));
  read_set_lines(r, c, r.element_sets, r.element_set_names,
                 r.element_set_names.at(upper_name(name)), "element");
}

void read_surface(Reader& r, const Card& c) {
  check_parameters(r, c, {{"NAME"}, {"TYPE"}});
  const std::string name = required_parameter(r, c, "NAME");
  const bool node_based = parameter_choice(r, c, "TYPE", {"ELEMENT", "NODE"}, "ELEMENT") == "NODE";
  const auto [it, inserted] = r.surface_names.emplace(upper_name(name), r.surfaces.size());
  if (!inserted) {
    throw InputError(r.where(c, "NAME"), "surface " + name + " is already defined at " +
                                             r.at(r.surfaces[it->second].defined) +
                                             ": give each *SURFACE its own name");
  }
  SurfaceRecord s;
  s.name = name;
  s.node_based = node_based;
  s.defined = r.loc(c);
  for (const DataLine& l : c.data) {
    const Fields f(r, c, l);
    if (node_based) {
      f.at_most(2, "a node or node set, and optionally its weight");
      s.items.push_back(f.item(0, "node"));
      if (f.given(1) && f.number(1, "weight") != 1.0) {
        f.fail("weight",
               "nodal area weights of node-based surfaces are not supported yet by abut: leave "
               "the weight out (or 1.0)");
      }
      continue;
    }
    f.at_most(2, "an element or element set, and a face label S1 to S6");
    s.items.push_back(f.item(0, "element"));
    if (!f.given(1)) {
      f.fail("face",
             "the face label is missing: give S1 to S6 (abut does not make a surface of "
             "all exterior faces of a set yet)");
    }
    const std::string label = deck::upper(f.text(1));
    if (label.size() != 2 || label[0] != 'S' || label[1] < '1' || label[1] > '6') {
      f.fail("face", "expected a face label S1 to S6, got '" + f.text(1) + "'");
    }
    s.faces.push_back(static_cast<std::int8_t>(label[1] - '1'));
  }
  r.surfaces.push_back(std::move(s));
}

}  // namespace abut::inp
