"""Thermal equilibrium of a bearing with a tilted (misaligned) journal, standalone (issue 20;
docs/film-physics.md, "Thermal films with a tilted journal"): fixed-geometry lobes, the plain
journal bearing and tilting pads.

The journal is held at the tilt (θx, θy) relative to the bearing (the bearing's misalignment
seen by a journal parallel to the shaft line, as :func:`rotordyn.bearings.tilt.
misaligned_equilibrium`); every film's thickness carries the tilt in its base thickness,
h(φ, z) = C_p − (C_p − C_b) cos(φ − φ_p) − (x + θy z) cos φ − (y − θx z) sin φ, and the
thermal model (THD: the energy equation on each film's full (φ, z) grid; or the
effective-temperature model) is iterated with the force balance on (x, y) under the load in
one C++ call (``_core.thermal_system_equilibrium``):

* fixed-geometry lobes: per lobe, with hot-oil carry-over between lobes, in the call of the
  untilted bearing (:func:`rotordyn.bearings.pad_thd.pad_thd_equilibrium`);
* the plain bearing (:func:`plain_tilted_thermal_equilibrium`): its one film with the plain
  film's heat balance (its own recirculation, as in a system), the system core's Newton on
  (x, y) — not the untilted standalone's ReynoldsSolver Newton, so a zero tilt equals the
  untilted standalone result to the equilibrium's tolerance, not bit for bit;
* tilting pads (:func:`pad_tilted_thermal_equilibrium`): the journal's tilt (and a spherical
  pad's pitch origin γ = θ·t) held in the pads' base films (:mod:`rotordyn.bearings.
  tilt_pads`), the pads free, in the call of the untilted bearing.

A tilted film is not symmetric in z: its grid is solved whole, and its temperature field is
not symmetrised. At that thermal equilibrium, with the temperature (viscosity) field
**frozen**, the four-coordinate films give the moments on the journal, the edge film and the
4×4 K, C over (x, y, θx, θy) (ΔH = −K Δr − C Δṙ, the convention of :mod:`rotordyn.bearings.
tilt`; tilting pads condensed at the whirl frequency). ``theta_x_rad``, ``theta_y_rad`` are the
inputs (the held tilt); the results carry it as ``journal_theta_x_rad``,
``journal_theta_y_rad``, with ``force_n`` and ``film_moment_n_m`` (the names of
:mod:`rotordyn.bearings.tilt_names`)."""

from __future__ import annotations

import copy
import dataclasses
import math

import numpy as np

from rotordyn import _core
from rotordyn._common import validate as v
from rotordyn.bearings._film import SystemParts, imposed_tilt, min_film, reduce_coefficients
from rotordyn.bearings.pad_thd import failed_equilibrium, pad_fields, pad_thd_equilibrium
from rotordyn.errors import InputError

TWO_PI = 2.0 * math.pi


