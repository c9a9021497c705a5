"""Equilibrium, stability/Campbell and boundary-refinement chunks as columnar blocks (issue
22): one C++ call per run of points on one model with one set of options
(``equilibrium_batch``, ``stability_batch``, ``max_real_batch``), whose flat result arrays
become the rows' columns at once (:mod:`.columns`), with no dict per row or per point.

The rows are those of the former per-point loops (same calls on the same solver in the same
order, the same values in the same row order): tests/test_sweep_columns.py.
"""

from __future__ import annotations

import math

import numpy as np

from rotordyn import _core
from rotordyn._common.whirl import WHIRL_NAMES
from rotordyn.analysis.linear import FD_REL_STEP
from rotordyn.errors import RotordynError
from rotordyn.results.modes import log_dec, settled_real
from rotordyn.sweep.columns import runs
from rotordyn.sweep.points import (CONVERGED, STATUS, equilibrium_options, mode_kind, operating,
                                   point_list, ref_bearing, segments, stable_modes)
from rotordyn.sweep.tilt_rows import batch_tilt, repeat_lists
from rotordyn.sweep.tracking import track_points
from rotordyn.units import hz_to_rad_s

_NAMES = np.array([WHIRL_NAMES[-1], WHIRL_NAMES[0], WHIRL_NAMES[1]])


def _operating(items, errs, catch, named):
    """(f, pc, a) per point, or None with the error in ``errs``."""
    ops = [None] * len(items)
    memo: dict = {}  # the items hold their models alive: ids are not reused meanwhile
    for k, it in enumerate(items):
        if errs[k]:
            continue
        try:
            ops[k] = operating(it[1], it[0], memo)
        except catch as exc:
            errs[k] = f"{type(exc).__name__}: {exc}" if named else str(exc)
    return ops


def _inputs(ops):
    return (np.array([hz_to_rad_s(o[0]) for o in ops]), np.array([o[1] for o in ops]),
            np.array([o[2] for o in ops]))


def _status(st):
    return st if st in STATUS else "error"


# -- equilibrium ----------------------------------------------------------------------------
def eq_blocks(job, variants, chunk_id, pids, asms):
    """Equilibria (one row per bearing; a point whose solve raised: one error row)."""
    items = point_list(job, variants, pids, asms)
    errs = [it[4] for it in items]
    ops = _operating(items, errs, (RotordynError, ArithmeticError, ValueError), False)
    blocks = []
    for i, j, good in segments(items, errs):
        if not good:
            blocks.append((np.array([i]), {"status": "error", "message": errs[i]}))
            continue
        seg = items[i:j]
        asm, opts = seg[0][1], seg[0][2]
        restart = [1 if k == 0 or not it[3] else 0 for k, it in enumerate(seg)]
        res = _core.equilibrium_batch(asm.solver, *_inputs(ops[i:j]), restart,
                                      equilibrium_options(opts))
        blocks += _eq_seg(asm, res, i)
    return blocks


