"""Pseudo-arclength continuation of the static equilibrium of eq. 12 (eq. 14:
K (r + a) = H(Ω, r, 0) + Q + C_s0) over an operating variable (speed, chamber pressure, a_y)
or any numeric model field (a clearance, a viscosity, a disk mass: a dotted path as a sweep
axis), with the linearised stability (eq. 19) at every point, its Hopf points (a complex pair
through the imaginary axis) and folds (a real eigenvalue through zero) located on the branch
(docs/nonlinear.md, "Continuation of equilibria").

Unknowns y = (r / L, p / D_p) (L the smallest film clearance, D_p = ``param_scale``). The
corrector is Newton on [R(r, p) / S; cᵀ(y − y_prev) − σ] = 0 (R the residual of eq. 14, S its
load scale as the core's equilibrium; c the previous tangent: the pseudo-arclength condition),
Jacobian [[(K + K_H) L / S, ∂R/∂p D_p / S]; cᵀ] — each iteration one film solve and one
linearisation in C++ (``SystemSolver.film_forces``, ``.linearize``; a few iterations per point,
so the loop stays in Python). ∂R/∂p: exact for p_c (−chamber load) and a_y (K times the
configuration direction), a central difference for the speed (films) and model fields (the
system re-assembled at p ± h). Each converged point is then handed to
:func:`rotordyn.equilibrium` at its parameter (started there: the core's tolerance test and
polish), whose status decides: only a converged equilibrium is linearised and kept."""

from __future__ import annotations

import math

import numpy as np

from rotordyn._common import validate as v
from rotordyn._common.status import CONVERGED
from rotordyn._common.threads import limited_blas
from rotordyn.analysis.assembly import Assembled, assembled, chamber_pressure
from rotordyn.analysis.equilibrium import equilibrium
from rotordyn.analysis.equilibrium_events import bifurcations
from rotordyn.analysis.field_axis import (OPERATING, FieldSystems, check_acts, field_parameter,
                                          field_value)
from rotordyn.analysis.linear import FD_REL_STEP, _linear_from
from rotordyn.errors import InputError, RotordynError
from rotordyn.model.system import System
from rotordyn.results.equilibrium import EquilibriumResult
from rotordyn.results.equilibrium_branch import EquilibriumBranchResult
from rotordyn.units import hz_to_rad_s

class _Problem:
    """The residual of eq. 14 and its derivatives at (r, p)."""

    def __init__(self, system, vary, speed_hz, pc, ay):
        self.system, self.vary = system, vary
        self.op = {"speed_hz": speed_hz, "chamber_pressure_pa": pc, "config_ay_m": ay}
        self.asm0 = assembled(system)
        self.n = self.asm0.n
        self.fields = None if vary in OPERATING else FieldSystems(system, vary, self.n)
        if vary == "config_ay_m":
            self.a_base = self.asm0.config_vector(0.0)
            self.a_dir = self.asm0.config_vector(1.0) - self.a_base

    def operating(self, p):
        op = dict(self.op)
        if self.vary in OPERATING:
            op[self.vary] = float(p)
        return op["speed_hz"], op["chamber_pressure_pa"], op["config_ay_m"]

    def system_at(self, p) -> System:
        return self.system if self.vary in OPERATING else self.fields.system_at(p)

    def _asm(self, p) -> Assembled:
        return self.asm0 if self.vary in OPERATING else self.fields.at(p)

    def _parts(self, p):
        asm = self._asm(p)
        spd, pc, ay = self.operating(p)
        if self.vary == "config_ay_m":
            a = self.a_base + float(p) * self.a_dir
        else:
            a = asm.config_vector(ay)
        m = asm.model
        return asm, hz_to_rad_s(spd), pc, a, np.asarray(m.K), np.asarray(m.Q), np.asarray(
            m.chamber)

    @staticmethod
    def _offset_load(asm, w, a) -> np.ndarray:
        """(K + Ω K_c) a (n,), N: the core's SystemModel::offset_load (the solver's H
        carries −Ω K_c r only)."""
        return np.asarray(asm.model.offset_load(float(w), np.asarray(a, dtype=float)))

    def load_scale(self, p) -> float:
        asm, w, pc, a, _, Q, ch = self._parts(p)
        return max(np.abs(Q).max(initial=0.0),
                   np.abs(self._offset_load(asm, w, a)).max(initial=0.0),
                   np.abs(pc * ch).max(initial=0.0), 1e-12)

    def residual(self, r, p):
        """R(r, p) (n,), N; a closing film raises ContactError."""
        asm, w, pc, a, K, Q, ch = self._parts(p)
        H = np.asarray(asm.solver.film_forces(r, np.zeros(self.n), w), dtype=float)
        return K @ r + self._offset_load(asm, w, a) - H - Q - pc * ch

    def jacobian_r(self, r, p):
        """∂R/∂r = K + K_H (n, n), N/m."""
        asm, w, _, _, K, _, _ = self._parts(p)
        return K + np.asarray(asm.solver.linearize(r, np.zeros(self.n), w).KH)

    def dR_dp(self, r, p, h):
        """∂R/∂p (n,) per unit of vary; h the central-difference step (speed, fields)."""
        if self.vary == "chamber_pressure_pa":
            return -np.asarray(self.asm0.model.chamber, dtype=float)
        if self.vary == "config_ay_m":
            return self._offset_load(self.asm0, self._parts(p)[1], self.a_dir)
        return (self.residual(r, p + h) - self.residual(r, p - h)) / (2 * h)


