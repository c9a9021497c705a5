"""Nonlinear transient of the system (paper eq. 12) with SUNDIALS CVODE: free response from a
disturbed equilibrium (orbits, limit cycles, paper Fig. 11) and unbalance response (the
waterfall of Fig. 13 is a set of these at increasing speeds)."""

from __future__ import annotations

import math

from rotordyn._common.threads import limited_blas

import numpy as np

from rotordyn import _core
from rotordyn.analysis.assembly import assembled, chamber_pressure
from rotordyn.analysis.equilibrium import equilibrium
from rotordyn.analysis.measurement import measurement_matrix
from rotordyn.errors import ConvergenceError, InputError
from rotordyn._common import validate as v
from rotordyn.model.system import System
from rotordyn.operation import Actuator, Controller, PressureSchedule, SpeedProfile
from rotordyn.results.equilibrium import CONVERGED
from rotordyn.results.transient import TransientResult
from rotordyn.units import hz_to_rad_s, rad_s_to_hz


# Output times this close to a discrete controller's sample instant k·T are moved onto it:
# CVODE refuses to step across a gap of a few ulps ("CV_TOO_CLOSE: tout too close to t0"),
# and a gap just above that is meaningless. The tolerance is far above the round-off of
# linspace and of k·T (≈ 1e-16 t) and far below any sample period (≥ 1e-7 s).
SAMPLE_SNAP_REL = 1e-12   # of the run's length
SAMPLE_SNAP_PERIOD = 1e-9  # of the sample time


def sample_aligned_outputs(t_out: np.ndarray, sample_time_s: float,
                           delay_s: float = 0.0) -> np.ndarray:
    """``t_out`` with every time within ``SAMPLE_SNAP_REL·t_end + SAMPLE_SNAP_PERIOD·T`` of a
    sample instant k·T (k ≥ 1) replaced by that instant, computed as the C++ core does
    (``double(k) * T``, bit for bit), so the core meets the two at exactly the same time
    and never steps across a round-off gap; with a computation delay τ > 0 the same for the
    instants k·T + τ where the commands are applied (``double(k) * T + τ``, or the next
    sample when within 1e-9 T of it, as the core does). Times stay strictly increasing (else
    unchanged)."""
    T = float(sample_time_s)
    t_out = np.asarray(t_out, dtype=float)
    k = np.rint(t_out / T)
    ts = k * T
    tol = SAMPLE_SNAP_REL * float(t_out[-1]) + SAMPLE_SNAP_PERIOD * T
    snapped = np.where((k >= 1) & (np.abs(t_out - ts) <= tol), ts, t_out)
    tau = float(delay_s)
    if tau > 0:
        ka = np.floor((snapped - tau) / T + 0.5)
        ta = ka * T + tau
        nxt = (ka + 1) * T
        ta = np.where(nxt - ta <= 1e-9 * T, nxt, ta)
        snapped = np.where((ka >= 0) & (np.abs(snapped - ta) <= tol), ta, snapped)
    if snapped.size > 1 and np.any(np.diff(snapped) <= 0):
        return t_out
    return snapped


# A discrete controller stops CVODE at every sample and restarts it (CVodeReInit: order 1, a
# fresh step size, a new Jacobian): the run costs about this much per sample whatever the
# rotor does. Measured on the paper rig (issue 21; docs/control.md §1, "Budget of a run") on
# the shared 2-core development machine at load ≈ 5: 0.43 ms per sample at T = 1e-4 s and
# 1e-5 s, 0.67-0.68 ms at 1e-6 s and 1e-7 s (two CVODE steps per sample).
DISCRETE_SAMPLE_COST_S = 5e-4
MAX_COST_S = 600.0  # default budget of an estimated run cost (10 min); math.inf: no limit


def _duration(s: float) -> str:
    return f"{s / 3600:.3g} h" if s >= 3600 else (f"{s / 60:.3g} min" if s >= 60 else f"{s:.3g} s")


