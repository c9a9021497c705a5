"""Hopf points of the stability boundary and their criticality (issue 19): the crossing
located by the threshold machinery (eigenvalue of eq. 19 through the imaginary axis), the
first Lyapunov coefficient l1 of eq. 12 there from directional finite differences of the
film forces (analysis/lyapunov.py, Kuznetsov's projection formula), the whirl frequency,
sub/supercritical, and the leading-order amplitude of the bifurcating limit cycle."""

from __future__ import annotations

import math

import numpy as np

from rotordyn._common import validate as v
from rotordyn._common.threads import limited_blas
from rotordyn.analysis.assembly import OPERATING, assembled, chamber_pressure
from rotordyn.analysis.field_axis import field_parameter
from rotordyn.analysis.linear import linearize
from rotordyn.analysis.lyapunov import central_second, central_third, first_lyapunov, \
    fitted_derivatives, hopf_vectors
from rotordyn.analysis.threshold import threshold
from rotordyn.errors import InputError, RotordynError
from rotordyn.model.paths import set_field
from rotordyn.model.system import System
from rotordyn.results.equilibrium import CONVERGED
from rotordyn.results.hopf import HopfResult
from rotordyn.units import hz_to_rad_s

#: default half-width of the directional polynomial fits, in scaled coordinates (positions
#: / the smallest film clearance L, velocities / (L ω_s)): 5e-2 (docs/nonlinear.md: the
#: cavitation set makes the discrete film force piecewise smooth; spans much below the
#: grid's switching scale see its kinks — on the rig as built l1 changes sign below 0.02)
FD_STEP = 5e-2
FD_METHODS = ("fit", "central")


def _operating(vary, value, fixed):
    p = dict(fixed)
    if vary in OPERATING:
        p[vary] = float(value)
    return p["speed_hz"], p["chamber_pressure_pa"], p["config_ay_m"]


def _system_at(system: System, vary: str, value) -> System:
    """``system`` with the model field ``vary`` at ``value`` (an operating variable: as is)."""
    if vary in OPERATING:
        return system
    return set_field(system, vary, float(value), where="vary")


def _jacobian(lm) -> np.ndarray:
    n = lm.M.shape[0]
    Minv = np.linalg.inv(lm.M)
    return np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ lm.K, -Minv @ lm.D]])


def _eig_near(A, target):
    lam = np.linalg.eigvals(A)
    return complex(lam[int(np.argmin(np.abs(lam - target)))])


def _critical_eigenvalue(A, whirl_hz):
    """The eigenvalue with Im > 0 nearest the axis at the whirl frequency (the threshold's
    crossing mode): of those with |Im/2π − f| < 2 % of f (or all with Im > 0), the one with
    the largest real part."""
    lam = np.linalg.eigvals(A)
    up = lam[lam.imag > 0]
    if up.size == 0:
        return None
    near = up[np.abs(up.imag / (2 * np.pi) - abs(whirl_hz)) < 0.02 * abs(whirl_hz) + 1e-9]
    cand = near if near.size else up
    return complex(cand[int(np.argmax(cand.real))])