def _eq_seg(asm, res, at):
    R, IT, RES = np.asarray(res.r), np.asarray(res.iterations), np.asarray(res.residual)
    HM = asm.bearing_h_min(np.asarray(res.h_min))
    HZ = np.asarray(res.h_min_z_m)
    FF = np.asarray(res.film_force)
    st = np.array([_status(s) for s in res.status], dtype=object)
    msg = np.array(res.message, dtype=object)
    raised = np.array([s == "error" for s in res.status])
    bs = asm.bearings
    nb = len(bs)
    out = []
    for a, b, bad in runs(raised):
        k = np.arange(a, b)
        if bad:
            out.append((at + k, {"status": st[a:b], "message": msg[a:b]}))
            continue
        ok = np.array([s in CONVERGED for s in res.status[a:b]])[:, None]
        nan = np.full((b - a, nb), math.nan)
        X = np.where(ok, R[a:b][:, [bc.jx for bc in bs]], nan)
        Y = np.where(ok, R[a:b][:, [bc.jy for bc in bs]], nan)
        c = np.array([bc.clearance_m if bc.clearance_m > 0 else math.nan for bc in bs])
        tilt = ok & np.array([bool(bc.rot) for bc in bs])[None, :]
        rot = [bc.rot if bc.rot else (0, 0) for bc in bs]
        hf = np.asarray(res.h_min)[a:b]  # the thinnest film of a lobed bearing
        hz_col = [asm.min_film_index(bc.index, hf) if bc.rot else np.zeros(b - a, dtype=int)
                  for bc in bs]
        hz_col = np.stack(hz_col, axis=1) if bs else np.zeros((b - a, 0), dtype=int)
        m = (b - a) * nb
        with np.errstate(invalid="ignore"):
            out.append((np.repeat(at + k, nb), {
                "bearing": np.tile(np.array([bc.name for bc in bs], dtype=object), b - a),
                "journal_x_m": X.ravel(), "journal_y_m": Y.ravel(),
                "x_over_c": (X / c).ravel(), "y_over_c": (Y / c).ravel(),
                "h_min_m": np.where(ok, HM[a:b], nan).ravel(),
                "iterations": np.repeat(IT[a:b].astype(np.int64), nb),
                "residual": np.repeat(RES[a:b], nb),
                "journal_theta_x_rad": np.where(tilt, R[a:b][:, [r[0] for r in rot]],
                                                nan).ravel(),
                "journal_theta_y_rad": np.where(tilt, R[a:b][:, [r[1] for r in rot]],
                                                nan).ravel(),
                "h_min_z_m": np.where(tilt, np.take_along_axis(HZ[a:b], hz_col, axis=1)
                                      if HZ.shape[1] else nan, nan).ravel(),
                "film_moment_x_n_m": np.where(tilt, FF[a:b][:, [r[0] for r in rot]],
                                              nan).ravel(),
                "film_moment_y_n_m": np.where(tilt, FF[a:b][:, [r[1] for r in rot]],
                                              nan).ravel(),
                "status": np.repeat(st[a:b], nb), "message": np.repeat(msg[a:b], nb)}))
            assert len(out[-1][0]) == m
    return out


# -- stability / Campbell -------------------------------------------------------------------
def stab_blocks(job, variants, chunk_id, pids, asms):
    """Stability points: equilibrium continued along the line, K_H/D_H, eigen-analysis (one
    row per mode; a failed point: one row), mode ids tracked along each line."""
    items = point_list(job, variants, pids, asms)
    errs = [it[4] for it in items]
    ops = _operating(items, errs, RotordynError, True)
    segs = []
    for i, j, good in segments(items, errs):
        segs.append((i, j, _stab_batch(job, items[i:j], ops[i:j]) if good else None))
    # mode ids tracked along lines (a failed point does not end a line)
    n = len(items)
    ids: list = [None] * n
    if job.options.get("track", True):
        pts, new_line = [], True
        for i, j, S in segs:
            for k in range(i, j):
                new_line = new_line or not items[k][3]
                if S is not None and S["ok"][k - i]:
                    pts.append((k, S["lam"][k - i], S["modes"][k - i], new_line,
                                items[k][1].mats[0]))
                    new_line = False
        for k, v in track_points(pts).items():
            ids[k] = v
    blocks = []
    for i, j, S in segs:
        if S is None:
            blocks.append((np.array([i]), {"status": "error", "message": errs[i]}))
            continue
        for a, b, good in runs(S["ok"]):
            k = np.arange(a, b)
            if not good:
                blocks.append((i + k, {"status": S["st"][a:b], "message": S["fail"][a:b]}))
            else:
                blocks.append(_stab_block(S, a, b, i, ids))
    return blocks


def _cut(EV, W, KIND, KE, modes, ok, n_modes):
    """The batch's per-point modes cut to ``n_modes`` by the API's rule
    (:func:`rotordyn.analysis.linear.mode_window`), padded as the batch pads (NaN, 0,
    "rotor"); the point's verdict (``max_real``, ``least_stable``) keeps every root."""
    from rotordyn.analysis.linear import mode_window

    sel = [mode_window(KIND[k, :KE[k]], n_modes) if ok[k] else np.zeros(0, int)
           for k in range(len(KE))]
    ke = np.array([len(q) if ok[k] else KE[k] for k, q in enumerate(sel)], dtype=np.int64)
    w = int(ke.max()) if ke.size else 0
    ev = np.full((len(KE), w), np.nan + 1j * np.nan)
    wh = np.zeros((len(KE), w), dtype=W.dtype)
    kd = np.full((len(KE), w), "rotor", dtype=object)
    md = list(modes)
    for k in np.flatnonzero(ok):
        q = sel[k]
        ev[k, :q.size], wh[k, :q.size], kd[k, :q.size] = EV[k, q], W[k, q], KIND[k, q]
        md[k] = np.asarray(modes[k])[:, q]
    return ev, wh, kd, ke, md