def controller_budget(controller: Controller, t_end_s: float, max_cost_s: float) -> None:
    """Refuse, before anything is allocated or solved, a controller whose sensor-noise table
    (samples × signals × 8 B, built in C++ before the first step) exceeds the shared memory
    limit, or a discrete one whose estimated cost (samples × ``DISCRETE_SAMPLE_COST_S``)
    exceeds ``max_cost_s``; each error names the field and gives the estimate."""
    T = controller.sample_time_s
    noise = np.asarray(controller.noise_std, dtype=float)
    if np.any(noise > 0):
        dt, name = (T, "sample_time_s") if controller.discrete else \
            (controller.noise_dt_s, "noise_dt_s")
        rows = math.ceil(t_end_s / dt) + 2
        ny = controller.n_inputs
        v.memory(f"controller.{name} (the sensor-noise table, {rows:.3g} samples of "
                 f"t_end_s / {name} = {t_end_s:g} s / {dt:g} s × {ny} signals × 8 B)",
                 8.0 * rows * ny)
    if controller.discrete:
        n = t_end_s / T
        # a computation delay applies each command at kT + τ: a second restart per sample
        est = n * DISCRETE_SAMPLE_COST_S * (2 if controller.computation_delay_s else 1)
        if est > max_cost_s:
            raise InputError(
                f"controller.sample_time_s: t_end_s / sample_time_s = {t_end_s:g} s / {T:g} s "
                f"= {n:.3g} samples, each a CVODE restart (about "
                f"{DISCRETE_SAMPLE_COST_S * 1e3:.2g} ms): an estimated {_duration(est)}, above "
                f"max_cost_s = {max_cost_s:g} s; use a longer sample time or a shorter run, or "
                "pass max_cost_s=math.inf to run it anyway")