@limited_blas
def hopf(system: System, vary: str = "chamber_pressure_pa", *, bounds=None, at=None,
         speed_hz: float = 50.0, chamber_pressure_pa: float = 0.0,
         config_ay_m: float | None = None, n_scan: int = 25, fd_step: float = FD_STEP,
         fd_method: str = "fit", param_step: float | None = None,
         grid_check: bool = False) -> HopfResult:
    """Hopf point on the stability boundary in ``vary`` and its first Lyapunov coefficient.

    ``vary``: an operating variable (``chamber_pressure_pa``, ``config_ay_m``, ``speed_hz``)
    or a numeric model field path (e.g. ``"bearings.*.clearance_m"``): then the system is
    re-assembled with the field at each value (the crossing, α', l1 on that system), and
    ``speed_hz``, ``chamber_pressure_pa``, ``config_ay_m`` are the fixed operating point.

    The crossing: :func:`rotordyn.threshold` in ``bounds`` (its first crossing), or ``at``
    (a value of ``vary`` already on the boundary, e.g. a boundary sweep's row). At the
    crossing: the equilibrium, the Jacobian A of eq. 12 in first-order form (perturbation-
    method K_H, D_H) in scaled coordinates x̃ = (r/L, ṙ/(L ω_s)) (L the smallest film
    clearance, ω_s = max(Ω, ω)), the pair ±iω, and l1 by Kuznetsov's formula with the
    second and third derivatives of the film forces H(r, ṙ) along real directions
    (:func:`lyapunov_at`: ``fd_method="fit"``, a degree-6 least-squares polynomial over
    ±``fd_step`` (scaled), or ``"central"`` differences with step ``fd_step``); l1 is also
    computed with fd_step/2, and a third of the difference is ``l1_error``.
    α' = dRe λ/d(vary) by a central difference of the eigenvalue with step ``param_step``
    (default 1e-4 of max(|value|, the span of bounds, 1 unit·1e-3)).
    ``grid_check``: l1 also on the system with every film grid refined twice (n_circ and
    n_axial × 2, the same operating point and fd_step): ``l1_refined``, and ``l1_error``
    becomes max(l1_error, |l1_refined − l1|) — on a cavitated film the fits see the grid's
    kinks, and a type that changes with the grid is reported ``degenerate``.

    Leading order: cycles |z|² = −α'(p − p_H)/(ω l1) on the side where that is positive,
    x(t) = x_e + 2 Re(z q e^{iωt}); at each journal the largest distance from the mean
    ``A_j = sqrt(amplitude_coefficient_j · |p − p_H|)`` (m), period 2π/ω.
    ``type``: ``supercritical`` (l1 < 0: stable cycles grow on the unstable side, soft
    onset), ``subcritical`` (l1 > 0: unstable cycles on the stable side, hard onset with
    hysteresis), ``degenerate`` (|l1| < 3 ``l1_error``: the sign is not resolved).
    A failure is a status (``no_crossing``, ``no_equilibrium``, ``error``) with a message.
    """
    vary = field_parameter(system, vary)
    fixed = {"speed_hz": v.speed("speed_hz", speed_hz),
             "chamber_pressure_pa": chamber_pressure(system, chamber_pressure_pa),
             "config_ay_m": None if config_ay_m is None else v.finite("config_ay_m",
                                                                       config_ay_m)}
    v.in_range("fd_step", fd_step, 1e-6, 0.5)
    v.choice("fd_method", fd_method, FD_METHODS)
    v.boolean("grid_check", grid_check)
    if (bounds is None) == (at is None):
        raise InputError("bounds, at: give exactly one (bounds: search the crossing with "
                         "rotordyn.threshold; at: the value of vary on the boundary)")
    asm = assembled(system)
    if not asm.bearings:
        raise InputError("system: a Hopf analysis needs at least one fluid-film bearing "
                         "(the nonlinearity of eq. 12 is in the films)")
    fixed_out = {k: val for k, val in fixed.items() if k != vary}  # (a field: all three)
    base = dict(vary=vary, fixed=fixed_out, fd_step=float(fd_step),
                bearing_names=tuple(bc.name for bc in asm.bearings),
                clearance_m=np.array([bc.clearance_m for bc in asm.bearings]))
    if at is None:
        lo, hi = v.bounds("bounds", bounds)
        th = threshold(system, vary, bounds=(lo, hi), n_scan=n_scan, **fixed_out)
        if th.status != "ok":
            return HopfResult.failed(th.status, th.message, **base)
        value, whirl, span = th.value, th.whirl_frequency_hz, hi - lo
        stable_side = th.stable_side
    else:
        value = v.finite("at", at)
        if vary == "chamber_pressure_pa" and value < 0:
            raise InputError(f"at: chamber_pressure_pa must be >= 0, got {at!r}")
        whirl, span, stable_side = math.nan, 0.0, ""
    try:
        res = _hopf_at(system, vary, value, whirl, span, stable_side, fixed, fd_step,
                       fd_method, param_step, base)
        if grid_check and res.ok:
            res = _grid_checked(system, res, fixed, fd_step, fd_method)
        return res
    except RotordynError as exc:
        return HopfResult.failed("error", str(exc), value=value, **base)


def _derivatives(method, field, z0, f0, h):
    if method == "central":
        return central_second(field, z0, f0, h), central_third(field, z0, h)
    return fitted_derivatives(field, z0, h)


