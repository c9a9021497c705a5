"""The frequency response of a SISO loop from one eigen-decomposition, and the frequency grid,
brackets and Brent refinements that locate its margins (:mod:`rotordyn.control.margins`).

Partial fractions (A = V Λ V⁻¹, A diagonalisable):

    L(s) = D + Σ_i r_i / (s − λ_i),   r_i = (C V)_i (V⁻¹ B)_i,
    dL/dω = −Σ_i r_i / (s − λ_i)² · ds/dω      (s = iω, or z = e^{iωT} for a discrete loop)

— O(n) per frequency instead of an LU of (sI − A) per frequency, for the grid on which every
crossing and peak is bracketed. The partial fractions lose digits where L is small against its
terms (cancellation, ~10⁻⁹ relative at |L| ~ 10⁻³ on the rig's loop), so they only bracket:
their grid values are compared with C (sI − A)⁻¹ B + D on a subsample (every
:data:`CHECK_EVERY`-th point and the points nearest each pole), and where one differs by more
than :data:`CHECK_RTOL` (an eigenvalue near 0 whose residue should vanish, a defective or
ill-conditioned eigenvector basis) the grid between its neighbouring subsample points is
recomputed by direct solves. Brent iterates on the direct solve (one LU of sI − A
per evaluation, as before this module), and every reported value is the direct solve at the
refined frequency, so the margins are those of the direct evaluation to round-off.
"""

from __future__ import annotations

import cmath
import math

import numpy as np

from rotordyn.control import lti
from rotordyn.errors import InputError

PER_DECADE = 60
MAX_POINTS = 200_000
XTOL = 1e-14  # Brent's tolerance on ln ω (rtol is 4 eps): round-off in ω
CHECK_EVERY = 16  # grid subsample compared with the direct solve
CHECK_RTOL = 1e-6  # largest accepted |L_modal − L_direct| / max(|L_direct|, CHECK_FLOOR)
CHECK_FLOOR = 1e-9  # |L| below it: round-off level of a loop gain (margins ignore it)


