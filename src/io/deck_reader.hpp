#pragma once
// State of one deck being read: the model under construction, the parameters, the current
// *INCLUDE placement, and the references that can only be checked once the whole deck is in
// (ids may be used before the command that defines them).
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <type_traits>
#include <unordered_map>
#include <vector>

#include "abut/io/deck.hpp"
#include "abut/mesh/generators.hpp"
#include "abut/mesh/refine.hpp"
#include "deck_block.hpp"
#include "deck_parameters.hpp"
#include "deck_text.hpp"
#include "deck_transform.hpp"

namespace abut::deck {

// Where the lines being read come from and how their content is placed.
struct IncludeFrame {
  Transform transform;
  IdOffsets offsets;
  std::filesystem::path directory;  // *INCLUDE paths are relative to this
};

// A reference to a *CURVE or *FUNCTION, bound once all of them are known.
struct FunctionBinding {
  std::int64_t id = 0;
  SourceLocation where;
  std::function<void(Model&, FunctionRef)> bind;
};

// A material's did: its *PROP_DAMAGE_JC, bound once the whole deck is read.
struct DamageBinding {
  std::int64_t id = 0;
  SourceLocation where;
  std::size_t material = 0;  // index into Model::materials
};

// A material's thpid: its *PROP_THERMAL, checked once the whole deck is read.
struct ThermalBinding {
  std::int64_t id = 0;
  SourceLocation where;  // the thpid field
};

// A row of *INITIAL_TEMPERATURE, *BC_TEMPERATURE, *LOAD_THERMAL_SURFACE or
// *LOAD_THERMAL_CONVECTION: its entity becomes nodes or faces on the final mesh
// (deck_finalize_thermal.cpp), in the entry `index` of the ThermalModel list of its keyword.
struct PendingThermal {
  enum class Kind { Initial, Prescribed, Flux, Convection } kind = Kind::Initial;
  EntityRef entity;
  std::size_t index = 0;
};

struct IdReference {
  std::int64_t id = 0;
  SourceLocation where;
};

// *ELEMENT_SOLID rows refer to nodes by id; resolved when every *NODE is in. The row's
// location is kept compactly (large meshes have many rows).
struct ElementNodes {
  std::size_t hex = 0;
  std::array<std::int64_t, 8> node_ids{};
  std::size_t file = 0;  // index into DeckReader::files
  std::size_t line = 0;
  const char* keyword = "*ELEMENT_SOLID";  // "$Elements" for a Gmsh mesh
};

// Solid cells other than hexahedra (*ELEMENT_SOLID in a degenerate form, *ELEMENT_SOLID_TET10,
// *ELEMENT_SOLID_H20), resolved like ElementNodes: cell `cell` of the block of its type.
struct CellNodes {
  CellType type = CellType::tet4;
  std::size_t cell = 0;
  std::vector<std::int64_t> node_ids;
  const char* keyword = "*ELEMENT_SOLID";
  std::vector<std::size_t> fields;  // the field (1-based node number) each node was given in
  std::size_t file = 0;
  std::size_t line = 0;
};

// *ELEMENT_SHELL rows, resolved like ElementNodes. A triangle has node_ids[3] == node_ids[2].
struct ShellNodes {
  std::size_t shell = 0;
  std::array<std::int64_t, 4> node_ids{};
  std::size_t file = 0;
  std::size_t line = 0;
  const char* keyword = "*ELEMENT_SHELL";
};

// The command that created hexes [first, end) and shells [first_shell, end_shell), to name it
// when an element's part is missing.
struct MeshSource {
  std::size_t first = 0, end = 0;
  SourceLocation where;
  std::size_t first_shell = 0, end_shell = 0;
};

// *PART_SHELL, applied once every *PART is known.
struct PendingPartShell {
  std::int64_t part = 0;
  int points = ShellSection{}.points;
  double hourglass = ShellSection{}.hourglass;
  SourceLocation where;  // the pid field
};

// *PART_SOLID, applied once every *PART is known.
struct PendingPartSolid {
  std::int64_t part = 0;
  Part::SolidIntegration integration = Part::SolidIntegration::Reduced;
  SourceLocation where;              // the pid field
  SourceLocation integration_where;  // the integration field
};

struct PendingNodeSet {
  std::size_t index = 0;  // into model.node_sets
  std::vector<IdReference> nodes;
};

// *SET_FACE: rows of corner-node ids, matched to element faces once the mesh is final.
struct PendingFaceSet {
  std::size_t index = 0;  // into model.face_sets
  struct Face {
    std::array<std::int64_t, 4> nodes{};  // a triangle: the fourth repeats the third
    SourceLocation where;                 // the row
  };
  std::vector<Face> faces;
};

// A physical group of an *INCLUDE_GMSH mesh that names a part: a physical volume (its solids),
// or a physical surface whose triangles and quadrilaterals become shells when the deck gives the
// part a thickness (else the surface is only a face set). Checked and completed in finish_gmsh.
struct GmshPart {
  std::int64_t part = 0;
  int dim = 3;
  std::string group;     // "physical volume 2 \"ball\" of ball.msh": how messages name it
  SourceLocation where;  // the *INCLUDE_GMSH file name
  struct Shell {
    std::int64_t id = 0;
    std::array<std::int64_t, 4> nodes{};  // a triangle repeats its third node
    bool linear = true;                   // tri3 or quad4: the only shells abut has
    SourceLocation where;                 // the element in the .msh file
  };
  std::vector<Shell> shells;
};

struct PendingOrder {
  EntityRef entity;
  int order = 1;
  std::optional<IdReference> region;
};

struct PendingTetrahedra {  // *CHANGE_TO_TETRAHEDRA
  EntityRef entity;
  CellType type = CellType::tet4;
  std::optional<IdReference> region;
};

struct PendingSmoothing {
  EntityRef entity;
  double max_angle = 0.0;
  bool internal = false;
  std::optional<IdReference> region;
};

// *MERGE_DUPLICATED_NODES, applied in deck order once every node, element and set is resolved.
struct PendingMerge {
  EntityRef secondary, main;        // entities s (nodes that go) and m (nodes that stay)
  std::optional<double> tolerance;  // empty: 1e-6 times the diagonal of the model's bounding box
  SourceLocation where;             // the data line
};

struct PendingVelocity {
  EntityRef entity;
  std::array<Row::NumberOrFunction, 3> velocity;
  std::array<SourceLocation, 3> velocity_where;
  Vec3 angular_velocity;
  Vec3 centre;
};

// A *CONTACT_* keyword (*CONTACT_NORMAL, *CONTACT_FRICTION, ...) that refines the *CONTACT with id
// `contact`, which may come before or after it in the deck. Applied in deck order once the whole
// deck is in (deck_finalize.cpp): `apply` sets the ContactSpec fields and checks them against the
// *CONTACT's own, raising InputError at the keyword's fields.
struct PendingContactKeyword {
  std::int64_t contact = 0;
  SourceLocation where;     // the coid field
  bool repeatable = false;  // may be given several times for one contact (*CONTACT_SCALE_PENALTY)
  std::function<void(ContactSpec&)> apply;
};

class DeckReader {
 public:
  // Reads a file or a text with the given placement; `depth` counts nested includes.
  void read_file(const std::filesystem::path& path, const IncludeFrame& frame, int depth);
  void read_text(const std::string& text, const std::string& name, const IncludeFrame& frame,
                 int depth);
  // Resolves every reference, refines the mesh, applies initial velocities.
  DeckResult finish();

