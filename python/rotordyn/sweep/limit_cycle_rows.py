"""The ``limit_cycle`` sweep analysis (issue 19): along each grid line of the varied axis
(``options.vary``: p_c, speed or a_y; the other axes fixed), the Hopf points of the line
(the ``hopf`` analysis's blocks: :func:`rotordyn.sweep.hopf_rows.hopf_line_blocks`), the
limit-cycle branch born at each one continued along the line by pseudo-arclength
continuation through folds (:func:`rotordyn.analysis.hopf.hopf_cycle`,
:func:`rotordyn.continuation`), and at every grid value the branch passes the cycle there
by shooting (:func:`rotordyn.periodic_orbit`, started from the branch interpolated linearly
between its two points that bracket the value): amplitude, period, whirl frequency, the
critical Floquet multiplier and stability, and whether the cycle coexists with a linearly
stable equilibrium (bistable: a stable cycle there).

Rows (one schema, ``record`` tells them apart):

* ``record = "hopf"``: the crossings of the line, the same columns and values as the
  ``hopf`` analysis's rows (``no_crossing`` for a line without one).
* ``record = "cycle"``: one row per grid point and cycle found there (``cycle`` = 1, 2, …
  by amplitude; a fold gives several), with the branch's Hopf point (``crossing``, ``value``,
  ``hopf_type``, ``l1``…), ``amplitude_m`` (the orbit's semi-major axis: its largest distance
  from its mean, at the active bearing's journal or ``options.station``), ``period_s``,
  ``whirl_frequency_hz`` = 1/period, ``max_multiplier`` (|μ| of the largest non-trivial
  Floquet multiplier), ``stable``, ``equilibrium_stable``/``max_real_1_per_s`` (the grid
  point's equilibrium, from the threshold scan), ``coexists_with_stable_equilibrium``,
  ``bistable`` (the point's equilibrium is stable and a stable cycle exists there). A point
  without a cycle is one row with status ``no_cycle`` (every branch of the line ended at a
  bound beyond the grid, a Hopf point or a rub, or the line has no Hopf point) or
  ``failed`` (a branch did not start, stopped early or left its bounds short of the grid's
  end value, or the shooting at the point failed; message says which).

Options (docs/nonlinear.md): the ``hopf`` analysis's, and the shooting's ``rtol``, ``tol``,
``sensitivity_rtol``, ``n_out``; the continuation's ``ds``, ``ds_max``, ``max_points``,
``newton`` (``exact`` — the default, also ``sensitivities`` —, ``fast``, ``broyden``: its
correctors only; the cycle at each grid value is shot by Newton with sensitivities); ``method``
(``shooting``, the default, or ``harmonic_balance``: the branches' correctors and the cycle at
each grid value by harmonic balance, with ``harmonics`` and ``time_points``; its Floquet
multipliers from the samples, by one sensitivity flow near the unit circle; the first cycle
at a Hopf point stays shot) — each cycle row's ``method`` says which computed it;
``start_amplitude``, ``distance``, ``station``. ``tol`` is the shooting's:
the threshold scan, crossings and l1 of the hopf rows keep the equilibrium's default
tolerance, so they equal a ``hopf`` sweep's rows.

Each line pins the chunk's fresh solver for the analyses it calls (no state from earlier
chunks), so rows do not depend on the worker."""

from __future__ import annotations

import copy
import dataclasses
import math

import numpy as np

from rotordyn.analysis.assembly import pin_assembled
from rotordyn.analysis.continuation import DEFAULT_NEWTON, continuation
from rotordyn.analysis.hb_continuation import HARMONICS, checked_orbit
from rotordyn.analysis.hopf import FD_STEP, hopf, hopf_cycle
from rotordyn.analysis.periodic import periodic_orbit
from rotordyn.analysis.transient import transient
from rotordyn.errors import RotordynError
from rotordyn.sweep import points as pt
from rotordyn.sweep.columns import merge
from rotordyn.sweep.hopf_rows import HOPF_COLUMNS, hopf_line_blocks
from rotordyn.sweep.lines import block_rows

#: statuses of limit-cycle rows beyond the common vocabulary
CYCLE_STATUS = ["no_cycle", "failed"]
#: output columns of a cycle row beyond the ``hopf`` analysis's
CYCLE_COLUMNS = ("cycle", "bearing", "amplitude_m", "amplitude_c", "period_s",
                 "max_multiplier", "critical_type", "stable", "equilibrium_stable",
                 "max_real_1_per_s", "coexists_with_stable_equilibrium", "bistable",
                 "newton_iterations")