class Response:
    """L(iω) (or L(e^{iωT})) and dL/dω of the SISO :class:`lti.SS` ``ss``, by partial
    fractions (module docstring) or, with ``modal=False`` or when the decomposition fails its
    check, by one dense solve per frequency (:func:`lti.freqresp`)."""

    def __init__(self, ss: lti.SS, modal: bool = True):
        self.ss = ss
        self.dt = ss.dt
        self.D = complex(ss.D[0, 0])
        self.modal = False
        self.checked = 0  # grid frequencies compared with the direct solve
        self.worst = 0.0  # the largest relative difference seen there
        self.redone = 0  # grid frequencies recomputed by direct solves
        self._mA = None
        self.ends = None  # (L(0), L(top), top ω) once computed (:func:`ends`)
        if not (modal and ss.n):
            return
        try:
            lam, V = np.linalg.eig(ss.A)
            right = np.linalg.solve(V, ss.B[:, 0].astype(complex))
        except np.linalg.LinAlgError:
            return
        res = (ss.C[0] @ V) * right
        if np.all(np.isfinite(res)) and np.all(np.isfinite(lam)):
            self.lam, self.res, self.modal = lam.astype(complex), res, True

    # ------------------------------------------------------------------------ evaluation
    def values(self, w, derivative: bool = False):
        """L on the angular frequencies ``w`` (rad/s), shape (n_f,), and dL/dω."""
        w = np.atleast_1d(np.asarray(w, float))
        if not self.modal:
            if derivative:
                G, dG = lti.freqresp(self.ss, w, True)
                return G[:, 0, 0], dG[:, 0, 0]
            return lti.freqresp(self.ss, w)[:, 0, 0]
        s, ds = lti.points(w, self.dt)
        Q = 1.0 / (s[:, None] - self.lam[None, :])
        L = Q @ self.res + self.D
        if derivative:
            return L, -((Q * Q) @ self.res) * ds
        return L

    def at(self, w: float) -> complex:
        """L at one angular frequency by the direct solve C (sI − A)⁻¹ B + D (the function
        Brent iterates on and every reported value)."""
        return self.at_d(w, False)[0]

    def at_d(self, w: float, derivative: bool = True) -> tuple[complex, complex]:
        """(L, dL/dω) at one angular frequency by the direct solve (one LU of sI − A)."""
        from scipy.linalg.lapack import zgetrf as getrf, zgetrs as getrs
        if self.ss.n == 0:
            return self.D, 0j
        if self.dt is None:
            s, ds = 1j * w, 1j
        else:
            s = cmath.exp(1j * w * self.dt)
            ds = 1j * self.dt * s
        if self._mA is None:
            self._mA = -self.ss.A.astype(complex)
            self._b = self.ss.B[:, :1].astype(complex)
            self._c = self.ss.C[0]
        M = self._mA.copy()
        M.flat[::M.shape[0] + 1] += s
        lu, piv, info = getrf(M)
        if info != 0:  # s on a pole
            return complex(np.inf), complex(np.inf)
        z, _ = getrs(lu, piv, self._b)
        L = complex(self._c @ z[:, 0]) + self.D
        if not derivative:
            return L, 0j
        z2, _ = getrs(lu, piv, z)
        return L, -complex(self._c @ z2[:, 0]) * ds

    def exact(self, w: float) -> complex:
        """Alias of :meth:`at` (the reported values)."""
        return self.at(w)

    def on_grid(self, w: np.ndarray):
        """(L, dL/dω) on the grid ``w``: the partial fractions, compared with the direct solve
        on a subsample (every :data:`CHECK_EVERY`-th point, the last one and the points
        nearest each pole); between a subsample point that differs by more than
        :data:`CHECK_RTOL` and its neighbours the grid is recomputed by direct solves."""
        if not self.modal:
            return self.values(w, True)
        L, dL = self.values(w, True)
        idx = set(range(0, w.size, CHECK_EVERY)) | {w.size - 1}
        wd = np.abs(self.lam.imag) if self.dt is None else \
            np.abs(np.angle(self.lam)) / self.dt
        idx |= set(np.searchsorted(w, wd).clip(0, w.size - 1).tolist())
        idx = np.array(sorted(idx))
        Ld = lti.freqresp(self.ss, w[idx])[:, 0, 0]
        with np.errstate(invalid="ignore", divide="ignore"):
            err = np.abs(L[idx] - Ld) / np.maximum(np.abs(Ld), CHECK_FLOOR)
        bad = ~(err <= CHECK_RTOL)
        self.checked = idx.size
        self.worst = float(np.max(np.where(np.isfinite(err), err, np.inf)))
        if not bad.any():
            return L, dL
        redo = np.zeros(w.size, bool)
        for j in np.flatnonzero(bad):
            lo = idx[j - 1] if j > 0 else 0
            hi = idx[j + 1] if j + 1 < idx.size else w.size - 1
            redo[lo:hi + 1] = True
        self.redone = int(redo.sum())
        G, dG = lti.freqresp(self.ss, w[redo], True)
        L, dL = L.copy(), dL.copy()
        L[redo], dL[redo] = G[:, 0, 0], dG[:, 0, 0]
        return L, dL


# ---------------------------------------------------------------------------- frequency grid

def closed_A(loop: lti.SS) -> np.ndarray:
    d = 1.0 + float(loop.D[0, 0])
    if abs(d) < 1e-12:
        raise InputError("loop: 1 + L(∞) = 0, the closed loop is ill-posed")
    return loop.A - loop.B @ loop.C / d


def poles(A, dt) -> np.ndarray:
    """Eigenvalues of A in the s-plane (discrete: ln z / T)."""
    return lti.SS(A, np.zeros((A.shape[0], 0)), np.zeros((0, A.shape[0])), np.zeros((0, 0)),
                  dt).poles_s()


def s_plane(lam, dt) -> np.ndarray:
    if dt is None:
        return lam
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.log(lam) / dt


def max_real(lam_s: np.ndarray) -> float:
    """max Re λ (1/s) of s-plane eigenvalues (−inf for none)."""
    return float(lam_s.real.max()) if lam_s.size else -math.inf


def grid_from(pole_sets, dt) -> np.ndarray:
    """Angular frequencies (rad/s): a log grid over the poles' range (≥ PER_DECADE points per
    decade, 10⁻³ below the slowest to 10³ above the fastest; discrete: up to Nyquist) with 33
    points clustered around each pole's damped frequency (±8 × max(|Re λ|, 10⁻⁶ ω_d)) and six
    at 0.9–1.1 ω_d."""
    lam = np.concatenate(pole_sets)
    lam = lam[np.isfinite(lam)]
    mags = np.abs(lam)
    mags = mags[mags > 0]
    if dt is None:
        lo = (mags.min() if mags.size else 1.0) * 1e-3
        hi = (mags.max() if mags.size else 1.0) * 1e3
    else:
        hi = math.pi / dt
        lo = min(mags.min() if mags.size else hi, hi) * 1e-3
    ndec = math.log10(hi / lo)
    base = np.logspace(math.log10(lo), math.log10(hi), max(int(PER_DECADE * ndec), 200))
    wd, sg = np.abs(lam.imag), np.abs(lam.real)
    keep = wd > 0
    wd, sg = wd[keep], sg[keep]
    width = np.maximum(sg, 1e-6 * wd)
    near = wd[:, None] + width[:, None] * np.linspace(-8, 8, 33)[None, :]
    rel = wd[:, None] * np.array([0.9, 0.95, 0.98, 1.02, 1.05, 1.1])[None, :]
    w = np.concatenate([base, near.ravel(), rel.ravel()])
    w = np.unique(w[(w >= lo) & (w <= hi)])
    if w.size > MAX_POINTS:
        raise InputError(f"loop: its frequency grid would need {w.size} points (> {MAX_POINTS})")
    return w