def refined(system: System, factor: int = 2) -> System:
    """``system`` with every film grid refined: n_circ and n_axial × ``factor`` (the bearings
    with a grid; a frozen viscosity field is dropped from the refined copy — it is tied to
    its grid)."""
    import dataclasses

    out = []
    for b in system.bearings:
        if hasattr(b, "n_circ") and hasattr(b, "n_axial"):
            kw = dict(n_circ=factor * b.n_circ, n_axial=factor * b.n_axial)
            if getattr(b, "viscosity_field_pa_s", None) is not None:
                kw["viscosity_field_pa_s"] = None
            b = dataclasses.replace(b, **kw)
        out.append(b)
    return dataclasses.replace(system, bearings=tuple(out))


GRID_CHECK_NO_EQUILIBRIUM = "grid_check: no equilibrium on the refined grid"
GRID_CHECK_NO_PAIR = "grid_check: no complex eigenvalue pair on the refined grid"


def _grid_checked(system, res, fixed, fd_step, fd_method):
    """l1 of ``res`` again on the refined films (same point, same fd_step). Without an
    equilibrium or a complex pair there, the type is ``degenerate`` with l1_error = inf (the
    sweep's hopf rows do the same: rotordyn.sweep.hopf_rows)."""
    import dataclasses

    fine = refined(_system_at(system, res.vary, res.value))
    spd, pc, ay = _operating(res.vary, res.value, fixed)
    lm = linearize(fine, spd, pc, ay)
    if lm.equilibrium.status not in CONVERGED:
        return dataclasses.replace(res, type="degenerate", l1_error=math.inf,
                                   message=GRID_CHECK_NO_EQUILIBRIUM)
    A = _jacobian(lm)
    lam = _critical_eigenvalue(A, res.whirl_frequency_hz)
    if lam is None:
        return dataclasses.replace(res, type="degenerate", l1_error=math.inf,
                                   message=GRID_CHECK_NO_PAIR)
    core = lyapunov_at(assembled(fine), np.asarray(lm.equilibrium.r, float), spd, lm.M, A,
                       lam.imag, fd_step, fd_method)
    err = max(res.l1_error, abs(core["l1"] - res.l1))
    return dataclasses.replace(res, l1_refined=float(core["l1"]), l1_error=float(err),
                               type=hopf_type(res.l1, err))


def hopf_type(l1: float, l1_error: float) -> str:
    """supercritical (l1 < 0), subcritical (l1 > 0), degenerate (|l1| < 3 l1_error)."""
    if not math.isfinite(l1) or l1 == 0 or abs(l1) < 3 * l1_error:
        return "degenerate"
    return "supercritical" if l1 < 0 else "subcritical"


def lyapunov_at(asm, r, speed_hz: float, M, A, omega: float, fd_step: float = FD_STEP,
                fd_method: str = "fit") -> dict:
    """l1 at the equilibrium r (n,) of ``asm`` (an assembled system) at ``speed_hz`` with
    the first-order Jacobian A (2n × 2n, SI) and mass matrix M, for the pair ±iω (1/s).
    Scaled coordinates x̃ = (r/L, ṙ/(L ω_s)), L the smallest film clearance,
    ω_s = max(Ω, ω); the second and third derivatives of the film forces H(r, ṙ) along
    real directions by ``fd_method`` (``fit``: a degree-6 least-squares polynomial over
    ±fd_step on 17 points; ``central``: 3-/4-point differences with step fd_step); l1 also
    with fd_step/2, ``l1_error`` = |difference|/3. Returns l1, l1_error, q (2n,) in SI,
    x0 (2n,), semi_major2_per_z2 (n_bearings,): each journal's largest squared distance
    from its mean per |z|² of the normal form, length_scale_m, velocity_scale."""
    n = asm.n
    L = float(min(bc.clearance_m for bc in asm.bearings))
    w = hz_to_rad_s(speed_hz)
    ws = max(abs(w), omega)
    d = np.concatenate([np.full(n, L), np.full(n, L * ws)])
    As = A * d[None, :] / d[:, None]
    Minv = np.linalg.inv(M)
    x0 = np.concatenate([np.asarray(r, float), np.zeros(n)])
    solver = asm.solver

    def field(xs):  # the nonlinear part of the scaled field: (0, M⁻¹ H) / d
        x = x0 + d * xs
        H = np.asarray(solver.film_forces(x[:n], x[n:], w), dtype=float)
        out = np.zeros(2 * n)
        out[n:] = Minv @ H / d[n:]
        return out

    z0 = np.zeros(2 * n)
    f0 = field(z0)
    q, p = hopf_vectors(As, omega)
    res = [first_lyapunov(As, omega, *_derivatives(fd_method, field, z0, f0, h), q, p)
           for h in (fd_step, 0.5 * fd_step)]
    q_phys = q * d
    amp = np.zeros(len(asm.bearings))
    for i, bc in enumerate(asm.bearings):
        wv = q_phys[[bc.jx, bc.jy]]
        amp[i] = 2 * (np.vdot(wv, wv).real + abs(wv @ wv))  # semi-major² per |z|²
    return {"l1": res[0]["l1"], "l1_error": abs(res[1]["l1"] - res[0]["l1"]) / 3.0,
            "q": q_phys, "x0": x0, "semi_major2_per_z2": amp, "length_scale_m": L,
            "velocity_scale": float(ws)}


