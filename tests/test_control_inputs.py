"""Bad input to the control API and CLI (issue 21, "The control API and CLI"): every public
function of ``rotordyn.control.*`` and the operation classes checks each argument by the
shared rule of ``rotordyn._common.validate`` and raises ``rotordyn.InputError`` naming the
field (and the allowed range) before any solve; a grid or a scan never turns bad input into
NaN or ``error`` rows; the CLI checks ``--out`` before computing and writes strict JSON.

Each case is a call as the issue states it (or the same defect on another argument); on the
code before the fix each leaked another exception (ValueError, ZeroDivisionError,
OverflowError, UFuncTypeError, "math domain error"), returned NaN/error rows, or was accepted.
"""

import json
import re
from types import SimpleNamespace

import numpy as np
import pytest
import rotordyn as rd
from rotordyn.cli import main as cli_main
from rotordyn.control import Actuator, Controller, PressureSchedule, SpeedProfile
from rotordyn.control.closedloop import (
    closed_loop,
    closed_loop_matrix,
    closed_loop_unbalance,
    loop_response,
)
from rotordyn.control.hinf import generalized_plant, hinf, lower_lft_response
from rotordyn.control.lqr import default_weights, lqg, lqr, state_scales
from rotordyn.control.pid import pid, tune_pd
from rotordyn.control.plant import plant
from rotordyn.control.reduction import balanced_truncation, modal_truncation
from rotordyn.control.schedule import pressure_schedule
from rotordyn.control.synchronous import minimise_semi_major, synchronous_bound
from rotordyn.control.threshold import closed_loop_max_real, closed_loop_threshold

AY, PC = -1.85e-3, 0.05e6
NAN, INF = float("nan"), float("inf")
UB = [(6, 2e-5, 0.0)]


@pytest.fixture(scope="module")
def fx():
    rig = rd.models.paper_rig()
    p = plant(rig, 50.0, PC, AY)
    k = pid(3.7e8, -5.9e5)
    return SimpleNamespace(rig=rig, p=p, k=k, n=p.A.shape[0],
                           friswell=rd.models.friswell_5_9_1())


def _sched(f, **kw):
    return pressure_schedule(f.rig, kw.pop("unbalances", UB), kw.pop("speeds", [30.0, 40.0]),
                             kw.pop("pressures", [0.0, 0.5e6]), **kw)


def _sync(f, **kw):
    return synchronous_bound(f.rig, kw.pop("unbalances", UB), kw.pop("speeds", [38.5]),
                             kw.pop("pressures", [0.5e6]), stations=kw.pop("stations", [4]),
                             **kw)


def _clu(f, **kw):
    return closed_loop_unbalance(f.rig, kw.pop("controller", f.k), kw.pop("unbalances", UB),
                                 kw.pop("speeds", [30.0]), **kw)


def _clt(f, **kw):
    return closed_loop_threshold(f.rig, kw.pop("controller", f.k), kw.pop("vary", "speed_hz"),
                                 bounds=kw.pop("bounds", (40.0, 60.0)), **kw)


