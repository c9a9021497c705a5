#include <pybind11/stl.h>

#include "bindings.hpp"
#include "rotordyn/build_info.hpp"

namespace rotordyn::py_bind {
void bind_info(py::module_& m) {
  m.def("build_info", &rotordyn::build_info,
        "Versions of rotordyn and of Eigen, SUNDIALS and SuiteSparse the core was built with.");
}
}  // namespace rotordyn::py_bind
