"""Gain scheduling of a feedback law over the speed.

Designs K_g = (A_g, B_g, C_g, D_g) at grid speeds Ω_0 < … < Ω_{G−1} are joined into one law
whose matrices at Ω are interpolated **element by element, piecewise linearly** between the
neighbouring grid points (constant outside; the transient refuses a run leaving the grid):

    M(Ω) = M_i + (M_{i+1} − M_i) s,   s = (Ω − Ω_i)/(Ω_{i+1} − Ω_i),   M ∈ {A, B, C, D}.

This is interpolation of the gains when the designs share one state structure — static laws
(u = D y: the gains themselves), and PD/PID laws from :func:`rotordyn.control.pid.pid` with a
common derivative filter τ_d, whose (A, B) are fixed and whose (C, D) are linear in
(k_p, k_d, k_i): the interpolated law is the PID with linearly interpolated gains. Laws whose
state coordinates differ from design to design (LQG/H∞ designed separately) have no common
structure and must not be interpolated this way; they are refused when A or B differ
between designs (``allow_state_interpolation=True`` overrides, at the user's risk).

The interpolated family is checked (:func:`schedule_stability`) at every design point and on a
dense grid between them: the linear closed loop re-linearised at each speed (the plant's
equilibrium continued along the speed) with the law interpolated at that speed.
The C++ right-hand side interpolates the same way at Ω(t) (``Controller.schedule_*``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from rotordyn._common import validate as v
from rotordyn.errors import InputError
from rotordyn.operation.controller import Controller
from rotordyn.operation.controller import check_schedule_covers as check_covers


def _pack(k: Controller) -> np.ndarray:
    return np.concatenate([k.A.ravel(order="F"), k.B.ravel(order="F"), k.C.ravel(order="F"),
                           k.D.ravel(order="F")])


def gain_schedule(designs, speeds_hz, *, name: str = "scheduled",
                  allow_state_interpolation: bool = False) -> Controller:
    """One law from ``designs`` (Controllers, one per speed of ``speeds_hz``, Hz, strictly
    increasing): element-wise linear interpolation over the speed (module docstring). The
    returned Controller's own (A, B, C, D) are the first design's; ``info`` keeps the grid."""
    designs = list(designs)
    sp = v.vector("speeds_hz", speeds_hz)
    if sp.size < 1 or sp.size != len(designs):
        raise InputError(f"speeds_hz: expected one speed per design ({len(designs)}), got "
                         f"{sp.size}")
    if np.any(np.diff(sp) <= 0) or np.any(sp < 0):
        raise InputError(f"speeds_hz: expected strictly increasing speeds >= 0 Hz, got {sp!r}")
    v.text("name", name)
    v.boolean("allow_state_interpolation", allow_state_interpolation)
    for i, k in enumerate(designs):
        if not isinstance(k, Controller):
            raise InputError(f"designs[{i}]: expected a rotordyn.control.Controller, got "
                             f"{type(k).__name__}")
        if k.schedule_law is not None:
            raise InputError(f"designs[{i}]: already a gain schedule")
    k0 = designs[0]
    for i, k in enumerate(designs[1:], 1):
        if (k.A.shape, k.B.shape) != (k0.A.shape, k0.B.shape) or \
                k.measurements != k0.measurements or k.sample_time_s != k0.sample_time_s:
            raise InputError(f"designs[{i}]: expected the structure of designs[0] (n_k "
                             f"{k0.n_states}, measurements {list(k0.measurements)}, sample "
                             f"time {k0.sample_time_s}), got n_k {k.n_states}, "
                             f"{list(k.measurements)}, {k.sample_time_s}")
        if not allow_state_interpolation and not (np.array_equal(k.A, k0.A)
                                                  and np.array_equal(k.B, k0.B)):
            raise InputError(f"designs[{i}]: its (A, B) differ from designs[0]'s: the designs "
                             f"have no common state structure, and interpolating their "
                             f"matrices is not interpolating gains (allow_state_interpolation="
                             f"True to do it anyway)")
    law = np.vstack([_pack(k) for k in designs])
    info = dict(k0.info, schedule_speed_hz=sp.tolist(),
                schedule="element-wise piecewise-linear interpolation over the speed")
    return k0.with_options(schedule_speed_hz=sp, schedule_law=law, name=name, info=info)


def law_at_speed(controller: Controller, speed_hz: float) -> Controller:
    """The fixed law of a scheduled ``controller`` at ``speed_hz`` (the interpolation the C++
    right-hand side does); an unscheduled one is returned as is."""
    if not isinstance(controller, Controller):
        raise InputError(f"controller: expected a rotordyn.control.Controller, got "
                         f"{type(controller).__name__}")
    f = v.finite("speed_hz", speed_hz)
    if controller.schedule_law is None:
        return controller
    x, law = controller.schedule_speed_hz, controller.schedule_law
    if f <= x[0]:
        row = law[0]
    elif f >= x[-1]:
        row = law[-1]
    else:
        i = int(np.searchsorted(x, f, side="right")) - 1
        s = (f - x[i]) / (x[i + 1] - x[i])
        row = law[i] + (law[i + 1] - law[i]) * s
    nk, ny = controller.n_states, controller.n_inputs
    o = np.cumsum([0, nk * nk, nk * ny, nk, ny])
    A = row[o[0]:o[1]].reshape((nk, nk), order="F")
    B = row[o[1]:o[2]].reshape((nk, ny), order="F")
    C = row[o[2]:o[3]].reshape((1, nk), order="F")
    D = row[o[3]:o[4]].reshape((1, ny), order="F")
    return controller.with_options(A=A, B=B, C=C, D=D, schedule_speed_hz=None,
                                   schedule_law=None, anti_windup_gain=None,
                                   anti_windup_mode="back-calculation")


@dataclass(frozen=True)
class ScheduleStability:
    """Closed-loop stability of a scheduled law over the speed: ``speed_hz`` (n,), ``design``
    (n,) True at grid points, ``max_real_1_per_s`` and ``min_damping`` (n,) of the linear
    closed loop with the law interpolated at that speed (NaN: no equilibrium there),
    ``point_stable`` (n,) each speed's verdict (:func:`rotordyn.results.modes.point_stable`:
    a root in the round-off band is marginally stable, not a sign; False where NaN)."""

    speed_hz: np.ndarray
    design: np.ndarray
    max_real_1_per_s: np.ndarray
    min_damping: np.ndarray
    point_stable: np.ndarray

    @property
    def stable(self) -> bool:
        """Every speed :attr:`point_stable` (the one verdict rule; max Re λ's raw sign called
        a conservative closed loop's round-off +1e-12 unstable)."""
        return bool(np.all(self.point_stable))

    @property
    def worst(self) -> tuple:
        """(speed Hz, max Re λ 1/s) of the least stable point."""
        i = int(np.nanargmax(self.max_real_1_per_s))
        return float(self.speed_hz[i]), float(self.max_real_1_per_s[i])

    def to_frame(self):
        import pandas as pd

        return pd.DataFrame({"speed_hz": self.speed_hz, "design": self.design,
                             "max_real_1_per_s": self.max_real_1_per_s,
                             "min_damping": self.min_damping,
                             "point_stable": self.point_stable})


def schedule_stability(system, controller: Controller, *, chamber_pressure_pa: float = 0.0,
                       config_ay_m: float | None = None, actuator=None,
                       n_between: int = 4, speeds_hz=None) -> ScheduleStability:
    """Linear closed-loop stability of the scheduled ``controller`` at each design speed and
    at ``n_between`` equally spaced speeds inside each grid interval (or at ``speeds_hz``),
    the plant re-linearised at each speed. A design whose interpolated neighbours are unstable
    shows here, not at the grid points."""
    from rotordyn.control.closedloop import closed_loop_matrix
    from rotordyn.control.plant import plant
    from rotordyn.results.modes import damping_ratio, point_stable

    if not isinstance(controller, Controller) or controller.schedule_law is None:
        raise InputError("controller: expected a scheduled law (rotordyn.control.gain_schedule."
                         "gain_schedule)")
    v.integer("n_between", n_between, lo=0, hi=1000)
    x = controller.schedule_speed_hz
    if speeds_hz is None:
        pts = [x[:1]]
        for a, b in zip(x[:-1], x[1:]):
            pts.append(np.linspace(a, b, n_between + 2)[1:])
        sp = np.concatenate(pts)
    else:
        sp = np.sort(v.vector("speeds_hz", speeds_hz))
    check_covers(controller, float(sp.min()), float(sp.max()))
    mr, mz = np.full(sp.size, math.nan), np.full(sp.size, math.nan)
    ok = np.zeros(sp.size, dtype=bool)
    for j, f in enumerate(sp):
        p = plant(system, float(f), chamber_pressure_pa, config_ay_m,
                  measurements=controller.measurements, actuator=actuator)
        lam = np.linalg.eigvals(closed_loop_matrix(p, law_at_speed(controller, float(f))))
        mr[j] = lam.real.max()
        mz[j] = damping_ratio(lam).min()
        ok[j] = bool(np.all(np.isfinite(lam))) and point_stable(lam)
    return ScheduleStability(sp, np.isin(sp, x), mr, mz, ok)


def tune_pd_schedule(system, speeds_hz, *, chamber_pressure_pa: float = 0.0,
                     config_ay_m: float | None = None, actuator=None,
                     **tune_kw) -> Controller:
    """PD laws tuned by :func:`rotordyn.control.pid.tune_pd` at each speed of ``speeds_hz``
    (each search started from the previous speed's gains), scheduled by
    :func:`gain_schedule` — the gains (k_p, k_d) interpolated linearly."""
    from rotordyn.control.pid import tune_pd
    from rotordyn.control.plant import active_bearing_index, plant

    sp = v.vector("speeds_hz", speeds_hz)
    designs, kw = [], dict(tune_kw)
    for f in sp:
        # tuned on the active bearing's journal wherever it sits (it was journal 0: the plain
        # NDE bearing's on tests/data/models/compressor_active.toml)
        p = plant(system, float(f), chamber_pressure_pa, config_ay_m,
                  measurements=[("journal", active_bearing_index(system))], actuator=actuator)
        k, _ = tune_pd(p, **kw)
        designs.append(k)
        kw.update(kp0=k.info["kp"], kd0=k.info["kd"])
    return gain_schedule(designs, sp, name="pd-scheduled")
