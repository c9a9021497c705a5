"""Fuzz cases of issue 21 (tests/test_fuzz.py runs them in the same worker process as
tests/fuzz_cases.py): control-law synthesis (``rotordyn.control``) on a cached linear plant
of the paper rig, the sweep spec loader (``SweepSpec.from_toml``), and the bearing elements'
file paths (a ``[[bearing]]`` table of a model TOML, ``TableBearing.from_csv``).

Each returns the list of violations of a result (non-finite or untruthful parts); a
rotordyn error is judged by ``fuzz_cases.run_case`` (an ``InputError`` must name a field).
"""

from __future__ import annotations

import math
import os
import tempfile

import numpy as np

_cache: dict = {}
AY = -1.85e-3


def _finite(name, x, violations):
    arr = np.asarray(x)
    if arr.dtype == object or not np.all(np.isfinite(arr)):
        violations.append(f"{name} is not finite: {x!r:.200}")


def _plant():
    """The rig's plant at the unstable point (50 Hz, 0.05 MPa, a_y = −1.85 mm), built once."""
    import rotordyn as rd
    from rotordyn.control import plant

    if "plant" not in _cache:
        _cache["plant"] = plant.plant(rd.models.paper_rig(), 50.0, 0.05e6, AY)
    return _cache["plant"]


def _check_closed_loop(cl, v):
    _finite("eigenvalues", cl.eigenvalues, v)
    if cl.stable != bool(np.all(cl.eigenvalues.real < 0)):
        v.append(f"stable={cl.stable} disagrees with the eigenvalues")
    if cl.stable != (cl.margins is not None):
        v.append(f"margins {'missing' if cl.stable else 'given'} for a "
                 f"{'stable' if cl.stable else 'unstable'} loop ({cl.margins_message})")
    for name in ("gain_margin_lower", "gain_margin_upper", "phase_margin_deg",
                 "peak_sensitivity", "delay_margin_s", "disk_margin"):
        x = getattr(cl, name)
        if cl.stable and math.isnan(x):
            v.append(f"{name} is NaN for a stable loop")


def control(p: dict) -> list:
    """One call of the control API with fuzzed arguments; a controller that comes back is
    closed on the plant (eigenvalues finite, ``stable`` agrees with them)."""
    import rotordyn as rd
    from rotordyn.control import (Actuator, Controller, PressureSchedule, SpeedProfile,
                                  closedloop, lqr, pid, plant, reduction)

    v: list = []
    call, a = p["call"], p["args"]
    if call == "plant":
        pl = plant.plant(rd.models.paper_rig(), a["speed_hz"], a["chamber_pressure_pa"],
                         a["config_ay_m"], measurements=a["measurements"],
                         actuator=Actuator(**a["actuator"]),
                         disturbance_stations=a["disturbance_stations"])
        for name in ("A", "B", "C", "Bd"):
            _finite(name, getattr(pl, name), v)
        return v
    if call == "actuator":
        act = Actuator(**a)
        _finite("actuator statespace", np.concatenate(
            [np.ravel(m) for m in act.statespace()]) if act.order else 0.0, v)
        return v
    if call == "profiles":
        if a["kind"] == "ramp":
            s = SpeedProfile.ramp(*a["values"])
            _finite("speed", s.speed_at(np.linspace(0.0, 10.0, 5)), v)
        elif a["kind"] == "table":
            s = SpeedProfile.table(*a["values"])
            _finite("speed", s.speed_at(np.linspace(0.0, 10.0, 5)), v)
        elif a["kind"] == "time_table":
            PressureSchedule.time_table(*a["values"])
        else:
            PressureSchedule.constant(a["values"][0]).with_harmonic(
                a["values"][1], **a["harmonic"])
        return v
    if call == "transient":  # the operation pieces in the nonlinear loop
        act = Actuator(**a["actuator"])
        sched = PressureSchedule.constant(a["pressure_pa"]).with_harmonic(
            a["amplitude_pa"], frequency_hz=a["frequency_hz"])
        k = None
        if a["law"] == "pid":
            k = pid.pid(3.7e8, -5.9e5)
        elif a["law"] == "discrete":
            k = Controller.static([[-3.7e8, 0.0]], [("journal", 0)],
                                  sample_time_s=a["sample_time_s"], noise_std=a["noise_std"])
        tr = rd.transient(rd.models.paper_rig(), a["t_end_s"], 50.0, 0.05e6, AY,
                          disturbance_m=(0.0, 3e-5), actuator=act, pressure=sched,
                          controller=k, n_out=41)
        if tr.status in ("ok", "contact"):
            _finite("r", tr.r, v)
            pc = tr.chamber_pressure_actual_pa
            _finite("p_c", pc, v)
            if np.any(pc < act.p_min_pa) or np.any(pc > act.p_max_pa):
                v.append(f"p_c outside [{act.p_min_pa}, {act.p_max_pa}]: "
                         f"{pc.min()}..{pc.max()}")
            if act.order and math.isfinite(act.rate_limit_pa_s):
                over = np.abs(np.diff(pc)) - act.rate_limit_pa_s * np.diff(tr.t)
                if over.max() > 1e-3 + 1e-9 * np.abs(pc).max():
                    v.append(f"rate limit exceeded by {over.max()} Pa")
        elif not tr.message:
            v.append(f"transient status {tr.status} without a message")
        return v
    pl = _plant()
    if call == "lqr":
        k, eig = lqr.lqr(pl, a.get("Q"), a.get("R"), **a["kw"])
        _finite("K", k, v)
        _finite("closed-loop eigenvalues", eig, v)
        if np.any(np.asarray(eig).real >= 0):
            v.append(f"LQR closed loop not stable: max Re {np.max(np.asarray(eig).real)}")
        return v
    if call == "lqg":
        k = lqr.lqg(pl, **a["kw"])
        _check_closed_loop(closedloop.closed_loop(pl, k), v)
        return v
    if call == "pid":
        k = pid.pid(*a["gains"], **a["kw"])
        _check_closed_loop(closedloop.closed_loop(pl, k, freqs_hz=a.get("freqs_hz")), v)
        return v
    if call == "controller":
        k = Controller(a["A"], a["B"], a["C"], a["D"], [("journal", 0)], **a["kw"])
        _check_closed_loop(closedloop.closed_loop(pl, k), v)
        return v
    if call == "modal":
        pr, info = reduction.modal_truncation(pl, a["max_frequency_hz"], **a["kw"])
    else:
        pr, info = reduction.balanced_truncation(pl, a["order"], **a["kw"])
    for name in ("A", "B", "C", "Bd"):
        _finite(name, getattr(pr, name), v)
    for key, x in info.items():
        if isinstance(x, float) and math.isnan(x):
            v.append(f"info[{key!r}] is NaN")
    return v


