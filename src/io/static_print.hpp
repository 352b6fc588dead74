#pragma once
// The printed results of a static analysis (*NODE PRINT, *EL PRINT, *CONTACT PRINT): blocks in
// the layout of CalculiX's .dat file (a header naming the quantity, the set and the time, then one
// row per node, element point or contact point), so that one script reads both codes' output.
#include <ostream>

#include "abut/model/model.hpp"
#include "abut/solver/static_solver.hpp"

namespace abut {

// Writes the blocks of every request of `step` due at this increment.
void print_static_results(std::ostream& out, const Model& model, const StaticStep& step,
                          const StaticSolver& solver, const StaticIncrement& increment);

}  // namespace abut