#: branch ends after which a grid value the branch did not pass has no cycle on it
NATURAL_ENDS = ("bound", "hopf", "rub", "equilibrium")
#: defaults of the options (docs/nonlinear.md)
DEFAULTS = {"rtol": 1e-7, "tol": 1e-6, "ds": 0.05, "ds_max": 0.2, "max_points": 60,
            "n_out": 1001, "start_amplitude": 0.08, "newton": DEFAULT_NEWTON,
            "method": "shooting", "harmonics": HARMONICS}


def semi_major_axis(x, y) -> float:
    """The largest distance of a closed orbit (x, y) (n_t,), m, from its mean position over
    one period (the samples close the period: the last repeats the first), refined between
    samples by the parabola through the squared distances of the largest sample and its two
    neighbours (error O(h³) in the sample spacing, against O(h²) of the largest sample: the
    same orbit sampled at another phase gives the same number to ~1e-8 at 1000 samples)."""
    x = np.asarray(x, float)[:-1]
    y = np.asarray(y, float)[:-1]
    d2 = (x - x.mean()) ** 2 + (y - y.mean()) ** 2
    k = int(np.argmax(d2))
    a, b, c = d2[k - 1], d2[k], d2[(k + 1) % d2.size]
    den = a - 2 * b + c
    peak = b - (c - a) ** 2 / (8 * den) if den < 0 else b
    return float(math.sqrt(max(peak, b)))


def _where(asm, station):
    """(name, (2, n) output matrix) of the amplitude's place: ``station`` or the active
    bearing's (else the first bearing's) journal."""
    if station is not None:
        return f"station {station}", asm.station_output_matrix(int(station))
    bc = pt.ref_bearing(asm)
    C = np.zeros((2, asm.n))
    C[0, bc.jx] = C[1, bc.jy] = 1.0
    return bc.name, C


def _cycle_columns(o, C, clearance, speed):
    xy = o.r @ C.T
    A = semi_major_axis(xy[:, 0], xy[:, 1])
    mc = o.critical_multiplier
    return {"amplitude_m": A, "amplitude_c": A / clearance if clearance > 0 else math.nan,
            "period_s": o.period_s, "whirl_frequency_hz": 1.0 / o.period_s,
            "whirl_ratio": 1.0 / (o.period_s * speed) if speed else math.nan,
            "max_multiplier": abs(mc) if mc is not None else math.nan,
            "critical_type": o.critical_type, "stable": bool(o.stable),
            "newton_iterations": int(o.stats.get("iterations", 0)),
            "method": str(o.stats.get("method", "shooting"))}


class _Line:
    """The operating point of a line's grid values, and the shooting options."""

    def __init__(self, job, asm, p0, xs):
        self.vary = job.options["vary"]
        self.p0 = dict(p0)
        self.xs = xs
        self.asm = asm
        self.system = asm.system
        o = job.options
        self.rtol = float(o.get("rtol", DEFAULTS["rtol"]))
        self.tol = float(o.get("tol", DEFAULTS["tol"]))
        self.srtol = o.get("sensitivity_rtol")
        self.n_out = int(o.get("n_out", DEFAULTS["n_out"]))
        self.newton = str(o.get("newton", DEFAULTS["newton"]))
        self.method = str(o.get("method", DEFAULTS["method"]))
        self.harmonics = int(o.get("harmonics", DEFAULTS["harmonics"]))
        self.time_points = o.get("time_points")

    def operating(self, value):
        p = dict(self.p0)
        p[self.vary] = float(value)
        return (float(p.get("speed_hz", 50.0)), float(p.get("chamber_pressure_pa", 0.0)),
                p.get("config_ay_m"))

    def corrector_options(self) -> dict:
        """The continuation's keywords of the method (shooting: its correctors)."""
        if self.method == "harmonic_balance":
            return {"method": self.method, "harmonics": self.harmonics,
                    "time_points": self.time_points}
        return {"newton": self.newton}

    def shoot(self, value, r, vel, period):
        f, pc, ay = self.operating(value)
        if self.method == "harmonic_balance":
            return checked_orbit(self.system, f, pc, ay, start=(r, vel), period_s=period,
                                 harmonics=self.harmonics, time_points=self.time_points,
                                 n_out=self.n_out, rtol=self.rtol, tol=self.tol,
                                 sensitivity_rtol=self.srtol)
        return periodic_orbit(self.system, f, pc, ay, start=(r, vel), period_s=period,
                              n_out=self.n_out, rtol=self.rtol, tol=self.tol,
                              sensitivity_rtol=self.srtol)