CASES = [
    # -- plant --------------------------------------------------------------------------------
    ("plant system text", lambda f: plant("paper-rig", 50.0), "system"),
    ("plant speed nan", lambda f: plant(f.rig, NAN), "speed_hz"),
    ("plant p_c negative", lambda f: plant(f.rig, 50.0, -1.0), "chamber_pressure_pa"),
    ("plant a_y on a system without active bearing",
     lambda f: plant(f.friswell, 50.0, 0.0, 0.0), "config_ay_m"),
    ("plant measurement index text",
     lambda f: plant(f.rig, 50.0, PC, AY, measurements=[("journal", "a")]), "measurements"),
    ("plant measurement station 99",
     lambda f: plant(f.rig, 50.0, PC, AY, measurements=[("displacement", 99)]), "measurements"),
    ("plant actuator text", lambda f: plant(f.rig, 50.0, actuator="valve"), "actuator"),
    ("plant disturbance station 99",
     lambda f: plant(f.rig, 50.0, disturbance_stations=[99]), "disturbance_stations"),
    ("plant disturbance stations text",
     lambda f: plant(f.rig, 50.0, disturbance_stations="ab"), "disturbance_stations"),
    # -- reduction ----------------------------------------------------------------------------
    ("modal_truncation plant text", lambda f: modal_truncation("p"), "plant"),
    ("modal_truncation frequency 0", lambda f: modal_truncation(f.p, 0.0), "max_frequency_hz"),
    ("modal_truncation keep_actuator text",
     lambda f: modal_truncation(f.p, keep_actuator="yes"), "keep_actuator"),
    ("modal_truncation check_hz from 0",
     lambda f: modal_truncation(f.p, check_hz=(0.0, 10.0)), "check_hz"),
    ("modal_truncation n_check 1", lambda f: modal_truncation(f.p, n_check=1), "n_check"),
    # issue 21 (fuzzing): c² of 1e300 was an OverflowError
    ("lqr clearance 1e300", lambda f: lqr(f.p, clearance_m=1e300), "clearance_m"),
    ("lqr pressure scale 1e-300", lambda f: lqr(f.p, pressure_scale_pa=1e-300),
     "pressure_scale_pa"),
    # issue 21 (fuzzing): no mode kept was a numpy ValueError
    ("modal_truncation keeps nothing",
     lambda f: modal_truncation(f.p, 1.0, keep_actuator=False), "max_frequency_hz"),
    ("balanced_truncation order 2.5", lambda f: balanced_truncation(f.p, 2.5), "order"),
    ("balanced_truncation check_hz text",
     lambda f: balanced_truncation(f.p, 8, check_hz="ab"), "check_hz"),
    ("balanced_truncation n_check 10**9",
     lambda f: balanced_truncation(f.p, 8, n_check=10**9), "n_check"),
    # -- LQR / LQG ----------------------------------------------------------------------------
    ("state_scales clearance 0", lambda f: state_scales(f.p, clearance_m=0.0), "clearance_m"),
    ("state_scales frequency nan", lambda f: state_scales(f.p, frequency_hz=NAN),
     "frequency_hz"),
    ("default_weights state_weight -1", lambda f: default_weights(f.p, state_weight=-1.0),
     "state_weight"),
    ("default_weights regularisation inf",
     lambda f: default_weights(f.p, regularisation=INF), "regularisation"),
    ("lqr plant text", lambda f: lqr("p"), "plant"),
    # issue: ValueError "array must not contain infs or NaNs"
    ("lqr Q nan", lambda f: lqr(f.p, Q=np.full((f.n, f.n), NAN)), "Q"),
    ("lqr Q shape", lambda f: lqr(f.p, Q=np.eye(3)), "Q"),
    ("lqr Q negative definite", lambda f: lqr(f.p, Q=-np.eye(f.n)), "Q"),
    ("lqr Q text", lambda f: lqr(f.p, Q="x"), "Q"),
    ("lqr R -1", lambda f: lqr(f.p, R=-1), "R"),
    ("lqr R nan", lambda f: lqr(f.p, R=[[NAN]]), "R"),
    # issue: ZeroDivisionError
    ("lqr pressure_scale 1e-300", lambda f: lqr(f.p, pressure_scale_pa=1e-300, R=-1),
     "pressure_scale_pa"),
    ("lqr unknown option", lambda f: lqr(f.p, clearence_m=3e-4), "clearence_m"),
    # issue: OverflowError; 0 and -1 were accepted
    ("lqg disturbance -1e300", lambda f: lqg(f.p, disturbance_force_n=-1e300),
     "disturbance_force_n"),
    ("lqg disturbance 0", lambda f: lqg(f.p, disturbance_force_n=0), "disturbance_force_n"),
    ("lqg disturbance -1", lambda f: lqg(f.p, disturbance_force_n=-1), "disturbance_force_n"),
    ("lqg disturbance 1e300", lambda f: lqg(f.p, disturbance_force_n=1e300),
     "disturbance_force_n"),
    ("lqg process_noise nan", lambda f: lqg(f.p, process_noise=NAN), "process_noise"),
    ("lqg measurement_noise 1e-300", lambda f: lqg(f.p, measurement_noise_m=1e-300),
     "measurement_noise_m"),
    ("lqg name 5", lambda f: lqg(f.p, name=5), "name"),
    # -- PD / PID -----------------------------------------------------------------------------
    ("pid kp text", lambda f: pid("1", 1e5), "kp"),
    ("pid kd nan", lambda f: pid(1e8, NAN), "kd"),
    ("pid ki inf", lambda f: pid(1e8, 1e5, ki=INF), "ki"),
    ("pid kd 1e300", lambda f: pid(1e8, 1e300), "kd"),
    ("pid tau 0", lambda f: pid(1e8, 1e5, tau_d_s=0.0), "tau_d_s"),
    ("pid tau 1e-300", lambda f: pid(1e8, 1e5, tau_d_s=1e-300), "tau_d_s"),
    # issue: "math domain error"
    ("pid direction inf", lambda f: pid(1e8, 1e5, direction_deg=INF), "direction_deg"),
    # issue: accepted
    ("pid bearing True", lambda f: pid(1e8, 1e5, bearing=True), "bearing"),
    ("pid bearing -1", lambda f: pid(1e8, 1e5, bearing=-1), "bearing"),
    ("pid name None", lambda f: pid(1e8, 1e5, name=None), "name"),
    ("tune_pd plant text", lambda f: tune_pd("p"), "plant"),
    # issue: UFuncTypeError
    ("tune_pd kp0 text", lambda f: tune_pd(f.p, kp0="1"), "kp0"),
    ("tune_pd kd0 0", lambda f: tune_pd(f.p, kd0=0.0), "kd0"),
    ("tune_pd ki text", lambda f: tune_pd(f.p, ki="x"), "ki"),
    ("tune_pd tau -1", lambda f: tune_pd(f.p, tau_d_s=-1.0), "tau_d_s"),
    ("tune_pd direction nan", lambda f: tune_pd(f.p, direction_deg=NAN), "direction_deg"),
    # issue: accepted
    ("tune_pd max_iter 0", lambda f: tune_pd(f.p, max_iter=0), "max_iter"),
    ("tune_pd max_iter 2.5", lambda f: tune_pd(f.p, max_iter=2.5), "max_iter"),
    # -- closed loop --------------------------------------------------------------------------
    ("closed_loop freqs text", lambda f: closed_loop(f.p, f.k, freqs_hz="x"), "freqs_hz"),
    ("closed_loop freqs empty", lambda f: closed_loop(f.p, f.k, freqs_hz=[]), "freqs_hz"),
    ("closed_loop freqs decreasing", lambda f: closed_loop(f.p, f.k, freqs_hz=[10.0, 5.0]),
     "freqs_hz"),
    ("closed_loop freqs nan", lambda f: closed_loop(f.p, f.k, freqs_hz=[NAN, 1.0]),
     "freqs_hz"),
    # issue: "max Re λ = 8.5e300"
    ("closed_loop sample time 1e-300",
     lambda f: closed_loop(f.p, f.k.with_options(sample_time_s=1e-300)), "sample_time_s"),
    ("closed_loop discrete freqs above Nyquist",
     lambda f: closed_loop(f.p, f.k.with_options(sample_time_s=1e-3), freqs_hz=[600, 700]),
     "freqs_hz"),
    ("closed_loop plant text", lambda f: closed_loop("p", f.k), "plant"),
    ("closed_loop controller text", lambda f: closed_loop(f.p, "pd"), "controller"),
    ("closed_loop controller measuring something else",
     lambda f: closed_loop(f.p, Controller.static([[1.0, 0.0]], [("journal_velocity", 0)])),
     "controller.measurements"),
    ("closed_loop_matrix controller text", lambda f: closed_loop_matrix(f.p, 5), "controller"),
    ("loop_response freqs text", lambda f: loop_response(f.p, f.k, "x"), "freqs_hz"),
    # issue: ValueError "invalid literal for int()"
    ("closed_loop_unbalance station text",
     lambda f: closed_loop_unbalance(f.rig, f.k, [("a", 1e-5, 0)], [30]), "unbalances"),
    ("closed_loop_unbalance no unbalance", lambda f: _clu(f, unbalances=[]), "unbalances"),
    ("closed_loop_unbalance speeds nan", lambda f: _clu(f, speeds=[NAN]), "speeds_hz"),
    ("closed_loop_unbalance speeds text", lambda f: _clu(f, speeds="x"), "speeds_hz"),
    ("closed_loop_unbalance p_c -1", lambda f: _clu(f, chamber_pressure_pa=-1.0),
     "chamber_pressure_pa"),
    ("closed_loop_unbalance p_c text", lambda f: _clu(f, chamber_pressure_pa="1e5"),
     "chamber_pressure_pa"),
    ("closed_loop_unbalance p_c time table",
     lambda f: _clu(f, chamber_pressure_pa=PressureSchedule.time_table([0, 1], [1e5, 2e5])),
     "chamber_pressure_pa"),
    ("closed_loop_unbalance a_y nan", lambda f: _clu(f, config_ay_m=NAN), "config_ay_m"),
    ("closed_loop_unbalance stations 99", lambda f: _clu(f, stations=[99]), "stations"),
    ("closed_loop_unbalance actuator text", lambda f: _clu(f, actuator="valve"), "actuator"),
    ("closed_loop_unbalance controller text", lambda f: _clu(f, controller="pd"),
     "controller"),
    ("closed_loop_unbalance discrete controller",
     lambda f: _clu(f, controller=f.k.with_options(sample_time_s=1e-4)), "sample_time_s"),
    ("closed_loop_unbalance measurement station 99",
     lambda f: _clu(f, controller=Controller.static([[1.0, 0.0]], [("displacement", 99)])),
     "measurements"),
    # -- threshold ----------------------------------------------------------------------------
    # issue: ValueError "not enough values to unpack"
    ("closed_loop_threshold bounds (0,)",
     lambda f: _clt(f, vary="chamber_pressure_pa", bounds=(0.0,)), "bounds"),
    # issue: returned no crossing
    ("closed_loop_threshold speed nan",
     lambda f: _clt(f, vary="chamber_pressure_pa", bounds=(0.0, 0.3e6), speed_hz=NAN),
     "speed_hz"),
    ("closed_loop_threshold p_c nan", lambda f: _clt(f, chamber_pressure_pa=NAN),
     "chamber_pressure_pa"),
    ("closed_loop_threshold p_c bounds negative",
     lambda f: _clt(f, vary="chamber_pressure_pa", bounds=(-1e5, 1e5)), "bounds"),
    ("closed_loop_threshold speed bounds 1e9", lambda f: _clt(f, bounds=(10.0, 1e9)),
     "bounds"),
    ("closed_loop_threshold vary", lambda f: _clt(f, vary="config_ax_m"), "vary"),
    ("closed_loop_threshold n_scan 1", lambda f: _clt(f, n_scan=1), "n_scan"),
    ("closed_loop_threshold xtol 0", lambda f: _clt(f, xtol=0.0), "xtol"),
    ("closed_loop_threshold a_y text", lambda f: _clt(f, config_ay_m="x"), "config_ay_m"),
    ("closed_loop_threshold a_y without active bearing",
     lambda f: closed_loop_threshold(f.friswell, f.k, "speed_hz", bounds=(10, 20),
                                     config_ay_m=0.0), "config_ay_m"),
    ("closed_loop_threshold actuator 5", lambda f: _clt(f, actuator=5), "actuator"),
    ("closed_loop_threshold controller text", lambda f: _clt(f, controller="pd"),
     "controller"),
    ("closed_loop_max_real speed nan",
     lambda f: closed_loop_max_real(f.rig, f.k, speed_hz=NAN, chamber_pressure_pa=PC,
                                    config_ay_m=AY), "speed_hz"),
    ("closed_loop_max_real exclude -1",
     lambda f: closed_loop_max_real(f.rig, f.k, speed_hz=50.0, chamber_pressure_pa=PC,
                                    config_ay_m=AY, exclude_above_hz=-1.0), "exclude_above_hz"),
    # -- open-loop schedule -------------------------------------------------------------------
    # issue: UFuncTypeError
    ("pressure_schedule p_max text", lambda f: _sched(f, p_max_pa="1e6"), "p_max_pa"),
    # issue: accepted (an all-NaN schedule)
    ("pressure_schedule p_min > p_max", lambda f: _sched(f, p_min_pa=0.6e6, p_max_pa=0.2e6),
     "p_min_pa"),
    ("pressure_schedule p_min nan", lambda f: _sched(f, p_min_pa=NAN), "p_min_pa"),
    ("pressure_schedule no grid pressure inside the limits",
     lambda f: _sched(f, pressures=[0.7e6, 0.8e6], p_max_pa=0.6e6), "pressures_pa"),
    # issue: ValueError "zero-size array"
    ("pressure_schedule unbalances []", lambda f: _sched(f, unbalances=[]), "unbalances"),
    ("pressure_schedule speeds nan", lambda f: _sched(f, speeds=[NAN]), "speeds_hz"),
    ("pressure_schedule speeds empty", lambda f: _sched(f, speeds=[]), "speeds_hz"),
    ("pressure_schedule speeds text", lambda f: _sched(f, speeds=["30", "40"]), "speeds_hz"),
    ("pressure_schedule pressures nan", lambda f: _sched(f, pressures=[NAN]), "pressures_pa"),
    ("pressure_schedule pressures negative", lambda f: _sched(f, pressures=[-1.0]),
     "pressures_pa"),
    ("pressure_schedule stations 99", lambda f: _sched(f, stations=[99]), "stations"),
    ("pressure_schedule stations empty", lambda f: _sched(f, stations=[]), "stations"),
    ("pressure_schedule stations text", lambda f: _sched(f, stations="ab"), "stations"),
    ("pressure_schedule min_damping 2", lambda f: _sched(f, min_damping=2.0), "min_damping"),
    ("pressure_schedule smooth -1", lambda f: _sched(f, smooth_pa_per_hz=-1.0),
     "smooth_pa_per_hz"),
    # issue: every grid point "error"
    ("pressure_schedule a_y without active bearing",
     lambda f: pressure_schedule(f.friswell, [(3, 1e-5, 0.0)], [30.0], [0.0],
                                 config_ay_m=0.0), "config_ay_m"),
    ("pressure_schedule system text",
     lambda f: pressure_schedule("paper-rig", UB, [30.0], [0.0]), "system"),
    # -- synchronous bound --------------------------------------------------------------------
    # issue: error rows
    ("synchronous_bound speeds nan", lambda f: _sync(f, speeds=[NAN]), "speeds_hz"),
    ("synchronous_bound pressures nan", lambda f: _sync(f, pressures=[NAN]), "pressures_pa"),
    ("synchronous_bound pressure above the valve", lambda f: _sync(f, pressures=[2e6]),
     "pressures_pa"),
    ("synchronous_bound stations 99", lambda f: _sync(f, stations=[99]), "stations"),
    ("synchronous_bound stations empty", lambda f: _sync(f, stations=[]), "stations"),
    ("synchronous_bound references 0", lambda f: _sync(f, references_m=[0.0]),
     "references_m"),
    ("synchronous_bound references text", lambda f: _sync(f, references_m="x"),
     "references_m"),
    ("synchronous_bound iters 5", lambda f: _sync(f, iters=5), "iters"),
    ("synchronous_bound actuator text", lambda f: _sync(f, actuator="valve"), "actuator"),
    ("synchronous_bound a_y nan", lambda f: _sync(f, config_ay_m=NAN), "config_ay_m"),
    ("minimise_semi_major limit -1",
     lambda f: minimise_semi_major(np.ones((1, 1, 2)), np.ones((1, 1, 2)), [-1.0]), "limit"),
    ("minimise_semi_major shape",
     lambda f: minimise_semi_major(np.ones((1, 2)), np.ones((1, 2)), [1.0]), "a, b"),
    ("minimise_semi_major iters 0",
     lambda f: minimise_semi_major(np.ones((1, 1, 2)), np.ones((1, 1, 2)), [1.0], iters=0),
     "iters"),
    # -- H-infinity (the checks come before slycot is needed) ---------------------------------
    ("hinf plant text", lambda f: hinf("p"), "plant"),
    ("hinf gamma_tol 0", lambda f: hinf(f.p, gamma_tol=0.0), "gamma_tol"),
    ("hinf disturbance -1", lambda f: hinf(f.p, disturbance_force_n=-1.0),
     "disturbance_force_n"),
    ("generalized_plant pressure_scale 1e-300",
     lambda f: generalized_plant(f.p, pressure_scale_pa=1e-300), "pressure_scale_pa"),
    ("lower_lft_response freqs text",
     lambda f: lower_lft_response(*generalized_plant(f.p)[:5],
                                  (np.zeros((0, 0)), np.zeros((0, 2)), np.zeros((1, 0)),
                                   np.zeros((1, 2))), "x"), "freqs_hz"),
    # -- operation: actuator, controller, profiles --------------------------------------------
    ("Actuator order True", lambda f: Actuator(order=True), "actuator.order"),
    ("Actuator natural frequency 1e300", lambda f: Actuator(natural_frequency_hz=1e300),
     "actuator.natural_frequency_hz"),
    ("Actuator damping text", lambda f: Actuator(damping="0.7"), "actuator.damping"),
    ("Actuator time constant nan (order 2)", lambda f: Actuator(time_constant_s=NAN),
     "actuator.time_constant_s"),
    ("Actuator p_min True", lambda f: Actuator(p_min_pa=True), "actuator.p_min_pa"),
    ("Actuator rate limit True", lambda f: Actuator(rate_limit_pa_s=True),
     "actuator.rate_limit_pa_s"),
    # issue 21 (fuzzing): integers beyond float64 were accepted, then an OverflowError
    ("Actuator p_max 10**400", lambda f: Actuator(p_max_pa=10**400), "actuator.p_max_pa"),
    ("Actuator rate limit 10**400", lambda f: Actuator(rate_limit_pa_s=10**400),
     "actuator.rate_limit_pa_s"),
    ("Controller sample time inf",
     lambda f: Controller.static([[1.0, 0.0]], [("journal", 0)], sample_time_s=INF),
     "controller.sample_time_s"),
    ("Controller sample time True",
     lambda f: Controller.static([[1.0, 0.0]], [("journal", 0)], sample_time_s=True),
     "controller.sample_time_s"),
    ("Controller noise_std -1",
     lambda f: Controller.static([[1.0, 0.0]], [("journal", 0)], noise_std=-1.0),
     "controller.noise_std"),
    ("Controller noise_std text",
     lambda f: Controller.static([[1.0, 0.0]], [("journal", 0)], noise_std="x"),
     "controller.noise_std"),
    ("Controller noise_std length",
     lambda f: Controller.static([[1.0, 0.0]], [("journal", 0)], noise_std=[1e-6] * 3),
     "controller.noise_std"),
    ("Controller noise_dt 1e-300",
     lambda f: Controller.static([[1.0, 0.0]], [("journal", 0)], noise_dt_s=1e-300),
     "controller.noise_dt_s"),
    ("Controller seed -1",
     lambda f: Controller.static([[1.0, 0.0]], [("journal", 0)], seed=-1), "controller.seed"),
    ("Controller name 5",
     lambda f: Controller.static([[1.0, 0.0]], [("journal", 0)], name=5), "controller.name"),
    ("Controller A text",
     lambda f: Controller("x", [[1.0, 0.0]], [[1.0]], [[0.0, 0.0]], [("journal", 0)]),
     "controller.A"),
    ("Controller gains text", lambda f: Controller.static([["a", "b"]], [("journal", 0)]),
     "controller.gains"),
    ("Controller measurement index text",
     lambda f: Controller.static([[1.0, 0.0]], [("journal", "0")]), "measurements"),
    ("Controller.scaled text", lambda f: f.k.scaled("2"), "gain"),
    ("Controller.with_options unknown", lambda f: f.k.with_options(sample_time=1e-4),
     "sample_time"),
    ("Controller.with_washout 0", lambda f: f.k.with_washout(0.0), "corner_hz"),
    ("SpeedProfile.constant nan", lambda f: SpeedProfile.constant(NAN), "speed_hz"),
    ("SpeedProfile.constant 1e9", lambda f: SpeedProfile.constant(1e9), "speed_hz"),
    ("SpeedProfile.ramp rate 1e-320", lambda f: SpeedProfile.ramp(10.0, 120.0, 1e-320),
     "rate_hz_per_s"),
    ("SpeedProfile.ramp start text", lambda f: SpeedProfile.ramp("10", 120.0, 1.0),
     "start_hz"),
    ("SpeedProfile.table text", lambda f: SpeedProfile.table(["0", "1"], [10.0, 20.0]),
     "speed_profile"),
    ("PressureSchedule.constant text", lambda f: PressureSchedule.constant("1e5"),
     "chamber_pressure_pa"),
    ("PressureSchedule.time_table text",
     lambda f: PressureSchedule.time_table([0.0, 1.0], ["1e5", "2e5"]), "chamber_pressure"),
    ("PressureSchedule.speed_table nan",
     lambda f: PressureSchedule.speed_table([10.0, 20.0], [1e5, NAN]), "chamber_pressure"),
    ("PressureSchedule.with_harmonic nan",
     lambda f: PressureSchedule.constant(1e5).with_harmonic(NAN, order=1), "amplitude_pa"),
]


