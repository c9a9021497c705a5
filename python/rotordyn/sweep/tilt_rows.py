"""The equilibrium's tilt outputs on the rows of stability and Campbell sweeps (issue 20):
when the model has a film with ``tilt = true``, every row (one per mode) carries its point's
tilting bearings and, per bearing (list columns in the order of ``tilt_bearing``), the
journal's rotations relative to the housing, the films' moments on the journal, the
bearing's minimum film and its axial position: the values and units of the equilibrium
sweep's columns of the same names (:func:`rotordyn.sweep.blocks.eq_blocks`), with the
point's own minimum film over every bearing staying in ``h_min_m`` (so the per-bearing one
is ``tilt_h_min_m``). A failed point's row has them null (never linearised, never a value
beside a failed status); docs/sweeps.md.
"""

from __future__ import annotations

import math

import numpy as np
import pyarrow as pa

# list column -> what it holds (units: the equilibrium rows' columns of the same name)
TILT_LISTS = ("journal_theta_x_rad", "journal_theta_y_rad", "film_moment_x_n_m",
              "film_moment_y_n_m", "tilt_h_min_m", "h_min_z_m")
TILT_OUTPUTS = {"tilt_bearing": pa.list_(pa.string()),
                **{k: pa.list_(pa.float64()) for k in TILT_LISTS}}
TILT_ANALYSES = ("stability", "campbell", "thermal")
# the thermal analysis's rows are one per film: its film's bearing's values, flat (NaN for an
# untilted film and a failed point), as SystemThermalResult.to_frame() and `rotordyn thermal`
THERMAL_TILT_OUTPUTS = {k: pa.float64() for k in ("journal_theta_x_rad", "journal_theta_y_rad",
                                                  "film_moment_x_n_m", "film_moment_y_n_m")}


def model_tilts(system) -> bool:
    """Whether any bearing of ``system`` has a tilting film (``tilt = true``)."""
    return any(bool(getattr(b, "tilt", False)) for b in system.bearings)


def tilt_on(job, base) -> bool:
    """Whether the rows of ``job`` (on the model ``base``) carry the tilt columns (the
    thermal analysis: :data:`THERMAL_TILT_OUTPUTS`)."""
    return job.analysis in TILT_ANALYSES and model_tilts(base)


def batch_tilt(asm, res) -> list:
    """Per point of a ``stability_batch`` result on ``asm``: {column: list} of its tilting
    bearings (NaN where the equilibrium did not converge; the caller writes only the
    converged points' rows)."""
    tb = [bc for bc in asm.bearings if bc.rot]
    R, FF = np.asarray(res.r), np.asarray(res.film_force)
    HF, HZ = np.asarray(res.h_min), np.asarray(res.h_min_z_m)
    HB = asm.bearing_h_min(HF) if len(tb) else None
    out = []
    for p in range(R.shape[0]):
        d = {"tilt_bearing": [bc.name for bc in tb]}
        d["journal_theta_x_rad"] = [float(R[p, bc.rot[0]]) for bc in tb]
        d["journal_theta_y_rad"] = [float(R[p, bc.rot[1]]) for bc in tb]
        d["film_moment_x_n_m"] = [float(FF[p, bc.rot[0]]) if FF.size else math.nan
                                  for bc in tb]
        d["film_moment_y_n_m"] = [float(FF[p, bc.rot[1]]) if FF.size else math.nan
                                  for bc in tb]
        d["tilt_h_min_m"] = [float(HB[p, bc.index]) for bc in tb]
        d["h_min_z_m"] = [float(HZ[p, asm.min_film_index(bc.index, HF[p])]) for bc in tb]
        out.append(d)
    return out


def equilibrium_tilt(asm, e) -> dict:
    """{column: list} of the tilting bearings of one converged EquilibriumResult ``e`` on
    ``asm`` (its ``tilt`` entries and per-bearing minimum films)."""
    tb = [bc for bc in asm.bearings if bc.rot]
    t = e.tilt or {}
    hm = np.atleast_1d(np.asarray(e.h_min_m, dtype=float))
    d = {"tilt_bearing": [bc.name for bc in tb]}
    for k in ("journal_theta_x_rad", "journal_theta_y_rad", "film_moment_x_n_m",
              "film_moment_y_n_m", "h_min_z_m"):
        d[k] = [float(t.get(bc.index, {}).get(k, math.nan)) for bc in tb]
    d["tilt_h_min_m"] = [float(hm[bc.index]) if bc.index < hm.size else math.nan for bc in tb]
    return d


def repeat_lists(per_point: list, counts) -> dict:
    """Row columns from per-point {column: list} (``per_point``) repeated ``counts[k]``
    times: object arrays holding one list per row."""
    m = int(np.sum(counts))
    cols = {k: np.empty(m, dtype=object) for k in TILT_OUTPUTS}
    at = 0
    for d, c in zip(per_point, counts):
        for k in TILT_OUTPUTS:
            for i in range(at, at + int(c)):
                cols[k][i] = d[k]
        at += int(c)
    return cols
