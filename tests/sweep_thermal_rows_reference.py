"""The dict-per-row sweep chunks of ``options.thermal`` (stability, Campbell, unbalance at each
point's own thermal equilibrium) as they were before their columnar blocks, kept verbatim
(python/rotordyn/sweep/thermal_rows.py at 75c072b, only the imports of the row helpers
changed: they moved to tests/sweep_rows_reference.py) as the reference of
tests/test_thermal_sweep.py: one dict per row, then the generic ``to_table``."""
# flake8: noqa
from __future__ import annotations

import math

import numpy as np
import pyarrow as pa

from rotordyn.analysis.thermal_dynamics import thermal_point
from rotordyn.errors import RotordynError
from rotordyn.results.equilibrium import CONVERGED
from rotordyn.sweep.points import STATUS, Variants, base_system, operating, ref_bearing, stable_modes
from rotordyn.sweep.work import Job, schema
from sweep_rows_reference import fail_row, points, to_table


def run_chunk(job: Job, chunk_id: int, lo: int, hi: int) -> pa.Table:
    rows: list[dict] = []
    variants = Variants(base_system(job.model_toml), job.model_toml)
    (unbalance_rows if job.analysis == "unbalance" else stab_rows)(job, variants, chunk_id, lo,
                                                                   hi, rows)
    return to_table(job, rows, schema(job.analysis, list(job.axes), thermal=True))

# extra output columns of a thermal stability / Campbell / unbalance sweep
THERMAL_COLUMNS = ("film", "film_effective_temperature_c", "film_max_temperature_c",
                   "film_power_loss_w", "max_temperature_c", "power_loss_w",
                   "thermal_iterations")


def thermal_columns(t) -> dict:
    """The thermal outputs of one point (a SystemThermalResult; NaN where it failed)."""
    ok = t.status in CONVERGED
    nan = [math.nan] * len(t.bearing_names)
    te = [float(x) for x in t.effective_temperature_c] if ok else nan
    tm = [float(x) for x in t.max_temperature_c] if ok else nan
    pw = [float(x) for x in t.power_loss_w] if ok else nan
    return {"film": list(t.bearing_names), "film_effective_temperature_c": te,
            "film_max_temperature_c": tm, "film_power_loss_w": pw,
            "max_temperature_c": max(tm) if ok else math.nan,
            "power_loss_w": float(sum(pw)) if ok else math.nan,
            "thermal_iterations": int(t.iterations)}


def _kw(opts):
    return dict(opts.get("thermal") or {})


def _status(s):
    return s if s in STATUS else "error"


