"""A control law leaving rotordyn for a real-time target: the law discretised at a sample
time (zero-order hold or Tustin, on the balanced realisation), and its coefficients written as
JSON and as a C header with a step function, so that a controller board runs exactly the
difference equation rotordyn closed its sampled-data loop with:

    u[k]   = C x[k] + D y[k]          (command increment, Pa, held for one sample)
    x[k+1] = A x[k] + B y[k]

y[k]: the measurements minus their value at the operating point (m or m/s, two signals, x
then y, per measurement), sampled at t = k T. The states are the balanced states of the law
(x = T x̃ with T diagonal powers of two; any realisation gives the same input–output map).
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np

from rotordyn._common import validate as v
from rotordyn._common.balance import scaled, state_scaling
from rotordyn._common.info import __version__
from rotordyn.control._checks import controller as check_controller
from rotordyn.errors import InputError
from rotordyn.operation.controller import MAX_SAMPLE_TIME_S, MIN_SAMPLE_TIME_S, Controller

FORMAT = "rotordyn/discrete-law/1"
UNITS = {"journal": "m", "journal_velocity": "m/s", "displacement": "m", "velocity": "m/s"}
METHODS = ("zoh", "tustin")


def discretise(k: Controller, sample_time_s: float, method: str = "zoh") -> Controller:
    """The continuous law ``k`` as a discrete :class:`Controller` with sample time
    ``sample_time_s`` (s, in [1e-7, 1]): ``"zoh"`` (exact for a piecewise-constant input:
    A_d = e^{AT}, B_d = ∫₀ᵀ e^{Aτ} dτ B) or ``"tustin"`` (bilinear). Computed on the
    balanced realisation, which it keeps."""
    from scipy.signal import cont2discrete

    check_controller(k, "controller", continuous=True)
    if k.anti_windup_gain is not None:
        # the continuous gain does not carry over (other states, a per-sample correction)
        raise InputError("controller.anti_windup_gain: discretise the law without anti-windup, "
                         "then add it to the discrete law (rotordyn.control.antiwindup."
                         "with_anti_windup)")
    T = v.in_range("sample_time_s", sample_time_s, MIN_SAMPLE_TIME_S, MAX_SAMPLE_TIME_S)
    method = v.choice("method", method, METHODS)
    A, B, C = k.A, k.B, k.C
    if k.n_states:
        A, B, C = scaled(A, B, C, state_scaling(A, B, C))
        Ad, Bd, Cd, Dd, _ = cont2discrete((A, B, C, k.D), T,
                                          method="zoh" if method == "zoh" else "bilinear")
    else:
        Ad, Bd, Cd, Dd = A, B, C, k.D
    if not all(np.all(np.isfinite(M)) for M in (Ad, Bd, Cd, Dd)):
        raise InputError(f"sample_time_s: the discretised law is not finite at T = {T:g} s")
    return k.with_options(A=np.asarray(Ad), B=np.asarray(Bd), C=np.asarray(Cd),
                          D=np.asarray(Dd), sample_time_s=T, name=f"{k.name}@{method}",
                          info=dict(k.info, discretised=method))


def signals(k: Controller) -> list[dict]:
    """The law's inputs in order: name, measurement, axis, unit."""
    out = []
    for kind, idx in k.measurements:
        for ax in ("x", "y"):
            out.append({"name": f"{kind}_{ax}[{idx}]", "measurement": [kind, idx], "axis": ax,
                        "unit": UNITS[kind]})
    return out


def coefficients(k: Controller) -> dict:
    """The discrete law as a JSON-ready dict (``FORMAT``): sample time, equations, inputs with
    units, output, A, B, C, D (row-major lists of floats, exact: JSON writes Python's
    shortest round-tripping repr)."""
    check_controller(k)
    if not k.discrete:
        raise InputError("controller.sample_time_s: expected a discrete law (a sample time); "
                         "discretise a continuous one with "
                         "rotordyn.control.export.discretise(controller, sample_time_s)")
    sig = signals(k)
    if len(sig) != k.n_inputs:
        raise InputError(f"controller: its {k.n_inputs} inputs do not match its measurements "
                         f"{list(k.measurements)} ({len(sig)} signals)")
    return {"format": FORMAT, "rotordyn_version": __version__, "name": k.name,
            "sample_time_s": k.sample_time_s,
            "computation_delay_s": k.computation_delay_s,
            "equations": "u[k] = C x[k] + D y[k]; x[k+1] = A x[k] + B y[k]; u applied "
                         "computation_delay_s after sample k and held for one sample "
                         "(zero-order hold)",
            "inputs": sig,
            "output": {"name": "chamber_pressure_command_pa", "unit": "Pa",
                       "meaning": "command increment added to the operating point's chamber "
                                  "pressure"},
            "n_states": k.n_states, "n_inputs": k.n_inputs,
            "A": k.A.tolist(), "B": k.B.tolist(), "C": k.C.tolist(), "D": k.D.tolist(),
            **_anti_windup(k)}


def _anti_windup(k: Controller) -> dict:
    """The law's anti-windup (rotordyn.control.antiwindup), if any, as JSON-ready fields."""
    if k.anti_windup_gain is None:
        return {}
    return {"anti_windup": {
        "mode": k.anti_windup_mode, "L": k.anti_windup_gain.tolist(),
        "equations": "once u[k] is applied: x[k+1] += L (u_delivered[k] - u[k]), u_delivered "
                     "- u the part of the command the valve does not follow (0 inside its "
                     "limits)" + ("; the command is formed as clip(schedule, p_min, p_max) + "
                                  "u[k]" if k.anti_windup_mode == "conditioning" else "")}}