def _stab_batch(job, seg, ops):
    asm, opts = seg[0][1], seg[0][2]
    n_modes = job.options.get("n_modes") or 0
    pads = any(getattr(b, "extra", ()) for b in asm.bearings)  # tilting pads' own modes
    restart = [1 if k == 0 or not it[3] else 0 for k, it in enumerate(seg)]
    # with tilting pads every mode is computed, classified, then cut by the API's rule
    # (rotordyn.analysis.linear.mode_window: n_modes counts the rotor's and sleeve's modes,
    # the pads' below the highest kept one listed beside them); the batch's own cut counted
    # pad roots, so a pad root took a rotor mode's slot
    res = _core.stability_batch(
        asm.solver, *_inputs(ops), restart, equilibrium_options(opts),
        0 if pads else int(n_modes),
        opts.get("linearization", "perturbation") == "finite_difference", FD_REL_STEP,
        asm.rotor.xy_pairs(), asm.rotor.rot_pairs(), [i for bc in asm.bearings for i in bc.sleeve])
    bc = ref_bearing(asm, job.options.get("bearing"))
    KE = np.asarray(res.n_eig).astype(np.int64)
    EV = np.asarray(res.eigenvalues)
    R = np.asarray(res.r)
    H = np.asarray(res.h_min)
    st = np.array([_status(s) for s in res.status], dtype=object)
    ok = np.array([s in CONVERGED for s in st]) & (KE > 0)
    W = np.asarray(res.whirl)
    KIND = np.where(np.asarray(res.sleeve_share) > 0.5, "sleeve", "rotor").astype(object)
    modes = list(res.modes)
    if pads:
        for k in np.flatnonzero(ok):
            Mw = (np.asarray(asm.model.mass_at(hz_to_rad_s(ops[k][0])))
                  if asm.model.has_table_mass() else asm.mats[0])
            KIND[k, :KE[k]] = mode_kind(asm, Mw, np.asarray(modes[k]), KIND[k, :KE[k]])
        if n_modes:
            EV, W, KIND, KE, modes = _cut(EV, W, KIND, KE, modes, ok, int(n_modes))
    fail = np.array([m or "no equilibrium" for m in res.message], dtype=object)
    valid = np.arange(EV.shape[1])[None, :] < KE[:, None]
    # every per-mode column of the batch at once (elementwise: the numbers of the point
    # loop; slots past a point's n_eig are padding, never read)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        MS = stable_modes(EV)
        RE = settled_real(EV)  # round-off of an undamped mode is 0, not a sign
        AB = np.abs(EV)
        DR = np.where(AB > 0, -RE / AB, np.nan)
        LD = log_dec(EV)  # the API's: −inf for a divergence, +0 for round-off
        FR = EV.imag / (2 * np.pi)
        # the thinnest film (NaN on a failed point: the batch's one rule, all its films NaN)
        HMIN = (np.fmin.reduce(H, axis=1) if H.shape[1] else np.full(len(st), math.nan))
    WN = _NAMES[np.clip(W, -1, 1) + 1]
    nan = np.full(len(st), math.nan)
    return {"ok": ok, "st": st, "fail": fail, "msg": np.array(res.message, dtype=object),
            "KE": KE, "EV": EV, "valid": valid, "MS": MS, "DR": DR, "LD": LD, "FR": FR,
            "WN": WN, "KIND": KIND, "IT": np.asarray(res.iterations).astype(np.int64),
            "jx": R[:, bc.jx] if bc else nan, "jy": R[:, bc.jy] if bc else nan, "HMIN": HMIN,
            "lam": [EV[k, :KE[k]] for k in range(len(st))], "modes": modes,
            # the verdict and max Re λ over every root of the point, not only the n_modes
            # kept (a mode above the cut can be the unstable one)
            "MX": np.asarray(res.max_real), "LS": np.asarray(res.least_stable),
            # the tilting films' outputs per point (docs/sweeps.md; none without one)
            "tilt": batch_tilt(asm, res) if any(b.rot for b in asm.bearings) else None}