def _check_acts(prob, r, lo, hi) -> None:
    """InputError naming ``vary`` when the model field changes nothing of eq. 14 and eq. 19
    between the bounds (:func:`rotordyn.analysis.field_axis.check_acts`): the assembled M,
    C, G, K, loads, configuration, and the film forces and their linearisation at the start's
    state ``r``."""
    def snapshot(p):
        asm, w, pc, a, K, Q, ch = prob._parts(p)
        m = asm.model
        z = np.zeros(prob.n)
        lin = asm.solver.linearize(r, z, w)
        M = m.mass_at(w) if m.has_table_mass() else m.M
        return (M, m.C, m.G, K, Q, ch, a, asm.solver.film_forces(r, z, w), lin.KH, lin.DH)

    check_acts(prob.vary, lo, hi, snapshot)


def _eigen(lm):
    n = lm.M.shape[0]
    Minv = np.linalg.inv(lm.M)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ lm.K, -Minv @ lm.D]])
    return np.linalg.eigvals(A)


@limited_blas
def equilibrium_continuation(system: System, vary: str, bounds, start="equilibrium", *,
                             speed_hz: float | None = None,
                             chamber_pressure_pa: float | None = None,
                             config_ay_m: float | None = None, ds: float = 0.02,
                             ds_min: float = 1e-5, ds_max: float = 0.05,
                             max_points: int = 200, direction: int = 1,
                             param_scale: float | None = None, tol: float = 1e-10,
                             max_iter: int = 25, fd_step: float = 1e-6,
                             refine: bool = True, progress=None) -> EquilibriumBranchResult:
    """Continue the static equilibrium over ``vary`` within ``bounds`` by pseudo-arclength.

    Parameters
    ----------
    vary
        ``"speed_hz"`` (Hz), ``"chamber_pressure_pa"`` (Pa), ``"config_ay_m"`` (m, the active
        bearing's vertical configuration) or a numeric model field path as a sweep axis
        (``"bearings.0.clearance_m"``, ``"bearings.*.viscosity_pa_s"``; SI unit of the
        field): the system is re-assembled at every value.
    bounds
        (low, high) in the unit of ``vary``; the branch ends on the first bound it reaches
        (the last point solved on the bound).
    start
        ``"equilibrium"``: :func:`rotordyn.equilibrium` at ``speed_hz``, ``chamber_pressure_pa``,
        ``config_ay_m`` (the varied operating value defaults to the bound the branch leaves
        from; a field starts at the system's value); or a converged EquilibriumResult of this
        system (its operating point).
    ds, ds_min, ds_max
        Arclength step in y = (r / L, p / param_scale), L the smallest film clearance; ×1.5
        after a corrector converging in ≤ 4 iterations, ÷2 after a failure or a tangent
        turning by more than 30°; the branch stops below ``ds_min``.
    direction
        +1: leave the start towards growing parameter, −1: decreasing.
    param_scale
        D_p (unit of vary); default high − low.
    tol
        Corrector tolerance: ‖R‖∞ relative to the load scale (as :func:`rotordyn.equilibrium`).
    fd_step
        h / param_scale of the central difference ∂R/∂p (speed, model fields).
    refine
        Locate every Hopf point and fold between two points by Brent's method on the
        arclength from the earlier point (each trial a corrected equilibrium): Hopf where the
        critical complex pair's real part is zero, fold where sign(det(K + K_H))·σ_min is.

    Returns
    -------
    EquilibriumBranchResult
        status ``"ok"`` with at least the start; the start's status (``no_equilibrium``,
        ``not_converged``) and no points when the start fails. ``stop`` says why the
        branch ended (``bound``, ``max_points``, ``step_min``, or the status of a failed
        equilibrium at the corrected point: ``no_equilibrium``, ``not_converged``).
    """
    vary = field_parameter(system, vary)
    lo, hi = v.bounds("bounds", bounds)
    if vary == "chamber_pressure_pa" and lo < 0:
        raise InputError(f"bounds: chamber_pressure_pa must be >= 0, got ({lo:g}, {hi:g})")
    if vary == "speed_hz" and lo <= 0 <= hi:
        raise InputError(f"bounds: a speed branch must not contain 0 Hz, got ({lo:g}, {hi:g})")
    ds, ds_min, ds_max, max_points, direction = v.arclength_steps(ds, ds_min, ds_max,
                                                                  max_points, direction)
    D_p = v.positive("param_scale", hi - lo if param_scale is None else param_scale)
    tol = v.in_range("tol", tol, 0.0, 1e-2, lo_open=True)
    max_iter = v.integer("max_iter", max_iter, lo=1, hi=1000)
    fd_step = v.in_range("fd_step", fd_step, 1e-12, 0.1)
    refine = v.boolean("refine", refine)
    asm0 = assembled(system)
    if not asm0.bearings:
        raise InputError("system: an equilibrium branch needs at least one bearing (a rotor "
                         "on linear supports has one equilibrium, independent of the speed)")

    # the start
    if isinstance(start, EquilibriumResult):
        if not start.converged:
            raise InputError(f"start: the equilibrium did not converge (status "
                             f"{start.status!r}: {start.message})")
        if start.r.shape != (asm0.n,):
            raise InputError(f"start: the equilibrium has {start.r.size} coordinates, the "
                             f"system {asm0.n}")
        act = [i for i, bc in enumerate(asm0.bearings) if bc.active] or [0]
        op = {"speed_hz": start.speed_hz, "chamber_pressure_pa": start.chamber_pressure_pa,
              "config_ay_m": float(start.config_ay_m[act[0]])}
        r0 = np.asarray(start.r, float)
    elif isinstance(start, str) and start == "equilibrium":
        edge = lo if direction > 0 else hi
        op = {"speed_hz": speed_hz, "chamber_pressure_pa": chamber_pressure_pa,
              "config_ay_m": config_ay_m}
        if vary in OPERATING and op[vary] is None:
            op[vary] = edge
        op["speed_hz"] = 50.0 if op["speed_hz"] is None else op["speed_hz"]
        op["chamber_pressure_pa"] = (0.0 if op["chamber_pressure_pa"] is None
                                     else op["chamber_pressure_pa"])
        r0 = None
    else:
        raise InputError("start: expected \"equilibrium\" or a converged EquilibriumResult, "
                         f"got {type(start).__name__}")
    op["speed_hz"] = v.speed("speed_hz", op["speed_hz"])
    op["chamber_pressure_pa"] = chamber_pressure(system, op["chamber_pressure_pa"])
    if op["config_ay_m"] is not None:
        op["config_ay_m"] = v.finite("config_ay_m", op["config_ay_m"])
    if vary in OPERATING:
        p0 = op[vary]
        if vary == "config_ay_m" and p0 is None:
            p0 = op["config_ay_m"] = float(asm0.config_vector()[[bc.jy for bc in
                                                                 asm0.bearings][0]])
    else:
        p0 = field_value(system, vary)
    if not lo <= p0 <= hi:
        raise InputError(f"bounds: ({lo:g}, {hi:g}) must contain the start's {vary} = {p0:g}")

    prob = _Problem(system, vary, op["speed_hz"], op["chamber_pressure_pa"],
                    op["config_ay_m"])
    n = prob.n
    L = float(min([bc.clearance_m for bc in asm0.bearings if bc.clearance_m > 0] or [1e-4]))
    S = prob.load_scale(p0)
    h_fd = fd_step * D_p
    scale = np.concatenate([np.full(n, L), [D_p]])
    stats = {"correctors": 0, "failed_correctors": 0, "iterations": 0, "film_solves": 0,
             "linearisations": 0, "refinements": 0}

    def solve_point(p, r_start):
        sys_p = prob.system_at(p)
        spd, pc, ay = prob.operating(p)
        # cold without a start (never this thread's last equilibrium): the same branch
        # whatever ran before (the start's root differed by 1e-11 c after another solve of
        # the same model, and every later point with it)
        e = equilibrium(sys_p, spd, pc, ay, tol=tol, r0=r_start, warm_start=False)
        return sys_p, spd, e

    def linear(sys_p, spd, e):
        lm = _linear_from(assembled(sys_p), e, spd, "perturbation", FD_REL_STEP)
        return lm, _eigen(lm)

    def bordered(r, p):
        Jr = prob.jacobian_r(r, p)
        Jp = prob.dR_dp(r, p, h_fd)
        stats["linearisations"] += 1
        return np.column_stack([Jr * L / S, Jp * D_p / S]), Jr

    def tangent(J, t_prev):
        B = np.vstack([J, t_prev])
        rhs = np.zeros(n + 1)
        rhs[-1] = 1.0
        t = np.linalg.solve(B, rhs)
        t /= np.linalg.norm(t)
        return t if float(t @ t_prev) >= 0 else -t

    def correct(y_pred, c, y_ref, sigma, jp_fixed=None):
        """Newton on [R/S; cᵀ(y − y_ref) − σ] from y_pred. Returns (y, iterations) or
        (None, message)."""
        y = y_pred.copy()
        stats["correctors"] += 1

        def merit(yy):
            R = prob.residual(yy[:n] * L, yy[n] * D_p) / S
            stats["film_solves"] += 1
            return R, float(c @ (yy - y_ref) - sigma)

        try:
            R, g = merit(y)
        except RotordynError as exc:
            return None, f"the predictor closes a film ({exc})"
        res = max(np.abs(R).max(), abs(g))
        for it in range(max_iter):
            if np.abs(R).max() < tol and abs(g) < tol:
                stats["iterations"] += it
                return y, it
            r, p = y[:n] * L, y[n] * D_p
            Jr = prob.jacobian_r(r, p)
            stats["linearisations"] += 1
            if jp_fixed is None:
                Jp = prob.dR_dp(r, p, h_fd)
            else:
                Jp = jp_fixed
            Jb = np.vstack([np.column_stack([Jr * L / S, Jp * D_p / S]), c])
            try:
                dy = np.linalg.solve(Jb, -np.concatenate([R, [g]]))
            except np.linalg.LinAlgError:
                return None, "singular bordered Jacobian"
            if not np.all(np.isfinite(dy)):
                return None, "non-finite corrector step"
            t = 1.0
            for _ in range(30):
                yt = y + t * dy
                try:
                    Rt, gt = merit(yt)
                except RotordynError:
                    t *= 0.5
                    continue
                rt = max(np.abs(Rt).max(), abs(gt))
                if rt <= (1 - 1e-4 * t) * res or rt < tol:
                    break
                t *= 0.5
            else:
                return None, f"line search failed (residual {res:.3g})"
            y, R, g, res = yt, Rt, gt, rt
        return None, f"no convergence in {max_iter} iterations (residual {res:.3g})"

    # --- the start point
    sys0, spd0, e0 = solve_point(p0, r0)
    base = dict(vary=vary, bounds=(lo, hi), fixed={k: val for k, val in op.items()
                                                  if k != vary},
                bearing_names=tuple(bc.name for bc in asm0.bearings),
                clearance_m=np.array([bc.clearance_m for bc in asm0.bearings]),
                journal_index=tuple((bc.jx, bc.jy) for bc in asm0.bearings))
    if e0.status not in CONVERGED:
        return EquilibriumBranchResult.failed(e0.status, f"start: {e0.message}", stats=stats,
                                              **base)
    pts = []  # dicts: p, e, lam, y, t, Jr, s, iterations

    def add(p, e, lam, y, t, Jr, s):
        pts.append({"p": float(p), "e": e, "lam": lam, "y": y, "t": t, "Jr": Jr, "s": s})
        if progress is not None:
            progress(len(pts) - 1, f"{vary} = {p:.6g}: max Re λ = {lam.real.max():.4g} 1/s")

    if vary not in OPERATING:
        _check_acts(prob, np.asarray(e0.r, float), lo, hi)
    lm0, lam0 = linear(sys0, spd0, e0)
    y0 = np.concatenate([np.asarray(e0.r) / L, [p0 / D_p]])
    J0, Jr0 = bordered(np.asarray(e0.r), p0)
    e_p = np.zeros(n + 1)
    e_p[-1] = float(direction)
    add(p0, e0, lam0, y0, tangent(J0, e_p), Jr0, 0.0)

    stop, message = "max_points", ""
    h = ds
    while len(pts) < max_points:
        last = pts[-1]
        y, t = last["y"], last["t"]
        out, info = correct(y + h * t, t, y, h)
        turned = False
        if out is None:
            stats["failed_correctors"] += 1
            message = info
            h /= 2
            if h < ds_min:
                stop = "step_min"
                break
            continue
        p_new = float(out[n] * D_p)
        if not lo <= p_new <= hi:
            # the last point: on the bound, by the corrector with p fixed there
            pb = hi if p_new > hi else lo
            w = (pb - last["p"]) / (p_new - last["p"])
            y_pred = y + w * (out - y)
            ep = np.zeros(n + 1)
            ep[-1] = 1.0
            out_b, info_b = correct(y_pred, ep, np.zeros(n + 1), pb / D_p)
            stop = "bound"
            if out_b is None:
                message = f"the point on the bound {vary} = {pb:g}: {info_b}"
                break
            out, p_new = out_b, float(pb)
        sys_p, spd_p, e = solve_point(p_new, out[:n] * L)
        if e.status not in CONVERGED:
            stop, message = e.status, f"at {vary} = {p_new:.6g}: {e.message}"
            break
        lm, lam = linear(sys_p, spd_p, e)
        y_new = np.concatenate([np.asarray(e.r) / L, [p_new / D_p]])
        J, Jr = bordered(np.asarray(e.r), p_new)
        t_new = tangent(J, t)
        if stop != "bound" and float(t_new @ t) < math.cos(math.radians(30)) and h > ds_min:
            turned = True
        if turned:
            stats["failed_correctors"] += 1
            message = "the tangent turned by more than 30°"
            h /= 2
            continue
        add(p_new, e, lam, y_new, t_new, Jr, last["s"] + float(t @ (y_new - y)))
        if stop == "bound":
            break
        if info <= 4:
            h = min(1.5 * h, ds_max)

    bif = bifurcations(pts, n, correct, prob, L, D_p, refine, stats, h_fd)
    return EquilibriumBranchResult.from_points(pts, bif, stop=stop, message=message,
                                               stats=stats, **base)
