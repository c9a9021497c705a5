// Nonlinear transient (CVODE): options, inputs and results; the GIL is released while
// integrating (the solver object must not be shared between threads).
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "rotordyn/transient.hpp"

namespace rotordyn::py_bind {

void bind_transient(py::module_& m) {
  py::class_<CvodeOptions>(m, "CvodeOptions", "CVODE settings (BDF, dense Newton).")
      .def(py::init<>())
      .def_readwrite("rtol", &CvodeOptions::rtol)
      .def_readwrite("atol_position", &CvodeOptions::atol_position)
      .def_readwrite("atol_velocity", &CvodeOptions::atol_velocity)
      .def_readwrite("max_steps", &CvodeOptions::max_steps)
      .def_readwrite("max_step", &CvodeOptions::max_step)
      .def_readwrite("stability_limit_detection", &CvodeOptions::stability_limit_detection)
      .def_readwrite("max_order", &CvodeOptions::max_order)
      .def_readwrite("analytic_jacobian", &CvodeOptions::analytic_jacobian)
      .def_readwrite("atol_pressure", &CvodeOptions::atol_pressure)
      .def_readwrite("atol_controller", &CvodeOptions::atol_controller)
      .def_readwrite("rub_fraction", &CvodeOptions::rub_fraction);
  py::class_<SpeedProfile>(m, "SpeedProfile", "Ω(t) piecewise linear through (t, omega).")
      .def(py::init<>())
      .def_readwrite("t", &SpeedProfile::t)
      .def_readwrite("omega", &SpeedProfile::omega);
  py::enum_<PressureSource>(m, "PressureSource")
      .value("constant", PressureSource::constant)
      .value("time_table", PressureSource::time_table)
      .value("speed_table", PressureSource::speed_table);
  py::class_<PressureCommand>(m, "PressureCommand")
      .def(py::init<>())
      .def_readwrite("source", &PressureCommand::source)
      .def_readwrite("table_x", &PressureCommand::table_x)
      .def_readwrite("table_p", &PressureCommand::table_p)
      .def_readwrite("harmonic_amplitude", &PressureCommand::harmonic_amplitude)
      .def_readwrite("harmonic_frequency", &PressureCommand::harmonic_frequency)
      .def_readwrite("harmonic_phase", &PressureCommand::harmonic_phase)
      .def_readwrite("harmonic_order", &PressureCommand::harmonic_order)
      .def_readwrite("harmonic_table_omega", &PressureCommand::harmonic_table_omega)
      .def_readwrite("harmonic_table_amplitude", &PressureCommand::harmonic_table_amplitude)
      .def_readwrite("harmonic_table_phase", &PressureCommand::harmonic_table_phase);
  py::class_<Actuator>(m, "Actuator")
      .def(py::init<>())
      .def_readwrite("order", &Actuator::order)
      .def_readwrite("time_constant", &Actuator::time_constant)
      .def_readwrite("natural_frequency", &Actuator::natural_frequency)
      .def_readwrite("damping", &Actuator::damping)
      .def_readwrite("p_min", &Actuator::p_min)
      .def_readwrite("p_max", &Actuator::p_max)
      .def_readwrite("rate_limit", &Actuator::rate_limit);
  py::class_<Controller>(m, "Controller")
      .def(py::init<>())
      .def_readwrite("enabled", &Controller::enabled)
      .def_readwrite("A", &Controller::A)
      .def_readwrite("B", &Controller::B)
      .def_readwrite("C", &Controller::C)
      .def_readwrite("D", &Controller::D)
      .def_readwrite("measurement", &Controller::measurement)
      .def_readwrite("offset", &Controller::offset)
      .def_readwrite("x0", &Controller::x0)
      .def_readwrite("sample_time", &Controller::sample_time)
      .def_readwrite("delay", &Controller::delay)
      .def_readwrite("tracking", &Controller::tracking)
      .def_readwrite("realise_schedule", &Controller::realise_schedule)
      .def_readwrite("schedule_omega", &Controller::schedule_omega)
      .def_readwrite("schedule_law", &Controller::schedule_law)
      .def_readwrite("noise_std", &Controller::noise_std)
      .def_readwrite("noise_dt", &Controller::noise_dt)
      .def_readwrite("seed", &Controller::seed);
  py::class_<AdaptiveHarmonic>(m, "AdaptiveHarmonic")
      .def(py::init<>())
      .def_readwrite("enabled", &AdaptiveHarmonic::enabled)
      .def_readwrite("order", &AdaptiveHarmonic::order)
      .def_readwrite("gain", &AdaptiveHarmonic::gain)
      .def_readwrite("measurement", &AdaptiveHarmonic::measurement)
      .def_readwrite("offset", &AdaptiveHarmonic::offset)
      .def_readwrite("table_omega", &AdaptiveHarmonic::table_omega)
      .def_readwrite("table_re", &AdaptiveHarmonic::table_re)
      .def_readwrite("table_im", &AdaptiveHarmonic::table_im)
      .def_readwrite("p0_re", &AdaptiveHarmonic::p0_re)
      .def_readwrite("p0_im", &AdaptiveHarmonic::p0_im)
      .def_readwrite("leak", &AdaptiveHarmonic::leak)
      .def_readwrite("gain_omega", &AdaptiveHarmonic::gain_omega)
      .def_readwrite("gain_table", &AdaptiveHarmonic::gain_table)
      .def_readwrite("freeze_saturated", &AdaptiveHarmonic::freeze_saturated)
      .def_readwrite("washout", &AdaptiveHarmonic::washout);
  py::class_<TransientInput>(m, "TransientInput")
      .def(py::init<>())
      .def_readwrite("omega", &TransientInput::omega)
      .def_readwrite("chamber_pressure", &TransientInput::chamber_pressure)
      .def_readwrite("a", &TransientInput::a)
      .def_readwrite("unbalance_cos", &TransientInput::unbalance_cos)
      .def_readwrite("unbalance_sin", &TransientInput::unbalance_sin)
      .def_readwrite("r0", &TransientInput::r0)
      .def_readwrite("v0", &TransientInput::v0)
      .def_readwrite("t_out", &TransientInput::t_out)
      .def_readwrite("speed", &TransientInput::speed)
      .def_readwrite("pressure", &TransientInput::pressure)
      .def_readwrite("actuator", &TransientInput::actuator)
      .def_readwrite("controller", &TransientInput::controller)
      .def_readwrite("adaptive", &TransientInput::adaptive)
      .def_readwrite("record_film_force", &TransientInput::record_film_force);
  py::class_<TransientResult>(m, "TransientResult")
      .def_readonly("t", &TransientResult::t)
      .def_readonly("r", &TransientResult::r)
      .def_readonly("v", &TransientResult::v)
      .def_readonly("h_min", &TransientResult::h_min)
      .def_readonly("speed", &TransientResult::speed)
      .def_readonly("angle", &TransientResult::angle)
      .def_readonly("pc_command", &TransientResult::pc_command)
      .def_readonly("pc", &TransientResult::pc)
      .def_readonly("controller_output", &TransientResult::controller_output)
      .def_readonly("actuator_states", &TransientResult::actuator_states)
      .def_readonly("controller_states", &TransientResult::controller_states)
      .def_readonly("adaptive_states", &TransientResult::adaptive_states)
      .def_readonly("film_force", &TransientResult::film_force)
      .def_readonly("status", &TransientResult::status)
      .def_readonly("message", &TransientResult::message)
      .def_readonly("steps", &TransientResult::steps)
      .def_readonly("rhs_evals", &TransientResult::rhs_evals)
      .def_readonly("jac_evals", &TransientResult::jac_evals)
      .def_readonly("newton_fails", &TransientResult::newton_fails)
      .def_readonly("error_test_fails", &TransientResult::error_test_fails)
      .def_readonly("linear_setups", &TransientResult::linear_setups)
      .def_readonly("newton_iters", &TransientResult::newton_iters)
      .def_readonly("stab_lim_order_reductions", &TransientResult::stab_lim_order_reductions)
      .def_readonly("reynolds_solves", &TransientResult::reynolds_solves)
      .def_readonly("reynolds_iterations", &TransientResult::reynolds_iterations);
  m.def("integrate", &integrate, py::arg("solver"), py::arg("input"), py::arg("options"),
        py::call_guard<py::gil_scoped_release>(),
        "Integrate eq. 12 with CVODE from t = 0 to input.t_out[-1].");
  m.def("cvode_flag_name", &cvode_flag_name, py::arg("flag"));
}

}  // namespace rotordyn::py_bind