def tilted_thermal_equilibrium(bearing, *, theta_x_rad: float, theta_y_rad: float, oil, opts,
                               load_n, speed_hz: float):
    """The thermal equilibrium of ``bearing`` (a :class:`rotordyn.bearings.
    FixedGeometryBearing`) under ``load_n`` (N) with the journal tilted by (θx, θy) rad
    relative to it; ``opts``: the checked options (:func:`rotordyn.bearings.pad_thd.
    pad_model_options`). A :class:`rotordyn.bearings.pad_thd.PadThdResult` with the tilt,
    the moments (N·m), the edge film and K4, C4 at the frozen field."""
    tx, ty = v.finite("theta_x_rad", theta_x_rad), v.finite("theta_y_rad", theta_y_rad)
    h, z = bearing.edge_film(0.0, 0.0, tx, ty)
    if not h > 0.0:
        raise InputError(f"theta_x_rad, theta_y_rad: the tilted journal closes a lobe's film at "
                         f"the edge z = {z:+g} m (minimum film {h:.6g} m of a centred journal); "
                         "expected a tilt whose edge film stays > 0 over the lobes at z = ±L/2")
    name = bearing.name or "bearing"
    lobes = bearing.films(0, 1, name, rot=(2, 3))
    for p in lobes:
        imposed_tilt(p.coupling, tx, ty)
    res = pad_thd_equilibrium(SystemParts(films=lobes, tables=[]), oil=oil, opts=opts,
                              load_n=load_n, speed_hz=speed_hz,
                              clearance_m=bearing.clearance_m, whirl_ratio=None)
    # the frozen field on the lobes' four-coordinate films: moments, edge film, K4, C4
    four = bearing.films(0, 1, name, rot=(2, 3))
    pad_fields(res.viscosity_pa_s, four, "viscosity_field_pa_s")
    model = _core.SystemModel()
    z = np.zeros((4, 4))
    model.M, model.K, model.C, model.G = z, z, z, z
    model.Q, model.chamber = np.zeros(4), np.zeros(4)
    model.films = [p.coupling for p in four]
    solver = _core.SystemSolver(model)
    r4 = np.array([res.x_m, res.y_m, tx, ty])
    w = TWO_PI * float(speed_hz)
    H = np.asarray(solver.film_forces(r4, np.zeros(4), w))
    h_min, h_ang, h_z = min_film(solver, [p.phi for p in four])
    lin = solver.linearize(r4, np.zeros(4), w)
    return dataclasses.replace(res, journal_theta_x_rad=tx, journal_theta_y_rad=ty,
                               force_n=H[:2].copy(), film_moment_n_m=H[2:].copy(),
                               h_min_m=h_min, h_min_angle_deg=h_ang, h_min_z_m=h_z,
                               K4=np.array(lin.KH), C4=np.array(lin.DH))




def _film_model(films, n: int, K=None, M=None, Q=None):
    """A SystemModel of ``films`` over n coordinates: structural K, M (zero unless given,
    e.g. the pads'), no damping or gyroscopics, the load Q (N; zero unless given)."""
    z = np.zeros((n, n))
    model = _core.SystemModel()
    model.M, model.K, model.C, model.G = (z if M is None else M), (z if K is None else K), z, z
    model.Q, model.chamber = (np.zeros(n) if Q is None else Q), np.zeros(n)
    model.films = list(films)
    return model


def _four_solver(films, K=None, M=None):
    """A SystemSolver over the four journal coordinates (and any pad coordinates after them)
    of ``films``, with the structural K, M of the pads (zero for plain films and lobes)."""
    return _core.SystemSolver(_film_model(films, 4 if K is None else K.shape[0], K, M))


