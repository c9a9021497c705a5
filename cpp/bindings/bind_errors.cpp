// Maps the C++ error hierarchy onto Python exceptions, all subclasses of RotordynError.
#include "bindings.hpp"
#include "rotordyn/errors.hpp"

namespace rotordyn::py_bind {

namespace {
PyObject* new_exc(py::module_& m, const char* name, PyObject* bases, const char* doc) {
  const std::string full = std::string("rotordyn.errors.") + name;
  PyObject* e = PyErr_NewExceptionWithDoc(full.c_str(), doc, bases, nullptr);
  if (!e) throw py::error_already_set();
  m.attr(name) = py::handle(e);
  return e;
}
PyObject* g_base = nullptr;
PyObject* g_input = nullptr;
PyObject* g_conv = nullptr;
PyObject* g_starved = nullptr;
PyObject* g_contact = nullptr;
PyObject* g_sundials = nullptr;
}  // namespace

void bind_errors(py::module_& m) {
  g_base = new_exc(m, "RotordynError", PyExc_Exception, "Base class of every rotordyn error.");
  py::tuple in_bases = py::make_tuple(py::handle(g_base), py::handle(PyExc_ValueError));
  g_input = new_exc(m, "InputError", in_bases.ptr(),
                    "Bad input: the message names the field and the allowed range.");
  py::tuple rt_bases = py::make_tuple(py::handle(g_base), py::handle(PyExc_RuntimeError));
  g_conv = new_exc(m, "ConvergenceError", rt_bases.ptr(), "An iteration did not converge.");
  {  // a ConvergenceError whose status is "starved" (class attribute, as failed equilibria's)
    py::tuple st_bases = py::make_tuple(py::handle(g_conv));
    g_starved = new_exc(m, "StarvedFilmError", st_bases.ptr(),
                        "A thermal film's metered supply and its hot oil fall short of the "
                        "flow it draws (status 'starved').");
    py::setattr(py::handle(g_starved), "status", py::str("starved"));
  }
  g_contact = new_exc(m, "ContactError", rt_bases.ptr(),
                      "Journal and bush (or sleeve) are in contact.");
  g_sundials = new_exc(m, "SundialsError", rt_bases.ptr(), "A SUNDIALS call failed.");
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const rotordyn::InputError& e) {
      PyErr_SetString(g_input, e.what());
    } catch (const rotordyn::ContactError& e) {
      PyErr_SetString(g_contact, e.what());
    } catch (const rotordyn::StarvedError& e) {
      PyErr_SetString(g_starved, e.what());
    } catch (const rotordyn::ConvergenceError& e) {
      PyErr_SetString(g_conv, e.what());
    } catch (const rotordyn::SundialsError& e) {
      PyErr_SetString(g_sundials, e.what());
    }
  });
}

}  // namespace rotordyn::py_bind