def _branch(job, line, hrow, span, verdicts):
    """(HopfResult, [branches], failure message) of the cycles born at the crossing
    ``hrow``. The first cycle is shot from the leading-order cycle at the distance from the
    Hopf point where its amplitude is ``start_amplitude`` of the clearance (at most 5 % of
    the line's span; ``distance`` × span if given), on the Hopf result's cycle side, else on
    the other; it is continued both ways (each with ``max_points``: on a cavitated film
    the parameter does not tell which way the cycles grow) within the line's range widened
    by max(5 %, 1.5 ds_max) of its span (the continuation's param_scale is the span, so the
    step out of the bounds starts beyond the end value and the end values are bracketed
    by branch points). When no leading-order start converges (the normal form fails at
    once on a cavitated film), the cycle a transient settles on at the unstable grid value
    nearest the Hopf point, continued both ways."""
    o = job.options
    f, pc, ay = line.operating(hrow["value"])
    h = hopf(line.system, line.vary, at=hrow["value"], speed_hz=f, chamber_pressure_pa=pc,
             config_ay_m=ay, fd_step=float(o.get("fd_step", FD_STEP)))
    if not h.ok:
        return h, [], f"the Hopf point at {hrow['value']:.6g}: {h.status}: {h.message}"
    ds = float(o.get("ds", DEFAULTS["ds"]))
    ds_max = max(float(o.get("ds_max", DEFAULTS["ds_max"])), ds)
    # the continuation drops the first point outside its bounds, and one step moves the
    # parameter by up to ds_max × param_scale (the tangent has unit length in the scaled
    # units; param_scale = the line's span): bounds wider than the grid by 1.5 such steps
    # keep a branch point beyond each end value, so the end values are bracketed
    margin = max(0.05, 1.5 * ds_max) * span
    lo, hi = min(line.xs) - margin, max(line.xs) + margin
    if line.vary == "speed_hz" and min(line.xs) > 0:
        lo = max(lo, 0.5 * min(line.xs))
    if "distance" in o:
        d = float(o["distance"]) * span
    else:
        L = h.length_scale_m
        kap = float(np.max(h.amplitude_coefficient))
        target = float(o.get("start_amplitude", DEFAULTS["start_amplitude"])) * L
        d = min(target ** 2 / kap if kap > 0 and math.isfinite(kap) else math.inf,
                0.05 * span)
    first_side = 1 if h.cycle_side == "above" else -1
    msgs = []
    for sgn in (first_side, -first_side, 0):
        settled = sgn == 0
        if settled:  # the cycle a transient settles on, on the line's unstable side
            c0, sgn = _settled_cycle(line, h, verdicts)
            if not c0.ok:
                msgs.append(c0.message)
                continue
        else:
            hs = h if sgn == first_side else dataclasses.replace(
                h, cycle_side="below" if h.cycle_side == "above" else "above")
            value = h.value + sgn * d
            try:
                c0 = hopf_cycle(line.system, hs, value, rtol=line.rtol, tol=line.tol,
                                max_iter=12)
            except (RotordynError, ArithmeticError, ValueError) as exc:
                msgs.append(f"{type(exc).__name__}: {exc}")
                continue
            if not c0.ok:
                msgs.append(f"at {value:.6g}: {c0.status}: {c0.message}")
                continue
        # the first step no longer than half the first cycle (scaled by the clearance): a
        # longer predictor jumps across the equilibrium onto the same family half a period
        # on, which reads as the Hopf end; the step then grows ×1.5 per easy corrector
        a0 = max(c0.amplitude(b) for b in range(c0.journal_x_m.shape[1])) / c0.length_scale_m
        ds0 = min(ds, max(0.5 * a0, 2e-3))
        kw = dict(ds=ds0, ds_min=min(1e-3, 0.5 * ds0),
                  ds_max=ds_max, param_scale=span, rtol=line.rtol, tol=line.tol,
                  sensitivity_rtol=line.srtol, n_out=101, **line.corrector_options())
        mp = int(o.get("max_points", DEFAULTS["max_points"]))
        out = []
        for direction in (sgn, -sgn):
            br = continuation(line.system, line.vary, (lo, hi), c0, direction=direction,
                              max_points=mp, **kw)
            if not br.ok:
                msgs.append(f"continuation: {br.status}: {br.message}")
                break
            out.append(br)
        else:
            return h, out, ""
    return h, [], ("no cycle started from the leading-order cycle at "
                   f"{d:.3g} either side of the Hopf point {h.value:.6g}, nor from a "
                   "transient: " + "; ".join(msgs))