def _hopf_at(system, vary, value, whirl, span, stable_side, fixed, fd_step, fd_method,
             param_step, base):
    spd, pc, ay = _operating(vary, value, fixed)
    sys_v = _system_at(system, vary, value)
    if sys_v is not system:  # a model field: the clearances at the Hopf point's value
        base = {**base, "clearance_m": np.array([bc.clearance_m
                                                 for bc in assembled(sys_v).bearings])}
    lm = linearize(sys_v, spd, pc, ay)
    e = lm.equilibrium
    if e.status not in CONVERGED:
        return HopfResult.failed("no_equilibrium", f"{e.status}: {e.message}", value=value,
                                 **base)
    A = _jacobian(lm)
    if not math.isfinite(whirl):
        lam = np.linalg.eigvals(A)
        up = lam[lam.imag > 0]
        whirl = float(up[int(np.argmax(up.real))].imag / (2 * np.pi)) if up.size else math.nan
    lam0 = _critical_eigenvalue(A, whirl)
    if lam0 is None:
        return HopfResult.failed("error", "no complex eigenvalue pair at the crossing (a "
                                 "real eigenvalue through zero is a fold of equilibria, not a "
                                 "Hopf point)", value=value, **base)
    omega = lam0.imag
    # α' = dRe λ/dp: the same eigenvalue followed to p ± dp
    dp = param_step if param_step is not None else 1e-4 * max(abs(value), span, 1e-3)
    dp = v.positive("param_step", dp)
    re = []
    for s in (1, -1):
        p2 = value + s * dp
        if vary == "chamber_pressure_pa" and p2 < 0:
            p2 = value  # one-sided at p_c = 0
        lm2 = linearize(_system_at(system, vary, p2), *_operating(vary, p2, fixed))
        if lm2.equilibrium.status not in CONVERGED:
            return HopfResult.failed("no_equilibrium", f"at {vary} = {p2:g}: "
                                     f"{lm2.equilibrium.message}", value=value, **base)
        re.append((p2, _eig_near(_jacobian(lm2), lam0).real))
    alpha_p = (re[0][1] - re[1][1]) / (re[0][0] - re[1][0])

    core = lyapunov_at(assembled(sys_v), np.asarray(e.r, float), spd, lm.M, A, omega,
                       fd_step, fd_method)
    if not (math.isfinite(core["l1"]) and math.isfinite(alpha_p)):
        return HopfResult.failed("error", "non-finite l1 or dRe λ/dp", value=value, **base)
    l1, l1_err = core["l1"], core["l1_error"]
    kind = hopf_type(l1, l1_err)
    z2_per = abs(alpha_p / (omega * l1)) if l1 != 0 else math.inf
    cycle_side = "above" if -alpha_p / l1 > 0 else "below"
    amp_coef = core["semi_major2_per_z2"]
    q_phys, x0, L, ws = core["q"], core["x0"], core["length_scale_m"], core["velocity_scale"]
    return HopfResult(value=float(value), whirl_frequency_hz=float(omega / (2 * np.pi)),
                      speed_hz=float(spd), l1=l1, l1_error=float(l1_err), type=kind,
                      alpha_prime=float(alpha_p), real_part=float(lam0.real),
                      stable_side=stable_side or ("above" if alpha_p < 0 else "below"),
                      cycle_side=cycle_side, amplitude_coefficient=amp_coef * z2_per,
                      z2_per_unit=float(z2_per), q=q_phys, x_equilibrium=x0,
                      length_scale_m=L, velocity_scale=float(ws), status="ok", message="",
                      **base)