def ends(loop: lti.SS, resp: Response) -> tuple:
    """(L at ω = 0 or None, L at the top end: ∞ (D) or Nyquist, top frequency rad/s);
    computed once per response."""
    if resp.ends is None:
        resp.ends = _ends(loop, resp)
    return resp.ends


def _ends(loop: lti.SS, resp: Response) -> tuple:
    L0 = lti.dc_value(loop)
    L0 = None if L0 is None else complex(L0[0, 0])
    if loop.dt is None:
        return L0, complex(loop.D[0, 0]), math.inf
    wn = math.pi / loop.dt
    return L0, resp.exact(wn), wn


# ------------------------------------------------------------------ roots and peaks on ln ω

def brent(fun, a, b):
    """Brent's root of ``fun`` on [a, b] to round-off, or None when the re-evaluated ends do
    not bracket one (a flat function at round-off level)."""
    from scipy.optimize import brentq
    try:
        return brentq(fun, a, b, xtol=XTOL, rtol=1e-15)
    except ValueError:
        return None


def roots(fun, w, vals) -> list:
    """Refined roots of ``fun`` (a function of ln ω) where ``vals`` changes sign on ``w``."""
    out = []
    x = np.log(w)
    for i in np.nonzero(np.signbit(vals[:-1]) != np.signbit(vals[1:]))[0]:
        if not (np.isfinite(vals[i]) and np.isfinite(vals[i + 1])):
            continue
        if vals[i] == 0:
            out.append(w[i])
            continue
        r = brent(fun, x[i], x[i + 1])
        if r is not None:
            out.append(math.exp(r))
    if vals.size and vals[-1] == 0:
        out.append(w[-1])
    return out


def peak(resp: Response, loop: lti.SS, w, p: float, q: float, grid) -> tuple[float, float]:
    """sup_ω |(p + q L)/(1 + L)| and its ω (rad/s; 0 or inf at the ends): the grid's local
    maxima within 80 % of the largest refined by Brent on d|M|²/dω = 2 Re(M̄ (q − p)/(1 + L)²
    dL/dω); ``grid``: (L, dL/dω) on ``w``."""
    L, dL = grid

    def m_and_slope(L, dL):
        M = (p + q * L) / (1 + L)
        dM = (q - p) / (1 + L) ** 2 * dL
        return np.abs(M), 2 * np.real(np.conj(M) * dM)

    mag, slope = m_and_slope(L, dL)
    best = (float(mag.max()), float(w[np.argmax(mag)]))
    top = mag.max()
    mid = mag[1:-1]
    i_loc = 1 + np.flatnonzero((mid >= mag[:-2]) & (mid >= mag[2:]) & (mid >= 0.8 * top))
    x = np.log(w)

    def f(lw):
        Li, dLi = resp.at_d(math.exp(lw))
        M = (p + q * Li) / (1 + Li)
        return 2 * ((M.conjugate() * ((q - p) / (1 + Li) ** 2 * dLi)).real)

    for i in i_loc:
        a, b = i - 1, i + 1
        if slope[a] > 0 > slope[i]:
            lw = brent(f, x[a], x[i])
        elif slope[i] > 0 > slope[b]:
            lw = brent(f, x[i], x[b])
        elif slope[a] > 0 > slope[b]:
            lw = brent(f, x[a], x[b])
        else:
            continue
        if lw is None:
            continue
        wi = math.exp(lw)
        Li = resp.exact(wi)
        val = abs((p + q * Li) / (1 + Li))
        if val > best[0]:
            best = (val, wi)
    L0, Linf, wtop = ends(loop, resp)
    for Le, we in ((L0, 0.0), (Linf, wtop)):
        if Le is not None:
            val = abs((p + q * Le) / (1 + Le))
            if val > best[0]:
                best = (val, we)
    return best
