#pragma once
// State of one Abaqus/CalculiX input file being read (docs/inp-reference.md). Cards are read in
// order into the records below, which keep user ids, names and the line each came from; finish()
// resolves every reference (names may be used before the card that defines them) and builds the
// Model: mesh, parts, node sets, face sets, contacts, amplitudes, equations and static steps.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "abut/io/deck.hpp"
#include "abut/mesh/topology.hpp"
#include "inp_lines.hpp"

namespace abut::inp {

// Where a record came from: file index (InpLines::files) and 1-based line.
struct Loc {
  std::uint32_t file = 0;
  std::uint32_t line = 0;
};

// A reference on a data line: an id (node or element) or the name of a set.
struct Item {
  std::int64_t id = 0;  // when name is empty
  std::string name;     // as written
  Loc where;
};

// *NSET / *ELSET (also NSET= of *NODE and ELSET= of *ELEMENT): ids in the order given, each
// with its line. A set named inside another is copied when read (CalculiX: previously defined).
struct IdSet {
  std::string name;  // as first written
  std::vector<std::int64_t> ids;
  std::vector<Loc> where;  // parallel to ids
  Loc defined;
  // Indices (sorted, unique), resolved by finish_mesh.
  std::vector<std::int32_t> members;
  std::int64_t model_id = 0;  // node sets: the id of its Model::node_sets entry
};

struct ElementRecord {
  std::int64_t id = 0;
  CellType type = CellType::hex8;
  bool reduced = false;                             // C3D8R, C3D20R
  std::array<std::int64_t, kMaxCellNodes> nodes{};  // the first topology(type).nodes
  Loc where;
};

// *SURFACE: element faces (elements or element sets with a face 0..5) or nodes (TYPE=NODE).
struct SurfaceRecord {
  std::string name;
  bool node_based = false;
  std::vector<Item> items;
  std::vector<std::int8_t> faces;  // parallel to items (element faces)
  Loc defined;
  EntityRef entity;  // FaceSet or NodeSet of the model, set by finish_mesh
};

struct MaterialRecord {
  std::string name;
  Loc defined;
  bool elastic = false;
  double young = 0.0, poisson = 0.0, density = 0.0;
  // *PLASTIC (isotropic hardening): von Mises flow stress against equivalent plastic strain.
  std::vector<double> plastic_strain, flow_stress;
  Loc plastic_defined;
};

struct SectionRecord {
  std::string elset, material;
  Loc where;
};

// *SURFACE BEHAVIOR of a surface interaction.
struct Behaviour {
  enum class Kind { Linear, Exponential, Tabular, Tied } kind = Kind::Linear;
  double slope = 0.0;                         // K (LINEAR, TIED)
  double c0 = 0.0, p0 = 0.0;                  // EXPONENTIAL
  std::vector<double> overclosure, pressure;  // TABULAR
  Loc where;
};

struct FrictionRecord {
  double mu = 0.0;
  std::optional<double> stick_slope;
  Loc where;
};

struct InteractionRecord {
  std::string name;
  Loc defined;
  std::optional<Behaviour> behaviour;
  std::optional<FrictionRecord> friction;
};

// One data line of *CONTACT PAIR.
struct PairRecord {
  std::string interaction, slave, master;
  bool node_to_surface = true;
  std::optional<double> adjust;
  bool small_sliding = false;
  Loc card, where;  // the keyword line and the data line
};

// *TIE (CalculiX): the slave surface's nodes follow the master faces (an exact tie, TieSpec).
struct TieRecord {
  std::string name, slave, master;
  std::optional<double> tolerance;  // POSITION TOLERANCE
  Loc card, where;                  // the keyword line and the data line
};

struct AmplitudeRecord {
  std::string name;
  bool total_time = false;
  std::vector<double> time, value;
  Loc where;
  FunctionRef curve;  // set by finish_steps
};

struct EquationRecord {
  struct Term {
    std::int64_t node = 0;
    int dof = 0;  // 0..2
    double coefficient = 0.0;
    Loc where;
  };
  std::vector<Term> terms;
  Loc where;  // the line with the number of terms
};

// *BOUNDARY, *CLOAD, *DLOAD: one card with its data lines.
enum class LoadKind { Boundary, Force, Pressure };
struct LoadLine {
  Item target;         // node / node set, or element / element set (*DLOAD)
  int first = 0;       // dof 0..2, or face 0..5 (*DLOAD)
  int last = 0;        // last dof (*BOUNDARY); = first otherwise
  double value = 0.0;  // displacement, force or pressure
};
struct LoadCard {
  LoadKind kind = LoadKind::Boundary;
  bool op_new = false;
  std::string amplitude;  // name, "" = none
  Loc where;
  std::vector<LoadLine> lines;
};

struct PrintCard {
  PrintRequest::Kind kind = PrintRequest::Kind::Node;
  std::string set;  // "" = all
  std::vector<std::string> quantities;
  bool totals = false, totals_only = false;
  int frequency = 1;
  Loc where;
};

// *CHANGE FRICTION (then friction) or *CHANGE SURFACE BEHAVIOR (then behaviour).
struct ChangeRecord {
  std::string interaction;
  std::optional<FrictionRecord> friction;
  std::optional<Behaviour> behaviour;
  bool surface_behaviour = false;  // *CHANGE SURFACE BEHAVIOR
  Loc where;
};

struct StepRecord {
  std::string title;
  std::optional<bool> nlgeom;  // as given on *STEP
  int max_increments = 100;
  Loc where;
  bool has_procedure = false;
  bool direct = false;
  double initial = 1.0, period = 1.0;
  std::optional<double> min_increment, max_increment;
  std::optional<double> force_tolerance, displacement_tolerance;  // *CONTROLS, FIELD
  std::vector<LoadCard> loads;
  std::vector<PrintCard> prints;
  std::vector<ChangeRecord> changes;
};

class Reader {
 public:
  explicit Reader(const std::vector<std::string>& files) : files_(files) {}