@pytest.mark.parametrize(("call", "field"), [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_bad_control_input_is_an_input_error_naming_the_field(fx, call, field):
    with pytest.raises(rd.InputError, match=re.escape(field)):
        call(fx)


def test_messages_state_the_allowed_range(fx):
    """The message names the field and what is allowed, e.g. the matrix rule of Q."""
    with pytest.raises(rd.InputError, match=r"Q: expected a finite symmetric positive "
                                            r"semi-definite \(20, 20\) matrix, got nan"):
        lqr(fx.p, Q=np.full((fx.n, fx.n), NAN))
    with pytest.raises(rd.InputError, match=r"sample_time_s: expected a value in \[1e-07, 1.0\]"):
        fx.k.with_options(sample_time_s=1e-300)
    with pytest.raises(rd.InputError, match=r"disturbance_force_n: expected a value in "
                                            r"\[1e-09, 1000000000.0\]"):
        lqg(fx.p, disturbance_force_n=0)


def test_synchronous_bound_methods_check_their_arguments(fx):
    b = _sync(fx)
    assert b.status[0, 0] == "ok"
    with pytest.raises(rd.InputError, match="pressure_pa"):
        b.column("x")
    with pytest.raises(rd.InputError, match="min_damping"):
        b.best_over_pressures(min_damping="x")
    with pytest.raises(rd.InputError, match="references_m"):
        b.with_references([NAN])
    with pytest.raises(rd.InputError, match="iters"):
        b.with_references([1.0], iters=2.5)
    with pytest.raises(rd.InputError, match="pressure_pa"):
        b.harmonic_schedule(NAN)


def test_physical_sample_time_still_closes_the_sampled_loop(fx):
    """The new sample-time range keeps realistic laws: a static law sampled at 33 kHz or at
    the range's ends closes the loop with finite eigenvalues (1e-300 s gave max Re λ =
    8.5e300)."""
    k = Controller.static(fx.k.D, [("journal", 0)])
    for ts in (1e-7, 1.0 / 33e3, 1e-3, 1.0):
        cl = closed_loop(fx.p, k.with_options(sample_time_s=ts))
        assert cl.eigenvalues.size == fx.n and np.all(np.isfinite(cl.eigenvalues)), ts


# -- CLI ------------------------------------------------------------------------------------
def test_cli_schedule_refuses_a_y_without_active_bearing(tmp_path, capsys):
    """Issue: exit 0 with every grid point ``error``; the real error was swallowed."""
    rc = cli_main(["control", "schedule", "friswell-5.9.1", "--unbalance", "3", "1e-5", "0",
                   "--speed-hz", "10", "12", "1", "--pressure-pa", "0", "0", "1",
                   "--config-ay-m", "0.0", "--json", "--out", str(tmp_path / "s")])
    err = capsys.readouterr().err
    assert rc == 2 and "config_ay_m" in err and "active bearing" in err, err


@pytest.mark.parametrize("command", ["closed-loop", "schedule"])
def test_cli_checks_out_before_computing(tmp_path, capsys, monkeypatch, command):
    """Issue: ``--out`` was checked after the whole computation (14 s, then ``[Errno 2]``)."""
    import rotordyn.control.plant
    import rotordyn.control.schedule

    def no_solve(*a, **k):
        raise AssertionError("solved before checking --out")

    monkeypatch.setattr(rotordyn.control.plant, "plant", no_solve)
    monkeypatch.setattr(rotordyn.control.schedule, "pressure_schedule", no_solve)
    a_file = tmp_path / "file"
    a_file.write_text("x")
    extra = ["--unbalance", "6", "2e-5", "0"] if command == "schedule" else []
    rc = cli_main(["control", command, "paper-rig", *extra, "--out", str(a_file / "sub")])
    err = capsys.readouterr().err
    assert rc == 2 and "--out" in err, err


def test_cli_closed_loop_checks_its_flags_before_the_design(tmp_path, capsys, monkeypatch):
    import rotordyn.control.plant

    def no_solve(*a, **k):
        raise AssertionError("solved before checking the flags")

    monkeypatch.setattr(rotordyn.control.plant, "plant", no_solve)
    for flags, name in ((["--n-out", "1"], "n_out"), (["--disturbance-c", "nan"],
                                                      "--disturbance-c"),
                        (["--run-up-hz", "10", "120", "0"], "rate_hz_per_s"),
                        (["--unbalance", "99", "1e-5", "0"], "unbalance"),
                        (["--speed-hz", "nan"], "speed_hz")):
        rc = cli_main(["control", "closed-loop", "paper-rig", *flags,
                       "--out", str(tmp_path / "o")])
        err = capsys.readouterr().err
        assert rc == 2 and name in err, (flags, err)


def test_cli_schedule_json_writes_null_not_nan(tmp_path, capsys):
    """Issue: ``--json`` printed bare ``NaN`` (not JSON); now null. A margin no grid point
    meets leaves the best constant pressure and the peaks undefined."""
    rc = cli_main(["control", "schedule", "paper-rig", "--unbalance", "6", "2e-5", "0",
                   "--config-ay-m", "0", "--speed-hz", "34", "36", "2", "--pressure-pa",
                   "0.4e6", "0.6e6", "0.2e6", "--min-damping", "0.9", "--json",
                   "--out", str(tmp_path / "s")])
    out = capsys.readouterr().out
    assert rc == 0
    assert "NaN" not in out
    s = json.loads(out)
    assert s["best_constant_pa"] is None and s["peak_schedule_m"] is None
    assert s["speeds_without_feasible_pressure"] == 2


# -- discrete controller: sample instants meeting output times ------------------------------
@pytest.mark.parametrize(("sample_time_s", "t_end_s", "n_out"),
                         [(3e-5, 0.002, 401), (7e-5, 0.002, 401), (3e-6, 0.002, 401),
                          (1.0 / 33e3, 0.01, 2001)])
def test_discrete_controller_survives_sample_instants_on_output_times(fx, sample_time_s,
                                                                      t_end_s, n_out):
    """Issue: a sample instant k·T within round-off of an output time stopped the run with
    ``not_converged`` ("CV_TOO_CLOSE … tout too close to t0"): 3e-5, 7e-5 and 3e-6 s with the
    default output spacing (5 µs), and realistic 33 kHz sampling at t = 9 ms. The output
    times are moved onto the instants (by at most 1e-12 of the run) before the core runs."""
    k = Controller.static(fx.k.D, [("journal", 0)], sample_time_s=sample_time_s)
    tr = rd.transient(fx.rig, t_end_s, 50.0, PC, AY, controller=k, disturbance_m=(0.0, 3e-5),
                      n_out=n_out)
    assert tr.status == "ok", tr.message
    assert np.abs(tr.t - np.linspace(0.0, t_end_s, n_out)).max() <= 2e-12 * t_end_s
    assert np.all(np.isfinite(tr.journal_y_m))


def test_sample_aligned_outputs_meets_the_cores_instants_exactly():
    from rotordyn.analysis.transient import sample_aligned_outputs

    T = 3e-5
    t = np.linspace(0.0, 0.01, 2001)
    s = sample_aligned_outputs(t, T)
    k = np.rint(t / T)
    hit = np.isclose(t, k * T, rtol=0, atol=1e-15) & (k >= 1)
    assert hit.sum() == 333
    assert np.array_equal(s[hit], k[hit] * T)  # double(k) * T, as cpp/src/transient.cpp
    assert np.array_equal(s[~hit], t[~hit]) and np.all(np.diff(s) > 0)
    assert np.abs(s - t).max() <= 1e-12 * 0.01 + 1e-9 * T


def test_remaining_options_are_checked(fx):
    """Options passed through ``**kw`` and ignored arguments: an InputError naming them
    (a TypeError from the dataclass, or silently ignored, before)."""
    with pytest.raises(rd.InputError, match="sampletime"):
        Controller.static([[1.0, 0.0]], [("journal", 0)], sampletime=1e-4)
    import control

    with pytest.raises(rd.InputError, match="noise"):
        Controller.from_lti(control.ss([], [], [], [[1.0, 0.0]]), [("journal", 0)], noise=1.0)
    b = _sync(fx)
    with pytest.raises(rd.InputError, match="speeds_hz"):
        b.harmonic_schedule(0.5e6, speeds_hz=[38.5])
    assert plant(fx.rig, 50.0, PC, AY, disturbance_stations=np.array([], int)).Bd.shape[1] == 0


def test_lqr_never_returns_an_unstable_design(fx):
    """Issue 21 (fuzzing): R = 1e-300 is positive definite, but the Riccati solution is lost
    to round-off and the 'optimal' closed loop had max Re λ = 8e268: a ConvergenceError now."""
    with pytest.raises(rd.ConvergenceError, match="lqr: the closed loop"):
        lqr(fx.p, R=1e-300)
    K, eig = lqr(fx.p)
    assert np.all(eig.real < 0)
