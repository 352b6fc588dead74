#pragma once
// The static side of the model: nonlinear static steps (Abaqus/CalculiX *STEP + *STATIC,
// OptiStruct NLSTAT, seed 003), their loads and boundary conditions, linear constraints, element
// face sets and print requests. Filled by the .inp reader (src/io/inp); read by the static solver
// (src/solver/static). Node and element references are indices, as everywhere in the model.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "abut/core/error.hpp"
#include "abut/core/functions.hpp"

namespace abut {

// A face of a solid element: its index in the Mesh::solid numbering (for a hexahedron its index in
// Mesh::hexes) and its local face (topology(type).faces, the order of the Abaqus faces S1..Sn:
// face = S number - 1).
struct SolidFace {
  std::int32_t solid = 0;
  std::int8_t face = 0;
};

// A set of element faces: a contact surface (either side, S2S or N2S), a pressure or a thermal
// load. Solid faces (Abaqus *SURFACE, TYPE=ELEMENT; IMPETUS *SET_FACE rows on solids), each once,
// outward as the element's face is, and whole shells (*SET_FACE rows on shells). Entities refer
// to it with EntityType::FaceSet and its id.
struct FaceSet {
  std::int64_t id = 0;
  std::string name;
  std::vector<SolidFace> faces;
  std::vector<std::int32_t> shells;  // shell indices (Mesh::shells), sorted
  SourceLocation where;
};

// *EQUATION: sum_k c_k u(node_k, dof_k) = 0. The first term's degree of freedom is the
// dependent one (Abaqus/CalculiX convention): it is eliminated, so it must not be constrained
// otherwise.
struct LinearConstraint {
  struct Term {
    std::int32_t node = 0;
    int dof = 0;  // 0..2 = x, y, z
    double coefficient = 0.0;
  };
  std::vector<Term> terms;
  SourceLocation where;
};

// How a step's value varies with time. Without a curve: linearly from its value at the start
// of the step to the given value at its end (the Abaqus/CalculiX default for static steps, RAMP);
// a boundary condition starts from the node's current displacement, a load from the value it had
// at the end of the previous step (0 when it is new). With a curve (*AMPLITUDE): value x curve,
// the curve's abscissa being the step time, or the total time with total_time.
struct StepAmplitude {
  FunctionRef curve;
  bool total_time = false;
};

// A prescribed displacement of one degree of freedom (*BOUNDARY; value 0 when the card gives
// none).
struct StepDisplacement {
  std::int32_t node = 0;
  int dof = 0;  // 0..2
  double value = 0.0;
  StepAmplitude amplitude;
  SourceLocation where;
};

// A concentrated force on one degree of freedom (*CLOAD).
struct StepForce {
  std::int32_t node = 0;
  int dof = 0;  // 0..2
  double value = 0.0;
  StepAmplitude amplitude;
  SourceLocation where;
};

// A uniform pressure on a hex face (*DLOAD with load type Pn): positive pushes against the
// face's outward normal (compresses the element), as in Abaqus.
struct StepPressure {
  SolidFace face;
  double value = 0.0;
  StepAmplitude amplitude;
  SourceLocation where;
};

// *CHANGE SURFACE BEHAVIOR: a new pressure-overclosure law (LINEAR, TABULAR or EXPONENTIAL; not
// TIED), which also unties a tied contact.
struct OverclosureChange {
  std::optional<double> slope;   // LINEAR: K [stress/length]
  FunctionRef table;             // TABULAR: pressure against overclosure
  std::optional<double> c0, p0;  // EXPONENTIAL (CalculiX form, ContactSpec::Exponential)
};

// *CHANGE FRICTION and *CHANGE SURFACE BEHAVIOR: the new laws of a contact (index into
// Model::contacts) from this step on.
struct ContactChange {
  std::size_t contact = 0;
  std::optional<double> friction;     // mu
  std::optional<double> stick_slope;  // tangential penalty [stress/length]
  SourceLocation where;
  std::optional<OverclosureChange> overclosure;
};

// *NODE PRINT, *EL PRINT, *CONTACT PRINT: quantities written to the printed table (.dat-like)
// at the end of every `frequency`-th increment and at the end of the step.
struct PrintRequest {
  enum class Kind { Node, Element, Contact } kind = Kind::Node;
  std::vector<std::string> quantities;  // upper case: U, RF, S, E, ELSE, ENER, CSTR, CDIS, CELS...
  std::string set_name;                 // as written in the deck ("" = all)
  std::vector<std::int32_t> members;    // node indices (Node, Contact) or hex indices (Element)
  bool totals = false;                  // TOTALS=YES: also the sum over the set
  bool totals_only = false;             // TOTALS=ONLY
  int frequency = 1;
  SourceLocation where;
};

// One nonlinear static step. Its lists hold everything in force during the step: the reader
// resolves OP=NEW / OP=MOD of the cards, so that a condition absent from a step's list is not
// applied in that step (a released boundary condition leaves its dof free; a removed load is 0).
struct StaticStep {
  std::string title;
  bool nonlinear_geometry = false;  // NLGEOM: once on, it stays on for the following steps
  double period = 1.0;              // step time
  double initial_increment = 1.0;   // [time]
  double min_increment = 0.0;       // [time]; 0: 1e-5 of the period
  double max_increment = 0.0;       // [time]; 0: the period
  bool fixed_increments = false;    // DIRECT: no cut-back, the initial increment throughout
  int max_increments = 100;         // INC
  // Newton controls of this step (*STATIC of a .k deck: tol_R, tol_C, n_iter); when empty, those
  // of StaticControls (static_solver.hpp).
  std::optional<double> force_tolerance;         // largest residual / average force
  std::optional<double> displacement_tolerance;  // largest correction / displacement increment
  std::optional<int> max_iterations;             // per attempt of an increment
  std::vector<StepDisplacement> displacements;
  std::vector<StepForce> forces;
  std::vector<StepPressure> pressures;
  std::vector<ContactChange> contact_changes;
  std::vector<PrintRequest> prints;
  SourceLocation where;
};

}  // namespace abut
