"""The synchronous (1×) bound of the single-chamber actuator: what ANY control law can do to
the steady unbalance response of the linear model.

At a constant speed Ω the linear model about the equilibrium at the mean chamber pressure
p₀ is time invariant, so the steady 1× response to the unbalance plus any chamber-pressure
command p_cmd(t) (open loop, feedback, anything periodic) depends on p_cmd only through
its 1× component p̂ (complex, p_cmd ∋ Re(p̂ e^{iθ})):

    q̂ = (K − Ω² M + iΩ D)⁻¹ (Ω² F_u + c_s H(iΩ) p̂)        (paper eq. 12 linearised)

with c_s the chamber-pressure load vector, H the valve (command → p_c) and F_u the unbalance
load. Each station's orbit is an ellipse with complex amplitudes (X, Y), affine in p̂; its
semi-major axis (|X + iY| + |X − iY|) / 2 (forward + backward whirl radii) is convex in p̂.
Minimising the largest semi-major axis over the stations subject to the valve's limits
(the command p₀ ± |p̂| inside [p_min, p_max]) is a convex problem in two real variables,
solved here by nested golden-section searches (0.618⁴⁰ ≈ 4e-9 of the search box) with an
exact penalty for the amplitude limit. The minimum over p₀ as well is the lowest steady 1×
amplitude any law driving this one actuator can reach in the linear model; with p₀ the
passive pressure it is what a 1× command added to that pressure can reach.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from rotordyn._common import validate as v
from rotordyn.analysis.assembly import assembled
from rotordyn.control import _checks as chk
from rotordyn.control.schedule import linear_model_grid
from rotordyn.errors import InputError

if TYPE_CHECKING:
    import pandas as pd

_GOLD = (np.sqrt(5.0) - 1.0) / 2.0


def semi_major(X, Y):
    """Semi-major axis of the orbit x = Re(X e^{iΩt}), y = Re(Y e^{iΩt}) (m; broadcasts)."""
    return 0.5 * (np.abs(X + 1j * Y) + np.abs(X - 1j * Y))


def _objective(a, b, p):
    """max over stations of the semi-major axis of (a + b p); a, b (N, n_st, 2), p (N,)."""
    z = a + b * p[:, None, None]
    return semi_major(z[..., 0], z[..., 1]).max(axis=1)


def _golden(f, lo, hi, iters):
    """Vectorised golden-section minimisation of convex f(x) (N,) on [lo, hi] (N,)."""
    for _ in range(iters):
        c = hi - _GOLD * (hi - lo)
        d = lo + _GOLD * (hi - lo)
        left = f(c) < f(d)
        hi = np.where(left, d, hi)
        lo = np.where(left, lo, c)
    x = 0.5 * (lo + hi)
    return x, f(x)


def minimise_semi_major(a, b, limit, *, iters: int = 40):
    """min over |p| ≤ limit of max_k semi-major axis of a_k + b_k p.

    a, b: (N, n_st, 2) complex (x, y amplitudes per station at p = 0, and per unit p);
    limit: (N,) ≥ 0. Returns (p (N,) complex, value (N,)). Nested golden sections over
    Re p (outer) and Im p (inner) on the box |Re p|, |Im p| ≤ limit, with the exact penalty
    L·max(0, |p| − limit) (L = 2 × the objective's Lipschitz constant), so the minimiser
    is the constrained one."""
    v.integer("iters", iters, lo=1, hi=200)
    try:
        a = np.asarray(a, complex)
        b = np.asarray(b, complex)
    except (TypeError, ValueError):
        raise InputError("a, b: expected complex arrays of shape (N, n_st, 2)") from None
    if a.ndim != 3 or a.shape[2] != 2 or b.shape != a.shape or a.shape[1] < 1:
        raise InputError(f"a, b: expected complex arrays of the same shape (N, n_st, 2), got "
                         f"{a.shape} and {b.shape}")
    if not (np.all(np.isfinite(a)) and np.all(np.isfinite(b))):
        raise InputError("a, b: expected finite amplitudes")
    lim = v.vector("limit", np.ravel(limit) if np.ndim(limit) else [limit] * a.shape[0],
                   a.shape[0])
    if np.any(lim < 0):
        raise InputError(f"limit: expected amplitude limits >= 0 Pa, got {float(lim.min())!r}")
    L = 2.0 * (np.abs(b[..., 0]) + np.abs(b[..., 1])).max(axis=1) + 1e-300

    def F(u, w):
        p = u + 1j * w
        return _objective(a, b, p) + L * np.maximum(0.0, np.abs(p) - lim)

    def inner(u):
        return _golden(lambda w: F(u, w), -lim, lim, iters)[1]

    u, _ = _golden(inner, -lim, lim, iters)
    w, _ = _golden(lambda w: F(u, w), -lim, lim, iters)
    p = u + 1j * w
    scale = np.where(np.abs(p) > lim, lim / np.maximum(np.abs(p), 1e-300), 1.0)
    p = p * scale  # the penalty leaves |p| ≤ limit up to the search tolerance
    return p, _objective(a, b, p)


def _references(references_m, ns, nst):
    if references_m is None:
        ref = np.ones(nst)
    elif np.ndim(references_m) == 0:
        ref = np.array([v.positive("references_m", references_m)])
    elif np.ndim(references_m) == 1:
        ref = v.vector("references_m", references_m)
    else:
        ref = v.matrix("references_m", references_m)
    try:
        ref = np.broadcast_to(ref, (ns, nst)).copy()
    except ValueError:
        raise InputError(f"references_m: expected {nst} values or ({ns}, {nst})") from None
    if not np.all(np.isfinite(ref)) or np.any(ref <= 0):
        raise InputError("references_m: expected finite amplitudes > 0 m")
    return ref


@dataclass(frozen=True)
class SynchronousBound:
    """Per (speed, mean pressure p₀) of the grid: the passive semi-major axes (p̂ = 0) and
    the optimal ones, the optimal 1× command p̂ (Pa, complex; the command's 1× part is
    Re(p̂ e^{iθ}) = |p̂| sin(θ + arg p̂ + 90°)), its limit, and the least damping ratio of
    the linear model at (speed, p₀).

    Arrays: passive_m, optimal_m (n_s, n_p, n_st); objective_passive, objective (the
    largest semi-major axis over the stations, each divided by its reference amplitude —
    1 m without references: metres), p_hat_pa, limit_pa, min_damping_ratio (n_s, n_p);
    status (n_s, n_p); references_m (n_s, n_st)."""

    speeds_hz: np.ndarray
    pressures_pa: np.ndarray
    stations: tuple
    passive_m: np.ndarray
    optimal_m: np.ndarray
    objective_passive: np.ndarray
    objective: np.ndarray
    p_hat_pa: np.ndarray
    limit_pa: np.ndarray
    min_damping_ratio: np.ndarray
    status: np.ndarray
    a: np.ndarray  # (n_s, n_p, n_st, 2) complex, response to the unbalance
    b: np.ndarray  # (n_s, n_p, n_st, 2) complex, response per Pa of 1× command
    references_m: np.ndarray

    def to_frame(self) -> pd.DataFrame:
        import pandas as pd
        ns, npp = self.objective.shape
        d = {"speed_hz": np.repeat(self.speeds_hz, npp),
             "chamber_pressure_pa": np.tile(self.pressures_pa, ns)}
        for k, s in enumerate(self.stations):
            d[f"passive_semi_major_m[{s}]"] = self.passive_m[:, :, k].ravel()
            d[f"optimal_semi_major_m[{s}]"] = self.optimal_m[:, :, k].ravel()
        d.update({"objective_passive": self.objective_passive.ravel(),
                  "objective": self.objective.ravel(),
                  "harmonic_amplitude_pa": np.abs(self.p_hat_pa).ravel(),
                  "harmonic_phase_deg": self.harmonic_phase_deg(self.p_hat_pa).ravel(),
                  "limit_pa": self.limit_pa.ravel(),
                  "min_damping_ratio": self.min_damping_ratio.ravel(),
                  "status": self.status.ravel().astype(str)})
        return pd.DataFrame(d)

    @staticmethod
    def harmonic_phase_deg(p_hat):
        """φ of the command A sin(θ + φ) equal to Re(p̂ e^{iθ}): φ = arg p̂ + 90° (degrees)."""
        return np.degrees(np.angle(p_hat)) + 90.0

    def column(self, pressure_pa: float) -> int:
        pressure_pa = v.finite("pressure_pa", pressure_pa)
        j = int(np.argmin(np.abs(self.pressures_pa - pressure_pa)))
        if not np.isclose(self.pressures_pa[j], pressure_pa, rtol=0, atol=1e-6):
            raise InputError(f"pressure_pa: {pressure_pa} is not on the grid "
                             f"{self.pressures_pa.tolist()}")
        return j

    def best_over_pressures(self, *, min_damping: float | None = None):
        """Per speed, the grid pressure p₀ with the lowest optimal objective (optionally only
        among p₀ whose passive linear model has every ζ ≥ ``min_damping``: no feedback
        needed for stability). Returns (p₀ (n_s,), objective (n_s,), index (n_s,))."""
        obj = np.where(self.status == "ok", self.objective, np.inf)
        if min_damping is not None:
            v.in_range("min_damping", min_damping, -1.0, 1.0)
            obj = np.where(self.min_damping_ratio >= min_damping, obj, np.inf)
        j = np.argmin(obj, axis=1)
        val = obj[np.arange(obj.shape[0]), j]
        p0 = np.where(np.isfinite(val), self.pressures_pa[j], np.nan)
        return p0, np.where(np.isfinite(val), val, np.nan), j

    def with_references(self, references_m, *, iters: int = 40) -> "SynchronousBound":
        """The same grid (no new equilibria) re-optimised for other reference amplitudes
        ((n_st,) or (n_s, n_st), m; e.g. (1e-6, 1) to minimise the first station alone)."""
        ns, nst = self.speeds_hz.size, len(self.stations)
        ref = _references(references_m, ns, nst)
        v.integer("iters", iters, lo=10, hi=200)
        return _optimise(self.speeds_hz, self.pressures_pa, self.stations, self.a, self.b,
                         self.limit_pa, self.min_damping_ratio, self.status, ref, iters)

    def harmonic_schedule(self, pressure_pa, speeds_hz=None):
        """Amplitude (Pa) and unwrapped phase (deg) tables of the optimal 1× command over the
        speeds, at the mean pressure ``pressure_pa`` (a grid value, or an array of grid values
        per speed — e.g. a static schedule). Returns (speeds_hz, amplitude_pa, phase_deg).
        ``speeds_hz``: must be None (the tables are on the bound's own speeds)."""
        if speeds_hz is not None:
            raise InputError("speeds_hz: expected None (the tables are on the bound's own "
                             "speeds; interpolate them or compute the bound on other speeds)")
        if np.ndim(pressure_pa) == 0:
            pp = np.full(self.speeds_hz.shape, v.finite("pressure_pa", pressure_pa))
        else:
            pp = v.vector("pressure_pa", pressure_pa, self.speeds_hz.size)
        j = np.array([self.column(p) for p in pp])
        ph = self.p_hat_pa[np.arange(self.speeds_hz.size), j]
        ok = np.isfinite(ph)
        phase = np.degrees(np.unwrap(np.angle(ph[ok]))) + 90.0
        return self.speeds_hz[ok], np.abs(ph[ok]), phase


def synchronous_bound(system, unbalances, speeds_hz, pressures_pa, *, stations,
                      references_m=None, config_ay_m: float | None = None, actuator=None,
                      iters: int = 40) -> SynchronousBound:
    """The synchronous bound of the module docstring over the (speed × mean pressure) grid.

    ``unbalances`` as in :func:`rotordyn.unbalance_response`; ``stations``: rotor stations
    whose largest orbit semi-major axis is minimised, each divided by its reference amplitude
    ``references_m`` ((n_st,) or (n_s, n_st), m; default 1 m: the plain largest axis — with
    the passive peaks as references the design maximises the smallest reduction factor);
    ``actuator``: the valve (default
    :class:`~rotordyn.control.Actuator`, 100 Hz): its lag H(iΩ) is in the map and its limits
    bound the command, |p̂| ≤ min(p₀ − p_min, p_max − p₀). Equilibria are continued in speed at
    each pressure (as :func:`rotordyn.control.schedule.pressure_schedule`)."""
    chk.system(system)
    act = chk.actuator(actuator)
    ub = chk.unbalances(system, unbalances)
    sp = chk.speeds("speeds_hz", speeds_hz)
    pp = chk.pressures("pressures_pa", pressures_pa)
    if np.any(pp < act.p_min_pa) or np.any(pp > act.p_max_pa):
        raise InputError(f"pressures_pa: expected mean pressures inside the valve's limits "
                         f"[{act.p_min_pa}, {act.p_max_pa}] Pa")
    st = chk.stations(system, stations)
    config_ay_m = chk.config_ay(system, config_ay_m)
    v.integer("iters", iters, lo=10, hi=200)
    ref = _references(references_m, sp.size, len(st))
    asm = assembled(system)
    Cout = [asm.station_output_matrix(s) for s in st]
    F1 = asm.unbalance_load(ub)
    num, den = act.transfer_function()
    ns, npp, nst = sp.size, pp.size, len(Cout)
    a = np.full((ns, npp, nst, 2), np.nan, dtype=complex)
    b = np.full((ns, npp, nst, 2), np.nan, dtype=complex)
    zmin = np.full((ns, npp), np.nan)
    status = np.full((ns, npp), "error", dtype=object)
    for i, j, stt, lm, w, zm in linear_model_grid(system, sp, pp, config_ay_m):
        status[i, j], zmin[i, j] = stt, zm
        if lm is None:
            continue
        H = np.polyval(num, 1j * w) / np.polyval(den, 1j * w)
        Z = lm.K - w**2 * lm.M + 1j * w * lm.D
        q = np.linalg.solve(Z, np.column_stack([w**2 * F1, H * np.asarray(lm.chamber)]))
        for k, Co in enumerate(Cout):
            a[i, j, k] = Co @ q[:, 0]
            b[i, j, k] = Co @ q[:, 1]
        if not (np.all(np.isfinite(a[i, j])) and np.all(np.isfinite(b[i, j]))
                and np.isfinite(zm)):
            status[i, j] = "error"  # never an ok point with a non-finite response
    lim = np.minimum(pp - act.p_min_pa, act.p_max_pa - pp)
    lim = np.broadcast_to(lim[None, :], (ns, npp)).copy()
    return _optimise(sp, pp, st, a, b, lim, zmin, status, ref, iters)


def _optimise(sp, pp, stations, a, b, lim, zmin, status, ref, iters):
    ns, npp, nst = a.shape[:3]
    ok = status == "ok"
    passive = np.where(ok[..., None], semi_major(a[..., 0], a[..., 1]), np.nan)
    phat = np.full((ns, npp), np.nan, dtype=complex)
    optimal = np.full((ns, npp, nst), np.nan)
    W = np.broadcast_to(ref[:, None, :, None], a.shape)
    if ok.any():
        p_ok, _ = minimise_semi_major(a[ok] / W[ok], b[ok] / W[ok], lim[ok], iters=iters)
        phat[ok] = p_ok
        z = a[ok] + b[ok] * p_ok[:, None, None]
        optimal[ok] = semi_major(z[..., 0], z[..., 1])
    R = ref[:, None, :]
    return SynchronousBound(sp, pp, stations, passive, optimal, (passive / R).max(axis=2),
                            (optimal / R).max(axis=2), phat, lim, zmin, status, a, b, ref)