  // Reads one card (inp_reader.cpp dispatches it to the keyword's reader).
  void read(const Card& card);
  // The end of the input: resolves every reference and builds the model (inp_finish*.cpp).
  DeckResult finish();
  // A note naming the nodes that no element uses (the static solver gives them no equations).
  void note_unattached_nodes();

  // Locations for messages.
  Loc loc(const Card& c) const { return {c.file, c.line}; }
  static Loc loc(const DataLine& l) { return {l.file, l.line}; }
  SourceLocation where(const Card& c, const std::string& field = "") const;
  SourceLocation where(Loc at, const std::string& keyword, const std::string& field = "") const;
  std::string at(Loc l) const;  // "file:line"
  // The index of a file read (the last of that name).
  std::uint32_t file_index(const std::string& name) const;
  void note(const Card& c, const std::string& message);

  Model model;
  std::vector<std::string> notes;
  Loc last_card;  // the last keyword read, where the input ends for what it lacks

  // Records, in deck order.
  std::unordered_map<std::int64_t, std::int32_t> node_index;  // user id -> index
  std::vector<Loc> node_where;                                // per node index
  std::vector<ElementRecord> elements;
  std::unordered_map<std::int64_t, std::size_t> element_index;  // user id -> elements index
  std::vector<IdSet> node_sets, element_sets;
  std::unordered_map<std::string, std::size_t> node_set_names, element_set_names;  // upper case
  std::vector<SurfaceRecord> surfaces;
  std::unordered_map<std::string, std::size_t> surface_names;
  std::vector<MaterialRecord> materials;
  std::unordered_map<std::string, std::size_t> material_names;
  std::vector<SectionRecord> sections;
  std::vector<InteractionRecord> interactions;
  std::unordered_map<std::string, std::size_t> interaction_names;
  std::vector<PairRecord> pairs;
  std::vector<TieRecord> ties;
  std::vector<AmplitudeRecord> amplitudes;
  std::unordered_map<std::string, std::size_t> amplitude_names;
  std::vector<EquationRecord> equations;
  std::vector<LoadCard> model_loads;  // *BOUNDARY before the first *STEP
  std::vector<StepRecord> steps;
  std::vector<std::string> title_lines;
  std::int64_t next_function_id = 1;  // ids of the curves made for amplitudes and tables

