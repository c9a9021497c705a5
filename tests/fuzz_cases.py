"""Cases of the property-based fuzz suite (tests/test_fuzz.py), run in a worker process so
that a crash (segfault, abort) or a hang of one case fails that case instead of the test run.

Each case returns a dict ``{"outcome": ..., "detail": ..., "violations": [...]}`` with
outcome ``"result"`` (a result came back; ``violations`` lists every untruthful or
non-finite part of it), ``"rotordyn"`` (a RotordynError; ``violations`` is non-empty when an
InputError's message names no field) or ``"bug"`` (any other exception: a traceback a user
would see). The worker adds ``"hang"`` (no answer within the per-case timeout) and
``"crash"`` (the process died).
"""

from __future__ import annotations

import contextlib
import io
import math
import multiprocessing as mp
import os
import re
import traceback

import numpy as np

CASE_TIMEOUT_S = float(os.environ.get("ROTORDYN_FUZZ_CASE_TIMEOUT", "60"))
# "field: expected ..." or "field: message": an InputError names what was wrong first.
_FIELD = re.compile(r"^[^:\n]{1,160}:\s")

_cache: dict = {}


def _rig():
    import rotordyn as rd

    if "rig" not in _cache:
        _cache["rig"] = rd.models.paper_rig()
    return _cache["rig"]


def _finite(name, x, violations):
    arr = np.asarray(x)
    if arr.dtype == object or not np.all(np.isfinite(arr)):
        violations.append(f"{name} is not finite: {x!r:.200}")


# -- cases --------------------------------------------------------------------------------
def bearing(p: dict) -> list:
    """JournalBearing(**geometry).<call>(**args)."""
    import rotordyn as rd

    v: list = []
    b = rd.JournalBearing(**p["geometry"])
    call = p["call"]
    out = getattr(b, call)(**p["args"])
    if call == "forces":
        _finite("force", out, v)
    elif call == "coefficients":
        _finite("K", out[0], v)
        _finite("C", out[1], v)
    elif call == "solve":
        _finite("force", out.force_n, v)
        _finite("h_min", out.h_min_m, v)
        if not out.h_min_m > 0:
            v.append(f"solve returned h_min {out.h_min_m} <= 0 without an error")
    elif call == "static_equilibrium":
        if out.status == "ok":
            for name in ("x_m", "y_m", "force_n", "residual_rel", "eccentricity_ratio"):
                _finite(name, getattr(out, name), v)
            if not out.eccentricity_ratio < 1:
                v.append(f"equilibrium outside the clearance: eps {out.eccentricity_ratio}")
            if out.residual_rel > max(10 * p["args"].get("rtol", 1e-10), 1e-6):
                v.append(f"status ok with residual {out.residual_rel}")
    return v