  const IncludeFrame& frame() const { return frames_.back(); }
  // The optional rows of *INCLUDE after the file name (scale factors and id offsets, translation,
  // rotation and mirror), as the frame of the included content; its directory is left empty.
  IncludeFrame placement(Block& block) const;

  // Ids read from a row with the current include offsets applied; an id that the offset pushes
  // past the largest integer is an InputError at the field.
  std::int64_t node_id(const Row& r, std::size_t i) const {
    return offset_id(r, i, r.id(i), frame().offsets.node);
  }
  std::int64_t element_id(const Row& r, std::size_t i) const {
    return offset_id(r, i, r.id(i), frame().offsets.element);
  }
  std::int64_t part_id(const Row& r, std::size_t i) const {
    return offset_id(r, i, r.id(i), frame().offsets.part);
  }
  std::int64_t material_id(const Row& r, std::size_t i) const {
    return offset_id(r, i, r.id(i), frame().offsets.material);
  }
  std::int64_t other_id(const Row& r, std::size_t i) const {
    return offset_id(r, i, r.id(i), frame().offsets.other);
  }
  // id + offset, or an InputError at field i of r when the sum does not fit in 64 bits.
  static std::int64_t offset_id(const Row& r, std::size_t i, std::int64_t id, std::int64_t offset);
  std::optional<std::int64_t> optional_other_id(const Row& r, std::size_t i) const;
  // The fid of a `fcn(fid)` field i of r (its value v), offset; empty for a number.
  std::optional<std::int64_t> function_id(const Row& r, std::size_t i,
                                          const Row::NumberOrFunction& v) const;