def _stab_block(S, a, b, at, ids):
    ke = S["KE"][a:b]
    V = S["valid"][a:b]
    EV = S["EV"][a:b]
    cols = np.nonzero(V)[1].astype(np.int64)
    mode_id = (np.concatenate([ids[at + k] if ids[at + k] is not None else np.arange(ke[k - a])
                               for k in range(a, b)]).astype(np.int64) if len(cols) else cols)
    mx = S["MX"][a:b]
    ls_stable = stable_modes(S["LS"][a:b][:, None])[:, 0]
    tilt = repeat_lists(S["tilt"][a:b], ke) if S["tilt"] is not None else {}
    return (np.repeat(at + np.arange(a, b), ke), {**tilt,
        "journal_x_m": np.repeat(S["jx"][a:b], ke), "journal_y_m": np.repeat(S["jy"][a:b], ke),
        "h_min_m": np.repeat(S["HMIN"][a:b], ke), "iterations": np.repeat(S["IT"][a:b], ke),
        "point_stable": np.repeat(np.where(V, S["MS"][a:b], True).all(axis=1) & ls_stable, ke),
        "max_real_1_per_s": np.repeat(mx, ke), "mode_id": mode_id, "mode": cols + 1,
        "freq_hz": S["FR"][a:b][V], "eig_real_1_per_s": EV.real[V],
        "damping_ratio": S["DR"][a:b][V], "log_dec": S["LD"][a:b][V],
        "whirl": S["WN"][a:b][V], "kind": S["KIND"][a:b][V], "mode_stable": S["MS"][a:b][V],
        "status": np.repeat(S["st"][a:b], ke), "message": np.repeat(S["msg"][a:b], ke)})


# -- boundary refinement --------------------------------------------------------------------
def boundary_blocks(job, variants, chunk_id, pids, asms, equilibria=None):
    """One row per mode of each listed point (a failed point: one row): the stability rows'
    mode columns (``mode_id`` the mode's slot here; the refinement's driver replaces it by the
    id tracked from a neighbour, :mod:`.boundary_modes`), max Re λ (rotor modes only with
    exclude_sleeve_modes) and its frequency, point_stable, ``level``; one ``max_real_batch``
    call per run of points on one model (the equilibrium continued along lines as the
    per-point loop did, across runs too). A point with a start in ``job.starts`` (point_id ->
    equilibrium, e.g. a solved neighbour's) starts there instead. ``equilibria`` (a list)
    receives the (n_pts, n) equilibria (NaN rows: none) when given."""
    excl = bool(job.options.get("exclude_sleeve_modes", False))
    items = point_list(job, variants, pids, asms)
    n = len(items)
    st = np.empty(n, dtype=object)
    msg = np.empty(n, dtype=object)
    y, fr = np.full(n, math.nan), np.full(n, math.nan)
    lam, whirl, share, pshare = [None] * n, [None] * n, [None] * n, [None] * n
    carry = None  # the last evaluated point's equilibrium (None: failed)
    errs = [it[4] for it in items]
    starts = getattr(job, "starts", None) or {}
    R = None
    for i, j, good in segments(items, errs):
        if not good:  # a model-variant error leaves the continuation as it was
            st[i], msg[i] = "error", errs[i]
            continue
        seg = items[i:j]
        asm, opts = seg[0][1], seg[0][2]
        valid, om, pcs, A = [], [], [], []
        for k, it in enumerate(seg):
            try:
                f, pc, a = operating(asm, it[0])
                valid.append(1)
            except (RotordynError, ArithmeticError, ValueError) as exc:
                st[i + k], msg[i + k] = "error", f"{type(exc).__name__}: {exc}"
                f, pc, a = math.nan, math.nan, np.zeros(asm.n)
                valid.append(0)
            om.append(hz_to_rad_s(f))
            pcs.append(pc)
            A.append(a)
        inp = _core.MaxRealBatchInput()
        inp.omega, inp.pressure, inp.a, inp.valid = om, pcs, np.array(A), valid
        inp.restart = [0 if it[3] else 1 for it in seg]
        inp.r0 = carry if (seg[0][3] and carry is not None) else np.zeros(0)
        inp.options = equilibrium_options(opts)
        inp.exclude_sleeve = excl
        inp.xy_pairs, inp.rot_pairs = asm.rotor.xy_pairs(), asm.rotor.rot_pairs()
        inp.sleeve = [q for bc in asm.bearings for q in bc.sleeve]
        inp.pads = [q for bc in asm.bearings for q in getattr(bc, "extra", ())]
        if starts:
            S = np.full((j - i, asm.n), math.nan)
            for k in range(i, j):
                r0 = starts.get(int(pids[k]))
                if r0 is not None and len(r0) == asm.n:
                    S[k - i] = r0
            inp.starts = S
        res = _core.max_real_batch(asm.solver, inp)
        if equilibria is not None:
            if R is None:
                R = np.full((n, asm.n), math.nan)
            if R.shape[1] == asm.n:
                R[i:j] = np.asarray(res.r)
        r_last = np.asarray(res.r_last)
        carry = r_last if r_last.size else None
        for k, (s, m) in enumerate(zip(res.status, res.message)):
            if s == "invalid":
                continue
            if s == "error":
                st[i + k], msg[i + k] = "error", m
            elif s in CONVERGED:
                st[i + k], msg[i + k] = s, ""
            else:
                st[i + k], msg[i + k] = _status(s), "no equilibrium"
        y[i:j], fr[i:j] = np.asarray(res.y), np.asarray(res.freq)
        ke, EV = np.asarray(res.n_eig), np.asarray(res.eigenvalues)
        W, SH = np.asarray(res.whirl), np.asarray(res.sleeve_share)
        PH = np.asarray(res.pad_share)
        for k in range(j - i):
            lam[i + k], whirl[i + k], share[i + k] = EV[k, :ke[k]], W[k, :ke[k]], SH[k, :ke[k]]
            pshare[i + k] = PH[k, :ke[k]]
    good = np.array([s in CONVERGED and lam[k] is not None and len(lam[k])
                     for k, s in enumerate(st)], dtype=bool)
    blocks = []
    for a, b, g in runs(good):
        k = np.arange(a, b)
        if g:
            blocks.append(_boundary_block(job, k, y, fr, st, lam, whirl, share, pshare))
        else:
            blocks.append((k, {"status": st[a:b], "message": msg[a:b]}))
    if equilibria is not None:
        equilibria.append(np.full((n, 0), math.nan) if R is None else R)
    return blocks