@limited_blas
def transient(system: System, t_end_s: float, speed_hz: float = 50.0,
              chamber_pressure_pa: float = 0.0, config_ay_m: float | None = None, *,
              unbalances=(), disturbance_m=(0.0, 0.0), r0=None, v0=None,
              n_out: int = 2001, rtol: float = 1e-6, atol_m: float = 1e-9,
              max_steps: int = 500000, speed=None, pressure=None, actuator=None,
              controller=None, measurements=None, measurement_offset=None,
              atol_pa: float = 1.0,
              max_step_s: float = 0.0, rub_fraction: float = 1e-3,
              max_cost_s: float = MAX_COST_S, adaptive=None,
              record_film_moments: bool = True,
              bdf_max_order: int = 5) -> TransientResult:
    """Integrate eq. 12 from t = 0 to ``t_end_s``.

    The start is the static equilibrium (eq. 14) with the journal of the active bearing (with
    none, of the first bearing, ``bearings[0]``) displaced by ``disturbance_m`` = (dx, dy),
    unless ``r0``/``v0`` are given (to disturb another journal, give ``r0``).
    ``unbalances``: [(station, mass_kg_m, phase_deg)] rotating with the rotor; with a
    varying speed the force is m e (Ω² e_r − Ω̇ e_t) at the rotor angle θ = ∫Ω dt (radial
    and tangential, the tangential one from the angular acceleration). Output at ``n_out``
    uniformly spaced times (with a discrete controller, a time within round-off of a sample
    instant k·T is that instant: :func:`sample_aligned_outputs`). A failure returns the rows reached (NaN after) with a ``status``:
    ``"rub"`` when the journal reached the bush — a film thinner than ``rub_fraction`` of its
    clearance (default 1e-3: below any real surface finish; checked after every step), or a
    closed film CVODE could not step past — ``"not_converged"`` when CVODE gave up (its flag
    name in ``message``); ``"ok"``, or ``"contact"`` for a completed run that started from a
    contact equilibrium. A start whose film is already closed is an ``InputError``.

    Time-varying operation (:mod:`rotordyn.control`): ``speed`` a
    :class:`~rotordyn.control.SpeedProfile` (replaces ``speed_hz``; the equilibrium is taken
    at its speed at t = 0); ``pressure`` a :class:`~rotordyn.control.PressureSchedule`
    (replaces ``chamber_pressure_pa``); ``actuator`` an :class:`~rotordyn.control.Actuator`
    (default: none, p_c = command without limits); ``controller`` a
    :class:`~rotordyn.control.Controller`, or a python-control ``StateSpace``/
    ``TransferFunction`` together with ``measurements`` (its inputs, in order), whose output is
    added to the command; the measurements are taken relative to ``measurement_offset``
    (default: their value at the starting equilibrium). ``atol_pa``: absolute tolerance of the actuator
    pressure state.

    ``adaptive``: an :class:`~rotordyn.control.adaptive.AdaptiveRejection` — an adaptive 1×
    command (two more CVODE states, the coefficient P of Re(P e^{iθ})) added to the command;
    its measurements relative to their value at the starting equilibrium. Its speed grid
    must cover the run (InputError naming ``adaptive.speeds_hz``).

    Tilting films (``tilt = true``): the result carries the journal's rotations at their
    bearings and, with ``record_film_moments`` (default), the films' moments at every output
    (one more film solve per output after the run; False: no moments, no extra solve).

    ``bdf_max_order`` (1–5, default 5): the highest BDF order CVODE may use. A model with
    many lightly damped modes far above the motion's frequencies (an unreduced rotor without
    material damping: free bending modes at 9–12 kHz, Re λ ≈ -0.01 1/s) sits outside the
    stability region of orders 3–5; CVODE's stability-limit detection then lowers the order
    again and again (``stats["stab_lim_order_reductions"]``) with error-test failures and tiny
    steps. Order 2 is A-stable: on a 4.3 t turbine rotor without reduction, 10 revolutions at
    55 Hz took 45,621 steps (16 s CPU) at order 5 and 1,130 steps (0.44 s) at order 2, and the
    order-2 run was closer to a tight reference (docs/transient-and-sweeps.md). On a reduced or
    film-damped model keep 5 (the paper rig: order 2 costs 9 % more right-hand sides and is 6×
    less accurate at equal tolerance).

    Budget (checked before anything is solved): a discrete controller restarts CVODE at each
    sample; a run estimated above ``max_cost_s`` (default 600 s; ``math.inf``: no limit) is an
    ``InputError`` naming ``controller.sample_time_s`` and ``t_end_s`` with the estimate. The
    sensor-noise table is under the shared memory limit.
    """
    if speed is not None:
        if not isinstance(speed, SpeedProfile):
            raise InputError(f"speed: expected a rotordyn.control.SpeedProfile, got "
                             f"{type(speed).__name__}")
        speed_hz = float(speed.speed_hz[0]) if speed.t_s[0] <= 0 else float(speed.speed_at(0.0))
    if pressure is not None:
        if not isinstance(pressure, PressureSchedule):
            raise InputError(f"pressure: expected a rotordyn.control.PressureSchedule, got "
                             f"{type(pressure).__name__}")
        if pressure.kind == "time_table":
            chamber_pressure_pa = float(np.interp(0.0, pressure.x, pressure.p_pa))
        elif pressure.kind == "speed_table":
            chamber_pressure_pa = float(np.interp(speed_hz, pressure.x, pressure.p_pa))
        else:
            chamber_pressure_pa = pressure.value_pa
    if actuator is not None and not isinstance(actuator, Actuator):
        raise InputError(f"actuator: expected a rotordyn.control.Actuator, got "
                         f"{type(actuator).__name__}")
    if controller is not None and not isinstance(controller, Controller) \
            and type(controller).__module__.startswith("control."):
        if measurements is None:
            raise InputError("measurements: a python-control controller needs the list of "
                             "measurements it reads, e.g. [('journal', 0)]")
        controller = Controller.from_lti(controller, measurements)
    if controller is not None and not isinstance(controller, Controller):
        raise InputError(f"controller: expected a rotordyn.control.Controller (use "
                         f"Controller.from_lti for a python-control system), got "
                         f"{type(controller).__name__}")
    v.positive("atol_pa", atol_pa)
    v.non_negative("max_step_s", max_step_s)
    v.positive("t_end_s", t_end_s)
    v.speed("speed_hz", speed_hz)
    chamber_pressure(system, chamber_pressure_pa)
    v.integer("n_out", n_out, lo=2)
    v.in_range("rtol", rtol, 1e-14, 0.1, hi_open=True)
    v.in_range("rub_fraction", rub_fraction, 0.0, 1.0, hi_open=True)
    v.integer("bdf_max_order", bdf_max_order, lo=1, hi=5)
    v.positive("atol_m", atol_m)
    v.integer("max_steps", max_steps, lo=1)
    if not isinstance(record_film_moments, (bool, np.bool_)):  # before any solve
        raise InputError(f"record_film_moments: expected True or False, got "
                         f"{record_film_moments!r}")
    if config_ay_m is not None:
        v.finite("config_ay_m", config_ay_m)
    if not (isinstance(max_cost_s, (float, np.floating)) and max_cost_s == math.inf):
        max_cost_s = v.positive("max_cost_s", max_cost_s)
    sp_run = (np.concatenate([speed.speed_at(np.array([0.0, float(t_end_s)])),
                              speed.speed_hz[(speed.t_s > 0) & (speed.t_s < float(t_end_s))]])
              if speed is not None else np.array([float(speed_hz)]))
    if adaptive is not None:
        from rotordyn.operation.adaptive import AdaptiveRejection

        if not isinstance(adaptive, AdaptiveRejection):
            raise InputError(f"adaptive: expected a rotordyn.control.adaptive."
                             f"AdaptiveRejection, got {type(adaptive).__name__}")
        adaptive.check_covers(float(sp_run.min()), float(sp_run.max()))
    if controller is not None:
        controller_budget(controller, float(t_end_s), float(max_cost_s))
        if controller.schedule_law is not None:
            from rotordyn.operation.controller import check_schedule_covers as check_covers

            check_covers(controller, float(sp_run.min()), float(sp_run.max()))
    asm = assembled(system)
    n = asm.n
    # Output arrays t, r, v, h_min in C++ and their numpy copies: refuse before allocating
    # (issue 13: n_out=10**7).
    v.memory("n_out", 2 * 8.0 * n_out * (2 * n + len(asm.bearings) + 1))
    ub_list = v.unbalances("unbalances", unbalances, system.rotor.n_stations)
    dx, dy = v.vector("disturbance_m", disturbance_m, 2)
    a = asm.config_vector(config_ay_m)
    start_status, start_note = "ok", ""
    if r0 is None:
        # From the concentric start (no warm start): a run beyond the threshold amplifies a
        # round-off difference in its starting point, so the start must not depend on what
        # this thread solved before (issue 13: same inputs, same answer, bit for bit).
        e = equilibrium(system, speed_hz, chamber_pressure_pa, config_ay_m, warm_start=False)
        if e.status not in CONVERGED:
            raise ConvergenceError(f"transient: no equilibrium to start from ({e.status}: "
                                   f"{e.message}); give r0")
        if e.status == "contact":  # the result says it started from a contact equilibrium
            start_status, start_note = "contact", f"started from a contact equilibrium: {e.message}"
        r_eq = e.r.copy()
        r_init = r_eq.copy()
        targets = [bc for bc in asm.bearings if bc.active] or asm.bearings[:1]
        if (dx or dy) and not targets:
            raise InputError("disturbance_m: the system has no journal bearing to disturb")
        for bc in targets[:1]:
            r_init[bc.jx] += dx
            r_init[bc.jy] += dy
    else:
        r_init = v.vector("r0", r0, n)
        r_eq = r_init.copy()
    v_init = np.zeros(n) if v0 is None else v.vector("v0", v0, n)
    h0 = np.asarray(asm.solver.film_h_min(r_init), dtype=float)
    if np.any(h0 <= 0):
        k = int(np.argmin(h0))
        field = "disturbance_m" if r0 is None else "r0"
        raise InputError(f"{field}: the start closes film '{asm.model.films[k].name}' "
                         f"(minimum film thickness {h0[k]:.3g} m): the journal would start "
                         "inside the bush")

    uc, us = np.zeros(n), np.zeros(n)
    for st, me, ph in ub_list:
        L = asm.station_load_matrix(st)
        p = np.radians(ph)
        # F = m e Ω² (cos(Ωt + p), sin(Ωt + p)) = Ω² (u_c cos Ωt + u_s sin Ωt)
        uc += me * (L[:, 0] * np.cos(p) + L[:, 1] * np.sin(p))
        us += me * (-L[:, 0] * np.sin(p) + L[:, 1] * np.cos(p))

    inp = _core.TransientInput()
    inp.omega = hz_to_rad_s(float(speed_hz))
    inp.chamber_pressure = float(chamber_pressure_pa)
    inp.a = a
    inp.unbalance_cos, inp.unbalance_sin = (uc, us) if ub_list else (np.zeros(0), np.zeros(0))
    inp.r0, inp.v0 = r_init, v_init
    inp.t_out = np.linspace(0.0, float(t_end_s), int(n_out))
    if controller is not None and controller.discrete:
        inp.t_out = sample_aligned_outputs(inp.t_out, controller.sample_time_s,
                                           controller.computation_delay_s)
    opt = _core.CvodeOptions()
    opt.rtol, opt.atol_position = float(rtol), float(atol_m)
    opt.atol_velocity = float(atol_m) * max(hz_to_rad_s(abs(float(speed_hz))), 1.0)
    opt.max_steps = int(max_steps)
    opt.atol_pressure = float(atol_pa)
    opt.atol_controller = float(atol_m)
    opt.max_step = float(max_step_s)
    opt.rub_fraction = float(rub_fraction)
    opt.max_order = int(bdf_max_order)
    if speed is not None:
        inp.speed = speed.to_core()
    if pressure is not None:
        inp.pressure = pressure.to_core()
    if actuator is not None:
        inp.actuator = actuator.to_core()
    if controller is not None:
        Cm, _ = measurement_matrix(system, controller.measurements)
        if measurement_offset is None:
            off = Cm @ np.concatenate([r_eq, np.zeros(n)])
        else:
            off = np.asarray(measurement_offset, dtype=float)
            if off.shape != (Cm.shape[0],) or not np.all(np.isfinite(off)):
                raise InputError(f"measurement_offset: expected {Cm.shape[0]} finite values")
        inp.controller = controller.to_core(Cm, off)
    if adaptive is not None:
        Cm, _ = measurement_matrix(system, adaptive.measurements)
        inp.adaptive = adaptive.to_core(Cm, Cm @ np.concatenate([r_eq, np.zeros(n)]))
    tb = [bc for bc in asm.bearings if bc.rot]  # tilting films: their moments recorded
    inp.record_film_force = [j for bc in tb for j in bc.rot[:2]] if record_film_moments else []
    res = _core.integrate(asm.solver, inp, opt)
    r = np.asarray(res.r)
    status, message = res.status, res.message
    if status == "ok" and not (np.all(np.isfinite(r)) and np.all(np.isfinite(res.v))):
        status, message = "error", "non-finite state in an integration reported as ok"
    bcs = asm.bearings
    return TransientResult(
        speed_hz=float(speed_hz), chamber_pressure_pa=float(chamber_pressure_pa),
        config_ay_m=float(a[bcs[0].jy]) if bcs else 0.0,
        t=np.asarray(res.t), r=r, v=np.asarray(res.v),
        journal_x_m=r[:, [bc.jx for bc in bcs]], journal_y_m=r[:, [bc.jy for bc in bcs]],
        clearance_m=np.array([bc.clearance_m for bc in bcs]),
        h_min_m=asm.bearing_h_min(np.asarray(res.h_min)),
        bearing_names=tuple(bc.name for bc in bcs),
        speed_hz_t=rad_s_to_hz(np.asarray(res.speed)), angle_rad=np.asarray(res.angle),
        chamber_pressure_command_pa=np.asarray(res.pc_command),
        chamber_pressure_actual_pa=np.asarray(res.pc),
        controller_output_pa=np.asarray(res.controller_output),
        actuator_states=np.asarray(res.actuator_states),
        controller_states=np.asarray(res.controller_states),
        adaptive_states=np.asarray(res.adaptive_states),
        **_tilt_histories(bcs, r, np.asarray(res.film_force)),
        equilibrium_r=r_eq,
        stats={"steps": res.steps, "rhs_evals": res.rhs_evals, "jac_evals": res.jac_evals,
               "newton_fails": res.newton_fails, "error_test_fails": res.error_test_fails,
               "linear_setups": res.linear_setups, "newton_iters": res.newton_iters,
               "stab_lim_order_reductions": res.stab_lim_order_reductions,
               "reynolds_solves": res.reynolds_solves,
               "reynolds_iterations": res.reynolds_iterations},
        status=start_status if status == "ok" else status,
        message="; ".join(m for m in (start_note, message) if m))


def _tilt_histories(bcs, r, ff) -> dict:
    """The tilting films' journal rotations relative to the housing (rad) and moments on the
    journal (N·m) at each output, (n_t, n_bearings), NaN for a bearing without a tilting film
    (``ff``: the core's recorded H at the rotations, in bearing order; no columns: not
    recorded, no moments); {} without a tilting film."""
    if not any(bc.rot for bc in bcs):
        return {}
    nt = r.shape[0]
    names = ("journal_theta_x_rad", "journal_theta_y_rad")
    if ff.shape[1]:  # recorded (not with record_film_moments=False)
        names += ("film_moment_x_n_m", "film_moment_y_n_m")
    out = {k: np.full((nt, len(bcs)), np.nan) for k in names}
    q = 0
    for b, bc in enumerate(bcs):
        if not bc.rot:
            continue
        out["journal_theta_x_rad"][:, b] = r[:, bc.rot[0]]
        out["journal_theta_y_rad"][:, b] = r[:, bc.rot[1]]
        if ff.shape[1]:
            out["film_moment_x_n_m"][:, b] = ff[:, q]
            out["film_moment_y_n_m"][:, b] = ff[:, q + 1]
        q += 2
    return out
