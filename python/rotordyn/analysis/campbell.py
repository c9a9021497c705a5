"""Campbell diagram of the full system (rotor, films, sleeves) with the equilibrium continued
from speed to speed, and critical speeds from the 1× (or n×) crossings (paper §6.3, Fig. 12)."""

from __future__ import annotations

from rotordyn._common.threads import limited_blas

import numpy as np

from rotordyn.analysis.assembly import assembled, chamber_pressure
from rotordyn.analysis.linear import _stability_from, continued_linear_models, linearize
from rotordyn.analysis.tracking import track_modes
from rotordyn.errors import InputError, RotordynError
from rotordyn._common import validate as v
from rotordyn.model.system import System
from rotordyn.results.campbell import CampbellResult
from rotordyn._common.status import point_messages
from rotordyn.results.equilibrium import CONVERGED

WHIRL_CODE = {"forward": 1, "backward": -1, "planar": 0}


@limited_blas
def campbell(system: System, speeds_hz, chamber_pressure_pa: float = 0.0,
             config_ay_m: float | None = None, *, n_modes: int | None = None,
             method: str = "perturbation", thermal=None) -> CampbellResult:
    """Eigenvalues of eq. 19 at each speed in ``speeds_hz`` (strictly increasing, Hz): the
    equilibrium is solved at each speed, warm-started from the previous one, then K_H(Ω),
    D_H(Ω) and the eigenvalues. A speed whose equilibrium fails is a NaN row with its status
    in ``point_status``; the diagram goes on. ``n_modes`` default: every mode of the system; it
    counts rotor (and sleeve) modes, never a tilting pad's own (those below the cut are kept
    besides, kind "pad"). ``thermal`` (None, True: the model's ``[thermal]``, or a dict of
    :func:`rotordyn.system_thermal_equilibrium` keywords): every speed at its own thermal
    equilibrium (cold start, field frozen for K_H, D_H; no continuation between speeds;
    the result's ``thermal`` per speed; :mod:`.thermal_dynamics`)."""
    sp = v.speeds("speeds_hz", speeds_hz)
    chamber_pressure(system, chamber_pressure_pa)
    if config_ay_m is not None:  # a NaN here made every point "error" (issue 13)
        v.finite("config_ay_m", config_ay_m)
    v.choice("method", method, ("perturbation", "finite_difference"))
    if thermal is not None and thermal is not False:
        from rotordyn.analysis.thermal_dynamics import thermal_campbell, thermal_keywords

        kw = thermal_keywords(thermal)
        nm = None if n_modes is None else v.integer("n_modes", n_modes, lo=1)
        return thermal_campbell(linearize, _stability_from, system, sp, chamber_pressure_pa,
                                config_ay_m, n_modes=nm, method=method, thermal=kw)
    asm = assembled(system)
    k = asm.n if n_modes is None else min(v.integer("n_modes", n_modes, lo=1), asm.n)
    # ``n_modes`` counts the system's modes; tilting pads' own modes below the cut are listed
    # besides them (issue 18), so the width has room for them.
    n_pad = sum(len(getattr(bc, "extra", ())) for bc in asm.bearings)
    width = k if n_modes is None else min(k + n_pad, asm.n)
    lam = np.full((sp.size, width), np.nan + 1j * np.nan)
    whirl = np.zeros((sp.size, width), dtype=np.int64)
    kind = np.full((sp.size, width), "rotor", dtype=object)
    status = np.empty(sp.size, dtype=object)
    message = [""] * sp.size
    errors: dict = {}
    shapes = np.full((sp.size, asm.n, width), np.nan + 0j)
    for i, stt, lm in continued_linear_models(system, sp, chamber_pressure_pa, config_ay_m,
                                              method, errors=errors):
        status[i] = stt
        if lm is None or stt not in CONVERGED:  # a failed point stays a NaN row
            message[i] = lm.equilibrium.message if lm is not None else errors.get(i, "")
            continue
        try:
            st = _stability_from(asm, lm, None if n_modes is None else k, verdict=False)
        except RotordynError as exc:
            status[i], message[i] = "error", f"{type(exc).__name__}: {exc}"
            continue
        m = min(width, len(st.eigenvalues))
        lam[i, :m] = st.eigenvalues[:m]
        whirl[i, :m] = [WHIRL_CODE[w] for w in st.whirl[:m]]
        kind[i, :m] = st.kind[:m]
        if st.modes is not None:
            shapes[i, :, :m] = st.modes[:, :m]
    # Modes tracked by eigenvector continuity (mass-weighted MAC between consecutive speeds).
    mode_id = track_modes(lam, shapes, weight=np.asarray(asm.model.M))
    return CampbellResult(sp, lam, whirl, model=system.reduction.method, kind=kind,
                          point_status=status.astype(str), mode_id=mode_id,
                          point_message=point_messages(status, message))