def plain_tilted_thermal_equilibrium(bearing, *, theta_x_rad: float, theta_y_rad: float, oil,
                                     opts, load_n, speed_hz: float):
    """The thermal equilibrium of a plain journal bearing (:class:`rotordyn.JournalBearing`
    or a model's :class:`rotordyn.FluidFilmBearing`) under ``load_n`` (N, on the journal) with
    the journal tilted by (θx, θy) rad relative to it; ``opts``: ``_core.ThermalOptions``
    (effective temperature) or ``_core.ThdOptions`` (THD). A
    :class:`rotordyn.bearings.ThermalEquilibriumResult` or :class:`rotordyn.bearings.thd.
    ThdEquilibriumResult` with the tilt, the moments (N·m), the edge film and K4, C4 at the
    frozen field (K, C: their translational block). A failed equilibrium raises
    ConvergenceError with the core's status and message."""
    from rotordyn.bearings.thd import ThdEquilibriumResult
    from rotordyn.bearings.thermal import Oil, ThermalEquilibriumResult
    from rotordyn.bearings.tilt_film import check_plain_pose, tilt_coupling

    if not isinstance(oil, Oil):
        raise InputError(f"oil: expected a rotordyn.bearings.Oil, got {oil!r}")
    tx, ty = v.finite("theta_x_rad", theta_x_rad), v.finite("theta_y_rad", theta_y_rad)
    check_plain_pose(bearing, 0.0, 0.0, tx, ty)
    load = np.asarray(load_n, dtype=float)
    if load.shape != (2,) or not np.all(np.isfinite(load)):
        raise InputError(f"load_n: expected two finite numbers (Fx, Fy) N, got {load_n!r}")
    lx, ly = float(load[0]), float(load[1])
    w = TWO_PI * v.speed("speed_hz", speed_hz)
    film = imposed_tilt(tilt_coupling(bearing, [0, 1, 2, 3], bearing_name(bearing)), tx, ty)
    model = _film_model([film], 2, Q=np.array([lx, ly]))
    thd = isinstance(opts, _core.ThdOptions)
    tf = _core.ThermalFilm()
    tf.film, tf.oil, tf.thd = 0, oil.to_core(), thd
    if thd:
        tf.thd_options = opts
    else:
        tf.options = opts
    eopt = _core.EquilibriumOptions()
    eopt.polish = True
    res = _core.thermal_system_equilibrium(model, [tf], w, 0.0, np.zeros(2), eopt)
    eq = res.equilibrium
    if eq.status not in ("ok", "contact"):
        raise failed_equilibrium("tilted thermal equilibrium", eq)
    st = res.films[0]
    x, y = (float(q) for q in eq.r)
    # the frozen field on the four-coordinate film: moments, edge film, K4, C4
    four = tilt_coupling(bearing, [0, 1, 2, 3], bearing_name(bearing))
    if thd:
        four.viscosity_field = np.array(st.viscosity_field)
    else:  # isoviscous at μ(T_eff) (a model bearing's own frozen field does not apply)
        g = four.geometry
        g.viscosity_pa_s = float(st.viscosity_pa_s)
        four.geometry = g
        four.viscosity_field = np.zeros((0, 0))
    solver = _four_solver([four])
    r4 = np.array([x, y, tx, ty])
    H = np.asarray(solver.film_forces(r4, np.zeros(4), w))
    h_min, h_ang, h_z = min_film(solver)
    lin = solver.linearize(r4, np.zeros(4), w)
    K4, C4 = np.array(lin.KH), np.array(lin.DH)
    common = dict(speed_hz=float(speed_hz), load_n=(lx, ly),
                  supply_temperature_c=float(opts.supply_temperature_c),
                  max_temperature_c=st.max_temperature_c,
                  inlet_temperature_c=st.inlet_temperature_c, power_loss_w=st.power_loss_w,
                  film_flow_m3_s=st.film_flow_m3_s, side_flow_m3_s=st.side_flow_m3_s,
                  supply_flow_m3_s=st.supply_flow_m3_s,
                  carry_over_effective=st.carry_over_effective, x_m=x, y_m=y,
                  eccentricity_ratio=math.hypot(x, y) / bearing.clearance_m,
                  K=K4[:2, :2].copy(), C=C4[:2, :2].copy(), iterations=int(res.iterations),
                  status=str(eq.status), message=str(eq.message), journal_theta_x_rad=tx,
                  journal_theta_y_rad=ty, force_n=H[:2].copy(), film_moment_n_m=H[2:].copy(),
                  h_min_m=h_min, h_min_angle_deg=h_ang, h_min_z_m=h_z, K4=K4, C4=C4)
    if not thd:
        return ThermalEquilibriumResult(
            effective_temperature_c=st.effective_temperature_c,
            temperature_rise_k=st.temperature_rise_k, viscosity_pa_s=st.viscosity_pa_s,
            **common)
    fl = st.flows
    return ThdEquilibriumResult(
        mean_temperature_c=st.mean_temperature_c,
        recirculation_temperature_c=st.recirculation_temperature_c,
        side_temperature_c=st.side_temperature_c, friction_power_w=st.friction_power_w,
        recirculation_flow_m3_s=st.recirculation_flow_m3_s,
        heat_to_journal_w=st.heat_to_journal_w, heat_to_bush_w=st.heat_to_bush_w,
        journal_temperature_c=st.journal_temperature_c,
        max_wall_temperature_c=st.max_wall_temperature_c,
        temperature_c=np.array(st.temperature_c), viscosity_pa_s=np.array(fl.viscosity_pa_s),
        inlet_mask=np.array(st.inlet_mask),
        flows={k: np.array(getattr(fl, k)) for k in
               ("q_phi_m3_s", "q_z_m3_s", "fill", "dissipation_w", "area_m2", "makeup_m3_s")},
        wall_temperature_c=np.array(st.wall_temperature_c), **common)


def bearing_name(bearing) -> str:
    return getattr(bearing, "name", "") or "bearing"


