"""Linearised model about the equilibrium (paper eq. 17-20) and eigenvalue stability (eq. 19).

K_H and D_H come from the perturbation method (linearised Reynolds equation sharing the base
solve's factorisation, the default) or from the paper's finite differences (eq. 20, central,
steps scaled to c and c·ω)."""

from __future__ import annotations

from rotordyn._common.threads import limited_blas

import numpy as np

from rotordyn import _core
from rotordyn.analysis.assembly import Assembled, assembled
from rotordyn.analysis.equilibrium import equilibrium
from rotordyn._common import validate as v
from rotordyn.model.system import System
from rotordyn.errors import ConvergenceError
from rotordyn.results.equilibrium import CONVERGED, EquilibriumResult
from rotordyn.results.modes import WHIRL_NAMES
from rotordyn.results.stability import LinearModel, StabilityResult
from rotordyn.units import hz_to_rad_s

LINEARIZATION_METHODS = ("perturbation", "finite_difference")
# Step of the eq. 20 differences, relative to c (positions) and c·ω (velocities). 1e-6 keeps
# the central differences inside one cavitation pattern (a 1e-5 velocity step crossed a
# pattern change on the rig at 70 Hz, 0.4 MPa: one D_H entry 1.03 % off); the forces are
# accurate to ~1e-15, so the truncation/round-off balance is still far from the limit.
FD_REL_STEP = 1e-6


