// abut._abut: the compiled half of the Python package (python/abut). The package's modules wrap
// it with the documented interface (abut.run, abut.check, abut.contact).
#include "bindings.hpp"

PYBIND11_MODULE(_abut, m) {
  m.doc() = "abut's solver and contact library (compiled part; use the abut package)";
  abut::python::bind_run(m);
  abut::python::bind_contact(m);
}
