"""What the two continuations of periodic orbits share (docs/nonlinear.md): the shooting
corrector's (:mod:`rotordyn.analysis.continuation`) and harmonic balance's
(:mod:`rotordyn.analysis.hb_continuation`) — the checked set-up of a branch from its start
orbit (the operating point, the parameter in the core's units, the orbit input; for a model
field the system re-assembled at each value), each point's
:class:`~rotordyn.results.PeriodicOrbitResult`, the Hopf end, and the assembly of the
:class:`~rotordyn.results.BranchResult` with its bifurcations."""

from __future__ import annotations

import dataclasses

import numpy as np

from rotordyn import _core
from rotordyn._common import validate as v
from rotordyn.analysis.assembly import OPERATING, assembled
from rotordyn.analysis.field_axis import FieldSystems, check_acts, field_parameter, field_value
from rotordyn.analysis.periodic import orbit_result
from rotordyn.errors import InputError
from rotordyn.results.continuation import BranchResult
from rotordyn.results.periodic import PeriodicOrbitResult
from rotordyn.units import hz_to_rad_s

#: the operating variables the core varies itself (any other ``vary`` is a model field path)
PARAM = {"chamber_pressure_pa": "chamber_pressure", "speed_hz": "speed",
         "config_ay_m": "config"}


#: the band of a branch point's screen about the unit circle (``floquet_margin``'s default)
FLOQUET_MARGIN = 0.01


def floquet_options(floquet, floquet_margin, floquet_tol, routes, default: str) -> tuple:
    """The checked Floquet options of a branch's correctors (both methods): the route (one of
    ``routes``, ``default`` when None), the screen's margin in [0, 0.5] (default
    FLOQUET_MARGIN) and the refinement tolerance in [0, 0.5] (default 0), which applies only
    to ``floquet="samples"``; InputError naming the field otherwise."""
    floquet = v.choice("floquet", default if floquet is None else floquet, routes)
    margin = v.in_range("floquet_margin",
                        FLOQUET_MARGIN if floquet_margin is None else floquet_margin, 0.0, 0.5)
    ftol = 0.0 if floquet_tol is None else v.in_range("floquet_tol", floquet_tol, 0.0, 0.5)
    if ftol > 0 and floquet != "samples":
        raise InputError(f"floquet_tol: applies only to floquet='samples' (it refines the "
                         f"samples' product), got floquet={floquet!r}")
    return floquet, float(margin), float(ftol)


def point_parameter(o: PeriodicOrbitResult, vary: str) -> float:
    """The value of ``vary`` at a branch point (a model field's: ``stats["field_value"]``)."""
    return float(getattr(o, vary) if vary in OPERATING else o.stats["field_value"])


def amplitude(o: PeriodicOrbitResult) -> np.ndarray:
    """(n_bearings,) the journals' amplitudes; a system without bearings: (1,) the largest
    distance of any coordinate from its mean over the orbit."""
    if o.journal_x_m.shape[1] == 0:
        return np.array([float(np.max(np.abs(o.r - o.r.mean(axis=0))))])
    return np.array([o.amplitude(b) for b in range(o.journal_x_m.shape[1])])


def names(bcs) -> tuple:
    return tuple(bc.name for bc in bcs) if bcs else ("largest coordinate",)


def clearances(bcs) -> np.ndarray:
    return np.array([bc.clearance_m for bc in bcs]) if bcs else np.array([np.nan])


