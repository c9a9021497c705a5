// rotordyn._core: thin pybind11 wrapper around the rotordyn C++ core.
#include "bindings.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() = "rotordyn C++ core (private; use the rotordyn package API)";
  using namespace rotordyn::py_bind;
  bind_errors(m);
  bind_info(m);
  bind_threads(m);
  bind_rotor(m);
  bind_modal(m);
  bind_harmonic(m);
  bind_reynolds(m);
  bind_system(m);
  bind_bearings(m);
  bind_transient(m);
  bind_periodic(m);
  bind_hill(m);
  bind_harmonic_balance(m);
  bind_continuation(m);
  bind_hb_continuation(m);
  bind_sleeve(m);
  bind_batch(m);
  bind_thermal(m);
  bind_unbalance(m);
  bind_threshold(m);
  bind_thd(m);
  bind_tracking(m);
}
