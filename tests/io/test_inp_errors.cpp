// The .inp reader's errors: every one an InputError naming the file and line (and the field
// where it helps) with a plain-English fix; nothing crashes and nothing is read without effect.
#include <gtest/gtest.h>

#include <string>

#include "abut/io/deck.hpp"

namespace abut {
namespace {

// Two unit cubes side by side along x (22 lines).
const std::string kModel = R"(*NODE, NSET=NALL
1, 0., 0., 0.
2, 1., 0., 0.
3, 2., 0., 0.
4, 0., 1., 0.
5, 1., 1., 0.
6, 2., 1., 0.
7, 0., 0., 1.
8, 1., 0., 1.
9, 2., 0., 1.
10, 0., 1., 1.
11, 1., 1., 1.
12, 2., 1., 1.
*ELEMENT, TYPE=C3D8, ELSET=EALL
1, 1, 2, 5, 4, 7, 8, 11, 10
2, 2, 3, 6, 5, 8, 9, 12, 11
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL
*SURFACE, NAME=TOP
EALL, S2
)";
const std::string kStep = "*STEP\n*STATIC\n*END STEP\n";

struct Expected {
  std::size_t line;
  std::string message;  // a part of the message
  std::string field = "";
};

// Reading `text` must raise an InputError at `e.line` of t.inp whose message contains
// `e.message`.
void expect_error(const std::string& text, const Expected& e) {
  try {
    read_inp_string_with_notes(text, "t.inp");
    ADD_FAILURE() << "expected an InputError containing '" << e.message << "'";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().file, "t.inp") << error.what();
    EXPECT_EQ(error.where().line, e.line) << error.what();
    EXPECT_NE(std::string(error.what()).find(e.message), std::string::npos) << error.what();
    if (!e.field.empty()) {
      EXPECT_EQ(error.where().field, e.field) << error.what();
    }
  }
}

TEST(InpErrors, Keywords) {
  expect_error(kModel + "*NODEPRNT, NSET=NALL\nU\n",
               {23, "unknown keyword *NODEPRNT; did you mean *NODE PRINT"});
  expect_error(kModel + "*FOOBAR\n", {23, "unknown keyword *FOOBAR"});
  expect_error(kModel + "*HYPERELASTIC\n100., 0.\n", {23, "*HYPERELASTIC is not supported yet"});
  expect_error("1, 0., 0., 0.\n", {1, "data line before the first keyword"});
  expect_error(kModel + "*ELASTIC\n1., 0.3\n", {23, "put it right after the *MATERIAL card"});
  expect_error(kModel + "*FRICTION\n0.1, 10.\n",
               {23, "put it right after the *SURFACE INTERACTION"});
  expect_error(kModel + "*STEP\n*STATIC\n*NODE\n13, 0., 0., 0.\n*END STEP\n",
               {25, "*NODE is model data: put it before the first *STEP"});
  expect_error(kModel + "*CLOAD\n1, 1, 1.\n", {23, "belongs to a step"});
  expect_error(kModel + "*STEP\n*STATIC\n", {23, "the step has no *END STEP"});
  expect_error(kModel + "*STEP\n*END STEP\n", {23, "add *STATIC"});
  expect_error(kModel + "*STEP\n*STATIC\n*STEP\n", {25, "close that step with *END STEP"});
  expect_error(kModel + "*STEP\n*DYNAMIC\n0.1, 1.\n*END STEP\n",
               {24, "*DYNAMIC is not supported yet by abut: its implicit solver runs *STATIC"});
  expect_error(kModel + "*STEP\n*FREQUENCY\n10\n*END STEP\n", {24, "*FREQUENCY is not supported"});
  expect_error(kModel + "*STEP\n*HEAT TRANSFER\n*END STEP\n", {24, "not supported yet"});
  expect_error(kModel, {21, "the input ends without *STEP"});  // at its last card
  const std::string interaction =
      "*SURFACE INTERACTION, NAME=A\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n1.e7\n";
  expect_error(
      kModel + interaction + "*STEP\n*STATIC\n*CHANGE SURFACE BEHAVIOR, INTERACTION=A\n*END STEP\n",
      {28, "must be followed by a *SURFACE BEHAVIOR card"});
  expect_error(kModel + interaction +
                   "*STEP\n*STATIC\n*CHANGE SURFACE BEHAVIOR, INTERACTION=A\n*SURFACE "
                   "BEHAVIOR, PRESSURE-OVERCLOSURE=TIED\n1.e8\n*END STEP\n",
               {29, "changing a contact to TIED", "PRESSURE-OVERCLOSURE"});
  expect_error(kModel + interaction +
                   "*STEP\n*STATIC\n*SURFACE BEHAVIOR, "
                   "PRESSURE-OVERCLOSURE=LINEAR\n1.e8\n*END STEP\n",
               {28, "after *CHANGE SURFACE BEHAVIOR"});
  expect_error(kModel + interaction +
                   "*STEP\n*STATIC\n*CHANGE SURFACE BEHAVIOR, INTERACTION=A\n*SURFACE "
                   "BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n1.e8\n*END STEP\n",
               {28, "no *CONTACT PAIR uses surface interaction A", "INTERACTION"});
  expect_error(kModel + "*STEP\n*STATIC\n*CHANGE FRICTION, INTERACTION=A\n*END STEP\n",
               {25, "must be followed by a *FRICTION card"});
}