@dataclasses.dataclass
class BranchSetup:
    """A branch's checked set-up: the assembled system, the start's kind and operating point,
    the parameter (``p_start`` in the unit of ``vary``; ``to_core`` the factor to the core's
    Pa, rad/s or m), the orbit input ``base`` (``_core.PeriodicInput``: kind, Ω, p_c, a,
    unbalance, t0, n_out) and, for a_y, the configuration direction."""

    vary: str
    lo: float
    hi: float
    asm: object
    n: int
    kind: str
    subharmonic: int
    bcs: tuple
    a0: np.ndarray
    p_start: float
    to_core: float
    omega: float
    base: object
    config_direction: np.ndarray | None
    param_scale: float
    start_speed: float = 0.0
    start_pc: float = 0.0
    #: a model field: the system re-assembled at each value, the operating a_y override (None:
    #: the model's configuration) and the unbalances [(station, m·e, phase)]
    field: FieldSystems | None = None
    ay_override: float | None = None
    unbalances: tuple = ()

    def input_at(self, p: float):
        """The orbit input (``_core.PeriodicInput``) on the system with the field at ``p``:
        the base with the configuration and unbalance of that assembly (a model field)."""
        asm = self.field.at(p)
        return periodic_input(asm, self.kind, self.base.omega, self.base.chamber_pressure,
                              asm.config_vector(self.ay_override), self.unbalances,
                              self.base.t0, self.base.n_out, self.base.period)

    def point_result(self, orbit, p_core: float, extra_stats: dict | None = None):
        """The :class:`PeriodicOrbitResult` of a corrected orbit (the core's) at p_core."""
        p = p_core / self.to_core
        if self.field is not None:
            asm = self.field.at(p)
            return orbit_result(asm, orbit, self.kind, self.start_speed, self.start_pc,
                                asm.config_vector(self.ay_override),
                                extra_stats={**(extra_stats or {}), "field": self.vary,
                                             "field_value": float(p)})
        spd = p if self.vary == "speed_hz" else self.start_speed
        pc = p if self.vary == "chamber_pressure_pa" else self.start_pc
        if self.vary != "config_ay_m":
            return orbit_result(self.asm, orbit, self.kind, float(spd), float(pc), self.a0,
                                extra_stats=extra_stats)
        a = np.asarray(self.base.a) + p * self.config_direction
        o = orbit_result(self.asm, orbit, self.kind, float(spd), float(pc), np.asarray(a),
                         extra_stats=extra_stats)
        # the result's config_ay_m is the first bearing's; the parameter is the active one's
        return dataclasses.replace(o, config_ay_m=float(p))

    def failed(self, message: str, stats: dict) -> BranchResult:
        """The branch of a start that did not converge: no points, status not_converged."""
        return BranchResult(
            vary=self.vary, kind=self.kind, parameter=np.zeros(0),
            amplitude_m=np.zeros((0, len(names(self.bcs)))),
            period_s=np.zeros(0), max_multiplier=np.zeros(0), stable=np.zeros(0, bool),
            critical_type=(), arclength=np.zeros(0), tangent_p=np.zeros(0),
            bearing_names=names(self.bcs), clearance_m=clearances(self.bcs), bifurcations=(),
            bounds=(self.lo, self.hi), stop="start", message=message, stats=stats,
            status="not_converged")


def periodic_input(asm, kind: str, omega: float, chamber_pressure: float, a, ub_list, t0: float,
                   n_out: int, period: float):
    """The ``_core.PeriodicInput`` of an orbit on the assembled system ``asm``: kind, Ω (rad/s),
    p_c, the configuration a (n,), the unbalances [(station, m·e kg·m, phase deg)] as the
    cosine and sine force vectors, t0, n_out and the period (forced: the forcing's)."""
    n = asm.n
    inp = _core.PeriodicInput()
    inp.kind = _core.OrbitKind.autonomous if kind == "autonomous" else _core.OrbitKind.forced
    inp.omega = float(omega)
    inp.chamber_pressure = float(chamber_pressure)
    uc, us = np.zeros(n), np.zeros(n)
    for st, me, ph in ub_list:
        L = asm.station_load_matrix(st)
        q = np.radians(ph)
        uc += me * (L[:, 0] * np.cos(q) + L[:, 1] * np.sin(q))
        us += me * (-L[:, 0] * np.sin(q) + L[:, 1] * np.cos(q))
    inp.unbalance_cos, inp.unbalance_sin = (uc, us) if ub_list else (np.zeros(0), np.zeros(0))
    inp.a = np.asarray(a, dtype=float)
    inp.t0 = float(t0)
    inp.n_out = int(n_out)
    inp.period = float(period)
    return inp