def stab_rows(job, variants, chunk_id, lo, hi, rows):
    """One row per mode of each point (stability/Campbell columns, mode ids tracked along
    each line as the isothermal sweep does), at the point's thermal equilibrium."""
    from rotordyn.analysis.linear import stability
    from rotordyn.results.modes import settled_real
    from sweep_rows_reference import track_line  # the former NumPy/SciPy tracking

    line, weight = [], None

    def flush():
        if line:
            got = {}
            blocks = {at: {} for at, _, _ in line}
            track_line(blocks, line, weight)
            got.update(blocks)
            for at, _, _ in line:
                ids = got[at]["mode_id"]
                for j, r in enumerate(rows[at:at + len(ids)]):
                    r["mode_id"] = int(ids[j])
            line.clear()

    for row, p, asm, opts, same, err in points(job, variants, chunk_id, lo, hi):
        if not same:
            flush()
        if err:
            rows.append(fail_row(row, "error", err))
            continue
        try:
            f, pc, _ = operating(asm, p)
            t = thermal_point(asm.system, f, pc, p.get("config_ay_m"), _kw(opts))
        except (RotordynError, ArithmeticError, ValueError) as exc:
            rows.append(fail_row(row, "error", f"{type(exc).__name__}: {exc}"))
            continue
        th = thermal_columns(t)
        if t.status not in CONVERGED:
            rows.append({**fail_row(row, _status(t.status),
                                    f"thermal equilibrium: {t.message}"), **th})
            continue
        try:
            st = stability(t.system, f, pc, p.get("config_ay_m"),
                           n_modes=opts.get("n_modes"),
                           method=opts.get("linearization", "perturbation"), warm_start=False,
                           **{k: opts[k] for k in ("tol", "max_iter") if k in opts})
        except (RotordynError, ArithmeticError, ValueError) as exc:
            rows.append({**fail_row(row, "error", f"{type(exc).__name__}: {exc}"), **th})
            continue
        if st.status not in CONVERGED or not len(st.eigenvalues):
            rows.append({**fail_row(row, _status(st.status), st.message or "no equilibrium"),
                         **th})
            continue
        lam = st.eigenvalues
        with np.errstate(divide="ignore", invalid="ignore"):
            ms = stable_modes(lam[None, :])[0]
            re = settled_real(lam[None, :])[0]
            ab = np.abs(lam)
            dr = np.where(ab > 0, -re / ab, np.nan)
            ld = np.where(lam.imag != 0, -2 * np.pi * re / lam.imag, np.nan)
        e = st.linear.equilibrium
        bc = ref_bearing(variants.get(p))
        jx = float(e.r[bc.jx]) if bc else math.nan
        jy = float(e.r[bc.jy]) if bc else math.nan
        hmin = float(np.nanmin(e.h_min_m)) if len(np.atleast_1d(e.h_min_m)) else math.nan
        at = len(rows)
        for k in range(len(lam)):
            rows.append({**row, "mode_id": k, "mode": k + 1, "freq_hz": lam[k].imag / (2 * np.pi),
                         "eig_real_1_per_s": float(lam[k].real), "damping_ratio": float(dr[k]),
                         "log_dec": float(ld[k]), "whirl": str(st.whirl[k]),
                         "kind": str(st.kind[k]) if st.kind[k] in ("rotor", "sleeve")
                         else None, "mode_stable": bool(ms[k]),
                         "point_stable": bool(np.all(ms)),
                         "max_real_1_per_s": float(lam.real.max()), "journal_x_m": jx,
                         "journal_y_m": jy, "h_min_m": hmin, "iterations": int(e.iterations),
                         "status": _status(st.status), "message": st.message, **th})
        if job.options.get("track", True) and st.modes is not None:
            line.append((at, lam, st.modes))
            weight = np.asarray(st.linear.M)
    flush()


def unbalance_rows(job, variants, chunk_id, lo, hi, rows):
    """One row per (speed, station) along each speed line, each speed at its own thermal
    equilibrium (:func:`rotordyn.unbalance_response` with ``thermal``, no refinement)."""
    from rotordyn.analysis.thermal_dynamics import thermal_unbalance
    from rotordyn.analysis.unbalance import unbalance_response
    from rotordyn.sweep.lines import unbalance_columns

    n_line = job.shape[-1]
    for s in range(lo, hi, n_line):
        e = min(s + n_line, hi)
        pts = list(points(job, variants, chunk_id, s, e))
        row0, p0, asm, opts, _, err = pts[0]
        if err:
            rows += [fail_row(r[0], "error", err) for r in pts]
            continue
        ub = [tuple(u) for u in opts["unbalances"]]
        stations = tuple(opts.get("stations") or dict.fromkeys(int(u[0]) for u in ub))
        speeds = np.array([r[1].get("speed_hz", 50.0) for r in pts])
        try:
            _, pc, _ = operating(asm, p0)
            res = thermal_unbalance(unbalance_response, asm.system, ub, speeds, dict(
                stations=stations, chamber_pressure_pa=pc, config_ay_m=p0.get("config_ay_m"),
                operating_speed_hz=tuple(opts["operating_speed_hz"])
                if "operating_speed_hz" in opts else None,
                method=opts.get("linearization", "perturbation"), check_stability=True,
                threads=1), _kw(opts))
        except (RotordynError, ArithmeticError, ValueError) as exc:
            rows += [fail_row(r[0], "error", f"{type(exc).__name__}: {exc}") for r in pts]
            continue
        status = [_status(x) for x in res.point_status]
        msg = list(res.point_message)  # why a speed failed: the thermal status or exception
        cols = unbalance_columns(res, speeds, stations, status, msg)
        ns = len(stations)
        for k, (row, *_rest) in enumerate(pts):
            th = thermal_columns(res.thermal[k]) if res.thermal[k] is not None else {}
            for j in range(ns):
                q = k * ns + j
                rows.append({**row, **{c: (v[q].item() if hasattr(v[q], "item") else v[q])
                                       for c, v in cols.items()}, **th})
