"""Static equilibrium of the multi-bearing system (paper eq. 14): Newton (default) or the
paper's successive substitution with the relaxation coefficient P_m (eq. 16)."""

from __future__ import annotations

from rotordyn._common.threads import limited_blas

import numpy as np

from rotordyn import _core
from rotordyn.analysis.assembly import assembled, chamber_pressure
from rotordyn._common.status import CONVERGED
from rotordyn.bearings import TiltingPadBearing
from rotordyn.errors import InputError
from rotordyn._common import validate as v
from rotordyn.model.system import System
from rotordyn.results.equilibrium import EquilibriumResult
from rotordyn.units import hz_to_rad_s


def equilibrium_options(method: str = "newton", pm: float | str = "auto", tol: float = 1e-10,
                        max_iter: int = 100, contact_fraction: float = 0.02):
    """The core's options of :func:`equilibrium` (arguments already validated); also the
    options of the analyses that solve their equilibria in one C++ call."""
    opt = _core.EquilibriumOptions()
    opt.method, opt.tol, opt.max_iter = method, float(tol), int(max_iter)
    opt.pm = -1.0 if pm == "auto" else float(pm)
    opt.contact_fraction = float(contact_fraction)
    opt.polish = True  # the answer is the root to round-off, not the first iterate within tol
    return opt


@limited_blas
def equilibrium(system: System, speed_hz: float = 50.0, chamber_pressure_pa: float = 0.0,
                config_ay_m: float | None = None, *, config_ax_m: float | None = None,
                method: str = "newton", pm: float | str = "auto", tol: float = 1e-10,
                max_iter: int = 100, warm_start: bool = True, r0=None,
                contact_fraction: float = 0.02) -> EquilibriumResult:
    """Equilibrium of K (r + a) = H(Ω, r, 0) + Q + C_s0 (eq. 14).

    Parameters
    ----------
    speed_hz : spin speed, Hz (> 0: counter-clockwise seen from the non-drive end).
    chamber_pressure_pa : p_c of every active bearing, Pa (≥ 0).
    config_ay_m, config_ax_m : housing offset of the active bearing (paper §6: a_y > 0 above
        the line through the ball bearings); None keeps the model's values.
    method : ``"newton"`` (line search, Jacobian K + K_H) or ``"successive"`` (eq. 16, with
        ``pm`` = P_m; ``"auto"`` picks the P_m that minimises the spectral radius of the
        iteration at the starting point).
    tol : residual ‖K(r + a) − H − Q − C_s0‖∞ relative to the largest load.
    warm_start : start from the last equilibrium of this system solved within the same
        public call (an analysis continuing along its own points calls this function so), else
        from the concentric, undeformed state; unless ``r0`` is given. A direct call starts
        cold: nothing of an earlier call survives into it (rotordyn._common.calls), so the
        same inputs give the same answer bit for bit whatever ran before. To continue from a
        known equilibrium pass its ``r`` as ``r0``.
    contact_fraction : a converged equilibrium whose minimum film thickness is below this
        fraction of its clearance has status ``"contact"``.

    Returns
    -------
    EquilibriumResult with ``status``: ``"ok"`` or ``"contact"`` (converged: only these are
    linearised, classified or integrated from), ``"not_converged"`` (the iteration failed) or
    ``"no_equilibrium"`` (the iteration failed with a film closing: no equilibrium with an
    open film was found); ``message`` says why.
    """
    v.speed("speed_hz", speed_hz)
    chamber_pressure(system, chamber_pressure_pa)
    if config_ay_m is not None:
        v.finite("config_ay_m", config_ay_m)
    if config_ax_m is not None:
        v.finite("config_ax_m", config_ax_m)
    v.choice("method", method, ("newton", "successive"))
    if pm != "auto":
        v.non_negative("pm", pm)
    v.in_range("tol", tol, 0.0, 1e-2, lo_open=True)
    v.integer("max_iter", max_iter, lo=1, hi=10_000)
    v.boolean("warm_start", warm_start)
    v.in_range("contact_fraction", contact_fraction, 0.0, 1.0, hi_open=True)
    asm = assembled(system)
    a = asm.config_vector(config_ay_m, config_ax_m)
    if r0 is not None:
        r_init = v.vector("r0", r0, asm.n)
    elif warm_start and asm.last_r is not None:
        r_init = asm.last_r
    else:
        r_init = np.zeros(0)
    opt = equilibrium_options(method, pm, tol, max_iter, contact_fraction)
    omega = hz_to_rad_s(float(speed_hz))
    if asm.pad_penalty is None:
        res = asm.solver.equilibrium(omega, float(chamber_pressure_pa), a, r_init, opt)
    else:
        # tilting pads: the pad assembly, and where it fails the pad-tilt homotopy from the
        # concentric state (no jump onto an unloaded pad's pressure-free branch) — C++, the
        # same function as the coefficient tables
        res = _core.pad_system_equilibrium(asm.solver, asm.model, omega,
                                           float(chamber_pressure_pa), a, r_init, np.zeros(0),
                                           opt, asm.pad_penalty)
    path = res.path
    r = np.asarray(res.r)
    if res.status == "ok":
        asm.last_r = r.copy()
    bcs = asm.bearings
    h_min, h_ang = asm.bearing_h_min(np.asarray(res.h_min), np.asarray(res.h_min_angle_deg))
    film_force = np.asarray(res.film_force)  # the bearings' own (C++: less −Ω K_c r)
    return EquilibriumResult(
        speed_hz=float(speed_hz), chamber_pressure_pa=float(chamber_pressure_pa),
        config_ay_m=np.array([a[bc.jy] for bc in bcs]),
        config_ax_m=np.array([a[bc.jx] for bc in bcs]),
        method=method, r=r, film_force_n=film_force,
        bearing_names=tuple(bc.name for bc in bcs),
        journal_x_m=np.array([r[bc.jx] for bc in bcs]),
        journal_y_m=np.array([r[bc.jy] for bc in bcs]),
        clearance_m=np.array([bc.clearance_m for bc in bcs]),
        h_min_m=h_min, h_min_angle_deg=h_ang,
        sleeve_m={bc.index: r[list(bc.sleeve)] for bc in bcs if bc.sleeve},
        iterations=int(res.iterations), reynolds_solves=int(res.reynolds_solves),
        residual=float(res.residual), status=res.status, message=res.message,
        pm=float(res.pm) if method == "successive" else float("nan"), path=path,
        tilt=tilt_outputs(asm, r, a, np.asarray(res.h_min_z_m), np.asarray(res.h_min),
                          film_force),
        pads=pad_outputs(asm, r, omega, np.asarray(res.h_min)) if res.status in CONVERGED
        else {},
    )


