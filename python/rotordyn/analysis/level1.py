"""API 617 Level I stability analysis (API 617 8th ed. Part 1 §4.8.5; API 684 2nd ed. §2.9).

The system is linearised once at its equilibrium at the speed (fluid films, sleeves and pads
included: :func:`rotordyn.linearize`; linear supports as they are). A destabilising
cross-coupled stiffness Q is added at the rotor (forces F_x = −Q y, F_y = +Q x, which feed a
forward whirl for Ω > 0 — ROSS's ``kxy = Q, kyx = −Q``) and the eigenvalues of eq. 19 with
K + Q K_Q are computed for each Q. The judged mode is a forward rotor mode (never a sleeve's or
a tilting pad's own mode, never a backward one). Q_0, where its log decrement reaches zero, is
found by bracketing (Q doubled from Q_A) and Brent's method, not on a grid. Q_A is the sum of
the stages' anticipated cross-couplings (:mod:`rotordyn.model.stage`).

Where Q acts (API 684 §2.9): at the rotor's mid-span for a between-bearing rotor, at the
stages' centroid for an overhung one (``at="auto"``); or shared between the stages in
proportion to their q_A (``at="stages"``), or at a station given by number. A point between FE
nodes is moved to the nearest node (its position is reported). In a reduced model the added
stiffness is reduced with the rotor's own transformation T (Tᵀ K_Q T)."""

from __future__ import annotations

import dataclasses

import numpy as np

from rotordyn._common.api import RESONANT_ZETA
from rotordyn._common import validate as v
from rotordyn._common.threads import limited_blas
from rotordyn.analysis.assembly import assembled
from rotordyn.analysis.linear import _stability_from, linearize
from rotordyn.errors import InputError
from rotordyn.model.rotor import Reduction, Support
from rotordyn.model.stage import Stage
from rotordyn.model.system import System
from rotordyn.results.equilibrium import CONVERGED
from rotordyn.results.level1 import Level1Result

MODES = ("first_forward", "least_damped")
PLACEMENTS = ("auto", "midspan", "centroid", "stages")
N_POINTS = 25       # points of the δ(Q) curve (the frame and the figure; Q_0 is not read off it)
Q_MAX_FACTOR = 100.0  # search Q up to 100 × the largest rotor diagonal stiffness


def _stages(system: System, stages) -> tuple[Stage, ...]:
    if stages is None:
        return system.stages
    out = []
    for i, st in enumerate(v.sequence("stages", stages)):
        if isinstance(st, dict):
            try:
                st = Stage(**st)
            except TypeError as exc:
                raise InputError(f"stages[{i}]: {exc}") from None
        if not isinstance(st, Stage):
            raise InputError(f"stages[{i}]: expected a Stage or a dict, got {type(st).__name__}")
        st.check(f"stages[{i}]", system.rotor.n_stations)
        out.append(st)
    return tuple(out)


def _placement(system: System, stages, q_stage: np.ndarray, at) -> tuple[list, str]:
    """[(label, node, share, z_m)] and why."""
    rotor = system.rotor
    pos = rotor.station_positions_m()
    nodes_z = rotor.node_positions_m()
    st_nodes = rotor.station_nodes()
    brg = sorted({b.station for b in system.bearings} | {s.station for s in system.supports})

    def at_z(z: float, share: float = 1.0):
        nd = int(np.argmin(np.abs(nodes_z - z)))
        hit = np.flatnonzero(st_nodes == nd)
        return (f"station {int(hit[0])}" if hit.size else f"node {nd}", nd, share,
                float(nodes_z[nd]))

    if isinstance(at, (int, np.integer)) and not isinstance(at, bool):
        k = v.integer("at", at, lo=0, hi=rotor.n_stations - 1)
        return ([(f"station {k}", int(st_nodes[k]), 1.0, float(pos[k]))],
                f"at station {k} (as given)")
    v.choice("at", at, PLACEMENTS)
    if at == "auto":
        lo, hi = (pos[brg[0]], pos[brg[-1]]) if brg else (np.inf, -np.inf)
        zs = [pos[s.station] for s in stages]
        inside = len(brg) >= 2 and any(lo <= z <= hi for z in zs)
        both = any(z < lo for z in zs) and any(z > hi for z in zs)
        at = ("midspan" if (inside or not stages) else "stages" if both  # double overhung
              else "centroid")
    if at == "midspan":
        if len(brg) < 2:
            raise InputError("at: 'midspan' needs two bearings or supports (the span); give a "
                             "station number or at='centroid'/'stages'")
        z = 0.5 * (pos[brg[0]] + pos[brg[-1]])
        p = at_z(z)
        return [p], (f"at mid-span between stations {brg[0]} and {brg[-1]} (z = {z:.4g} m; "
                     f"nearest FE node {p[0]}, z = {p[3]:.4g} m), API 684 for a between-bearing "
                     "rotor")
    if not stages:
        raise InputError(f"at: {at!r} needs stage data ([[stage]] or stages=)")
    if at == "centroid":
        z = float(np.sum(q_stage * pos[[s.station for s in stages]]) / np.sum(q_stage))
        p = at_z(z)
        return [p], (f"at the stages' centroid (q_A-weighted, z = {z:.4g} m; nearest FE node "
                     f"{p[0]}), API 684 for an overhung rotor")
    share = q_stage / np.sum(q_stage)
    return ([(f"station {s.station}", int(st_nodes[s.station]), float(w), float(pos[s.station]))
             for s, w in zip(stages, share)],
            "at each stage, in proportion to its q_A")