def spec(p: dict) -> list:
    """Load a (mutated) sweep spec; one that loads has a finite grid of the stated size."""
    from rotordyn.sweep.spec import SweepSpec

    v: list = []
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "spec.toml")
        with open(path, "w", encoding="utf-8") as fh:
            fh.write(p["text"])
        s = SweepSpec.from_toml(path, check_model=p["check_model"])
    n = s.n_points
    if not (isinstance(n, int) and n >= 1):
        v.append(f"n_points {n!r}")
    for name, vals in s.axes.items():
        if name.startswith("options.") or not vals:
            continue
        if not all(isinstance(x, (int, float)) and math.isfinite(x) for x in vals):
            v.append(f"axis {name} has non-finite values: {vals[:5]!r}")
    if n <= 2000:
        got = sum(1 for _ in s.points())
        if got != n:
            v.append(f"points() gave {got} points, n_points says {n}")
    return v


def element_file(p: dict) -> list:
    """A bearing element through its file path: a model TOML whose ``[[bearing]]`` table is
    fuzzed (it must round-trip and its coefficients at one speed are finite), or a table
    bearing's CSV."""
    import rotordyn as rd
    from rotordyn.bearings import TableBearing

    v: list = []
    if p["path"] == "csv":
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "table.csv")
            with open(path, "wb") as fh:
                fh.write(p["data"])
            b = TableBearing.from_csv(path, station=p["station"], extrapolate=p["extrapolate"])
        K, C = b.coefficients(p["speed_hz"])[:2]
        _finite("K", K, v)
        _finite("C", C, v)
        if b.has_mass:
            _finite("M", b.mass(p["speed_hz"]), v)
        return v
    s = rd.System.from_toml(p["text"], is_text=True)
    back = rd.System.from_toml(s.to_toml(), is_text=True)
    if back != s:
        v.append("to_toml round trip changed the model")
    if p.get("solve"):
        b = s.bearings[-1]
        if hasattr(b, "coefficient_table"):
            tab = b.coefficient_table([p["speed_hz"]], (0.0, -200.0))
            for i, stt in enumerate(tab.status):
                if stt in ("ok", "contact"):
                    _finite(f"K[{i}]", tab.K[i], v)
                    _finite(f"C[{i}]", tab.C[i], v)
                elif not tab.message[i]:
                    v.append(f"row {i} status {stt} without a message")
    return v


CASES = {"control": control, "spec": spec, "element_file": element_file}