  // Context of the card being read.
  bool in_step = false;
  // The Newton tolerances of *CONTROLS, PARAMETERS=FIELD in force (unset: abut's defaults).
  std::optional<double> force_tolerance, displacement_tolerance;
  std::optional<std::size_t> material;     // the *MATERIAL block being read
  std::optional<std::size_t> interaction;  // the *SURFACE INTERACTION block being read
  bool change_friction = false;            // a *CHANGE FRICTION waits for its *FRICTION
  bool change_behaviour = false;  // a *CHANGE SURFACE BEHAVIOR waits for its *SURFACE BEHAVIOR
  // Abaqus *OUTPUT, HISTORY is in force: *NODE OUTPUT asks for histories of its NSET, which
  // finish() turns into OutputRequests::history_nodes (name and place of each).
  bool history_output = false;
  std::vector<std::pair<std::string, Loc>> history_node_sets;
  StepRecord& step() { return steps.back(); }

  // The set of a name, created empty when new (for NSET=, ELSET=, *NSET, *ELSET).
  IdSet& node_set(const std::string& name, Loc at);
  IdSet& element_set(const std::string& name, Loc at);

 private:
  const std::vector<std::string>& files_;
};

// Upper case, for case-insensitive names.
std::string upper_name(std::string_view name);

// The parameters a keyword accepts; anything else on its keyword line is an error.
struct ParameterRule {
  enum class Kind {
    Value,        // NAME=value
    Flag,         // NAME
    FlagOrValue,  // NAME or NAME=value
    Unsupported,  // a parameter of Abaqus/CalculiX that abut does not implement: an error
    Ignored,      // no effect on abut's results: a note
  };
  std::string_view name;  // display form, e.g. "SMALL SLIDING"
  Kind kind = Kind::Value;
  std::string_view why = {};  // Unsupported: the reason; Ignored: the note
};
void check_parameters(Reader& r, const Card& c, std::span<const ParameterRule> rules);
inline void check_parameters(Reader& r, const Card& c, std::initializer_list<ParameterRule> rules) {
  check_parameters(r, c, std::span<const ParameterRule>(rules.begin(), rules.size()));
}
// Parameters by name, in any case and with or without blanks ("SMALL SLIDING").
const Parameter* find_parameter(const Card& c, std::string_view name);
std::optional<std::string> parameter_value(const Card& c, std::string_view key);
std::string required_parameter(const Reader& r, const Card& c, std::string_view key);
bool has_parameter(const Card& c, std::string_view key);
// A parameter whose value is one of `choices` (compared as lookup keys); `fallback` if absent.
std::string parameter_choice(const Reader& r, const Card& c, std::string_view key,
                             std::initializer_list<std::string_view> choices,
                             std::string_view fallback);
// The card must have no data lines (`why` says where its values go instead).
void no_data(const Reader& r, const Card& c, const std::string& why = "");

// One data line split at its commas.
class Fields {
 public:
  Fields(const Reader& r, const Card& c, const DataLine& l);
  std::size_t size() const { return fields_.size(); }
  bool given(std::size_t i) const { return i < fields_.size() && !fields_[i].empty(); }
  const std::string& text(std::size_t i) const;
  Loc loc() const { return {line_.file, line_.line}; }
  SourceLocation where(const std::string& field = "") const;
  [[noreturn]] void fail(const std::string& field, const std::string& message) const;
  double number(std::size_t i, const std::string& field) const;
  double number_or(std::size_t i, const std::string& field, double fallback) const;
  std::int64_t integer(std::size_t i, const std::string& field) const;
  // An id (> 0) or, when the field is not a number, a set name.
  Item item(std::size_t i, const std::string& field) const;
  // No more than n fields with text (trailing empty fields are fine).
  void at_most(std::size_t n, const std::string& what) const;