def pad_tilted_thermal_equilibrium(bearing, *, theta_x_rad: float, theta_y_rad: float, oil,
                                   opts, load_n, speed_hz: float,
                                   whirl_ratio: float | None):
    """The thermal equilibrium of a :class:`rotordyn.bearings.TiltingPadBearing` under
    ``load_n`` (N) with the journal tilted by (θx, θy) rad relative to it, the pads free
    (tilt, pivot and, with spherical pivots, pitch): the journal's tilt held in the pads' base
    films (:mod:`rotordyn.bearings.tilt_pads`), then the untilted bearing's C++ call
    (:func:`rotordyn.bearings.pad_thd.pad_thd_equilibrium`: K, C 2×2 reduced over the pads
    at ``whirl_ratio``·Ω). A :class:`rotordyn.bearings.pad_thd.PadThdResult` with the tilt,
    the moments (N·m), the thinnest pad's edge film and K4, C4 (4×4 over x, y, θx, θy, the
    pads condensed at the same whirl frequency) at the frozen fields. ``r``, ``K_full``,
    ``C_full``, ``M_full``: over [x, y, pad coordinates] of the held tilt (a spherical pad's
    pitch measured from γ = θ·t_k)."""
    from rotordyn.bearings.tilt_pads import N_JOURNAL, _film_at, _layout, check_pad_pose

    _, _, tx, ty = check_pad_pose(bearing, 0.0, 0.0, theta_x_rad, theta_y_rad)
    load = np.asarray(load_n, dtype=float)
    if load.shape != (2,) or not np.all(np.isfinite(load)):
        raise InputError(f"load_n: expected two finite numbers (Fx, Fy) N, got {load_n!r}")
    lay = _layout(bearing)
    pose = np.array([0.0, 0.0, tx, ty])
    p0 = lay.pitch_offsets(tx, ty)
    model = lay.model([0, 1], pose, p0, load)
    idx = [0, 1] + list(range(N_JOURNAL, N_JOURNAL + lay.n))
    model.M = lay.M[np.ix_(idx, idx)]  # the pads' inertia: K, C condensed at the whirl

    def full(r):
        rf = np.zeros(N_JOURNAL + lay.n)
        rf[idx] = np.asarray(r, dtype=float)
        rf[2], rf[3] = tx, ty
        rf[N_JOURNAL:] += p0
        return rf
    res = pad_thd_equilibrium(SystemParts(films=[], tables=[], n_extra=lay.n), oil=oil,
                              opts=opts, load_n=load, speed_hz=speed_hz,
                              clearance_m=bearing.clearance_m, whirl_ratio=whirl_ratio,
                              tilts=lambda r: lay.pads(full(r))[0], model=model)
    # the frozen fields on the pads' four-coordinate films: moments, edge film, K4, C4
    four = bearing.system_parts(0, 1, N_JOURNAL, bearing_name(bearing), rot=(2, 3)).films
    pad_fields(res.viscosity_pa_s, four, "viscosity_field_pa_s")
    frozen = copy.copy(lay)
    frozen.solver = _four_solver([p.coupling for p in four], lay.K, lay.M)
    w = TWO_PI * float(speed_hz)
    rf = full(res.r)
    film = _film_at(frozen, rf, w, 0)
    lin = frozen.solver.linearize(rf, np.zeros(len(rf)), w)
    nu = 0.0 if whirl_ratio is None else float(whirl_ratio) * w  # as pad_thd_equilibrium
    K4, C4 = reduce_coefficients(np.asarray(lin.KH) + lay.K, np.asarray(lin.DH), lay.M, nu,
                                 N_JOURNAL)
    return dataclasses.replace(res, journal_theta_x_rad=tx, journal_theta_y_rad=ty,
                               force_n=film.force_n.copy(),
                               film_moment_n_m=film.film_moment_n_m.copy(), h_min_m=film.h_min_m,
                               h_min_angle_deg=film.h_min_angle_deg, h_min_z_m=film.h_min_z_m,
                               K4=K4, C4=C4)


__all__ = ["pad_tilted_thermal_equilibrium", "plain_tilted_thermal_equilibrium",
           "tilted_thermal_equilibrium"]