def to_json(k: Controller, path=None) -> str:
    """The coefficients (:func:`coefficients`) as JSON text; written to ``path`` if given."""
    text = json.dumps(coefficients(k), indent=1)
    if path is not None:
        Path(path).write_text(text + "\n")
    return text


def _c_array(name: str, M: np.ndarray) -> str:
    vals = [repr(float(x)) for x in np.ravel(M)] or ["0.0"]
    body = ",\n    ".join(", ".join(vals[i:i + 4]) for i in range(0, len(vals), 4))
    return f"static const double {name}[{max(M.size, 1)}] = {{\n    {body}\n}};\n"


def to_c_header(k: Controller, path=None, *, prefix: str = "rotordyn_law") -> str:
    """A self-contained C99 header: the sizes, the sample time, the coefficient arrays
    (row-major, 17 significant digits) and ``static inline double <prefix>_step(double
    x[NX], const double y[NY])`` that returns u[k] and advances x to x[k+1] (start from
    x = 0 at the operating point). Written to ``path`` if given."""
    c = coefficients(k)
    prefix = v.text("prefix", prefix)
    if not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]{0,62}", prefix):
        raise InputError(f"prefix: expected a C identifier (letters, digits, _; not starting "
                         f"with a digit; at most 63 characters), got {prefix!r}")
    P = prefix.upper()
    nx, ny = k.n_states, k.n_inputs
    inputs = "\n".join(f" *   y[{i}] = {s['name']} ({s['unit']})"
                       for i, s in enumerate(c["inputs"]))
    arrays = "".join(_c_array(f"{prefix}_{m}", getattr(k, m)) for m in "ABCD")
    aw = ""
    if k.anti_windup_gain is not None:
        cond = (" The command is formed as clip(schedule, p_min, p_max) + u[k] (conditioning)."
                if k.anti_windup_mode == "conditioning" else "")
        aw = (_c_array(f"{prefix}_L", k.anti_windup_gain) + f"""
/* Anti-windup ({k.anti_windup_mode}): once u[k] is applied, call with the part of the
 * command the valve does not follow, excess = u_delivered[k] - u[k] (0 inside its limits;
 * e.g. clip(cmd, p_min, p_max) - cmd): x[k+1] += L excess.{cond} */
static inline void {prefix}_anti_windup(double x[], double excess)
{{
    int i;
    if (excess == 0.0) return;
    for (i = 0; i < {P}_NX; ++i) x[i] += {prefix}_L[i] * excess;
}}
""")
    text = f"""/* Discrete control law "{k.name}" exported by rotordyn {__version__} ({FORMAT}).
 * Sample time {k.sample_time_s!r} s. Every sample:
 *   u[k] = C x[k] + D y[k]   (chamber-pressure command increment, Pa; hold for one sample)
 *   x[k+1] = A x[k] + B y[k]
 * Inputs (measurement minus its value at the operating point):
{inputs}
 * Start from x = 0. Arrays are row-major.
 */
#ifndef {P}_H
#define {P}_H

#define {P}_NX {nx}
#define {P}_NY {ny}
#define {P}_SAMPLE_TIME_S {k.sample_time_s!r}
#define {P}_COMPUTATION_DELAY_S {k.computation_delay_s!r}

{arrays}{aw}
/* Returns u[k] for the measurements y[k]; advances the state x[k] -> x[k+1]. */
static inline double {prefix}_step(double x[], const double y[])
{{
    double u = 0.0;
    double xn[{max(nx, 1)}];
    int i, j;
    for (j = 0; j < {P}_NX; ++j) u += {prefix}_C[j] * x[j];
    for (j = 0; j < {P}_NY; ++j) u += {prefix}_D[j] * y[j];
    for (i = 0; i < {P}_NX; ++i) {{
        double s = 0.0;
        for (j = 0; j < {P}_NX; ++j) s += {prefix}_A[i * {P}_NX + j] * x[j];
        for (j = 0; j < {P}_NY; ++j) s += {prefix}_B[i * {P}_NY + j] * y[j];
        xn[i] = s;
    }}
    for (i = 0; i < {P}_NX; ++i) x[i] = xn[i];
    (void)xn;
    return u;
}}

#endif /* {P}_H */
"""
    if path is not None:
        Path(path).write_text(text)
    return text


def simulate(k: Controller, y: np.ndarray, u_range=None) -> np.ndarray:
    """u[k] of the discrete law for measurements ``y`` (n_k, n_y) from x = 0 (reference for
    the exported coefficients). ``u_range`` (lo, hi), Pa: the increment the valve delivers
    around a constant operating point, clip(u, lo, hi); with the law's anti-windup the state
    takes x[k+1] += L (clip(u[k]) − u[k]). The requested u[k] is returned."""
    check_controller(k)
    lo, hi = (-np.inf, np.inf) if u_range is None else v.bounds("u_range", u_range)
    L = k.anti_windup_gain
    if not k.discrete:
        raise InputError("controller.sample_time_s: expected a discrete law")
    y = v.matrix("y", y)
    if y.shape[1] != k.n_inputs:
        raise InputError(f"y: expected {k.n_inputs} columns, got {y.shape[1]}")
    x = np.zeros(k.n_states)
    u = np.empty(y.shape[0])
    for i, yi in enumerate(y):
        u[i] = (k.C @ x + k.D @ yi)[0]
        x = k.A @ x + k.B @ yi
        d = min(max(u[i], lo), hi) - u[i]
        if L is not None and d != 0.0:
            x = x + L * d
    if not np.all(np.isfinite(u)):
        raise InputError("y: the law's output is not finite (an unstable law or huge inputs)")
    return u