  // An `entype, enid` pair; `allowed` lists the types the command accepts.
  EntityRef entity(const Row& r, std::size_t type_field, std::size_t id_field,
                   std::initializer_list<EntityType> allowed) const;
  // Directions must not be rotated or mirrored by an *INCLUDE (velocities, X/Y/Z choices).
  void require_unrotated(const SourceLocation& where, const std::string& what) const;

  // Runs a mesh generator, adds the command's location to its errors and records the new
  // nodes and hexes. `size` is what the generator will add: refused first, at `where`, when the
  // whole mesh would not fit in the available memory (memory_budget.hpp).
  void generate(const std::function<void()>& generator, const SourceLocation& where,
                const MeshSize& size);
  // Adds one *NODE; duplicate ids are an error.
  void add_node(std::int64_t id, const Vec3& p, std::uint8_t fixed, const SourceLocation& where);
  // Adds one hex of *ELEMENT_SOLID (nodes resolved later).
  // `where.keyword` names the rows in messages about the element.
  void add_element(std::int64_t id, std::int64_t part, const std::array<std::int64_t, 8>& node_ids,
                   const SourceLocation& where);
  SourceLocation element_where(const ElementNodes& e, const std::string& field) const;
  // Adds one solid cell of another type (nodes resolved later); ids share the hexes' namespace.
  // `fields[k]`: the node field (n1 = 1) node k came from, for messages.
  void add_cell(std::int64_t id, std::int64_t part, CellType type,
                std::vector<std::int64_t> node_ids, std::vector<std::size_t> fields,
                const char* keyword, const SourceLocation& where);
  SourceLocation cell_where(const CellNodes& e, const std::string& field) const;
  // deck_finalize_elements.cpp: the node indices of the cells, checked to exist.
  void resolve_cell_nodes();
  // Adds one shell of *ELEMENT_SHELL (nodes resolved later); shell ids are their own namespace.
  void add_shell(std::int64_t id, std::int64_t part, const std::array<std::int64_t, 4>& node_ids,
                 const SourceLocation& where);
  SourceLocation shell_where(const ShellNodes& e, const std::string& field) const;
  // deck_finalize_shells.cpp: shell nodes, areas, parts, *PART_SHELL, and the commands that do
  // not take shell parts yet. Part ids must have been checked to exist.
  void resolve_shells();
  // deck_finalize_shells.cpp: the node indices and areas of *ELEMENT_SHELL rows; before
  // merge_duplicated_nodes, which replaces nodes in every element.
  void resolve_shell_nodes();
  // deck_finalize_static.cpp: with *STATIC, the explicit-only commands are refused and the
  // boundary conditions and loads become the lists of each static step; without it, options
  // that only static steps have are refused. Runs last, on the final mesh.
  void finish_static_steps();
  // deck_finalize_thermal.cpp: thpid references, the nodes and faces of the thermal keywords,
  // and the checks that need the whole deck (a thermal keyword without a thermal material, heat
  // in static steps). On the final mesh, before finish_static_steps.
  void finish_thermal();
  // deck_finalize_merge.cpp: *MERGE_DUPLICATED_NODES, once element nodes, node sets and shell
  // nodes are resolved and before anything else stores node indices; remaps the node sets.
  void merge_duplicated_nodes();
  // deck_finalize_faces.cpp: the faces of every *SET_FACE, matched by their corner nodes to the
  // solid faces and shells of the final mesh (after merging, refinement and tetrahedra).
  void resolve_face_sets();
  // deck_finalize_elements.cpp: every hex has a positive initial volume, else an InputError at
  // its *ELEMENT_SOLID row or generator keyword naming the element and node ids. After the merge
  // (which may flatten a hex) and before refinement (which needs sound hexes).
  void check_element_volumes() const;
  // keyword_gmsh.cpp: the parts of *INCLUDE_GMSH meshes exist (a located error naming the
  // physical group otherwise), and their physical surfaces with a shell thickness become shells.
  // First in finish(), before shells and parts are resolved.
  void finish_gmsh();
  // Records an id of a kind (e.g. "component"); a second use is an error naming the first.
  void claim_id(const std::string& kind, std::int64_t id, const SourceLocation& where);
  // The index of a file name in `files` (added when new).
  std::size_t file_index(const std::string& name);
  // Index of a node id, or -1.
  std::int32_t node_index(std::int64_t id) const;