class _NoCycle:
    ok = False

    def __init__(self, message):
        self.message = message


def _settled_cycle(line, h, verdicts):
    """(cycle, direction towards the Hopf point) from a transient at the grid value of the
    line's unstable side nearest the Hopf point: 60 whirl periods from the equilibrium
    disturbed by 0.1 c, then shooting from its last period (the attracting cycle, the one a
    disturbance throws the journal onto)."""
    xs = np.asarray(line.xs, float)
    unst = np.flatnonzero(np.asarray(verdicts) == 0)  # the verdict's unstable points
    if unst.size == 0:
        return _NoCycle("transient: no grid value of the line has an unstable equilibrium"), 0
    k = int(unst[np.argmin(np.abs(xs[unst] - h.value))])
    f, pc, ay = line.operating(xs[k])
    period = 1.0 / h.whirl_frequency_hz
    try:
        tr = transient(line.system, 60 * period, f, pc, ay,
                       disturbance_m=(0.0, 0.1 * h.length_scale_m), n_out=60 * 50 + 1)
        o = periodic_orbit(line.system, f, pc, ay, start=tr, rtol=line.rtol, tol=line.tol,
                           sensitivity_rtol=line.srtol)
    except (RotordynError, ArithmeticError, ValueError) as exc:
        return _NoCycle(f"transient at {xs[k]:.6g}: {type(exc).__name__}: {exc}"), 0
    if not o.ok:
        return _NoCycle(f"transient at {xs[k]:.6g}, then shooting: {o.status}: "
                        f"{o.message}"), 0
    return o, (1 if h.value > xs[k] else -1)


def _starts(h, br, g, n, span):
    """Starts for the cycle at grid value g from every segment of the branch ``br`` whose
    ends bracket g: ("branch", [(r, v, period), …]) interpolated linearly between the two
    points, then the nearer point itself (the interpolation of two large orbits can close
    the film). Beyond the last point of a branch that ended on an equilibrium (``hopf``: the
    end estimated by the continuation; ``equilibrium``: the last point, a cycle below 1 % of
    the clearance), when the end is the branch's own Hopf point ``h`` (within 5 % of the
    line's span): ("hopf", None), the leading-order cycle of ``h`` on its cycle side; when
    the branch ended at another Hopf point of the line: the last point's cycle (the
    leading order of ``h`` does not hold there: on the rig it closes the film)."""
    P = list(br.parameter)
    X = [(np.concatenate([o.r[0], o.v[0]]), o.period_s) for o in br.orbits]
    out = []
    for i in range(len(P) - 1):
        a, b = P[i], P[i + 1]
        if not (min(a, b) <= g <= max(a, b)) or a == b or (g == b and i + 2 < len(P)):
            continue
        w = (g - a) / (b - a)
        x = (1 - w) * X[i][0] + w * X[i + 1][0]
        T = (1 - w) * X[i][1] + w * X[i + 1][1]
        near = X[i] if w <= 0.5 else X[i + 1]
        out.append(("branch", [(x[:n], x[n:], T), (near[0][:n], near[0][n:], near[1])]))
    if not P or br.stop not in ("hopf", "equilibrium"):
        return out
    bif = br.bifurcations[-1] if br.bifurcations else {}
    end = float(bif["parameter"]) if br.stop == "hopf" and bif.get("kind") == "hopf" \
        else P[-1]
    if abs(end - h.value) <= 0.05 * span:  # back at its own Hopf point
        if min(P[-1], h.value) <= g <= max(P[-1], h.value) and g not in (P[-1], h.value) \
                and (g > h.value) == (h.cycle_side == "above"):
            out.append(("hopf", None))
    elif min(P[-1], end) <= g <= max(P[-1], end) and g != P[-1]:
        out.append(("branch", [(X[-1][0][:n], X[-1][0][n:], X[-1][1])]))
    return out