def hopf_cycle(system: System, result: HopfResult, value: float, *, rtol: float = 1e-8,
               tol: float = 1e-6, **kw):
    """The limit cycle at ``value`` of ``result.vary`` near the Hopf point ``result``, by
    shooting (:func:`rotordyn.periodic_orbit`) from the leading-order cycle
    x_e(value) + 2 Re(z q) with period 2π/ω (x_e the equilibrium at ``value``). InputError
    when ``value`` is on the side without cycles. Keywords go to
    :func:`rotordyn.periodic_orbit` on the system at ``value`` (a model field ``vary``: the
    system re-assembled with the field there); very near the point (the cycle's radial
    multiplier within ~1e-5 of 1) pass ``method="harmonic_balance"``: shooting's flow map is
    at its integration noise there and lands on other cycles or is refused
    (docs/nonlinear.md, "l1 inside the kink-free piece")."""
    from rotordyn.analysis.equilibrium import equilibrium
    from rotordyn.analysis.periodic import periodic_orbit

    if not isinstance(result, HopfResult) or not result.ok:
        raise InputError("result: expected a HopfResult with status ok")
    x, period = result.cycle_state(value)
    spd, pc, ay = _operating(result.vary, value, result.fixed | {result.vary: value})
    system = _system_at(system, result.vary, value)
    e = equilibrium(system, spd, pc, ay)
    n = x.size // 2
    if e.status in CONVERGED:  # the cycle about this point's own equilibrium
        x = x.copy()
        x[:n] += np.asarray(e.r) - result.x_equilibrium[:n]
    return periodic_orbit(system, spd, pc, ay, start=(x[:n], x[n:]), period_s=period,
                          rtol=rtol, tol=tol, **kw)


def hopf_branch(system: System, result: HopfResult, bounds, *, distance: float | None = None,
                rtol: float = 1e-8, tol: float = 1e-6, **kw):
    """The branch of limit cycles born at the Hopf point ``result``: the first cycle by
    :func:`hopf_cycle` at ``distance`` (unit of vary; default 0.2 % of the bounds' span)
    from the point on its cycle side, then :func:`rotordyn.continuation` away from the point
    within ``bounds`` (keywords passed on; a model field ``vary``: on the system with the
    field at the first cycle's value, by ``method="harmonic_balance"``; another method is
    refused before any solve; the first cycle by the same method and harmonics). Returns the BranchResult (a failed first cycle:
    ConvergenceError with its message)."""
    from rotordyn.analysis.continuation import continuation, field_method_error
    from rotordyn.errors import ConvergenceError

    lo, hi = v.bounds("bounds", bounds)
    if not isinstance(result, HopfResult) or not result.ok:
        raise InputError("result: expected a HopfResult with status ok")
    d = v.positive("distance", distance if distance is not None else 2e-3 * (hi - lo))
    sgn = 1 if result.cycle_side == "above" else -1
    value = result.value + sgn * d
    how = {}
    if result.vary not in OPERATING:  # a model field: harmonic-balance correctors only
        kw.setdefault("method", "harmonic_balance")
        if kw["method"] != "harmonic_balance":  # refused before the first cycle's solve
            raise field_method_error(result.vary)
        how = {k: kw[k] for k in ("method", "harmonics", "time_points") if k in kw}
    first = hopf_cycle(system, result, value, rtol=rtol, tol=tol, **how)
    if not first.ok:
        raise ConvergenceError(f"hopf_branch: the first cycle at {result.vary} = "
                               f"{value:.6g} did not converge: {first.message}")
    return continuation(_system_at(system, result.vary, value), result.vary, (lo, hi), first,
                        direction=sgn, rtol=rtol, tol=tol, **kw)