TEST(InpErrors, Parameters) {
  expect_error(kModel + "*NSET, NSET=A, COLOR=RED\n1\n",
               {23, "unknown parameter COLOR of *NSET (it takes NSET, GENERATE)", "COLOR"});
  expect_error(kModel + "*NSET\n1\n", {23, "the parameter NSET= is missing"});
  expect_error(kModel + "*NSET, NSET=A, NSET=B\n1\n", {23, "given twice", "NSET"});
  expect_error(kModel + "*ELEMENT, ELSET=E2\n3, 1, 2, 5, 4, 7, 8, 11, 10\n",
               {23, "the parameter TYPE= is missing"});
  expect_error(kModel + "*STEP, PERTURBATION\n*STATIC\n*END STEP\n",
               {23, "PERTURBATION is not supported yet", "PERTURBATION"});
  expect_error(kModel + "*STEP\n*STATIC\n*CLOAD, OP=REPLACE\n1, 1, 1.\n*END STEP\n",
               {25, "expected OP= one of MOD, NEW", "OP"});
  expect_error(kModel + "*STEP, NLGEOM\n*STATIC\n*END STEP\n*STEP, NLGEOM=NO\n*STATIC\n*END STEP\n",
               {26, "NLGEOM cannot be switched off"});
  expect_error(kModel +
                   "*SURFACE INTERACTION, NAME=A\n*SURFACE BEHAVIOR, "
                   "PRESSURE-OVERCLOSURE=HARD\n",
               {24, "PRESSURE-OVERCLOSURE=HARD is not supported yet"});
  expect_error(kModel +
                   "*CONTACT PAIR, INTERACTION=A, TYPE=SURFACE TO SURFACE, ADJUST=NS\nTOP, "
                   "TOP\n",
               {23, "ADJUST=<node set> is not supported yet", "ADJUST"});
}

TEST(InpErrors, Numbers) {
  expect_error("*NODE\n1, 0., abc, 0.\n", {2, "expected a number, got 'abc'", "y"});
  expect_error(kModel + "*MATERIAL, NAME=B\n*ELASTIC\n-5., 0.3\n",
               {25, "Young's modulus > 0", "E"});
  expect_error(kModel + "*STEP\n*STATIC\n0.5, 0.1\n*END STEP\n",
               {25, "initial increment in (0, time period]"});
  expect_error(kModel + "*AMPLITUDE, NAME=A\n0., 0., 1.\n", {24, "time, value pairs"});
  expect_error(kModel + "*STEP\n*STATIC\n*NODE PRINT\nU, UX\n*END STEP\n",
               {26, "unknown key 'UX' for *NODE PRINT (abut prints U, RF)", "key"});
  expect_error(kModel +
                   "*SURFACE INTERACTION, NAME=A\n*SURFACE BEHAVIOR, "
                   "PRESSURE-OVERCLOSURE=EXPONENTIAL\n0., 1.\n",
               {25, "expected the distance c0 > 0", "c0"});
  expect_error(kModel +
                   "*SURFACE INTERACTION, NAME=A\n*SURFACE BEHAVIOR, "
                   "PRESSURE-OVERCLOSURE=TABULAR\n0., 0.\n",
               {24, "at least two"});
  expect_error(kModel + "*AMPLITUDE, NAME=A\n1., 0., 0., 1.\n", {24, "must increase"});
  expect_error(kModel + "*EQUATION\n3\n1, 1, 1., 2, 1, -1.\n*STEP\n*STATIC\n*END STEP\n",
               {24, "fewer terms than its count"});
}