# A pad whose peak film pressure is below this fraction of its film's pressure scale
# μ|Ω|(R/c)² carries no load: the round-off pressures of a pressure-free pad (4e-8 Pa on the
# compressor's top pads at 40 Hz against a 1e6 Pa scale) are 14 orders below it.
UNLOADED_PAD_REL = 1e-9


def pad_outputs(asm, r, omega: float, h_min_films) -> dict:
    """Per tilting-pad bearing (any, tilted or not), every pad's state at the equilibrium
    ``r`` (pad order, tuples): ``pad_pivot_deg`` (pivot angle, deg), ``pad_tilt_rad`` (δ_k,
    rad), ``pad_p_max_pa`` (peak film pressure, Pa), ``pad_h_min_m`` (minimum film, m) and
    ``pad_unloaded`` (True for a pad whose film carries no pressure: its peak is below
    ``UNLOADED_PAD_REL`` μ|Ω|(R/c)² — an unloaded pad, prone to flutter). Refreshes the
    films' pressures with one film evaluation at ``r``."""
    pad_bearings = [bc for bc in asm.bearings
                    if isinstance(asm.system.bearings[bc.index], TiltingPadBearing)]
    if not pad_bearings:
        return {}
    asm.solver.film_forces(r, np.zeros(len(r)), omega)  # the pressures at r
    out = {}
    for bc in pad_bearings:
        b = asm.system.bearings[bc.index]
        films = [k for k, o in enumerate(asm.film_owner) if o == bc.index]
        eta = [j for j, lab in zip(bc.extra, bc.labels) if lab.endswith(".eta")]
        psi = np.radians(b.pivot_angles_deg())
        tilt = (np.asarray([r[j] for j in eta]) + r[bc.jx] * np.sin(psi)
                - r[bc.jy] * np.cos(psi)) / b.lever_m
        p_max = np.array([float(np.max(asm.solver.last_pressure(k))) for k in films])
        R = 0.5 * b.diameter_m
        scale = b.viscosity_pa_s * abs(omega) * (R / b.clearance_m) ** 2
        out[bc.index] = {
            "pad_pivot_deg": tuple(float(x) for x in b.pivot_angles_deg()),
            "pad_tilt_rad": tuple(float(x) for x in tilt),
            "pad_p_max_pa": tuple(float(x) for x in p_max),
            "pad_h_min_m": tuple(float(h_min_films[k]) for k in films),
            "pad_unloaded": tuple(bool(x <= UNLOADED_PAD_REL * scale) for x in p_max)}
    return out


def tilt_outputs(asm, r, a, h_min_z_films, h_min_films=None, film_force=None) -> dict:
    """Per tilting-film bearing: its journal rotations relative to the housing, the housing
    misalignment, the axial position of its minimum film (EquilibriumResult.tilt; a lobed
    or pad bearing's: its thinnest film's, ``h_min_films`` the films' minimum films) and,
    with ``film_force`` (the films' H at the equilibrium, (n,)), the films' moments on the
    journal about x and y (N·m, the rotations' entries of H); for
    tilting pads also every pad's minimum film and its z (tuples, pad order) and, with
    spherical pivots, the pads' pitches (rad)."""
    out = {}
    for bc in asm.bearings:
        if not bc.rot:
            continue
        i = asm.film_owner.index(bc.index) if h_min_films is None \
            else int(asm.min_film_index(bc.index, h_min_films))
        out[bc.index] = {"journal_theta_x_rad": float(r[bc.rot[0]]),
                         "journal_theta_y_rad": float(r[bc.rot[1]]),
                         "config_theta_x_rad": float(a[bc.rot[0]]),
                         "config_theta_y_rad": float(a[bc.rot[1]]),
                         "h_min_z_m": float(h_min_z_films[i])}
        if film_force is not None and len(film_force) == len(r):
            out[bc.index]["film_moment_x_n_m"] = float(film_force[bc.rot[0]])
            out[bc.index]["film_moment_y_n_m"] = float(film_force[bc.rot[1]])
        if bc.extra and h_min_films is not None:  # tilting pads: every pad's edge film
            films = [k for k, o in enumerate(asm.film_owner) if o == bc.index]
            out[bc.index]["pad_h_min_m"] = tuple(float(h_min_films[k]) for k in films)
            out[bc.index]["pad_h_min_z_m"] = tuple(float(h_min_z_films[k]) for k in films)
            pitch = [j for j, lab in zip(bc.extra, bc.labels) if lab.endswith(".pitch")]
            if pitch:
                out[bc.index]["pad_pitch_rad"] = tuple(float(r[j]) for j in pitch)
    return out
