"""What one chunk of a sweep does (runs inside a dask worker process): one tidy DataFrame
per chunk; a failed point becomes rows with ``status``/``message``, never a lost chunk."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from rotordyn.errors import RotordynError

STATUS = ["ok", "no_equilibrium", "contact", "not_converged", "error"]


def _status(s: str) -> str:
    return s if s in STATUS else "error"


def _inputs(p: dict) -> dict:
    return {"speed_hz": float(p.get("speed_hz", 50.0)),
            "chamber_pressure_pa": float(p.get("chamber_pressure_pa", 0.0)),
            "config_ay_m": float(p["config_ay_m"]) if "config_ay_m" in p else math.nan}


def _point(system, analysis: str, inp: dict, options: dict) -> list[dict]:
    import rotordyn as rd

    ay = None if math.isnan(inp["config_ay_m"]) else inp["config_ay_m"]
    if analysis == "equilibrium":
        e = rd.equilibrium(system, inp["speed_hz"], inp["chamber_pressure_pa"], ay,
                           method=options.get("method", "newton"))
        rows = []
        for i, name in enumerate(e.bearing_names):
            rows.append({"bearing": name, "journal_x_m": e.journal_x_m[i],
                         "journal_y_m": e.journal_y_m[i], "x_over_c": e.x_over_c[i],
                         "y_over_c": e.y_over_c[i], "h_min_m": e.h_min_m[i],
                         "iterations": e.iterations, "residual": e.residual,
                         "status": _status(e.status), "message": e.message})
        return rows
    if analysis == "stability":
        st = rd.stability(system, inp["speed_hz"], inp["chamber_pressure_pa"], ay,
                          n_modes=options.get("n_modes"))
        if len(st.eigenvalues) == 0:
            return [{"status": _status(st.status), "message": st.message}]
        rows = []
        for k, lam in enumerate(st.eigenvalues):
            rows.append({"mode": k + 1, "freq_hz": lam.imag / (2 * np.pi),
                         "eig_real_1_per_s": lam.real, "damping_ratio": st.damping_ratio[k],
                         "log_dec": st.log_dec[k], "whirl": st.whirl[k], "kind": st.kind[k],
                         "stable": st.stable, "status": _status(st.status),
                         "message": st.message})
        return rows
    if analysis == "waterfall":
        f = inp["speed_hz"]
        revs = int(options.get("revolutions", 60))
        spr = int(options.get("samples_per_revolution", 64))
        ub = [tuple(u) for u in options.get("unbalances", [])]
        tr = rd.transient(system, revs / f, f, inp["chamber_pressure_pa"], ay, unbalances=ub,
                          n_out=revs * spr + 1, rtol=float(options.get("rtol", 1e-6)))
        if tr.status != "ok":
            return [{"status": _status(tr.status), "message": tr.message}]
        freq, ax = tr.spectrum(last_fraction=0.5, axis="x")
        _, ay_ = tr.spectrum(last_fraction=0.5, axis="y")
        keep = freq <= float(options.get("max_harmonic", 4.0)) * f
        return [{"freq_hz": fr, "amplitude_x_m": a1, "amplitude_y_m": a2,
                 "order": fr / f, "status": "ok", "message": ""}
                for fr, a1, a2 in zip(freq[keep], ax[keep], ay_[keep])]
    raise ValueError(analysis)


def run_chunk(model_toml: str, analysis: str, options: dict, chunk_id: int,
              points: list) -> pd.DataFrame:
    """Run the points of one chunk (in order, so equilibria continue from point to point)."""
    import rotordyn as rd

    system = rd.System.from_toml(model_toml, is_text=True)
    rows = []
    for point_id, p in points:
        inp = _inputs(p)
        try:
            out = _point(system, analysis, inp, options)
        except RotordynError as exc:
            out = [{"status": "error", "message": f"{type(exc).__name__}: {exc}"}]
        except (ValueError, ArithmeticError, np.linalg.LinAlgError) as exc:
            out = [{"status": "error", "message": f"{type(exc).__name__}: {exc}"}]
        for r in out:
            rows.append({"point_id": point_id, "chunk_id": chunk_id, **inp, **r})
    df = pd.DataFrame(rows)
    return df