TEST(InpErrors, Mesh) {
  expect_error(kModel + "*NODE\n3, 5., 5., 5.\n", {24, "node 3 is already defined at t.inp:4"});
  expect_error(kModel + "*ELEMENT, TYPE=C3D8\n2, 1, 2, 5, 4, 7, 8, 11, 10\n",
               {24, "element 2 is already defined at t.inp:16"});
  expect_error(kModel + "*ELEMENT, TYPE=C3D15\n3, 1, 2, 5, 4, 7, 8, 11, 10\n",
               {23, "element type C3D15 is not supported yet", "TYPE"});
  expect_error(kModel + "*CONTROLS, PARAMETERS=FIELD\n2., 0.01\n",
               {24, "expected a tolerance between 0 and 1", "R_n"});
  // CalculiX's C3D20 line: 16 entries, then the rest on the next line.
  expect_error(kModel + "*ELEMENT, TYPE=C3D20\n3, 1, 2, 5, 4, 7, 8, 11, 10\n",
               {24, "expected the element number and 20 node numbers (C3D20), got 9 fields"});
  expect_error(kModel + "*ELEMENT, TYPE=C3D8\n3, 1, 2, 5, 4, 7, 8, 11\n",
               {24, "expected the element number and 8 node numbers"});
  expect_error(kModel + "*ELEMENT, TYPE=C3D8, ELSET=EALL\n3, 1, 2, 5, 4, 7, 8, 11, 99\n" + kStep,
               {24, "node 99 of element 3 is not defined", "n8"});
  // Nodes 5-8 below 1-4: inside out.
  expect_error(kModel + "*ELEMENT, TYPE=C3D8, ELSET=EALL\n3, 7, 8, 11, 10, 1, 2, 5, 4\n" + kStep,
               {24, "element 3 (C3D8) is inside out or folded"});
  expect_error(kModel + "*ELEMENT, TYPE=C3D8\n3, 1, 2, 5, 4, 7, 8, 11, 10\n" + kStep,
               {24, "element 3 has no *SOLID SECTION"});
  expect_error(kModel + "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n" + kStep,
               {23, "element 1 already has the section of t.inp:20"});
  expect_error(kModel + "*NSET, NSET=A\n1, 77\n" + kStep,
               {24, "node 77 of node set A is not defined"});
  expect_error(kModel + "*NSET, NSET=A\nB\n", {24, "node set B is not defined before this line"});
  expect_error(kModel + "*SURFACE, NAME=S\n1, S7\n", {24, "face label S1 to S6", "face"});
  expect_error(kModel + "*SURFACE, NAME=S\n1\n", {24, "the face label is missing"});
  expect_error(kModel + "*SURFACE, NAME=top\n2, S1\n", {23, "surface top is already defined"});
}

TEST(InpErrors, UndefinedNames) {
  expect_error(kModel + "*SOLID SECTION, ELSET=NONE, MATERIAL=STEEL\n" + kStep,
               {23, "element set NONE is not defined"});
  expect_error(kModel + "*ELSET, ELSET=E2\n2\n*SOLID SECTION, ELSET=E2, MATERIAL=WOOD\n" + kStep,
               {25, "material WOOD is not defined", "MATERIAL"});
  expect_error(kModel + "*STEP\n*STATIC\n*BOUNDARY\nNOSET, 1, 3\n*END STEP\n",
               {26, "node set NOSET is not defined"});
  expect_error(kModel + "*STEP\n*STATIC\n*CLOAD\n99, 1, 1.\n*END STEP\n",
               {26, "node 99 is not defined"});
  expect_error(kModel + "*STEP\n*STATIC\n*DLOAD\n9, P1, 1.\n*END STEP\n",
               {26, "element 9 is not defined"});
  expect_error(kModel + "*STEP\n*STATIC\n*CLOAD, AMPLITUDE=RAMP2\n1, 1, 1.\n*END STEP\n",
               {25, "amplitude RAMP2 is not defined", "AMPLITUDE"});
  expect_error(kModel +
                   "*SURFACE INTERACTION, NAME=A\n*SURFACE BEHAVIOR, "
                   "PRESSURE-OVERCLOSURE=LINEAR\n1.e7\n*CONTACT PAIR, INTERACTION=A, "
                   "TYPE=SURFACE TO SURFACE\nTOP, BOTTOM\n" +
                   kStep,
               {27, "surface BOTTOM is not defined", "master"});
  expect_error(kModel + "*CONTACT PAIR, INTERACTION=A, TYPE=SURFACE TO SURFACE\nTOP, TOP\n" + kStep,
               {23, "surface interaction A is not defined", "INTERACTION"});
  expect_error(kModel +
                   "*SURFACE INTERACTION, NAME=A\n*CONTACT PAIR, INTERACTION=A, "
                   "TYPE=SURFACE TO SURFACE\nTOP, TOP\n" +
                   kStep,
               {23, "has no *SURFACE BEHAVIOR"});
  expect_error(kModel +
                   "*STEP\n*STATIC\n*CHANGE FRICTION, INTERACTION=X\n*FRICTION\n0.1, 1.\n*END "
                   "STEP\n",
               {25, "surface interaction X is not defined"});
}