def coordinate_labels(asm: Assembled) -> tuple:
    """Names of the system coordinates: ``station<k>.x``/``.y`` (a full model: also
    ``.rot_x``/``.rot_y``, and ``node<i>.…`` for FE nodes that are not stations; a reduced
    model: the rotations ``.rot_x``/``.rot_y`` of the stations a tilting film keeps as
    masters, then ``cb_mode<j>``), then ``<bearing>.sleeve<j>`` and the elements' own
    coordinates (pad tilts, pivots, pitches)."""
    s = asm.system
    if asm.rotor.reduction is None:
        station_of = {int(nd): st for st, nd in enumerate(s.rotor.station_nodes())}
        comp = ("x", "y", "rot_x", "rot_y")  # the FE node's DOF order
        names = [(f"station{station_of[d // 4]}" if d // 4 in station_of else f"node{d // 4}")
                 + f".{comp[d % 4]}" for d in (int(x) for x in asm.rotor.full.dofs)]
    else:
        names = [f"station{st}.{c}" for st in s.reduction.master_stations for c in "xy"]
        names += [f"station{st}.{c}" for st in s.tilt_stations() for c in ("rot_x", "rot_y")]
        names += [f"cb_mode{j + 1}" for j in range(asm.n_rotor - len(names))]
    for bc in asm.bearings:
        names += [f"{bc.name}.sleeve{j + 1}" for j in range(len(bc.sleeve))]
    names += list(getattr(asm, "extra_labels", []))
    return tuple(names)


def _linear_from(asm: Assembled, e: EquilibriumResult, speed_hz: float, method: str,
                 rel_step: float) -> LinearModel:
    w = hz_to_rad_s(float(speed_hz))
    m = asm.model
    n = asm.n
    if e.status in CONVERGED:
        if method == "perturbation":
            lin = asm.solver.linearize(e.r, np.zeros(n), w)
        else:
            lin = asm.solver.linearize_fd(e.r, w, rel_step)
        KH, DH = np.asarray(lin.KH), np.asarray(lin.DH)
        if np.asarray(m.Kc).size:  # the solver's K_H carries the shaft's Ω K_c: take it out
            KH = KH - w * np.asarray(m.Kc)
        if not (np.all(np.isfinite(KH)) and np.all(np.isfinite(DH))):
            raise ConvergenceError(f"linearize: non-finite K_H or D_H at {speed_hz:g} Hz "
                                   f"({method}); the film solve is not trustworthy here")
        if asm.bearings and not (np.any(KH) or np.any(DH)):
            raise ConvergenceError(f"linearize: K_H and D_H are identically zero at {speed_hz:g} Hz "
                                   f"({method}): a degenerate linearisation")
    else:
        KH = DH = np.full((n, n), np.nan)
    K0, C0, G = (np.asarray(x) for x in (m.K, m.C, m.G))
    kc = np.asarray(m.Kc)
    if kc.size:  # rotating shaft damping: K_s at this speed, K + Ω K_c (K_H: the bearings')
        K0 = K0 + w * kc
    # bearing tables with mass coefficients: M(Ω) at this speed
    M = np.asarray(m.mass_at(w) if m.has_table_mass() else m.M)
    return LinearModel(speed_hz=float(speed_hz), M=M, D=C0 + w * G + DH, K=K0 + KH, KH=KH,
                       DH=DH, K_structure=K0, C_structure=C0, G=G,
                       chamber=np.asarray(m.chamber), labels=coordinate_labels(asm),
                       equilibrium=e, method=method)


@limited_blas
def linearize(system: System, speed_hz: float = 50.0, chamber_pressure_pa: float = 0.0,
              config_ay_m: float | None = None, *, method: str = "perturbation",
              rel_step: float = FD_REL_STEP, **equilibrium_kw) -> LinearModel:
    """Equilibrium, then K_H and D_H (eq. 18) and the matrices of eq. 19.

    method: ``"perturbation"`` (default) or ``"finite_difference"`` (eq. 20, central, steps
    ``rel_step``·c and ``rel_step``·c·ω). Other keywords go to :func:`equilibrium`.
    """
    v.choice("method", method, LINEARIZATION_METHODS)
    v.in_range("rel_step", rel_step, 1e-10, 0.1, hi_open=True)
    e = equilibrium(system, speed_hz, chamber_pressure_pa, config_ay_m, **equilibrium_kw)
    return _linear_from(assembled(system), e, speed_hz, method, rel_step)


def mode_window(kind, n_modes: int) -> np.ndarray:
    """Indices of the modes kept by a cut to ``n_modes`` (modes in ascending damped frequency,
    ``kind`` (k,) "rotor"/"sleeve"/"pad"): the lowest ``n_modes`` modes that are not a tilting
    pad's own, plus the pad modes below the highest of them (they are listed, never counted)."""
    kind = np.asarray(kind)
    own = np.flatnonzero(kind != "pad")[:n_modes]
    top = own[-1] if own.size else -1
    return np.flatnonzero((kind != "pad") & (np.arange(kind.size) <= top)
                          | (kind == "pad") & (np.arange(kind.size) < top))


def _stability_from(asm: Assembled, lm: LinearModel, n_modes: int | None,
                    verdict: bool = True) -> StabilityResult:
    """The modes of ``lm`` (the lowest ``n_modes``); ``verdict``: also every root past that
    cut for the point's verdict (an extra eigenvalues-only solve; a Campbell diagram, which
    reports no verdict, skips it)."""
    n = asm.n
    xy = asm.rotor.xy_pairs()
    if lm.status not in CONVERGED or not np.all(np.isfinite(lm.K)):
        empty = np.zeros(0, dtype=complex)
        return StabilityResult(lm, empty, np.zeros(0, dtype=object), np.zeros(0, dtype=object),
                               np.zeros((0, 4, 0), dtype=complex), status=lm.status,
                               message=lm.equilibrium.message or "no equilibrium")
    pads = [i for bc in asm.bearings for i in getattr(bc, "extra", ())]
    # With tilting pads the cut to the lowest ``n_modes`` is taken over the system's modes, not
    # the pads' own (issue 18: pad modes took slots and rotor branches vanished from a
    # Campbell): every mode is computed, classified, then cut below.
    ask = n if (pads or n_modes is None) else int(n_modes)
    r = _core.modal(lm.M, lm.D, lm.K, xy, ask, True, asm.rotor.rot_pairs())
    lam = np.asarray(r.eigenvalues)
    # the verdict covers every root: a cut to n_modes leaves the rest out of the modes only
    every = (np.asarray(_core.modal(lm.M, lm.D, lm.K, xy, 0, False,
                                    asm.rotor.rot_pairs()).eigenvalues)
             if ask < n and verdict else None)
    phi = np.asarray(r.modes)  # (n, k)
    whirl_code = np.asarray(r.whirl)
    if not (np.all(np.isfinite(lam)) and np.all(np.isfinite(phi))):
        raise ConvergenceError(f"stability: non-finite eigenvalues at {lm.speed_hz:g} Hz")
    # Which part carries the mode: kinetic-energy share of the sleeve coordinates.
    sl = [i for bc in asm.bearings for i in bc.sleeve]
    kin_total = np.real(np.einsum("ik,ij,jk->k", phi.conj(), lm.M, phi))
    if sl:
        Ms = lm.M[np.ix_(sl, sl)]
        kin_s = np.real(np.einsum("ik,ij,jk->k", phi[sl].conj(), Ms, phi[sl]))
    else:
        kin_s = np.zeros(len(lam))
    kind = np.where(kin_s > 0.5 * kin_total, "sleeve", "rotor").astype(object)
    if pads:  # tilting-pad coordinates: modes carried by the pads
        Mp = lm.M[np.ix_(pads, pads)]
        kin_p = np.real(np.einsum("ik,ij,jk->k", phi[pads].conj(), Mp, phi[pads]))
        kind[kin_p > 0.5 * kin_total] = "pad"
        if n_modes is not None:
            every = lam  # the verdict over every root, pads' own included
            sel = mode_window(kind, n_modes)
            lam, phi, whirl_code, kind = lam[sel], phi[:, sel], whirl_code[sel], kind[sel]
    rotor = asm.rotor.expand(phi[:asm.n_rotor])
    n_nodes = rotor.shape[0] // 4
    sleeves = {bc.index: asm.sleeves[bc.index].transformation @ phi[list(bc.sleeve)]
               for bc in asm.bearings if bc.sleeve}
    return StabilityResult(lm, lam, np.array([WHIRL_NAMES[int(x)] for x in whirl_code],
                                             dtype=object),
                           kind, rotor.reshape(n_nodes, 4, -1), sleeves, status=lm.status,
                           message=lm.equilibrium.message, modes=phi, all_eigenvalues=every)


@limited_blas
def stability(system: System, speed_hz: float = 50.0, chamber_pressure_pa: float = 0.0,
              config_ay_m: float | None = None, *, n_modes: int | None = None,
              method: str = "perturbation", thermal=None, **equilibrium_kw) -> StabilityResult:
    """Eigenvalues of eq. 19 at the equilibrium: damped natural frequencies, damping ratios,
    logarithmic decrements, whirl, mode shapes (full rotor and full sleeve); ``.stable`` when
    every real part is negative. ``n_modes``: lowest damped frequencies kept (default all),
    counted over the rotor's (and sleeves') modes: a tilting pad's own modes (kind "pad") below
    the cut are kept besides them, never counted (:func:`mode_window`).

    ``thermal``: None (isothermal films), True (the model's ``[thermal]``) or a dict of
    :func:`rotordyn.system_thermal_equilibrium` keywords: the point's thermal equilibrium
    first, then K_H, D_H with its temperature field frozen (the result's ``thermal``;
    ConvergenceError when the thermal equilibrium fails; :mod:`.thermal_dynamics`)."""
    if n_modes is not None:
        n_modes = min(v.integer("n_modes", n_modes, lo=1), assembled(system).n)
    if thermal is not None and thermal is not False:
        from rotordyn.analysis.thermal_dynamics import thermal_keywords, thermal_stability

        return thermal_stability(stability, system, speed_hz, chamber_pressure_pa, config_ay_m,
                                 n_modes=n_modes, method=method,
                                 thermal=thermal_keywords(thermal), **equilibrium_kw)
    lm = linearize(system, speed_hz, chamber_pressure_pa, config_ay_m, method=method,
                   **equilibrium_kw)
    return _stability_from(assembled(system), lm, n_modes)


def continued_linear_models(system: System, speeds_hz, chamber_pressure_pa: float,
                            config_ay_m: float | None, method: str,
                            continue_on=("ok",), errors: dict | None = None):
    """Yield ``(index, status, LinearModel | None)`` along increasing ``speeds_hz``: each
    equilibrium starts from the last one whose status is in ``continue_on`` (continuation),
    then K_H(Ω), D_H(Ω). A point whose solve raises is ``(i, "error", None)`` (``errors[i]``:
    ``"<ErrorClass>: <what>"`` when a dict is given); the sequence goes on. Used by the Campbell diagram, gain schedules and bearing coefficients (the
    unbalance response runs the same sequence in one C++ call, ``_core.unbalance_sweep``)."""
    from rotordyn.errors import RotordynError

    asm = assembled(system)
    r0 = None
    for i, s in enumerate(speeds_hz):
        try:
            e = equilibrium(system, float(s), chamber_pressure_pa, config_ay_m, r0=r0,
                            warm_start=r0 is None)
            lm = _linear_from(asm, e, float(s), method, FD_REL_STEP)
        except RotordynError as exc:
            if errors is not None:
                errors[i] = f"{type(exc).__name__}: {exc}"
            yield i, "error", None
            continue
        if e.status in continue_on:
            r0 = e.r
        yield i, e.status, lm