def _shoot(line, h, g, how, starts):
    """(the converged cycle at g or None, failure messages) from the starts of one
    segment, tried in order."""
    if how == "hopf":
        starts = [None]
    msgs = []
    for k, st in enumerate(starts):
        what = ("the leading-order cycle" if how == "hopf" else
                "the branch interpolated" if k == 0 else "the nearer branch point")
        try:
            o = hopf_cycle(line.system, h, g, rtol=line.rtol, tol=line.tol,
                           n_out=line.n_out, sensitivity_rtol=line.srtol) \
                if how == "hopf" else line.shoot(g, *st)
        except (RotordynError, ArithmeticError, ValueError) as exc:
            msgs.append(f"shooting from {what}: {type(exc).__name__}: {exc}")
            continue
        if o.ok:
            return o, msgs
        msgs.append(f"shooting from {what}: {o.status}: {o.message}")
    return None, msgs


def _same(a, b, tol, clearance) -> bool:
    """Whether two cycles at one grid value are one (reached from two segments): amplitude
    within max(1e-4 relative, 10 tol × clearance) and period within max(1e-5, 10 tol)
    relative (tol the shooting's): one cycle converged from two starts differs by about the
    tolerance (measured on the rig at tol 1e-4: 1.1e-4 c in amplitude, 2.5e-5 in the
    period), two cycles of a fold by far more except right at the fold."""
    da = abs(a["amplitude_m"] - b["amplitude_m"])
    dT = abs(a["period_s"] - b["period_s"])
    return (da <= max(1e-4 * b["amplitude_m"], 10 * tol * clearance) and
            dT <= max(1e-5, 10 * tol) * b["period_s"])


def _short_of_the_end(br, xs) -> bool:
    """Whether the branch, stopped at a bound, has its last point inside the grid's range
    on the side it was heading to (the grid values beyond it then are not bracketed)."""
    p = float(br.parameter[-1])
    up = br.tangent_p[-1] > 0 if len(br) < 2 else br.parameter[-1] > br.parameter[-2]
    return p < max(xs) if up else p > min(xs)


