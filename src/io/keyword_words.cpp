// The .k dialect's words for the settings that the solvers' messages ask for (Sources::name):
// where a message suggests giving a setting, the user reads the keyword and field to write.
#include "deck_reader.hpp"

namespace abut::deck {

void name_keyword_words(Sources& sources) {
  sources.name("analytic_tool", "a *CONTACT_TOOL");
  sources.name("boundary_condition", "a boundary condition (*NODE bc or *BC_MOTION)");
  sources.name("conductance_function", "fid_thermal of *CONTACT");
  sources.name("detection_depth", "depth of *CONTACT_NORMAL");
  sources.name("ductile_failure", "ductile failure (*PROP_DAMAGE_JC)");
  sources.name("initial_velocity", "*INITIAL_VELOCITY");
  sources.name("max_increments", "n_inc of *STATIC");
  sources.name("max_step", "dt_max of *TIME");
  sources.name("min_step", "dt_min of *TIME");
  sources.name("pair_penalty_scale", "a pair scale factor (*CONTACT_SCALE_PENALTY)");
  sources.name("penalty", "pfac of *CONTACT");
  sources.name("rigid_motion", "*BC_MOTION (entype P)");
  sources.name("static_materials",
               "linear elastic and J2 plastic materials (*MAT_ELASTIC, *MAT_METAL, *MAT_JC)");
  sources.name("thermal_properties", "thpid of the material and its *PROP_THERMAL");
  sources.name("tie_by_penalty", "tie = PENALTY of *CONTACT_FRICTION");
  sources.name("unit_system", "*UNIT_SYSTEM");
}

}  // namespace abut::deck