  void bind_function(std::int64_t id, const SourceLocation& where,
                     std::function<void(Model&, FunctionRef)> bind) {
    function_bindings.push_back({id, where, std::move(bind)});
  }

  Model model;
  std::vector<std::string> notes;
  std::vector<std::string> files;  // every file read, for compact locations
  Parameters parameters;

  std::vector<FunctionBinding> function_bindings;
  std::map<std::int64_t, DuctileFailure> damage_properties;  // *PROP_DAMAGE_JC by did
  std::vector<DamageBinding> damage_bindings;
  std::vector<ThermalBinding> thermal_bindings;  // thpid fields of the materials
  std::vector<PendingThermal> thermal_entities;
  std::vector<SourceLocation> thermal_keywords;  // the first line of each thermal keyword block
  std::vector<IdReference> geometry_references;  // gids that must exist
  std::vector<ElementNodes> element_nodes;
  std::vector<ShellNodes> shell_nodes;
  std::vector<CellNodes> cell_nodes;
  std::vector<PendingPartShell> part_shells;
  std::vector<PendingPartSolid> part_solids;
  // *STATIC: the end time t_end of each step of model.static_steps (as given, for the checks of
  // boundary-condition windows against step ends).
  std::vector<double> static_step_ends;
  std::set<std::int64_t> parts_with_thickness;  // *PART rows that give h
  std::vector<MeshSource> mesh_sources;
  std::vector<PendingNodeSet> node_sets;
  std::vector<PendingFaceSet> face_sets;
  std::vector<GmshPart> gmsh_parts;
  std::vector<std::pair<std::int64_t, SourceLocation>> part_set_members;  // (part id, where)
  std::vector<std::pair<std::int64_t, SourceLocation>> geometry_parts;    // *GEOMETRY_PART pids
  std::vector<PendingOrder> orders;
  POrderForm p_order_form = POrderForm::split;  // *CONTROL_P-ORDER
  std::vector<PendingSmoothing> smoothing;
  std::vector<PendingTetrahedra> tetrahedra;
  std::vector<PendingVelocity> velocities;
  std::vector<PendingMerge> merges;
  std::vector<EntityRef> entity_references;  // entities that must exist
  std::vector<PendingContactKeyword> contact_keywords;
  std::optional<SourceLocation> time_where, units_where, title_where, output_where,
      output_fields_where, bulk_viscosity_where, p_order_form_where;
  std::size_t end_line = 0;  // the last line read of the main deck, for what it lacks

 private:
  void read_lines(const std::vector<std::string>& lines, const std::string& name, int depth);
  void dispatch(Block& block, int depth);
  void read_include(Block& block, int depth);