def prepare(system, vary: str, bounds, start, unbalances, param_scale, n_out: int) -> BranchSetup:
    """The checked set-up of a branch over ``vary`` within ``bounds`` from the orbit
    ``start`` (InputError naming the field for a bad one). ``vary``: an operating variable
    (OPERATING) or a numeric model field path; a field must act on the equations of motion
    between the bounds (:func:`rotordyn.analysis.field_axis.check_acts` at the start's
    state)."""
    vary = field_parameter(system, vary)
    lo, hi = v.bounds("bounds", bounds)
    if not isinstance(start, PeriodicOrbitResult):
        raise InputError("start: expected a PeriodicOrbitResult (a converged orbit from "
                         f"rotordyn.periodic_orbit), got {type(start).__name__}")
    if not start.ok:
        raise InputError(f"start: the orbit did not converge (status {start.status!r}: "
                         f"{start.message})")
    asm = assembled(system)
    if start.r.shape[1] != asm.n:
        raise InputError(f"start: the orbit has {start.r.shape[1]} coordinates, the system "
                         f"{asm.n}")
    return setup_at(system, vary, (lo, hi), start.kind, start.speed_hz,
                    start.chamber_pressure_pa, start.config_ay_m, float(start.t[0]),
                    float(start.period_s), unbalances, param_scale, n_out,
                    state=(np.asarray(start.r[0], float), np.asarray(start.v[0], float)))


def setup_at(system, vary: str, bounds, kind: str, speed_hz: float, chamber_pressure_pa: float,
             config_ay_m: float, t0: float, period_s: float, unbalances, param_scale,
             n_out: int, state=None) -> BranchSetup:
    """The set-up of a branch over ``vary`` through an orbit of ``kind`` at this operating
    point (``config_ay_m`` the first bearing's a_y, as a PeriodicOrbitResult has it; ``t0``
    the orbit's start time, ``period_s`` its period): :func:`prepare` without a start orbit
    (e.g. a branch started at a Hopf point). A model field ``vary`` is checked to act at the
    state (r, ṙ) ``state`` (None: the centred journals at rest)."""
    vary = field_parameter(system, vary)
    lo, hi = v.bounds("bounds", bounds)
    if param_scale is None:
        param_scale = hi - lo
    param_scale = v.positive("param_scale", param_scale)
    v.integer("n_out", n_out, lo=2, hi=1_000_000)
    asm = assembled(system)
    n = asm.n
    ub_list = v.unbalances("unbalances", unbalances, system.rotor.n_stations)
    if kind == "forced" and not ub_list:
        raise InputError("unbalances: a forced start needs its unbalances "
                         "[(station, mass_kg_m, phase_deg)] again")
    if kind == "autonomous" and ub_list:
        raise InputError("unbalances: an autonomous branch has no unbalance forcing")
    subharmonic = 1
    if kind == "forced":
        subharmonic = max(1, int(round(period_s * abs(speed_hz))))
    bcs = asm.bearings
    ay_override = None
    if bcs and abs(asm.config_vector(None)[bcs[0].jy] - config_ay_m) > 1e-15:
        ay_override = float(config_ay_m)
    a0 = asm.config_vector(ay_override)
    if vary in OPERATING:
        p_start = {"chamber_pressure_pa": chamber_pressure_pa, "speed_hz": speed_hz,
                   "config_ay_m": config_ay_m}[vary]
    else:
        p_start = field_value(system, vary)
    if not lo <= p_start <= hi:
        raise InputError(f"bounds: ({lo:g}, {hi:g}) must contain the start's {vary} = "
                         f"{p_start:g}")
    if vary == "speed_hz" and (lo <= 0 <= hi):
        raise InputError(f"bounds: a speed branch must not contain 0 Hz, got ({lo:g}, {hi:g})")

    omega = hz_to_rad_s(float(speed_hz))
    period = (subharmonic * 2 * np.pi / abs(omega) if kind == "forced" else float(period_s))
    base = periodic_input(asm, kind, omega, float(chamber_pressure_pa), a0, ub_list,
                          float(t0), n_out, period)
    # p in the core's units: Pa, rad/s or m (a field: its SI unit); a(p) = a_base + p ·
    # direction for config
    to_core = hz_to_rad_s(1.0) if vary == "speed_hz" else 1.0
    direction = None
    if vary == "config_ay_m":
        a_base = asm.config_vector(0.0)
        direction = asm.config_vector(1.0) - a_base
        base.a = a_base
    field = None
    if vary not in OPERATING:
        field = FieldSystems(system, vary, n)
        if state is None:
            state = (np.zeros(n), np.zeros(n))
        _check_field_acts(field, kind, omega, float(chamber_pressure_pa), ay_override,
                          ub_list, state, lo, hi)
    return BranchSetup(vary=vary, lo=lo, hi=hi, asm=asm, n=n, kind=kind,
                       subharmonic=subharmonic, bcs=bcs, a0=a0, p_start=float(p_start),
                       to_core=to_core, omega=omega, base=base, config_direction=direction,
                       param_scale=float(param_scale), start_speed=float(speed_hz),
                       start_pc=float(chamber_pressure_pa), field=field,
                       ay_override=ay_override, unbalances=tuple(ub_list))


