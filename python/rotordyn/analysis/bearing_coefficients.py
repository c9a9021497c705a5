"""Each bearing element's stiffness and damping coefficients over speed, in the system: at
every speed the system's equilibrium (continued from the previous speed), its film K_H, D_H
(paper eq. 17–20), and for each bearing the 2×2 K, C its journal sees, with the element's own
coordinates (tilting pads, the active bearing's sleeve masters) condensed at the whirl
frequency ν = ``whirl_ratio`` · Ω:

    Z(ν) = K_b + iν C_b − ν² M_b,   Z_jj − Z_jp Z_pp⁻¹ Z_pj = K + iν C

(K_b, C_b, M_b the element's own matrices on its journal and coordinates: film plus pad tilt
springs and inertias, or sleeve stiffness and mass). This is what an API 684 report tabulates
as the bearing's kxx … cyy at each speed; an element without own coordinates (plain, table)
gives its K_H, D_H block unchanged."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from rotordyn._common import validate as v
from rotordyn._common.status import CONVERGED
from rotordyn.analysis.linear import continued_linear_models
from rotordyn.bearings._film import reduce_coefficients
from rotordyn.bearings.coefficients import COEFF_NAMES
from rotordyn.errors import InputError
from rotordyn.units import hz_to_rad_s

if TYPE_CHECKING:
    import pandas as pd

COLUMNS = ("bearing", "station", "speed_hz") + tuple(
    f"{n}_n_per_m" for n in COEFF_NAMES[:4]) + tuple(
    f"{n}_n_s_per_m" for n in COEFF_NAMES[4:]) + ("status",)


def _element_matrices(lm, b, name: str, idx: list[int]):
    """(K_b, C_b, M_b) of one element on [journal x, y, own coordinates] (``idx``)."""
    K = lm.KH[np.ix_(idx, idx)].copy()
    C = lm.DH[np.ix_(idx, idx)].copy()
    M = np.zeros_like(K)
    if len(idx) == 2:
        return K, C, M
    if hasattr(b, "system_parts"):  # pads: tilt springs and inertias couple journal and pads
        # (a tilting journal's pads: their pitch coordinates too; the rotations' indices only
        # place the films' columns, not M, K)
        parts = b.system_parts(0, 1, 2, name, rot=(0, 1)) if getattr(b, "tilt", False) \
            else b.system_parts(0, 1, 2, name)
        if parts.M.shape == K.shape:
            return K + parts.K, C + parts.C, parts.M
    own = idx[2:]  # sleeve masters: their stiffness and mass (no journal coupling)
    K[2:, 2:] += lm.K_structure[np.ix_(own, own)]
    C[2:, 2:] += lm.C_structure[np.ix_(own, own)]
    M[2:, 2:] = lm.M[np.ix_(own, own)]
    return K, C, M


def bearing_coefficients(system, speeds_hz, chamber_pressure_pa: float = 0.0,
                         config_ay_m: float | None = None, *, whirl_ratio: float = 1.0,
                         progress=None, equilibria: list | None = None) -> pd.DataFrame:
    """Every fluid-film or table bearing's kxx … cyy over ``speeds_hz`` (Hz), in the system.

    Returns a tidy frame, one row per (bearing, speed): ``bearing`` (its name, or
    ``bearing[i]``), ``station``, ``speed_hz``, ``kxx_n_per_m`` … ``kyy_n_per_m`` (N/m),
    ``cxx_n_s_per_m`` … ``cyy_n_s_per_m`` (N·s/m), ``status`` (the equilibrium's; NaN
    coefficients where it did not converge). Convention dF = −K dq − C dq̇ (DESIGN frame: x
    horizontal, y up). ``whirl_ratio``: ν/Ω at which pads and sleeve are condensed (1:
    synchronous, as API 684 tabulates them; 0: static condensation). ``progress``: called as
    ``progress(i, n)`` after each speed. ``equilibria``: a list that receives, in increasing
    speed, ``(speed_hz, status, EquilibriumResult | None)`` of each speed's equilibrium (None
    where the solve raised), for tables of the same operating points."""
    import pandas as pd
    sp = np.atleast_1d(np.asarray(speeds_hz, dtype=float))
    if sp.ndim != 1 or sp.size == 0 or not np.all(np.isfinite(sp)) or np.any(sp < 0):
        raise InputError(f"speeds_hz: expected finite speeds ≥ 0 Hz, got {speeds_hz!r}")
    v.finite("whirl_ratio", whirl_ratio)
    if whirl_ratio < 0:
        raise InputError(f"whirl_ratio: expected ≥ 0, got {whirl_ratio!r}")
    if not system.bearings:
        return pd.DataFrame({c: [] for c in COLUMNS})
    order = np.argsort(sp, kind="stable")
    rows: dict[int, list] = {}
    for k, status, lm in continued_linear_models(system, sp[order], chamber_pressure_pa,
                                                 config_ay_m, "perturbation",
                                                 continue_on=("ok", "contact")):
        i = int(order[k])
        if equilibria is not None:
            equilibria.append((float(sp[i]), status, lm.equilibrium if lm is not None else None))
        out = []
        lab = list(lm.labels) if lm is not None else []
        for bi, b in enumerate(system.bearings):
            name = b.name or f"bearing[{bi}]"
            KC = np.full(8, np.nan)
            if lm is not None and status in CONVERGED:
                idx = [lab.index(f"station{b.station}.x"), lab.index(f"station{b.station}.y")]
                idx += [j for j, s in enumerate(lab) if s.startswith(name + ".")]
                Kb, Cb, Mb = _element_matrices(lm, b, name, idx)
                K, C = reduce_coefficients(Kb, Cb, Mb, whirl_ratio * hz_to_rad_s(sp[i]))
                KC = np.concatenate([K.ravel(), C.ravel()])
            out.append([name, int(b.station), float(sp[i]), *KC, status])
        rows[i] = out
        if progress is not None:
            progress(len(rows), sp.size)
    flat = [r for i in range(sp.size) for r in rows.get(i, [])]
    df = pd.DataFrame(flat, columns=list(COLUMNS))
    return df.sort_values(["bearing", "speed_hz"], key=lambda c: c.map(
        {(b.name or f"bearing[{i}]"): i for i, b in enumerate(system.bearings)})
        if c.name == "bearing" else c, ignore_index=True, kind="stable")


__all__ = ["COLUMNS", "bearing_coefficients"]