  std::vector<IncludeFrame> frames_{IncludeFrame{}};
  std::vector<std::string> include_stack_;
  std::unordered_map<std::int64_t, std::int32_t> node_index_;
  std::set<std::int64_t> hex_ids_, shell_ids_;
  std::map<std::pair<std::string, std::int64_t>, SourceLocation> claimed_ids_;
  // Nodes removed by *MERGE_DUPLICATED_NODES: user id -> (user id of the node in its place, index
  // of the command in `merges`), so that a reference to one says what became of it.
  std::map<std::int64_t, std::pair<std::int64_t, std::size_t>> merged_nodes_;
  void require_unmerged(const EntityRef& entity) const;
};

// The reader of each supported keyword (keyword_*.cpp).
using KeywordReader = void (*)(DeckReader&, Block&);
void read_title(DeckReader&, Block&);
void read_parameter(DeckReader&, Block&);
void read_parameter_default(DeckReader&, Block&);
void read_unit_system(DeckReader&, Block&);
void read_time(DeckReader&, Block&);
void read_output(DeckReader&, Block&);
void read_output_fields(DeckReader&, Block&);  // keyword_control.cpp (abut's own)
void read_output_node_history(DeckReader&, Block&);  // keyword_control.cpp (abut's own)
void read_control_bulk_viscosity(DeckReader&, Block&);
void read_node(DeckReader&, Block&);
void read_element_solid(DeckReader&, Block&);
void read_element_solid_tet10(DeckReader&, Block&);
void read_element_solid_h20(DeckReader&, Block&);
void read_element_shell(DeckReader&, Block&);
void read_component_shell_plate(DeckReader&, Block&);
void read_component_shell_tube(DeckReader&, Block&);
void read_component_box(DeckReader&, Block&);
void read_component_sphere(DeckReader&, Block&);
void read_component_cylinder(DeckReader&, Block&);
void read_change_p_order(DeckReader&, Block&);
void read_control_p_order(DeckReader&, Block&);
void read_change_to_tetrahedra(DeckReader&, Block&);
void read_smooth_mesh(DeckReader&, Block&);
void read_merge_duplicated_nodes(DeckReader&, Block&);
void read_mat_elastic(DeckReader&, Block&);
void read_mat_mooney_rivlin(DeckReader&, Block&);
void read_mat_rigid(DeckReader&, Block&);
void read_mat_metal(DeckReader&, Block&);
void read_mat_jc(DeckReader&, Block&);
void read_prop_damage_jc(DeckReader&, Block&);
// keyword_thermal.cpp
void read_prop_thermal(DeckReader&, Block&);
void read_initial_temperature(DeckReader&, Block&);
void read_bc_temperature(DeckReader&, Block&);
void read_load_thermal_surface(DeckReader&, Block&);
void read_load_thermal_convection(DeckReader&, Block&);
// A material's thpid field (0 or empty: none): sets Material::thermal_id of the material about
// to be added and records the reference, checked once the deck is in.
std::int64_t thermal_property_id(DeckReader& d, const Row& r, std::size_t i);
void read_part(DeckReader&, Block&);
void read_part_shell(DeckReader&, Block&);
void read_part_solid(DeckReader&, Block&);  // keyword_static.cpp
void read_static(DeckReader&, Block&);      // keyword_static.cpp
void read_set_node(DeckReader&, Block&);
void read_set_part(DeckReader&, Block&);
void read_set_face(DeckReader&, Block&);
void read_include_gmsh(DeckReader&, Block&);
void read_initial_velocity(DeckReader&, Block&);
void read_bc_motion(DeckReader&, Block&);
void read_load_gravity(DeckReader&, Block&);
void read_load_pressure(DeckReader&, Block&);
void read_curve(DeckReader&, Block&);
void read_function(DeckReader&, Block&);
void read_geometry_box(DeckReader&, Block&);
void read_geometry_sphere(DeckReader&, Block&);
void read_geometry_pipe(DeckReader&, Block&);
void read_geometry_ellipsoid(DeckReader&, Block&);
void read_geometry_part(DeckReader&, Block&);
void read_contact(DeckReader&, Block&);
void read_contact_discretization(DeckReader&, Block&);
void read_contact_normal(DeckReader&, Block&);
void read_contact_friction(DeckReader&, Block&);
void read_contact_friction_pair(DeckReader&, Block&);
void read_contact_adhesion(DeckReader&, Block&);
void read_contact_stiffness(DeckReader&, Block&);
void read_contact_thermal(DeckReader&, Block&);
void read_contact_gap(DeckReader&, Block&);
void read_contact_edge(DeckReader&, Block&);
void read_contact_erosion(DeckReader&, Block&);
void read_contact_tool(DeckReader&, Block&);  // keyword_contact_tool.cpp
// keyword_contact_tool.cpp: the tool of a contact with surface 2 TOOL exists, and the contact asks
// for nothing a tool contact does not do (InputError at the field).
void check_tool_contact(const Model& model, const ContactSpec& c);
void read_contact_scale_penalty(DeckReader&, Block&);
void read_contact_initial(DeckReader&, Block&);
void read_contact_stabilization(DeckReader&, Block&);  // keyword_contact_stabilization.cpp
void read_contact_smoothing(DeckReader&, Block&);      // keyword_contact_smoothing.cpp
void read_sensor(DeckReader&, Block&);                 // keyword_sensor.cpp
void read_contact_sensor(DeckReader&, Block&);
void read_contact_release_bc(DeckReader&, Block&);
// keyword_sensor.cpp: the contacts and sensors that *SENSOR and *CONTACT_SENSOR name exist.
void check_sensors(const Model& model);
void read_contact_dependency(DeckReader&, Block&);
// keyword_contact_dependency.cpp: a dependency without its parameter (law) is an error.
void check_contact_dependency(const ContactSpec& c);

// keyword_contact_laws.cpp, shared with keyword_contact_friction.cpp.
// Records a *CONTACT_* keyword whose first field is coid; `apply` runs once the deck is in.
void refine_contact(DeckReader& d, const Row& r, std::function<void(ContactSpec&)> apply,
                    bool repeatable = false);
// Options of different keywords that the contact library does not combine (one of them would do
// nothing): an InputError at the *CONTACT_* field. Run once every keyword is merged.
void check_contact_options(const Model& model, const ContactSpec& c);
// Records where row r (first field coid) gives `setting` of its contact: field `column` (Sources).
void contact_place(DeckReader& d, const Row& r, std::string_view setting, std::size_t column);
// keyword_contact_tie.cpp: moves the contacts with an exact tie (FREEZE, tie = EXACT) from
// model.contacts to model.ties; InputError at any option of theirs a tie would not use.
void extract_exact_ties(Model& model);
// keyword_words.cpp: the dialect's words for the concepts the solvers' messages ask for.
void name_keyword_words(Sources& sources);
// "*CONTACT <id> at <file>:<line>", for messages that point at the contact a keyword refines.
std::string contact_at(const ContactSpec& c);

template <class T>
struct WordChoice {
  std::string_view word;  // upper case, or an integer synonym such as "1000"
  T value;
};
// A field that is one of the words of `choices` (any case; an integer written as 5 or 5.0 matches
// "5"); `fallback` when empty. `expected` lists the choices for the error message.
template <class T>
T word_choice(const Row& r, std::size_t i, T fallback,
              std::type_identity_t<std::initializer_list<WordChoice<T>>> choices,
              const std::string& expected) {
  if (!r.given(i)) return fallback;
  std::string w = upper(r.text(i));
  if (const auto n = parse_integer(w)) w = std::to_string(*n);
  for (const WordChoice<T>& c : choices)
    if (w == c.word) return c.value;
  r.fail(i, "expected " + expected + ", got '" + r.text(i) + "'");
}

// The deck word of an entity type: N, NS, P, PS, ALL, G.
std::string entity_word(EntityType t);
// "1, 2, 5" (the first 20 ids) or "none", for messages that say what exists (deck_finalize.cpp).
std::string joined(const std::set<std::int64_t>& ids);
SourceLocation with_field(SourceLocation where, const std::string& field);

// deck_catalogue.cpp: the supported keywords, the other IMPETUS keywords, suggestions.
KeywordReader find_keyword_reader(const std::string& keyword);
bool is_known_impetus_keyword(const std::string& keyword);
std::optional<std::string> closest_keyword(const std::string& keyword);

// A translational constraint word: 0, X, Y, Z, XY, YZ, ZX, XYZ (any order) -> DofMask bits.
std::uint8_t parse_dof_mask(const Row& r, std::size_t i);
// X, Y or Z -> 0..2 (and RX, RY, RZ -> 3..5 when rotations are allowed).
int parse_direction(const Row& r, std::size_t i, bool rotations);

}  // namespace abut::deck