def limit_cycle_line(job, variants, lo, hi, at, asms):
    """The blocks of the line [lo, hi) (module docstring; its first point at chunk-local
    index ``at``): the Hopf blocks of the line (:func:`~rotordyn.sweep.hopf_rows.
    hopf_line_blocks`) with the cycle columns null, then one single-row block per cycle row
    (each costs a shooting solve), joined per run of points (:func:`~rotordyn.sweep.columns.
    merge`)."""
    scan = {}
    # the hopf rows without the shooting's ``tol``: the threshold scan, the crossings and
    # l1 read ``tol`` as the equilibrium's tolerance (default 1e-10, as in a hopf sweep),
    # and ``method`` as the equilibrium's solver (here: the cycles' method)
    hjob = copy.copy(job)
    hjob.options = {k: x for k, x in job.options.items()
                    if k not in ("tol", "method", "harmonics", "time_points")}
    line_asms = [None] * (hi - lo)
    hblocks = hopf_line_blocks(hjob, variants, lo, hi, 0, line_asms, scan)
    asms[at:at + hi - lo] = line_asms
    hrows: list = []
    block_rows(job, 0, lo, hi, line_asms, hblocks, hrows)
    nan_cols = {c: math.nan for c in CYCLE_COLUMNS}
    nan_cols.update(cycle=None, bearing=None, critical_type=None, stable=None,
                    equilibrium_stable=None, coexists_with_stable_equilibrium=None,
                    bistable=None, newton_iterations=None)
    blocks = [(np.asarray(pts) + at, {**nan_cols, **cols, "record": "hopf"})
              for pts, cols in hblocks]
    vary = job.options["vary"]
    idx0, p0 = job.point(lo)
    try:
        asm = variants.get(p0)
    except RotordynError as exc:
        blocks.append((at + np.arange(hi - lo), {**nan_cols, "record": "cycle",
                                                 "status": "failed", "message": str(exc)}))
        return blocks
    pin_assembled(asm)
    pts = [job.point(pid) for pid in range(lo, hi)]
    xs = [p[vary] for _, p in pts]
    span = max(xs) - min(xs)
    line = _Line(job, asm, p0, xs)
    ys = scan.get("y", np.full(len(xs), np.nan))
    # the scan's verdicts (1 stable, 0 unstable, -1 failed: the round-off band's rule, not
    # the raw sign of max Re λ, which called a conservative point's +1e-12 unstable)
    verdicts = scan.get("stable", np.full(len(xs), -1))
    name, C = _where(asm, job.options.get("station"))
    bc = pt.ref_bearing(asm)
    clearance = bc.clearance_m if (bc is not None and job.options.get("station") is None) \
        else min(b.clearance_m for b in asm.bearings)

    branches, problems = [], []
    for hr in hrows:
        if hr.get("status") != "ok" or not math.isfinite(hr.get("value", math.nan)):
            if hr.get("status") == "error":
                problems.append(f"crossing {hr['crossing']}: {hr['message']}")
            continue
        if any(b[2].stop == "hopf" and abs(b[2].bifurcations[-1]["parameter"] -
                                           hr["value"]) < 1e-2 * span
               and abs(b[1].value - hr["value"]) > 1e-2 * span for b in branches):
            continue  # this crossing ends a branch already continued from another one
        try:
            h, brs, msg = _branch(job, line, hr, span, verdicts)
        except (RotordynError, ArithmeticError, ValueError, np.linalg.LinAlgError) as exc:
            h, brs, msg = None, [], f"{type(exc).__name__}: {exc}"
        if not brs:
            problems.append(f"crossing {hr['crossing']}: {msg}")
            continue
        hcols = {c: hr[c] for c in ("crossing", "value", "stable_side", "evaluations",
                                    *HOPF_COLUMNS)}
        for br in brs:
            if br.stop not in NATURAL_ENDS:
                problems.append(f"crossing {hr['crossing']}: the branch stopped early "
                                f"({br.stop}: {br.message}) at {vary} = "
                                f"{br.parameter[-1]:.6g}")
            elif br.stop == "bound" and len(br) and _short_of_the_end(br, xs):
                problems.append(f"crossing {hr['crossing']}: the branch left its bounds "
                                f"after {vary} = {br.parameter[-1]:.6g}, short of the "
                                "grid's end value (not bracketed)")
            branches.append((hcols, h, br))

    n = asm.n
    asms[at:at + hi - lo] = [asm] * (hi - lo)
    for k, (idx, p) in enumerate(pts):
        row = {**nan_cols, "record": "cycle"}
        here = np.array([at + k])
        y = float(ys[k])
        eq_st = bool(verdicts[k] == 1) if verdicts[k] >= 0 else None
        row.update(max_real_1_per_s=y, equilibrium_stable=eq_st, bearing=name)
        g = p[vary]
        f = line.operating(g)[0]
        found, failed = [], []
        for hcols, h, br in branches:
            for how, starts in _starts(h, br, g, n, span):
                o, msgs = _shoot(line, h, g, how, starts)
                if o is None:
                    failed.append((hcols, "; ".join(msgs)))
                    continue
                cols = _cycle_columns(o, C, clearance, f)
                if any(_same(c, cols, line.tol, clearance) for _, c in found):
                    continue  # the same cycle reached from two segments
                found.append((hcols, cols))
        found.sort(key=lambda t: t[1]["amplitude_m"])
        bistable = bool(eq_st) and any(c["stable"] for _, c in found)
        for j, (hcols, cols) in enumerate(found):
            blocks.append((here, {**row, **hcols, **cols, "cycle": j + 1,
                                  "coexists_with_stable_equilibrium": bool(eq_st),
                                  "bistable": bistable, "status": "ok", "message": ""}))
        for hcols, msg in failed:
            blocks.append((here, {**row, **hcols, "cycle": 0, "bistable": bistable,
                                  "status": "failed", "message": msg}))
        if not found and not failed:
            if problems:
                st, msg = "failed", "; ".join(problems)
            elif not branches:
                st, msg = "no_cycle", "no Hopf point on the line: no cycle branch"
            else:
                st, msg = "no_cycle", "no cycle branch passes this value"
            blocks.append((here, {**row, "cycle": 0, "bistable": False,
                                  "status": st, "message": msg}))
    return merge(blocks)