def system(p: dict) -> list:
    """An analysis of the paper rig at one operating point, checked for a truthful status."""
    import rotordyn as rd
    from rotordyn.results.equilibrium import CONVERGED

    v: list = []
    rig = _rig()
    a = p["analysis"]
    op = p["op"]
    if a == "equilibrium":
        e = rd.equilibrium(rig, *op, **p.get("kw", {}))
        if e.status in CONVERGED:
            _finite("r", e.r, v)
            _finite("film_force", e.film_force_n, v)
            _finite("h_min", e.h_min_m, v)
            tol = p.get("kw", {}).get("tol", 1e-10)
            if not e.residual < tol * 1.0000001:
                v.append(f"{e.status} with residual {e.residual} >= tol {tol}")
            thin = bool(np.any(e.h_min_m < p.get("kw", {}).get("contact_fraction", 0.02)
                               * e.clearance_m))
            if thin != (e.status == "contact"):
                v.append(f"status {e.status} but h_min/c = {e.h_min_m / e.clearance_m}")
        elif not e.message:
            v.append(f"failed status {e.status} without a message")
    elif a in ("stability", "linearize"):
        fn = rd.stability if a == "stability" else rd.linearize
        res = fn(rig, *op, **p.get("kw", {}))
        lm = res.linear if a == "stability" else res
        if lm.status in CONVERGED:
            _finite("K_H", lm.KH, v)
            _finite("D_H", lm.DH, v)
            if a == "stability":
                if len(res.eigenvalues) == 0:
                    v.append("converged equilibrium without eigenvalues")
                _finite("eigenvalues", res.eigenvalues, v)
                stable = bool(np.all(res.eigenvalues.real
                                     < 1e-9 * np.maximum(np.abs(res.eigenvalues), 1.0)))
                if res.stable != stable:
                    v.append(f"stable={res.stable} disagrees with the eigenvalues")
        else:
            if not np.all(np.isnan(lm.KH)):
                v.append(f"failed equilibrium ({lm.status}) linearised")
            if a == "stability" and (res.stable or len(res.eigenvalues)):
                v.append(f"failed equilibrium ({res.status}) classified: stable={res.stable}")
    elif a == "transient":
        tr = rd.transient(rig, *op, **p.get("kw", {}))
        if tr.status in CONVERGED:
            _finite("r", tr.r, v)
            _finite("v", tr.v, v)
        elif not tr.message:
            v.append(f"transient status {tr.status} without a message")
    elif a == "campbell":
        c = rd.campbell(rig, *op, **p.get("kw", {}))
        for i, s in enumerate(c.point_status):
            row = c.eigenvalues[i]
            if s in CONVERGED:
                _finite(f"eigenvalues[{i}]", row[~np.isnan(row)], v)
            elif not np.all(np.isnan(row)):
                v.append(f"campbell point {i} ({s}) has eigenvalues")
    elif a == "unbalance":
        u = rd.unbalance_response(rig, *op, **p.get("kw", {}))
        for i, s in enumerate(u.point_status):
            vals = np.concatenate([u.x[i], u.y[i]]) if hasattr(u, "x") else None
            if vals is None:
                break
            if s in CONVERGED:
                _finite(f"response[{i}]", vals, v)
            elif not np.all(np.isnan(vals)):
                v.append(f"unbalance point {i} ({s}) has a response")
    elif a == "statespace":
        ss = rd.statespace(rig, speed_hz=op[0], chamber_pressure_pa=op[1], config_ay_m=op[2],
                           **p.get("kw", {}))
        for name in ("A", "B", "C", "D"):
            _finite(name, getattr(ss, name), v)
    elif a == "threshold":
        th = rd.threshold(rig, *op, **p.get("kw", {}))
        if th.status == "ok" and not math.isfinite(th.value):
            v.append(f"threshold ok with value {th.value}")
        bad = th.scan[~th.scan["status"].isin(CONVERGED)]
        if np.any(np.isfinite(bad["max_real_1_per_s"])):
            v.append("a failed scan point has a max Re λ")
    else:
        raise ValueError(a)
    return v


def toml(p: dict) -> list:
    """Load a (mutated) model text; a model that loads must round-trip through to_toml."""
    import rotordyn as rd

    v: list = []
    s = rd.System.from_toml(p["text"], is_text=True)
    back = rd.System.from_toml(s.to_toml(), is_text=True)
    if back != s:
        v.append("to_toml round trip changed the model")
    if p.get("modes"):
        m = rd.modes(s, n_modes=min(4, 2 * len(s.reduction.master_stations) or 4), without_bearings=True)
        _finite("frequencies", m.frequencies_hz, v)
    return v


def cli(p: dict) -> list:
    """``rotordyn ARGV`` in-process: exit 0/1, or 2 with one line naming the field; never a
    traceback or an internal error."""
    from rotordyn.cli import main

    v: list = []
    out, err = io.StringIO(), io.StringIO()
    cwd = os.getcwd()
    os.chdir(p["cwd"])
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            code = main(list(p["argv"]))
    finally:
        os.chdir(cwd)
    text = err.getvalue().strip()
    _cache["detail"] = f"exit {code}"
    if code not in (0, 1, 2):
        v.append(f"exit code {code}")
    if "internal error" in text or "Traceback" in text:
        v.append(f"internal error: {text[-400:]}")
    if code == 2:
        lines = [ln for ln in text.splitlines() if ln.startswith("rotordyn: error:")]
        if len(lines) != 1:
            v.append(f"exit 2 without exactly one error line: {text[-400:]!r}")
        elif not _FIELD.match(lines[0][len("rotordyn: error: "):]):
            v.append(f"exit 2 message names no field: {lines[0]!r}")
    return v


