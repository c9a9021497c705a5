"""Campbell diagram of the full system (rotor, films, sleeves) with the equilibrium continued
from speed to speed, and critical speeds from the 1× (or n×) crossings (paper §6.3, Fig. 12)."""

from __future__ import annotations

import numpy as np

from rotordyn.analysis.assembly import assembled
from rotordyn.analysis.linear import _stability_from, continued_linear_models
from rotordyn.analysis.tracking import track_modes
from rotordyn.errors import InputError, RotordynError
from rotordyn import _validate as v
from rotordyn.model.system import System
from rotordyn.results.campbell import CampbellResult

WHIRL_CODE = {"forward": 1, "backward": -1, "planar": 0}


def campbell(system: System, speeds_hz, chamber_pressure_pa: float = 0.0,
             config_ay_m: float | None = None, *, n_modes: int | None = None,
             method: str = "perturbation") -> CampbellResult:
    """Eigenvalues of eq. 19 at each speed in ``speeds_hz`` (strictly increasing, Hz): the
    equilibrium is solved at each speed, warm-started from the previous one, then K_H(Ω),
    D_H(Ω) and the eigenvalues. A speed whose equilibrium fails is a NaN row with its status
    in ``point_status``; the diagram goes on. ``n_modes`` default: every mode of the system."""
    sp = np.asarray(speeds_hz, dtype=float)
    if sp.ndim != 1 or sp.size == 0 or not np.all(np.isfinite(sp)):
        raise InputError("speeds_hz: expected a non-empty 1-D array of finite speeds")
    if sp.size > 1 and np.any(np.diff(sp) <= 0):
        raise InputError("speeds_hz: expected strictly increasing speeds")
    v.non_negative("chamber_pressure_pa", chamber_pressure_pa)
    asm = assembled(system)
    k = int(n_modes or asm.n)
    v.integer("n_modes", k, lo=1)
    lam = np.full((sp.size, k), np.nan + 1j * np.nan)
    whirl = np.zeros((sp.size, k), dtype=np.int64)
    kind = np.full((sp.size, k), "rotor", dtype=object)
    status = np.empty(sp.size, dtype=object)
    shapes = np.full((sp.size, asm.n, k), np.nan + 0j)
    for i, stt, lm in continued_linear_models(system, sp, chamber_pressure_pa, config_ay_m,
                                              method):
        status[i] = stt
        if lm is None:
            continue
        try:
            st = _stability_from(asm, lm, k)
        except RotordynError:
            status[i] = "error"
            continue
        m = min(k, len(st.eigenvalues))
        lam[i, :m] = st.eigenvalues[:m]
        whirl[i, :m] = [WHIRL_CODE[w] for w in st.whirl[:m]]
        kind[i, :m] = st.kind[:m]
        shapes[i, :, :m] = st.modes[:, :m]
    # Modes tracked by eigenvector continuity (mass-weighted MAC between consecutive speeds).
    mode_id = track_modes(lam, shapes, weight=np.asarray(asm.model.M))
    return CampbellResult(sp, lam, whirl, model=system.reduction.method, kind=kind,
                          point_status=status.astype(str), mode_id=mode_id)
