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
from rotordyn.units import hz_to_rad_s, tilt_unit_stem

if TYPE_CHECKING:
    import pandas as pd

COLUMNS = ("bearing", "station", "speed_hz") + tuple(
    f"{n}_n_per_m" for n in COEFF_NAMES[:4]) + tuple(
    f"{n}_n_s_per_m" for n in COEFF_NAMES[4:]) + ("status",)
# A tilting film (tilt = true): its 4×4 over (x, y, θx, θy) beyond the translational block,
# K[i, j] = −∂H_i/∂r_j, C the same per velocity, as columns ``k<i><j>_<unit stem>`` with tx,
# ty for θx, θy: the force–tilt, moment–translation and tilt–tilt blocks, each entry's unit
# from rotordyn.units.tilt_unit_stem (N/rad … N·m·s/rad); NaN for a bearing without one.
_Q = ("x", "y", "tx", "ty")
TILT_COLUMNS = tuple(f"{kc}{_Q[i]}{_Q[j]}_{tilt_unit_stem(kc, i, j)}"
                     for kc in ("k", "c") for i in range(4) for j in range(4)
                     if i >= 2 or j >= 2)


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


def _tilt_entries(lm, b, name: str, idx: list[int], rot, nu: float) -> np.ndarray:
    """The 12 entries of :data:`TILT_COLUMNS` of a tilting film's element: its own
    coordinates condensed at ν onto (x, y, θx, θy) as :func:`_element_matrices` condenses
    them onto (x, y) (the element's own M, K, C do not involve the rotations)."""
    K2, C2, M2 = _element_matrices(lm, b, name, idx)
    KH2, DH2 = lm.KH[np.ix_(idx, idx)], lm.DH[np.ix_(idx, idx)]
    idx4 = idx[:2] + list(rot) + idx[2:]
    K4 = lm.KH[np.ix_(idx4, idx4)].copy()
    C4 = lm.DH[np.ix_(idx4, idx4)].copy()
    M4 = np.zeros_like(K4)
    pos = [0, 1] + list(range(4, len(idx4)))
    K4[np.ix_(pos, pos)] += K2 - KH2
    C4[np.ix_(pos, pos)] += C2 - DH2
    M4[np.ix_(pos, pos)] = M2
    K, C = reduce_coefficients(K4, C4, M4, nu, n_journal=4)
    keep = [(i, j) for i in range(4) for j in range(4) if i >= 2 or j >= 2]
    return np.array([K[i, j] for i, j in keep] + [C[i, j] for i, j in keep])


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
    where the solve raised), for tables of the same operating points. With a tilting film
    (``tilt = true``) the frame also has :data:`TILT_COLUMNS`: the rest of that film's 4×4
    over (x, y, θx, θy), condensed alike (NaN for the other bearings)."""
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
    tilts = any(getattr(b, "tilt", False) for b in system.bearings)
    rot = {}
    if tilts:
        from rotordyn.analysis.assembly import assembled

        rot = {bc.index: bc.rot for bc in assembled(system).bearings if bc.rot}
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
            KT = np.full(len(TILT_COLUMNS) if tilts else 0, np.nan)
            if lm is not None and status in CONVERGED:
                idx = [lab.index(f"station{b.station}.x"), lab.index(f"station{b.station}.y")]
                idx += [j for j, s in enumerate(lab) if s.startswith(name + ".")]
                Kb, Cb, Mb = _element_matrices(lm, b, name, idx)
                nu = whirl_ratio * hz_to_rad_s(sp[i])
                K, C = reduce_coefficients(Kb, Cb, Mb, nu)
                KC = np.concatenate([K.ravel(), C.ravel()])
                if bi in rot:
                    KT = _tilt_entries(lm, b, name, idx, rot[bi], nu)
            out.append([name, int(b.station), float(sp[i]), *KC, status, *KT])
        rows[i] = out
        if progress is not None:
            progress(len(rows), sp.size)
    flat = [r for i in range(sp.size) for r in rows.get(i, [])]
    df = pd.DataFrame(flat, columns=list(COLUMNS) + (list(TILT_COLUMNS) if tilts else []))
    return df.sort_values(["bearing", "speed_hz"], key=lambda c: c.map(
        {(b.name or f"bearing[{i}]"): i for i, b in enumerate(system.bearings)})
        if c.name == "bearing" else c, ignore_index=True, kind="stable")


__all__ = ["COLUMNS", "TILT_COLUMNS", "bearing_coefficients"]