 private:
  const Reader& reader_;
  const Card& card_;
  const DataLine& line_;
  std::vector<std::string> fields_;
};

// A number as written in an input file (Fortran D exponents accepted); nullopt if it is not one.
std::optional<double> inp_number(std::string_view text);

// The keyword readers (inp_mesh.cpp, inp_materials.cpp, inp_contact.cpp, inp_loads.cpp,
// inp_steps.cpp).
using KeywordReader = void (*)(Reader&, const Card&);
void read_heading(Reader&, const Card&);
void read_node(Reader&, const Card&);
void read_element(Reader&, const Card&);
void read_nset(Reader&, const Card&);
void read_elset(Reader&, const Card&);
void read_surface(Reader&, const Card&);
void read_material(Reader&, const Card&);
void read_elastic(Reader&, const Card&);
void read_density(Reader&, const Card&);
void read_plastic(Reader&, const Card&);
void read_thermal_property(Reader&, const Card&);
void read_solid_section(Reader&, const Card&);
void read_surface_interaction(Reader&, const Card&);
void read_surface_behavior(Reader&, const Card&);
void read_friction(Reader&, const Card&);
void read_contact_pair(Reader&, const Card&);
void read_tie(Reader&, const Card&);
void read_change_friction(Reader&, const Card&);
void read_change_surface_behavior(Reader&, const Card&);
void read_change_surface_behavior(Reader&, const Card&);
void read_amplitude(Reader&, const Card&);
void read_equation(Reader&, const Card&);
void read_boundary(Reader&, const Card&);
void read_cload(Reader&, const Card&);
void read_dload(Reader&, const Card&);
void read_step(Reader&, const Card&);
void read_static(Reader&, const Card&);
void read_end_step(Reader&, const Card&);
void read_node_print(Reader&, const Card&);
void read_el_print(Reader&, const Card&);
void read_contact_print(Reader&, const Card&);
void read_controls(Reader&, const Card&);
// inp_output.cpp: the output cards that choose the states' fields and frequency.
void read_node_file(Reader&, const Card&);     // *NODE FILE, *NODE OUTPUT
void read_el_file(Reader&, const Card&);       // *EL FILE, *ELEMENT OUTPUT
void read_contact_file(Reader&, const Card&);  // *CONTACT FILE, *CONTACT OUTPUT
void read_output(Reader&, const Card&);        // *OUTPUT
// inp_gmsh.cpp: *INCLUDE of a Gmsh mesh or of a file Gmsh meshes (InpLines hands it on).
void read_gmsh_include(Reader&, const Card&);

// inp_catalogue.cpp: what each keyword is.
enum class Scope { Model, Step, Either };
enum class Family { None, Material, Interaction };
struct KeywordEntry {
  std::string_view name;  // display form
  KeywordReader reader = nullptr;
  Scope scope = Scope::Either;
  Family family = Family::None;
};
const KeywordEntry* find_keyword(const std::string& key);
// Output-only keywords (skipped with a note): the note's reason; nullopt if not one.
std::optional<std::string_view> output_only_keyword(const std::string& key);
// Other Abaqus/CalculiX keywords: the reason they are not supported yet; nullopt if unknown.
std::optional<std::string_view> unsupported_keyword(const std::string& key);
// Close matches among every known keyword, for "did you mean".
std::vector<std::string> closest_keywords(const std::string& key);

// inp_finish.cpp / inp_finish_steps.cpp.
void finish_mesh(Reader& r);      // nodes, hexes, parts, materials, node sets, face sets
void finish_contacts(Reader& r);
void finish_ties(
    Reader& r);  // *TIE -> Model::ties  // amplitudes' curves are made first (finish_steps)
void finish_steps(Reader& r);     // amplitudes, equations, static steps
// inp_words.cpp: the dialect's words for the concepts the solvers' messages ask for.
void name_inp_words(Sources& sources);
// The indices of a node / element item (an id or a set name); InputError at the item. Element
// indices are the mesh's solid numbering (Mesh::solid).
std::vector<std::int32_t> nodes_of(const Reader& r, const Item& item, const std::string& keyword);
std::vector<std::int32_t> solids_of(const Reader& r, const Item& item, const std::string& keyword);
// InputError at `where` (a line of `keyword`) unless element (a solid index) has the face 0-based
// `face` (S1 to S6 on hexahedra, S5 on wedges, S4 on tetrahedra).
void require_face(const Reader& r, std::int32_t element, int face, Loc where,
                  const std::string& keyword);
// Node set / element set contents as indices (sorted, unique); InputError at `at` if undefined.
std::vector<std::int32_t> node_set_members(const Reader& r, const std::string& name, Loc at,
                                           const std::string& keyword);
std::vector<std::int32_t> element_set_members(const Reader& r, const std::string& name, Loc at,
                                              const std::string& keyword);

}  // namespace abut::inp
