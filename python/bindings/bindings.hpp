#pragma once
// The parts of Python's compiled module abut._abut (module.cpp): runs and checks of decks
// (run.cpp) and the contact library on numpy arrays (contact.cpp).
#include <pybind11/pybind11.h>

namespace abut::python {

void bind_run(pybind11::module_& m);
void bind_contact(pybind11::module_& m);

}  // namespace abut::python
