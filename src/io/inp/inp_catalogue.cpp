// The keywords of Abaqus/CalculiX input files: those abut reads (with where they may stand), the
// output-only ones it skips with a note, the others it names as not supported yet, and
// did-you-mean suggestions. Keyword names: CalculiX 2.11 manual, section 7 (installed with
// calculix-ccx-doc), and the Abaqus keywords a CalculiX user meets most.
#include <algorithm>
#include <map>

#include "inp_reader.hpp"
#include "io/deck_text.hpp"

namespace abut::inp {
namespace {

const std::map<std::string, KeywordEntry>& supported() {
  static const std::map<std::string, KeywordEntry> table = [] {
    const KeywordEntry entries[] = {
        {"*HEADING", read_heading, Scope::Model},
        {"*NODE", read_node, Scope::Model},
        {"*INCLUDE", read_gmsh_include, Scope::Model},  // of a Gmsh mesh (inp_lines.cpp)
        {"*ELEMENT", read_element, Scope::Model},
        {"*NSET", read_nset, Scope::Model},
        {"*ELSET", read_elset, Scope::Model},
        {"*SURFACE", read_surface, Scope::Model},
        {"*MATERIAL", read_material, Scope::Model},
        {"*ELASTIC", read_elastic, Scope::Model, Family::Material},
        {"*DENSITY", read_density, Scope::Model, Family::Material},
        {"*PLASTIC", read_plastic, Scope::Model, Family::Material},
        {"*CONDUCTIVITY", read_thermal_property, Scope::Model, Family::Material},
        {"*SPECIFIC HEAT", read_thermal_property, Scope::Model, Family::Material},
        {"*SOLID SECTION", read_solid_section, Scope::Model},
        {"*SURFACE INTERACTION", read_surface_interaction, Scope::Model},
        {"*SURFACE BEHAVIOR", read_surface_behavior, Scope::Either, Family::Interaction},
        {"*FRICTION", read_friction, Scope::Either, Family::Interaction},
        {"*GAP CONDUCTANCE", read_thermal_property, Scope::Model, Family::Interaction},
        {"*CONTACT PAIR", read_contact_pair, Scope::Model},
        {"*TIE", read_tie, Scope::Model},
        {"*CHANGE FRICTION", read_change_friction, Scope::Step},
        {"*CHANGE SURFACE BEHAVIOR", read_change_surface_behavior, Scope::Step},
        {"*AMPLITUDE", read_amplitude, Scope::Either},
        {"*EQUATION", read_equation, Scope::Model},
        {"*BOUNDARY", read_boundary, Scope::Either},
        {"*CLOAD", read_cload, Scope::Step},
        {"*DLOAD", read_dload, Scope::Step},
        {"*STEP", read_step, Scope::Model},
        {"*STATIC", read_static, Scope::Step},
        {"*END STEP", read_end_step, Scope::Step},
        {"*NODE PRINT", read_node_print, Scope::Step},
        {"*EL PRINT", read_el_print, Scope::Step},
        {"*CONTACT PRINT", read_contact_print, Scope::Step},
        {"*CONTROLS", read_controls, Scope::Either},
        {"*NODE FILE", read_node_file, Scope::Either},
        {"*NODE OUTPUT", read_node_file, Scope::Either},
        {"*EL FILE", read_el_file, Scope::Either},
        {"*ELEMENT OUTPUT", read_el_file, Scope::Either},
        {"*CONTACT FILE", read_contact_file, Scope::Either},
        {"*CONTACT OUTPUT", read_contact_file, Scope::Either},
        {"*OUTPUT", read_output, Scope::Either},
    };
    std::map<std::string, KeywordEntry> m;
    for (const KeywordEntry& e : entries) m.emplace(lookup_key(e.name), e);
    return m;
  }();
  return table;
}

struct Described {
  std::string_view name, why;
};

constexpr std::string_view kOutput =
    "is output only: skipped (abut writes its own results; *NODE PRINT, *EL PRINT and *CONTACT "
    "PRINT requests are kept in the model, and *NODE FILE, *EL FILE and *OUTPUT choose the "
    "states' fields and frequency)";

const Described kOutputOnly[] = {
    {"*SECTION PRINT", kOutput},
    {"*FACE PRINT", kOutput},
    {"*ENERGY PRINT", kOutput},
    {"*ENERGY OUTPUT", kOutput},
    {"*MONITOR", kOutput},
    {"*PREPRINT", kOutput},
    {"*PRINT", kOutput},
    {"*FILE FORMAT", kOutput},
    {"*RESTART", kOutput},
    {"*DIAGNOSTICS", kOutput},
    {"*INTEGRATED OUTPUT", kOutput},
    {"*ELEMENT MATRIX OUTPUT", kOutput},
    {"*PHYSICAL CONSTANTS",
     "sets constants for thermal radiation and NEWTON gravity, which abut does not model: "
     "skipped"},
};

constexpr std::string_view kProcedure =
    "is not supported yet by abut: its implicit solver runs *STATIC steps only";
constexpr std::string_view kMaterial =
    "is not supported yet by abut: materials are linear elastic (*ELASTIC, *DENSITY)";
constexpr std::string_view kSection =
    "is not supported yet by abut: it reads *SOLID SECTION for C3D8 and C3D8R hexahedra only";
constexpr std::string_view kGeneric = "is not supported yet by abut";
constexpr std::string_view kParts =
    "is not supported yet by abut: it reads flat input files (in Abaqus/CAE, write the input "
    "file without parts and assemblies)";

const Described kUnsupported[] = {
    {"*BUCKLE", kProcedure},
    {"*CFD", kProcedure},
    {"*COMPLEX FREQUENCY", kProcedure},
    {"*COUPLED TEMPERATURE-DISPLACEMENT", kProcedure},
    {"*DYNAMIC", kProcedure},
    {"*ELECTROMAGNETICS", kProcedure},
    {"*FREQUENCY", kProcedure},
    {"*GREEN", kProcedure},
    {"*HEAT TRANSFER", kProcedure},
    {"*MODAL DYNAMIC", kProcedure},
    {"*NO ANALYSIS", kProcedure},
    {"*SENSITIVITY", kProcedure},
    {"*STEADY STATE DYNAMICS", kProcedure},
    {"*UNCOUPLED TEMPERATURE-DISPLACEMENT", kProcedure},
    {"*VISCO", kProcedure},
    {"*GEOSTATIC", kProcedure},
    {"*SOILS", kProcedure},
    {"*DYNAMIC TEMPERATURE-DISPLACEMENT", kProcedure},
    {"*SUBSTRUCTURE GENERATE", kProcedure},
    {"*CREEP", kMaterial},
    {"*CYCLIC HARDENING", kMaterial},
    {"*DAMPING", kMaterial},
    {"*DEFORMATION PLASTICITY", kMaterial},
    {"*DEPVAR", kMaterial},
    {"*ELECTRICAL CONDUCTIVITY", kMaterial},
    {"*EXPANSION", kMaterial},
    {"*HYPERELASTIC", kMaterial},
    {"*HYPERFOAM", kMaterial},
    {"*MAGNETIC PERMEABILITY", kMaterial},
    {"*USER MATERIAL", kMaterial},
    {"*VISCOELASTIC", kMaterial},
    {"*FLUID CONSTANTS", kMaterial},
    {"*SPECIFIC GAS CONSTANT", kMaterial},
    {"*BEAM GENERAL SECTION", kSection},
    {"*BEAM SECTION", kSection},
    {"*FLUID SECTION", kSection},
    {"*MEMBRANE SECTION", kSection},
    {"*SHELL GENERAL SECTION", kSection},
    {"*SHELL SECTION", kSection},
    {"*PART", kParts},
    {"*END PART", kParts},
    {"*ASSEMBLY", kParts},
    {"*END ASSEMBLY", kParts},
    {"*INSTANCE", kParts},
    {"*END INSTANCE", kParts},
    {"*BOUNDARYF", kGeneric},
    {"*CFLUX", kGeneric},
    {"*CHANGE MATERIAL", kGeneric},
    {"*CHANGE PLASTIC", kGeneric},
    {"*CHANGE SOLID SECTION", kGeneric},
    {"*CLEARANCE", kGeneric},
    {"*CONTACT DAMPING", kGeneric},
    {"*CYCLIC SYMMETRY MODEL", kGeneric},
    {"*DASHPOT", kGeneric},
    {"*DESIGNVARIABLES", kGeneric},
    {"*DFLUX", kGeneric},
    {"*DISTRIBUTING COUPLING", kGeneric},
    {"*DSLOAD", kGeneric},
    {"*FILM", kGeneric},
    {"*GAP", kGeneric},
    {"*INITIAL CONDITIONS", kGeneric},
    {"*MASS FLOW", kGeneric},
    {"*MODAL DAMPING", kGeneric},
    {"*MODEL CHANGE", kGeneric},
    {"*MPC", kGeneric},
    {"*NODAL THICKNESS", kGeneric},
    {"*NORMAL", kGeneric},
    {"*OBJECTIVE", kGeneric},
    {"*ORIENTATION", kGeneric},
    {"*PRE-TENSION SECTION", kGeneric},
    {"*RADIATE", kGeneric},
    {"*RETAINED NODAL DOFS", kGeneric},
    {"*RIGID BODY", kGeneric},
    {"*SELECT CYCLIC SYMMETRY MODES", kGeneric},
    {"*SPRING", kGeneric},
    {"*SUBMODEL", kGeneric},
    {"*SUBSTRUCTURE MATRIX OUTPUT", kGeneric},
    {"*TEMPERATURE", kGeneric},
    {"*TIME POINTS", kGeneric},
    {"*TRANSFORM", kGeneric},
    {"*TRANSFORMF", kGeneric},
    {"*VALUES AT INFINITY", kGeneric},
    {"*VIEWFACTOR", kGeneric},
    {"*CONTACT", kGeneric},
    {"*CONTACT INCLUSIONS", kGeneric},
    {"*CONTACT PROPERTY ASSIGNMENT", kGeneric},
    {"*CONTACT CONTROLS", kGeneric},
    {"*COUPLING", kGeneric},
    {"*KINEMATIC COUPLING", kGeneric},
    {"*KINEMATIC", kGeneric},
    {"*DISTRIBUTING", kGeneric},
    {"*MASS", kGeneric},
    {"*ROTARY INERTIA", kGeneric},
    {"*PARAMETER", kGeneric},
    {"*SYSTEM", kGeneric},
    {"*NGEN", kGeneric},
    {"*NFILL", kGeneric},
    {"*NCOPY", kGeneric},
    {"*ELGEN", kGeneric},
    {"*NMAP", kGeneric},
    {"*PREDEFINED FIELD", kGeneric},
    {"*FIELD", kGeneric},
    {"*INITIAL STATE", kGeneric},
    {"*BULK VISCOSITY", kGeneric},
    {"*IMPORT", kGeneric},
    {"*MAP SOLUTION", kGeneric},
    {"*INERTIA RELIEF", kGeneric},
    {"*MATRIX GENERATE", kGeneric},
    {"*SURFACE SMOOTHING", kGeneric},
    {"*CONNECTOR SECTION", kGeneric},
    {"*CONNECTOR BEHAVIOR", kGeneric},
    {"*ADAPTIVE MESH", kGeneric},
};

template <class Table>
std::optional<std::string_view> find_in(const Table& table, const std::string& key) {
  for (const Described& d : table)
    if (lookup_key(d.name) == key) return d.why;
  return std::nullopt;
}

}  // namespace

const KeywordEntry* find_keyword(const std::string& key) {
  const auto it = supported().find(key);
  return it == supported().end() ? nullptr : &it->second;
}

std::optional<std::string_view> output_only_keyword(const std::string& key) {
  return find_in(kOutputOnly, key);
}

std::optional<std::string_view> unsupported_keyword(const std::string& key) {
  return find_in(kUnsupported, key);
}

std::vector<std::string> closest_keywords(const std::string& key) {
  // Close matches only: at most a quarter of the letters wrong (at least 2), best first.
  const std::size_t limit = std::max<std::size_t>(2, key.size() / 4);
  std::vector<std::pair<std::size_t, std::string>> found;
  const auto consider = [&](std::string_view name) {
    const std::size_t d = deck::edit_distance(key, lookup_key(name));
    if (d <= limit) found.emplace_back(d, std::string(name));
  };
  for (const auto& [k, entry] : supported()) consider(entry.name);
  for (const Described& d : kOutputOnly) consider(d.name);
  for (const Described& d : kUnsupported) consider(d.name);
  std::stable_sort(found.begin(), found.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  // The closest ones only (ties), at most three.
  std::vector<std::string> names;
  for (std::size_t i = 0; i < found.size() && i < 3 && found[i].first == found[0].first; ++i)
    names.push_back(found[i].second);
  return names;
}

}  // namespace abut::inp
