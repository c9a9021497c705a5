"""Open-loop chamber-pressure schedule p_c(Ω): over a (speed × p_c) grid of linear models,
the pressure at each speed that minimises the steady unbalance response at chosen stations
subject to a stability margin (least damping ratio of every mode) and the actuator limits
(paper §7, the "open-loop approach")."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from rotordyn._common import validate as v
from rotordyn.analysis.assembly import assembled
from rotordyn.analysis.linear import continued_linear_models
from rotordyn.control import _checks as chk
from rotordyn.errors import InputError
from rotordyn.results.modes import damping_ratio
from rotordyn.units import hz_to_rad_s

if TYPE_CHECKING:
    import pandas as pd


@dataclass(frozen=True)
class ScheduleResult:
    """grid: tidy table (speed_hz, chamber_pressure_pa, amplitude_m per station,
    objective_m, min_damping_ratio, feasible, status); speeds_hz, pressures_pa: the chosen
    schedule (NaN where no pressure is feasible); best_constant_pa: the single pressure
    feasible at every speed with the smallest peak objective (NaN if none)."""

    grid: pd.DataFrame
    speeds_hz: np.ndarray
    pressures_pa: np.ndarray
    objective_m: np.ndarray
    best_constant_pa: float
    best_constant_objective_m: np.ndarray
    stations: tuple
    min_damping: float

    def to_frame(self) -> pd.DataFrame:
        import pandas as pd
        return pd.DataFrame({"speed_hz": self.speeds_hz, "chamber_pressure_pa": self.pressures_pa,
                             "objective_m": self.objective_m,
                             "best_constant_objective_m": self.best_constant_objective_m})

    def schedule(self):
        """The :class:`~rotordyn.control.PressureSchedule` p_c(Ω) (NaN speeds dropped)."""
        from rotordyn.operation.profiles import PressureSchedule

        ok = np.isfinite(self.pressures_pa)
        if not ok.any():
            raise InputError("schedule: no feasible pressure at any speed")
        return PressureSchedule.speed_table(self.speeds_hz[ok], self.pressures_pa[ok])

    def __repr__(self):
        return (f"ScheduleResult({len(self.speeds_hz)} speeds, p_c {np.nanmin(self.pressures_pa):.4g}"
                f"..{np.nanmax(self.pressures_pa):.4g} Pa, best constant {self.best_constant_pa:.4g} Pa)")


def linear_model_grid(system, sp, pp, config_ay_m):
    """The linear models of a (speed × p_c) grid: equilibria continued in speed at each
    pressure, K_H and D_H by perturbation. Yields (i, j, status, model, ω rad/s, least damping
    ratio of all modes); model and ω are None and the ratio NaN unless the status is ok.
    Shared by the open-loop schedule and the synchronous bound."""
    chk.system(system)
    sp = chk.speeds("speeds_hz", sp)
    pp = chk.pressures("pressures_pa", pp)
    config_ay_m = chk.config_ay(system, config_ay_m)
    for j, p in enumerate(pp):
        for i, stt, lm in continued_linear_models(system, sp, float(p), config_ay_m,
                                                  "perturbation", continue_on=("ok",)):
            if stt != "ok":
                yield i, j, stt, None, None, np.nan
                continue
            zmin = damping_ratio(np.linalg.eigvals(lm.state_matrix())).min()
            yield i, j, stt, lm, hz_to_rad_s(sp[i]), zmin


def pressure_schedule(system, unbalances, speeds_hz, pressures_pa, *, stations=None,
                      config_ay_m: float | None = None, min_damping: float = 0.0,
                      p_min_pa: float = 0.0, p_max_pa: float = 1e6,
                      smooth_pa_per_hz: float | None = None) -> ScheduleResult:
    """Evaluate every (speed, p_c) of the grid on the linear model (equilibria continued in
    speed at each pressure; K_H, D_H by perturbation) and pick, per speed, the feasible
    pressure minimising the largest response amplitude √(|X|² + |Y|²) at ``stations``.
    Feasible: the least damping ratio of all modes ≥ ``min_damping`` and
    p_min_pa ≤ p_c ≤ p_max_pa. ``smooth_pa_per_hz``: optional limit on the schedule's slope
    (a dynamic-programming pass over the grid; None: pointwise choice).
    ``unbalances`` as in :func:`rotordyn.unbalance_response`."""
    import pandas as pd
    chk.system(system)
    ub = chk.unbalances(system, unbalances)
    sp = chk.speeds("speeds_hz", speeds_hz)
    pp = chk.pressures("pressures_pa", pressures_pa)
    outs = chk.stations(system, stations) if stations is not None \
        else tuple(dict.fromkeys(s for s, _, _ in ub))
    config_ay_m = chk.config_ay(system, config_ay_m)
    v.in_range("min_damping", min_damping, -1.0, 1.0)
    p_min_pa = v.non_negative("p_min_pa", p_min_pa)
    p_max_pa = v.positive("p_max_pa", p_max_pa)
    if not p_min_pa < p_max_pa:
        raise InputError(f"p_min_pa/p_max_pa: expected p_min_pa < p_max_pa, got {p_min_pa!r} "
                         f"and {p_max_pa!r}")
    if not np.any((pp >= p_min_pa) & (pp <= p_max_pa)):
        raise InputError(f"pressures_pa: expected at least one grid pressure inside "
                         f"[p_min_pa, p_max_pa] = [{p_min_pa:g}, {p_max_pa:g}] Pa, got "
                         f"{pp.min():g} .. {pp.max():g}")
    if smooth_pa_per_hz is not None:
        v.positive("smooth_pa_per_hz", smooth_pa_per_hz)
    asm = assembled(system)
    Cout = [asm.station_output_matrix(s) for s in outs]
    F1 = asm.unbalance_load(ub)
    amp = np.full((sp.size, pp.size, len(outs)), np.nan)
    zmin = np.full((sp.size, pp.size), np.nan)
    status = np.full((sp.size, pp.size), "error", dtype=object)
    for i, j, stt, lm, w, zm in linear_model_grid(system, sp, pp, config_ay_m):
        status[i, j], zmin[i, j] = stt, zm
        if lm is None:
            continue
        q = np.linalg.solve(lm.K - w**2 * lm.M + 1j * w * lm.D, w**2 * F1)
        for k, Co in enumerate(Cout):
            x, y = Co @ q
            amp[i, j, k] = np.hypot(abs(x), abs(y))
        if not (np.all(np.isfinite(amp[i, j])) and np.isfinite(zm)):
            status[i, j] = "error"  # never an ok point with a non-finite response
    obj = amp.max(axis=2)
    feas = (status == "ok") & (zmin >= min_damping) & (pp >= p_min_pa)[None, :] \
        & (pp <= p_max_pa)[None, :] & np.isfinite(obj)
    cost = np.where(feas, obj, np.inf)
    if smooth_pa_per_hz is None:
        jbest = np.argmin(cost, axis=1)
    else:
        # Minimise the largest amplitude along the path (min-max DP) under the slope limit.
        ok_move = np.abs(pp[:, None] - pp[None, :])
        acc = cost[0].copy()
        back = np.zeros((sp.size, pp.size), dtype=int)
        for i in range(1, sp.size):
            lim = smooth_pa_per_hz * (sp[i] - sp[i - 1])
            cand = np.where(ok_move <= lim + 1e-9, acc[:, None], np.inf)  # from a -> to b
            back[i] = np.argmin(cand, axis=0)
            acc = np.maximum(cand[back[i], np.arange(pp.size)], cost[i])
        jbest = np.zeros(sp.size, dtype=int)
        jbest[-1] = int(np.argmin(acc))
        for i in range(sp.size - 1, 0, -1):
            jbest[i - 1] = back[i, jbest[i]]
    chosen = pp[jbest].astype(float)
    chosen_obj = obj[np.arange(sp.size), jbest]
    none = ~np.isfinite(cost[np.arange(sp.size), jbest])
    chosen[none], chosen_obj[none] = np.nan, np.nan
    allfeas = feas.all(axis=0)
    if allfeas.any():
        peak = np.where(allfeas, obj.max(axis=0), np.inf)
        jc = int(np.argmin(peak))
        best_c, best_obj = float(pp[jc]), obj[:, jc]
    else:
        best_c, best_obj = float("nan"), np.full(sp.size, np.nan)
    rows = {"speed_hz": np.repeat(sp, pp.size), "chamber_pressure_pa": np.tile(pp, sp.size)}
    for k, s in enumerate(outs):
        rows[f"amplitude_m[{s}]"] = amp[:, :, k].ravel()
    rows.update({"objective_m": obj.ravel(), "min_damping_ratio": zmin.ravel(),
                 "feasible": feas.ravel(), "status": status.ravel().astype(str)})
    return ScheduleResult(pd.DataFrame(rows), sp, chosen, chosen_obj, best_c, best_obj, outs,
                          float(min_damping))