def _check_field_acts(field: FieldSystems, kind, omega, pc, ay_override, ub_list, state, lo,
                      hi) -> None:
    """InputError naming ``vary`` when the field changes nothing of eq. 12 between the
    bounds: M (at Ω), C, G, K, the loads, the chamber force, the configuration, the unbalance
    forcing, and the film forces and their linearisation at the state (r, ṙ) (the start
    orbit's first; a film closed there at a bound counts as a change)."""
    r, vel = state

    def snapshot(p):
        asm = field.at(p)
        m = asm.model
        inp = periodic_input(asm, kind, omega, pc, asm.config_vector(ay_override), ub_list,
                             0.0, 2, 1.0)
        M = m.mass_at(omega) if m.has_table_mass() else m.M
        lin = asm.solver.linearize(r, vel, omega)  # a closed film: check_acts counts a change
        return (M, m.C, m.G, m.K, m.Q, pc * np.asarray(m.chamber), inp.a, inp.unbalance_cos,
                inp.unbalance_sin, lin.film_force, lin.KH, lin.DH)

    check_acts(field.vary, lo, hi, snapshot)


def _point_clearances(orbits, bcs) -> np.ndarray:
    """(n_bearings,) the bearings' clearances, or (n_points, n_bearings) each point's where a
    model field changes them along the branch."""
    c = clearances(bcs)
    if not bcs or not orbits:
        return c
    per = np.array([o.clearance_m for o in orbits], dtype=float).reshape(len(orbits), -1)
    return c if np.all(per == per[0]) and np.array_equal(per[0], c) else per


def rejected(status: str, message: str, new_tangent, tangent) -> tuple[bool, str]:
    """Whether a corrected branch point is refused, and why: the corrector's failure, or a
    tangent turned by more than 30° from the previous one (the step jumped branches)."""
    if status == "ok" and float(np.dot(new_tangent, tangent)) < np.cos(np.radians(30)):
        return True, "the tangent turned by more than 30°"
    return status != "ok", message


def halved(h: float, ds_min: float, status: str, message: str, stop: str):
    """After a refused corrector (``status``, the core's ``message``): (the halved step, the
    stop reason), the step None when the branch ends there — below ``ds_min``, or a cycle
    that shrank onto the equilibrium (a Hopf end) with no smaller step left."""
    if status == "not_converged" and "equilibrium" in message:
        stop = "equilibrium"
        if h / 2 < ds_min:
            return None, stop
    h /= 2
    if h < ds_min:
        return None, ("rub" if status == "rub" else
                      "equilibrium" if stop == "equilibrium" else "step_min")
    return h, stop