def _coupling_matrix(asm, placement) -> np.ndarray:
    """K_Q (n, n) for Q = 1 N/m on the system coordinates: f_x = −Q y, f_y = +Q x at each
    placement node (times its share)."""
    rm = asm.rotor
    dofs = {int(d): i for i, d in enumerate(np.asarray(rm.full.dofs))}
    T = None if rm.reduction is None else np.asarray(rm.reduction.T)
    K = np.zeros((asm.n, asm.n))
    for label, nd, share, _ in placement:
        rows = []
        for c in (0, 1):
            i = dofs.get(4 * nd + c)
            if i is None:
                raise InputError(f"at: {label} has a rigid support (its translations are fixed); "
                                 "the cross-coupling cannot act there")
            e = np.zeros(asm.n)
            if T is None:
                e[i] = 1.0
            else:
                e[:asm.n_rotor] = T[i]
            rows.append(e)
        sx, sy = rows
        K += share * (np.outer(sx, sy) - np.outer(sy, sx))
    return K


# RESONANT_ZETA (rotordyn._common.api, imported above): a root damped beyond it has no resonance


def _candidates(st, max_freq_hz) -> np.ndarray:
    """Indices of the rotor modes of a StabilityResult that are not backward (no sleeve or pad
    mode; oscillating; at most ``max_freq_hz``): forward ones, and planar ones (nearly straight
    orbits, as on anisotropic supports, or a forward/backward pair that coincides on isotropic
    ones at Q = 0)."""
    f = st.frequencies_hz
    ok = (st.whirl != "backward") & (st.kind == "rotor") & (f > 0)
    if max_freq_hz is not None:
        ok &= f <= max_freq_hz
    return np.flatnonzero(ok)


def _whirl_index(phi: np.ndarray, xy) -> np.ndarray:
    """(|F|² − |B|²)/(|F|² + |B|²) of each shape's orbits (k,) over the (ix, iy) pairs: > 0
    when they turn forward (the rule of the C++ whirl classification, without its band)."""
    ix = [p[0] for p in xy]
    iy = [p[1] for p in xy]
    X, Y = phi[ix], phi[iy]
    area = np.sum(np.imag(X * Y.conj()), axis=0)
    scale = np.sum(np.abs(X) ** 2 + np.abs(Y) ** 2, axis=0)
    return 2.0 * area / np.where(scale > 0, scale, 1.0)


def _first_forward(st, idx) -> int:
    """The first forward mode at Q = 0: the lowest-frequency forward rotor mode that has a
    resonance (damping ratio below 1/√2; a root damped beyond that, such as a rigid-body mode
    on very damped films, δ > 2π, has none), else the lowest forward one."""
    res = [j for j in idx if st.damping_ratio[j] < RESONANT_ZETA]
    return int(res[0] if res else idx[0])


def _mac(a: np.ndarray, b: np.ndarray, M: np.ndarray) -> float:
    """Mass-weighted modal assurance criterion of two complex shapes, in [0, 1]."""
    ab = a.conj() @ M @ b
    return float(abs(ab) ** 2 / max(abs(a.conj() @ M @ a) * abs(b.conj() @ M @ b), 1e-300))


def rigid_support_critical_hz(system: System) -> float:
    """First undamped natural frequency (Hz, at rest) of the rotor with rigid supports at its
    bearings and supports (the denominator of API 617's critical speed ratio); NaN when it
    cannot be computed."""
    from rotordyn.analysis.modes import modes
    from rotordyn.errors import RotordynError

    stations = sorted({b.station for b in system.bearings} | {s.station for s in system.supports})
    if len(stations) < 2:
        return float("nan")
    s = dataclasses.replace(system, supports=tuple(Support(k, "rigid") for k in stations),
                            bearings=(), thermal=None,  # (no films: no oil system)
                            reduction=Reduction(method="none"))
    try:
        f = modes(s, 0.0, reduction="none", n_modes=4).frequencies_hz
    except RotordynError:
        return float("nan")
    f = f[np.isfinite(f) & (f > 0)]
    return float(f.min()) if f.size else float("nan")


