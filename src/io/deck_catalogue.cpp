// The keywords abut reads, the other commands of the IMPETUS command set (so that a deck using
// one gets "not supported yet" rather than "unknown"), and did-you-mean suggestions.
// Command names: IMPETUS command help file (keyword reference, source [HELP]).
#include <algorithm>
#include <map>
#include <string_view>

#include "deck_reader.hpp"
#include "io/deck_text.hpp"

namespace abut::deck {
namespace {

const std::map<std::string, KeywordReader, std::less<>>& supported() {
  static const std::map<std::string, KeywordReader, std::less<>> table = {
      {"*TITLE", read_title},
      {"*PARAMETER", read_parameter},
      {"*PARAMETER_DEFAULT", read_parameter_default},
      {"*UNIT_SYSTEM", read_unit_system},
      {"*TIME", read_time},
      {"*OUTPUT", read_output},
      {"*OUTPUT_FIELDS", read_output_fields},                    // abut's own
      {"*OUTPUT_NODE_HISTORY", read_output_node_history},        // abut's own
      {"*CONTROL_BULK_VISCOSITY", read_control_bulk_viscosity},  // abut's own (LS-DYNA's name)
      {"*NODE", read_node},
      {"*ELEMENT_SOLID", read_element_solid},
      {"*ELEMENT_SOLID_TET10", read_element_solid_tet10},
      {"*ELEMENT_SOLID_H20", read_element_solid_h20},
      {"*ELEMENT_SHELL", read_element_shell},
      {"*INCLUDE_GMSH", read_include_gmsh},  // abut's own
      {"*COMPONENT_BOX", read_component_box},
      {"*COMPONENT_SPHERE", read_component_sphere},
      {"*COMPONENT_CYLINDER", read_component_cylinder},
      {"*COMPONENT_SHELL_PLATE", read_component_shell_plate},
      {"*COMPONENT_SHELL_TUBE", read_component_shell_tube},
      {"*CHANGE_P-ORDER", read_change_p_order},
      {"*CONTROL_P-ORDER", read_control_p_order},            // abut's own
      {"*CHANGE_TO_TETRAHEDRA", read_change_to_tetrahedra},  // abut's own
      {"*SMOOTH_MESH", read_smooth_mesh},
      {"*MERGE_DUPLICATED_NODES", read_merge_duplicated_nodes},
      {"*MAT_ELASTIC", read_mat_elastic},
      {"*MAT_MOONEY_RIVLIN", read_mat_mooney_rivlin},
      {"*MAT_RIGID", read_mat_rigid},
      {"*MAT_METAL", read_mat_metal},
      {"*MAT_JC", read_mat_jc},
      {"*PROP_DAMAGE_JC", read_prop_damage_jc},
      {"*PROP_THERMAL", read_prop_thermal},
      {"*PART", read_part},
      {"*PART_SHELL", read_part_shell},
      {"*PART_SOLID", read_part_solid},
      {"*SET_NODE", read_set_node},
      {"*SET_PART", read_set_part},
      {"*SET_FACE", read_set_face},
      {"*STATIC", read_static},
      {"*INITIAL_VELOCITY", read_initial_velocity},
      {"*BC_MOTION", read_bc_motion},
      {"*LOAD_GRAVITY", read_load_gravity},
      {"*LOAD_PRESSURE", read_load_pressure},
      {"*INITIAL_TEMPERATURE", read_initial_temperature},
      {"*BC_TEMPERATURE", read_bc_temperature},
      {"*LOAD_THERMAL_SURFACE", read_load_thermal_surface},
      {"*LOAD_THERMAL_CONVECTION", read_load_thermal_convection},  // abut's own
      {"*CURVE", read_curve},
      {"*FUNCTION", read_function},
      {"*GEOMETRY_BOX", read_geometry_box},
      {"*GEOMETRY_SPHERE", read_geometry_sphere},
      {"*GEOMETRY_PIPE", read_geometry_pipe},
      {"*GEOMETRY_ELLIPSOID", read_geometry_ellipsoid},
      {"*GEOMETRY_PART", read_geometry_part},
      {"*CONTACT", read_contact},
      {"*CONTACT_ADHESION", read_contact_adhesion},
      {"*CONTACT_DEPENDENCY", read_contact_dependency},
      {"*CONTACT_DISCRETIZATION", read_contact_discretization},
      {"*CONTACT_EDGE", read_contact_edge},
      {"*CONTACT_EROSION", read_contact_erosion},
      {"*CONTACT_FRICTION", read_contact_friction},
      {"*CONTACT_FRICTION_PAIR", read_contact_friction_pair},  // abut's own (Radioss fric_ID)
      {"*CONTACT_GAP", read_contact_gap},
      {"*CONTACT_TOOL", read_contact_tool},
      {"*CONTACT_INITIAL", read_contact_initial},
      {"*CONTACT_NORMAL", read_contact_normal},
      {"*CONTACT_SCALE_PENALTY", read_contact_scale_penalty},
      {"*CONTACT_STIFFNESS", read_contact_stiffness},
      {"*CONTACT_THERMAL", read_contact_thermal},
      {"*CONTACT_SENSOR", read_contact_sensor},                // abut's own (Radioss sens_ID)
      {"*CONTACT_STABILIZATION", read_contact_stabilization},  // abut's own (OptiStruct CNTSTB)
      {"*CONTACT_SMOOTHING", read_contact_smoothing},          // abut's own (OptiStruct SMOOTH)
      {"*CONTACT_RELEASE_BC", read_contact_release_bc},        // abut's own (Radioss IBC)
      {"*SENSOR", read_sensor},                                // abut's own (Radioss /SENSOR)
  };
  return table;
}

// Handled by the reader itself.
constexpr std::string_view kControlKeywords[] = {"*INCLUDE", "*END"};

constexpr std::string_view kOtherImpetusKeywords[] = {
    "*ACTIVATE_ELEMENTS",
    "*ADD_MASS",
    "*BALANCE_SURFACE_MASS",
    "*BC_PERIODIC",
    "*BC_SYMMETRY",
    "*BC_TELEPORT",
    "*BOLT_FAILURE",
    "*CFD_BLAST_1D",
    "*CFD_DETONATION",
    "*CFD_DOMAIN",
    "*CFD_GAS",
    "*CFD_HE",
    "*CFD_SOURCE",
    "*CFD_STATE",
    "*CFD_STRUCTURE_INTERACTION",
    "*CFD_WIND_TUNNEL",
    "*CHANGE_PART_ID",
    "*COMPONENT_BOLT",
    "*COMPONENT_BOX_IRREGULAR",
    "*COMPONENT_PIPE",
    "*COMPONENT_REBAR",
    "*CONNECTOR_DAMPER",
    "*CONNECTOR_GLUE_LINE",
    "*CONNECTOR_GLUE_SURFACE",
    "*CONNECTOR_RIGID",
    "*CONNECTOR_SPOT_WELD",
    "*CONNECTOR_SPOT_WELD_NODE",
    "*CONNECTOR_SPR",
    "*CONNECTOR_SPRING",
    "*CONTACT_ACCURACY",
    "*CONTACT_REBAR",
    "*COORDINATE_SYSTEM",
    "*COORDINATE_SYSTEM_CYLINDRICAL",
    "*COORDINATE_SYSTEM_FIXED",
    "*COORDINATE_SYSTEM_FUNCTION",
    "*COORDINATE_SYSTEM_NODE",
    "*COUPLING_REBAR",
    "*DEFINE_ELEMENT_SET",
    "*DETONATION",
    "*ELEMENT_CHEX",
    "*ELEMENT_CPRISM",
    "*ELEMENT_CTET",
    "*ELEMENT_LTET",
    "*ELEMENT_QHEX",
    "*ELEMENT_QPRISM",
    "*ELEMENT_QTET",
    "*ELEMENT_REBAR",
    "*EOS_GRUNEISEN",
    "*EOS_TAIT",
    "*EROSION_CRITERION",
    "*EROSION_CRITERION_SPH_DRIVEN",
    "*FRAGMENT_CLEANUP",
    "*FREQUENCY_CUTOFF",
    "*GENERATE_COMPONENT_DISTRIBUTION",
    "*GENERATE_PARTICLE_DISTRIBUTION",
    "*GEOMETRY_COMPOSITE",
    "*GEOMETRY_EFP",
    "*GEOMETRY_SEED_COORDINATE",
    "*GEOMETRY_SEED_NODE",
    "*IB_CONTROL",
    "*IB_INHIBITION",
    "*INCLUDE_BINARY",
    "*INITIAL_CONTACT",
    "*INITIAL_DAMAGE_MAP",
    "*INITIAL_DAMAGE_RANDOM",
    "*INITIAL_DAMAGE_SURFACE_RANDOM",
    "*INITIAL_DISPLACEMENT",
    "*INITIAL_FACE_DATA",
    "*INITIAL_MATERIAL_DIRECTION",
    "*INITIAL_MATERIAL_DIRECTION_PATH",
    "*INITIAL_MATERIAL_DIRECTION_VECTOR",
    "*INITIAL_MATERIAL_DIRECTION_WRAP",
    "*INITIAL_PLASTIC_STRAIN_FUNCTION",
    "*INITIAL_STATE",
    "*INITIAL_STATE_HAZ",
    "*INITIAL_STRESS_FUNCTION",
    "*INITIAL_THICKNESS",
    "*LOAD_AIR_BLAST",
    "*LOAD_CENTRIFUGAL",
    "*LOAD_DAMPING",
    "*LOAD_ELEMENT_SMOOTHING",
    "*LOAD_EM_CABLE",
    "*LOAD_FORCE",
    "*LOAD_FORCE_INTERACT",
    "*LOAD_SHEAR",
    "*LOAD_SURFACE_SMOOTHING",
    "*LOAD_THERMAL_BODY",
    "*LOAD_THERMAL_RADIATION",
    "*LOAD_UNDEX",
    "*MAP",
    "*MAT_BB",
    "*MAT_BERGSTROM_BOYCE",
    "*MAT_CABLE",
    "*MAT_CERAMIC",
    "*MAT_CONCRETE_2018",
    "*MAT_CONCRETE_2021",
    "*MAT_CREEP",
    "*MAT_EXPLOSIVE_HVRB",
    "*MAT_EXPLOSIVE_INITIATION",
    "*MAT_EXPLOSIVE_JWL",
    "*MAT_FABRIC",
    "*MAT_FABRIC_ISOTROPIC",
    "*MAT_FLUID",
    "*MAT_FOAM",
    "*MAT_FORMING",
    "*MAT_FORMING_R",
    "*MAT_GRANULAR_CAP",
    "*MAT_HJC_CONCRETE",
    "*MAT_HOEK_BROWN",
    "*MAT_HOT_FORMING",
    "*MAT_HSS",
    "*MAT_JC_FIELD",
    "*MAT_JH_CERAMIC",
    "*MAT_LEE_TARVER",
    "*MAT_MMC",
    "*MAT_MMC_OST",
    "*MAT_MM_CERAMIC",
    "*MAT_MM_CONCRETE",
    "*MAT_MM_OST_CERAMIC",
    "*MAT_OBJECT",
    "*MAT_POWDER_BURN",
    "*MAT_POWDER_BURN_POROUS",
    "*MAT_REBAR",
    "*MAT_USER_X",
    "*MAT_VISCOUS_FOAM",
    "*MAT_VISCO_PLASTIC",
    "*MAT_YEOH",
    "*MAT_ZA",
    "*MERGE",
    "*MERGE_FAILURE_BOLT",
    "*MERGE_FAILURE_COHESIVE",
    "*MERGE_FAILURE_FORCE",
    "*OBJECT",
    "*OUTPUT_CONTACT_FORCE",
    "*OUTPUT_DAMAGE_MAP",
    "*OUTPUT_DEBUG",
    "*OUTPUT_ELEMENT",
    "*OUTPUT_ERROR",
    "*OUTPUT_FORMING",
    "*OUTPUT_J_INTEGRAL",
    "*OUTPUT_NODE",
    "*OUTPUT_SECTION",
    "*OUTPUT_SENSOR",
    "*OUTPUT_SENSOR_EXTENDED",
    "*OUTPUT_SENSOR_PATH",
    "*OUTPUT_SENSOR_THICKNESS",
    "*OUTPUT_USER",
    "*OUTPUT_USER_COLLECTION",
    "*PARAMETER_RANGE_BOOL",
    "*PARAMETER_RANGE_CONTINUOUS",
    "*PARAMETER_RANGE_DISCRETE",
    "*PARTICLE_AIR",
    "*PARTICLE_DETONATION",
    "*PARTICLE_DOMAIN",
    "*PARTICLE_DOMAIN_CLEANUP",
    "*PARTICLE_HE",
    "*PARTICLE_SOIL",
    "*PARTICLE_SPH",
    "*PARTICLE_SPH_JET",
    "*PARTICLE_SPH_JET_LSC",
    "*PATH",
    "*PETRIFY",
    "*POWDER_BURN_IGNITE",
    "*POWDER_BURN_SHAPE_FUNCTION",
    "*PRESTRESS_BLIND_HOLE_BOLT",
    "*PRESTRESS_BOLT",
    "*PROP_DAMAGE_BRITTLE",
    "*PROP_DAMAGE_CL",
    "*PROP_DAMAGE_CL_0_45_90",
    "*PROP_DAMAGE_CL_0_45_90_REGULARIZE",
    "*PROP_DAMAGE_CL_ANISOTROPIC",
    "*PROP_DAMAGE_CL_EXTENDED",
    "*PROP_DAMAGE_CL_EXTENDED_REGULARIZE",
    "*PROP_DAMAGE_CL_REGULARIZE",
    "*PROP_DAMAGE_GOLDTHORPE",
    "*PROP_DAMAGE_HC",
    "*PROP_DAMAGE_IMP",
    "*PROP_DAMAGE_IMP_ISO",
    "*PROP_DAMAGE_JC",
    "*PROP_DAMAGE_JC_MODIFIED",
    "*PROP_DAMAGE_JC_REGULARIZE",
    "*PROP_DAMAGE_MTSB",
    "*PROP_DAMAGE_STRAIN",
    "*PROP_DAMAGE_XW",
    "*PROP_SPOT_WELD",
    "*RANDOM_NUMBER_GENERATOR_SEED",
    "*REDISTRIBUTE_MESH_CARTESIAN",
    "*REFINE",
    "*REMAP",
    "*RIGID_BODY_ADD_NODES",
    "*RIGID_BODY_DAMPING",
    "*RIGID_BODY_INERTIA",
    "*RIGID_BODY_JOINT",
    "*RIGID_BODY_MERGE",
    "*RIGID_BODY_UPDATE",
    "*SCRIPT_PYTHON",
    "*SET_ELEMENT",
    "*SET_FACE",
    "*SET_GEOMETRY",
    "*SMOOTH_PRESSURE",
    "*SMS",
    "*SUBDIVIDE_PART_THICKNESS",
    "*TABLE",
    "*TRANSFORM_MESH_CARTESIAN",
    "*TRANSFORM_MESH_CYLINDRICAL",
    "*TRIM",
    "*TRIM_HOLE",
    "*VAA",
    "*VELOCITY_CAP",
    "*WELD",
};

}  // namespace

KeywordReader find_keyword_reader(const std::string& keyword) {
  const auto it = supported().find(keyword);
  return it == supported().end() ? nullptr : it->second;
}

bool is_known_impetus_keyword(const std::string& keyword) {
  return std::find(std::begin(kOtherImpetusKeywords), std::end(kOtherImpetusKeywords), keyword) !=
         std::end(kOtherImpetusKeywords);
}

std::optional<std::string> closest_keyword(const std::string& keyword) {
  // Suggest only close matches: at most a quarter of the name's letters wrong (at least 2).
  std::size_t best = std::max<std::size_t>(2, keyword.size() / 4) + 1;
  std::optional<std::string> suggestion;
  const auto consider = [&](std::string_view candidate) {
    // A length difference alone costs that many edits: skip the quadratic distance then (a
    // keyword of a million characters would take seconds against every name).
    const std::size_t longer = std::max(keyword.size(), candidate.size());
    if (longer - std::min(keyword.size(), candidate.size()) >= best) return;
    const std::size_t d = edit_distance(keyword, candidate);
    if (d < best) {
      best = d;
      suggestion = std::string(candidate);
    }
  };
  for (const auto& [name, reader] : supported()) consider(name);
  for (const auto name : kControlKeywords) consider(name);
  for (const auto name : kOtherImpetusKeywords) consider(name);
  return suggestion;
}

}  // namespace abut::deck