def hopf_estimate(orbits, beyond: PeriodicOrbitResult, vary: str) -> dict:
    """The Hopf point where the branch meets the equilibrium: p against the signed amplitude
    (positive on the branch, negative beyond) through the last two points and the one
    beyond, a parabola p = p_H + b·A + c·A² evaluated at A = 0 (near a Hopf point
    A² ∝ |p − p_H|). ``curvature`` c (unit of ``vary`` per m²): with the cycles on the
    unstable side of the equilibrium and stable, the Hopf point is supercritical."""
    pts = list(orbits[-2:]) + [beyond]
    p = np.array([point_parameter(o, vary) for o in pts])
    A = np.array([amplitude(o)[0] for o in pts])
    A[-1] = -A[-1]
    if len(pts) == 3:
        coef = np.polyfit(A, p, 2)
        p_h, curv = float(coef[2]), float(coef[0])
    else:
        w = A[0] / (A[0] - A[1])
        p_h, curv = float(p[0] + w * (p[1] - p[0])), float("nan")
    nb = max(beyond.journal_x_m.shape[1], 1)
    return {"kind": "hopf", "index": len(orbits) - 1, "parameter": p_h,
            "amplitude_m": np.zeros(nb), "multiplier": complex(1.0), "curvature": curv,
            "period_s": float(beyond.period_s), "beyond_parameter": float(p[-1]),
            "beyond_amplitude_m": float(-A[-1])}


def assemble(vary, kind, orbits, tangents, arcl, bcs, bounds, stop, message, stats):
    """The :class:`BranchResult` of the accepted points (``tangents``: each point's tangent,
    its last entry dp/ds) with the bifurcations between successive points: ``fold`` where
    dp/ds changes sign (interpolated linearly in s), else where the critical multiplier's
    modulus crosses 1 its type on the unstable side (``stability_change`` for a real +1)."""
    n_pts = len(orbits)
    p = np.array([point_parameter(o, vary) for o in orbits])
    amp = np.array([amplitude(o) for o in orbits]).reshape(n_pts, len(names(bcs)))
    mm = np.array([abs(o.critical_multiplier) if o.critical_multiplier is not None else 0.0
                   for o in orbits])
    stable = np.array([o.stable for o in orbits], dtype=bool)
    ctype = tuple(o.critical_type for o in orbits)
    tp = np.array([t[-1] for t in tangents])
    bif = []
    for i in range(1, n_pts):
        turned = tp[i - 1] * tp[i] < 0
        crossed = (mm[i - 1] - 1.0) * (mm[i] - 1.0) < 0
        if not (turned or crossed):
            continue
        if turned:
            # where dp/ds = 0, linear in the arclength between the two points
            w = tp[i - 1] / (tp[i - 1] - tp[i])
            k = "fold"
        else:
            w = (1.0 - mm[i - 1]) / (mm[i] - mm[i - 1])
            unstable_side = i if mm[i] > 1 else i - 1
            ct = ctype[unstable_side]
            k = {"fold": "stability_change"}.get(ct, ct)
        mu = orbits[i].critical_multiplier
        bif.append({"kind": k, "index": i, "parameter": float(p[i - 1] + w * (p[i] - p[i - 1])),
                    "amplitude_m": amp[i - 1] + w * (amp[i] - amp[i - 1]),
                    "multiplier": complex(mu) if mu is not None else complex(np.nan)})
    return BranchResult(
        vary=vary, kind=kind, parameter=p, amplitude_m=amp,
        period_s=np.array([o.period_s for o in orbits]), max_multiplier=mm, stable=stable,
        critical_type=ctype, arclength=np.array(arcl, dtype=float), tangent_p=tp,
        bearing_names=names(bcs), clearance_m=_point_clearances(orbits, bcs),
        bifurcations=tuple(bif),
        orbits=tuple(orbits), bounds=bounds, stop=stop, message=message, stats=stats,
        status="ok")