@limited_blas
def level1(system: System, speed_hz: float, chamber_pressure_pa: float = 0.0,
           config_ay_m: float | None = None, *, stages=None, at="auto",
           mode: str = "first_forward", max_freq_hz: float | None = None,
           gas_density_kg_m3: float | None = None, csr_limit: float | None = None,
           q_max_n_per_m: float | None = None, n_points: int = N_POINTS,
           q_points_n_per_m=None, **equilibrium_kw) -> Level1Result:
    """API 617 Level I stability analysis at ``speed_hz`` (run it at the maximum continuous
    speed; the stages' rated power at that speed).

    Parameters
    ----------
    stages : the stage data (:class:`rotordyn.model.stage.Stage` or dicts of its fields);
        default the model's ``[[stage]]`` tables. Without any, Q_0 and the curve are computed
        and the criteria are "not evaluated (no stage data)".
    at : where Q acts: ``"auto"`` (mid-span between the outermost bearings/supports; the
        stages' centroid when every stage overhangs on one side; each stage when they overhang
        on both sides), ``"midspan"``, ``"centroid"``, ``"stages"`` (shared in proportion to
        q_A) or a station number.
    mode : the judged mode: ``"first_forward"`` (default, the standard's wording): the
        lowest-frequency rotor mode at Q = 0 whose orbits turn forward (however elliptic) and
        that has a resonance (damping ratio below 1/√2), followed along Q by its shape; or
        ``"least_damped"``: the smallest log decrement of all forward rotor modes (up to
        ``max_freq_hz``) at each Q, so Q_0 is where the system first loses stability
        (conservative: lightly damped high modes count).
    max_freq_hz : judge only forward modes at most this frequency (Hz).
    gas_density_kg_m3 : average gas density (first-stage suction and last-stage discharge),
        echoed for the screening figure. csr_limit : the Region B boundary CSR read from the
        standard's figure at that density; with it the screening criterion is judged.
    q_max_n_per_m : the largest Q searched (default 100 × the largest rotor diagonal
        stiffness). n_points : points of the δ(Q) curve (≥ 3), from 0 to 1.2 max(Q_0, Q_A);
        q_points_n_per_m : further Q values (N/m, ≥ 0) put on the curve (e.g. another tool's).
    Other keywords go to :func:`rotordyn.equilibrium`.
    """
    from scipy.optimize import brentq
    v.positive("speed_hz", speed_hz)
    v.choice("mode", mode, MODES)
    if max_freq_hz is not None:
        v.positive("max_freq_hz", max_freq_hz)
    if gas_density_kg_m3 is not None:
        v.positive("gas_density_kg_m3", gas_density_kg_m3)
    if csr_limit is not None:
        v.positive("csr_limit", csr_limit)
    if q_max_n_per_m is not None:
        v.positive("q_max_n_per_m", q_max_n_per_m)
    n_points = v.integer("n_points", n_points, lo=3, hi=10_000)
    extra_q = (np.zeros(0) if q_points_n_per_m is None
               else v.vector("q_points_n_per_m", q_points_n_per_m))
    if extra_q.size > 10_000 or np.any(extra_q < 0) or not np.all(np.isfinite(extra_q)):
        raise InputError("q_points_n_per_m: expected at most 10000 finite values ≥ 0 N/m")
    stg = _stages(system, stages)
    q_stage = np.array([s.cross_coupling_n_per_m(speed_hz) for s in stg])
    q_a = float(q_stage.sum()) if stg else float("nan")
    placement, why = _placement(system, stg, q_stage, at)
    asm = assembled(system)
    k_q = _coupling_matrix(asm, placement)
    stage_rows = tuple(dict(dataclasses.asdict(s), q_a_n_per_m=float(q))
                       for s, q in zip(stg, q_stage))
    f_crit = rigid_support_critical_hz(system)
    common = dict(placement=tuple(placement), placement_why=why, stages=stage_rows, mode=mode,
                  csr=float(speed_hz / f_crit) if np.isfinite(f_crit) else float("nan"),
                  first_critical_hz=f_crit,
                  gas_density_kg_m3=float("nan") if gas_density_kg_m3 is None
                  else float(gas_density_kg_m3),
                  csr_limit=float("nan") if csr_limit is None else float(csr_limit))

    lm = linearize(system, speed_hz, chamber_pressure_pa, config_ay_m, **equilibrium_kw)
    nan = float("nan")
    if lm.status not in CONVERGED:
        e = np.zeros(0)
        return Level1Result(float(speed_hz), e, e, e, q_a, nan, nan, nan, status=lm.status,
                            message=lm.equilibrium.message or "no equilibrium", **common)

    cache: dict[float, tuple[float, float]] = {}
    shapes: dict[float, np.ndarray] = {}  # the judged mode's shape at each evaluated Q

    def at_q(q: float) -> tuple[float, float]:
        """(δ, f) of the judged mode at Q: "first_forward" follows the first forward mode of
        Q = 0 by its shape (MAC against the nearest Q evaluated so far), "least_damped" takes
        the smallest δ of the forward rotor modes."""
        q = float(q)
        if q in cache:
            return cache[q]
        st = _stability_from(asm, dataclasses.replace(lm, K=lm.K + q * k_q), None)
        idx = _candidates(st, max_freq_hz)
        if not shapes and mode == "first_forward":  # the seed: orbits turning forward
            idx = idx[_whirl_index(st.modes[:, idx], asm.rotor.xy_pairs()) > 0]
        if not idx.size:
            cache[q] = (float("nan"), float("nan"))
            return cache[q]
        if mode == "least_damped":
            j = int(idx[np.argmin(st.log_dec[idx])])
        elif not shapes:
            j = _first_forward(st, idx)
        else:
            ref = shapes[min(shapes, key=lambda x: abs(x - q))]
            j = int(idx[np.argmax([_mac(ref, st.modes[:, i], lm.M) for i in idx])])
        shapes[q] = st.modes[:, j]
        cache[q] = (float(st.log_dec[j]), float(st.frequencies_hz[j]))
        return cache[q]

    # the stiffness scale: the largest diagonal entry of K on the rotor's coordinates
    k_ref = float(np.max(np.abs(np.diag(lm.K)[:asm.n_rotor]))) if asm.n_rotor else 1.0
    q_scale = q_a if np.isfinite(q_a) and q_a > 0 else 1e-3 * k_ref
    if mode == "first_forward":
        # The mode is picked at a Q small enough not to change it (1e-4 Q_A) but large enough
        # to split a forward/backward pair that coincides at Q = 0 (isotropic supports), and
        # followed from there.
        at_q(1e-4 * q_scale)
    d0, f0 = at_q(0.0)
    if not np.isfinite(d0):
        e = np.zeros(0)
        return Level1Result(float(speed_hz), e, e, e, q_a, nan, nan, nan, status="error",
                            message="no forward rotor mode" + (f" below {max_freq_hz:g} Hz"
                                                               if max_freq_hz else ""), **common)
    q_max = float(q_max_n_per_m) if q_max_n_per_m is not None else Q_MAX_FACTOR * k_ref
    message = ""
    if d0 <= 0.0:
        q0 = 0.0
        message = "the judged forward mode has no positive damping at Q = 0"
    else:
        lo, hi = 0.0, min(q_scale, q_max)
        while at_q(hi)[0] > 0.0 and hi < q_max:
            lo, hi = hi, min(2.0 * hi, q_max)
        if at_q(hi)[0] > 0.0:
            q0 = float("inf")
            message = f"δ stays positive up to Q = {q_max:.4g} N/m"
        else:
            q0 = float(brentq(lambda q: at_q(q)[0], lo, hi, xtol=1e-12 * hi, rtol=1e-10))
            if abs(at_q(q0)[0]) > 1e-6 * max(1.0, d0):
                message = (f"δ jumps through zero at Q_0 (the judged mode changes there: "
                           f"{at_q(q0)[0]:.3g})")
    top = max(x for x in (q0, q_a, 0.0) if np.isfinite(x))
    if top == 0.0:
        top = min(q_max, 1e-3 * k_ref)
    qs = set(np.linspace(0.0, 1.2 * top, n_points).tolist())
    qs |= {x for x in (q0, q_a) if np.isfinite(x)} | set(extra_q.tolist())
    qs = np.array(sorted(qs))
    vals = np.array([at_q(q) for q in qs])
    # A δ(Q) that dips below zero and recovers between two doublings of the bracket: the
    # curve shows it, and Q_0 is the first crossing.
    below = np.flatnonzero((vals[:, 0] < 0.0) & (qs < q0))
    if q0 > 0.0 and below.size and below[0] > 0:
        k = below[0]
        q0 = float(brentq(lambda q: at_q(q)[0], qs[k - 1], qs[k], xtol=1e-12 * qs[k],
                          rtol=1e-10))
        message = "δ(Q) crosses zero more than once; Q_0 is the first crossing"
        qs = np.array(sorted(set(qs.tolist()) | {q0}))
        vals = np.array([at_q(q) for q in qs])
    d_a = at_q(q_a)[0] if np.isfinite(q_a) else nan
    return Level1Result(float(speed_hz), qs, vals[:, 0], vals[:, 1], q_a, q0, d_a, q_max,
                        status=lm.status, message=message, log_dec_0=d0, freq_0_hz=f0, **common)
