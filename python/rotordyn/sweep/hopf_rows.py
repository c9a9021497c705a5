"""The ``hopf`` sweep analysis: every threshold crossing of a ``threshold`` line
(:func:`rotordyn.sweep.lines.threshold_line`), with the first Lyapunov coefficient there
(:func:`rotordyn.analysis.hopf.lyapunov_at`), dRe λ/d(vary), the Hopf type and the
leading-order cycle amplitude coefficient at the reference bearing, and with
``options.grid_check`` l1 again on every film grid refined twice (``l1_refined``; a type
that changes with the grid is ``degenerate``, as :func:`rotordyn.hopf` with ``grid_check``)
(docs/nonlinear.md).
Each crossing's equilibrium is solved cold (no warm start), so its row does not depend on
the chunking."""

from __future__ import annotations

import math

import numpy as np

from rotordyn.analysis.hopf import (FD_STEP, GRID_CHECK_NO_EQUILIBRIUM, GRID_CHECK_NO_PAIR,
                                    _critical_eigenvalue, hopf_type, lyapunov_at)
from rotordyn.errors import RotordynError
from rotordyn.sweep import points as pt
from rotordyn.sweep.lines import max_real, threshold_line
from rotordyn.units import hz_to_rad_s

#: output columns beyond the threshold's (``l1_refined``: ``options.grid_check``, else NaN)
HOPF_COLUMNS = ("l1", "l1_error", "hopf_type", "alpha_prime", "amplitude_coefficient_m2",
                "l1_refined")


def _jacobian(asm, r, f):
    w = hz_to_rad_s(f)
    lin = asm.solver.linearize(np.asarray(r), np.zeros(asm.n), w)
    M, C0, G, K0 = asm.mats
    if asm.model.has_table_mass():
        M = np.asarray(asm.model.mass_at(w))
    M = np.asarray(M)
    D = C0 + w * G + np.asarray(lin.DH)
    K = K0 + np.asarray(lin.KH)
    Minv = np.linalg.inv(M)
    n = asm.n
    return M, np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ K, -Minv @ D]])


def _refined_l1(fine, p, opts, whirl_hz, fd_step):
    """l1 at the crossing ``p`` on the refined films ``fine`` (the hopf analysis's
    ``grid_check``, as :func:`rotordyn.analysis.hopf._grid_checked`: a cold equilibrium, the
    pair nearest the coarse grid's whirl, the same fd_step), or (None, why)."""
    f, pc, a = pt.operating(fine, p)
    e = pt.solve_equilibrium(fine, f, pc, a, None, opts)
    if e.status not in pt.CONVERGED:
        return None, GRID_CHECK_NO_EQUILIBRIUM
    M, A = _jacobian(fine, e.r, f)
    lam = _critical_eigenvalue(A, whirl_hz)
    if lam is None:
        return None, GRID_CHECK_NO_PAIR
    return float(lyapunov_at(fine, e.r, f, M, A, lam.imag, fd_step)["l1"]), ""


def _one(job, asm, p, vary, whirl, span, opts, excl, fd_step, fine=None):
    f, pc, a = pt.operating(asm, p)
    e = pt.solve_equilibrium(asm, f, pc, a, None, opts)
    if e.status not in pt.CONVERGED:
        raise ArithmeticError(f"no equilibrium at the crossing ({e.status})")
    M, A = _jacobian(asm, e.r, f)
    lam0 = _critical_eigenvalue(A, whirl)
    if lam0 is None:
        raise ArithmeticError("no complex eigenvalue pair at the crossing")
    x = p[vary]
    dp = 1e-4 * max(abs(x), span)
    ys = []
    for s in (1, -1):
        q = dict(p)
        q[vary] = x + s * dp
        y, _, _, _ = max_real(job, asm, q, np.asarray(e.r), opts, excl)
        ys.append(y)
    alpha = (ys[0] - ys[1]) / (2 * dp)
    core = lyapunov_at(asm, e.r, f, M, A, lam0.imag, fd_step)
    l1, err = core["l1"], core["l1_error"]
    bc = pt.ref_bearing(asm)
    k = asm.bearings.index(bc) if bc is not None else 0
    coef = core["semi_major2_per_z2"][k] * abs(alpha / (lam0.imag * l1)) if l1 else math.inf
    out = {"l1": l1, "l1_error": err, "hopf_type": hopf_type(l1, err),
           "alpha_prime": alpha, "amplitude_coefficient_m2": coef, "l1_refined": math.nan,
           "note": ""}
    if fine is not None:
        l1r, why = _refined_l1(fine, p, opts, lam0.imag / (2 * np.pi), fd_step)
        if l1r is None:
            out.update(l1_error=math.inf, hopf_type="degenerate", note=why)
        else:
            err = max(err, abs(l1r - l1))
            out.update(l1_refined=l1r, l1_error=err, hopf_type=hopf_type(l1, err))
    return out


def hopf_line_blocks(job, variants, lo, hi, at, asms, scan=None):
    """The threshold blocks of the line [lo, hi) (:func:`~rotordyn.sweep.lines.
    threshold_line`: one C++ call for the scan and every crossing), each crossing with its
    Hopf columns; a failed l1 keeps the crossing and gets status ``error`` with the
    message. The Hopf columns of a crossing are its own work (a cold equilibrium, the
    Jacobian, two max Re λ for dRe λ/d(vary) and the l1 normal form), one per crossing.
    ``scan``: as for :func:`~rotordyn.sweep.lines.threshold_line`."""
    vary = job.options["vary"]
    excl = bool(job.options.get("exclude_sleeve_modes", False))
    fd_step = float(job.options.get("fd_step", FD_STEP))
    grid_check = bool(job.options.get("grid_check", False))
    blocks = threshold_line(job, variants, lo, hi, at, asms, scan)
    _, p0 = job.point(lo)
    _, p1 = job.point(hi - 1)
    span = abs(p1[vary] - p0[vary])
    out = []
    for pts, cols in blocks:
        cols = dict(cols)
        st = cols["status"]
        if isinstance(st, str):  # no crossing, or the line's model failed: no Hopf columns
            cols.update({c: (math.nan if c != "hopf_type" else "") for c in HOPF_COLUMNS})
            out.append((pts, cols))
            continue
        m = len(pts)
        st, msg = list(st), list(cols["message"])
        H = {c: np.full(m, math.nan) for c in HOPF_COLUMNS if c != "hopf_type"}
        H["hopf_type"] = np.full(m, "", dtype=object)
        _, pb = job.point(lo)
        for j in range(m):
            if st[j] != "ok":
                continue
            p = dict(pb)
            p[vary] = cols["value"][j]
            try:
                asm = variants.get(p)
                one = _one(job, asm, p, vary, cols["whirl_frequency_hz"][j], span,
                           pt.point_options(job, p), excl, fd_step,
                           variants.refined(p) if grid_check else None)
            except (RotordynError, ArithmeticError, ValueError,
                    np.linalg.LinAlgError) as exc:
                st[j], msg[j] = "error", f"l1: {type(exc).__name__}: {exc}"
                continue
            for c in HOPF_COLUMNS:
                H[c][j] = one[c]
            if one["note"]:
                msg[j] = one["note"]
        cols.update(H, status=np.array(st, dtype=object), message=np.array(msg, dtype=object))
        out.append((pts, cols))
    return out