def element(p: dict) -> list:
    """A rotordyn.bearings element built from fields and its coefficient table over speeds
    (tilting pads: the C++ pad assembly; dampers: end seals; tables: interpolation and mass).
    A row is either converged with finite K, C and a journal inside the clearance, or not ok
    with NaN coefficients and a message."""
    from rotordyn import bearings as B

    v: list = []
    cls = {"fixed_geometry": B.FixedGeometryBearing, "tilting_pad": B.TiltingPadBearing,
           "squeeze_film_damper": B.SqueezeFilmDamper, "table": B.TableBearing}[p["kind"]]
    b = cls(**p["fields"])
    if p["kind"] == "table":
        K, C = b.coefficients(p["speed_hz"])[:2]
        _finite("K", K, v)
        _finite("C", C, v)
        if b.has_mass:
            _finite("M", b.mass(p["speed_hz"]), v)
        return v
    if p["kind"] == "squeeze_film_damper":  # no spin: orbit coefficients and film forces
        oc = b.orbit_coefficients(eccentricity_ratio=p["eps"], whirl_hz=p["speed_hz"])
        for k, x in oc.items():
            _finite(k, x, v)
        c = p["fields"].get("clearance_m", 0.0)
        f = b.forces(x_m=0.5 * p["eps"] * c, y_m=0.0, vx_m_s=0.0, vy_m_s=p["speed_hz"] * 1e-5)
        _finite("force", f, v)
        return v
    tab = b.coefficient_table(p["speeds_hz"], p["load_n"])
    # the journal stays inside the machined clearance C_b/(1 - m) (preload m; lobes)
    limit = tab.clearance_m / (1.0 - b.resolved()[0]) if p["kind"] == "fixed_geometry" else \
        tab.clearance_m
    for i, stt in enumerate(tab.status):
        if stt in ("ok", "contact"):
            _finite(f"K[{i}]", tab.K[i], v)
            _finite(f"C[{i}]", tab.C[i], v)
            e = math.hypot(tab.x_m[i], tab.y_m[i]) / limit
            if not e < 1.0 + 1e-9 and p["kind"] != "tilting_pad":
                v.append(f"row {i} {stt} outside the clearance: eps {e}")
        else:
            if not tab.message[i]:
                v.append(f"row {i} status {stt} without a message")
            if np.any(np.isfinite(tab.K[i])) or np.any(np.isfinite(tab.C[i])):
                v.append(f"row {i} status {stt} with finite coefficients")
    return v


CASES = {"bearing": bearing, "element": element, "system": system, "toml": toml, "cli": cli}


def run_case(kind: str, payload: dict) -> dict:
    import rotordyn as rd

    try:
        if kind not in CASES:  # the cases of issue 21
            from fuzz_cases_more import CASES as MORE

            CASES.update(MORE)
        violations = CASES[kind](payload)
        return {"outcome": "result", "violations": violations,
                "detail": _cache.pop("detail", "")}
    except rd.RotordynError as exc:
        msg = str(exc)
        bad = []
        if isinstance(exc, rd.InputError) and not _FIELD.match(msg):
            bad.append(f"InputError names no field: {msg!r}")
        return {"outcome": "rotordyn", "violations": bad, "detail": f"{type(exc).__name__}: {msg}"}
    except Exception:  # noqa: BLE001 - the point: any other exception is a bug
        return {"outcome": "bug", "violations": [traceback.format_exc(limit=8)],
                "detail": traceback.format_exc(limit=8)}


# -- worker process -------------------------------------------------------------------------
def _serve(conn):
    os.environ.setdefault("OMP_NUM_THREADS", "1")
    import matplotlib

    matplotlib.use("Agg")
    while True:
        msg = conn.recv()
        if msg is None:
            return
        conn.send(run_case(*msg))


class Worker:
    """One persistent worker process; restarted after a crash or a hang."""

    def __init__(self):
        self._ctx = mp.get_context("spawn")
        self._proc = None
        self._conn = None

    def _start(self):
        parent, child = self._ctx.Pipe()
        self._proc = self._ctx.Process(target=_serve, args=(child,), daemon=True)
        self._proc.start()
        self._conn = parent

    def run(self, kind: str, payload: dict, timeout: float = CASE_TIMEOUT_S) -> dict:
        if self._proc is None or not self._proc.is_alive():
            self._start()
        self._conn.send((kind, payload))
        if not self._conn.poll(timeout):
            self._kill()
            return {"outcome": "hang", "violations": [f"no answer in {timeout} s"],
                    "detail": ""}
        try:
            return self._conn.recv()
        except EOFError:
            code = self._proc.exitcode if self._proc else None
            self._kill()
            return {"outcome": "crash", "violations": [f"worker died (exit {code})"],
                    "detail": ""}

    def _kill(self):
        if self._proc is not None:
            self._proc.kill()
            self._proc.join(5)
        self._proc = self._conn = None

    def close(self):
        if self._proc is not None and self._proc.is_alive():
            self._conn.send(None)
            self._proc.join(5)
            if self._proc.is_alive():
                self._proc.kill()
        self._proc = self._conn = None
