// The .inp dialect's words for the settings that the solvers' messages ask for (Sources::name);
// the concepts Abaqus/CalculiX input has no card for keep the model's words.
#include "inp_reader.hpp"

namespace abut::inp {

void name_inp_words(Sources& sources) {
  sources.name("boundary_condition", "a boundary condition (*BOUNDARY)");
  sources.name("detection_depth", "POSITION TOLERANCE of *TIE");
  sources.name("linear_constraint", "*EQUATION");
  sources.name("max_increments", "INC of *STEP");
  sources.name("penalty", "the slope of *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR");
  sources.name("static_materials", "linear elastic and J2 plastic materials (*ELASTIC, *PLASTIC)");
  sources.name("thermal_properties", "*CONDUCTIVITY and *SPECIFIC HEAT");
}

}  // namespace abut::inp