TEST(InpErrors, PhysicsNotSupportedYet) {
  expect_error(kModel + "*BOUNDARY\n1, 4, 6\n", {24, "degrees of freedom 4 to 6 are rotations"});
  expect_error(kModel + "*STEP\n*STATIC\n*DLOAD\nEALL, GRAV, 9810., 0., 0., -1.\n*END STEP\n",
               {26, "load type 'GRAV' is not supported yet", "load type"});
  expect_error(kModel + "*MATERIAL, NAME=B\n*ELASTIC\n1., 0.3\n*EXPANSION\n1.e-5\n",
               {26, "*EXPANSION is not supported yet"});
  expect_error(kModel + "*MATERIAL, NAME=B\n*ELASTIC\n1., 0.3\n0.9, 0.3, 100.\n",
               {26, "temperature-dependent properties"});
  expect_error(kModel +
                   "*SURFACE INTERACTION, NAME=A\n*SURFACE BEHAVIOR, "
                   "PRESSURE-OVERCLOSURE=TIED\n1.e9\n*CONTACT PAIR, INTERACTION=A, "
                   "TYPE=SURFACE TO SURFACE\nTOP, TOP\n" +
                   kStep,
               {24, "needs the stick slope of a *FRICTION card"});
  expect_error(kModel +
                   "*SURFACE, NAME=N, TYPE=NODE\n1\n*SURFACE INTERACTION, NAME=A\n*SURFACE "
                   "BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n1.\n*CONTACT PAIR, "
                   "INTERACTION=A, TYPE=SURFACE TO SURFACE\nN, TOP\n" +
                   kStep,
               {29, "suits TYPE=NODE TO SURFACE only", "slave"});
  expect_error(kModel + "*EQUATION\n2\n1, 1, 1., 2, 1, -1.\n*BOUNDARY\n1, 1, 1\n" + kStep,
               {27, "is the dependent term of the *EQUATION at t.inp:24"});
}

// *PLASTIC (CalculiX User's Manual): isotropic hardening, one curve starting at plastic strain 0.
TEST(InpErrors, Plastic) {
  const std::string b = kModel + "*MATERIAL, NAME=B\n*ELASTIC\n1., 0.3\n";
  expect_error(b + "*PLASTIC, HARDENING=KINEMATIC\n100., 0.\n",
               {26, "HARDENING=KINEMATIC is not supported yet", "HARDENING"});
  expect_error(b + "*PLASTIC\n100., 0.01\n", {27, "the first line must be at plastic strain 0"});
  expect_error(b + "*PLASTIC\n100., 0.\n120., 0.1\n130., 0.1\n",
               {29, "the plastic strains must increase"});
  expect_error(b + "*PLASTIC\n0., 0.\n", {27, "expected a yield stress > 0"});
  expect_error(b + "*PLASTIC\n100., 0., 20.\n120., 0.1, 300.\n",
               {28, "temperature-dependent hardening"});
  expect_error(b + "*PLASTIC\n100., 0.\n*PLASTIC\n100., 0.\n", {28, "already has a *PLASTIC"});
}

TEST(InpErrors, ErrorsInIncludedFilesNameThatFile) {
  // A missing top-level file is an error too (no crash).
  EXPECT_THROW(read_inp_with_notes("/nonexistent/model.inp"), InputError);
  EXPECT_THROW(read_deck("/nonexistent/MODEL.INP"), InputError);
}

}  // namespace
}  // namespace abut