def _boundary_block(job, k, y, fr, st, lam, whirl, share, pshare):
    """The mode rows of the converged points ``k`` (stability rows' per-mode columns)."""
    ke = np.array([len(lam[q]) for q in k])
    EV = np.concatenate([lam[q] for q in k])
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        RE = settled_real(EV)
        AB = np.abs(EV)
        DR = np.where(AB > 0, -RE / AB, np.nan)
        LD = log_dec(EV)  # the API's: −inf for a divergence, +0 for round-off
    MS = stable_modes(EV)
    rep = np.repeat(k, ke)
    # the point's verdict by the stability rows' rule (every root mode_stable, round-off
    # band included) over the roots max Re λ counts: the rotor's alone with
    # exclude_sleeve_modes. max Re λ's raw sign called an undamped rotor's +1e-12 unstable.
    SH = np.concatenate([share[q] for q in k])
    counts = ~(SH > 0.5) if job.options.get("exclude_sleeve_modes", False) else np.ones_like(MS)
    PS = np.logical_and.reduceat(MS | ~counts, np.r_[0, np.cumsum(ke)[:-1]])
    return (rep, {"mode_id": np.concatenate([np.arange(m) for m in ke]).astype(np.int64),
                  "mode": np.concatenate([np.arange(1, m + 1) for m in ke]).astype(np.int64),
                  "freq_hz": EV.imag / (2 * np.pi), "eig_real_1_per_s": EV.real,
                  "damping_ratio": DR, "log_dec": LD,
                  "whirl": _NAMES[np.clip(np.concatenate([whirl[q] for q in k]), -1, 1) + 1],
                  # the stability rows' kinds: "pad" where the tilting pads' tilt/pivot
                  # coordinates carry more than half the kinetic energy (mode_kind's rule)
                  "kind": np.where(np.concatenate([pshare[q] for q in k]) > 0.5, "pad",
                                   np.where(SH > 0.5, "sleeve", "rotor")),
                  "mode_stable": MS, "point_stable": np.repeat(PS, ke),
                  "max_real_1_per_s": y[rep], "max_real_freq_hz": fr[rep],
                  "level": job.level, "status": st[rep], "message": ""})
