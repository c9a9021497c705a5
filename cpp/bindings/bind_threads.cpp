#include "bindings.hpp"
#include "rotordyn/threads.hpp"

namespace rotordyn::py_bind {
void bind_threads(py::module_& m) {
  m.def("set_eigen_threads", &rotordyn::set_eigen_threads, py::arg("n"),
        "Threads of Eigen's own matrix products, process-wide (0: OpenMP's count).");
  m.def("eigen_threads", &rotordyn::eigen_threads);
}
}  // namespace rotordyn::py_bind
