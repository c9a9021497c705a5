"""The first Lyapunov coefficient of a Hopf point (Kuznetsov, *Elements of Applied Bifurcation
Theory*, 3rd ed., §3.5, eq. 3.20) from directional finite differences of a vector field.

For ẋ = A x + ½ B(x, x) + ⅙ C(x, x, x) + O(|x|⁴) about the equilibrium, with
A q = iω q, Aᵀ p = −iω p, ⟨q, q⟩ = 1, ⟨p, q⟩ = 1 (⟨u, v⟩ = ūᵀ v):

    l1 = 1/(2ω) Re[ ⟨p, C(q, q, q̄)⟩ − 2 ⟨p, B(q, A⁻¹ B(q, q̄))⟩
                    + ⟨p, B(q̄, (2iω I − A)⁻¹ B(q, q))⟩ ].

The caller supplies the second and third derivatives along real directions, D²f[u, u] and
D³f[u, u, u]; the complex multilinear forms follow by polarisation. Generic (any smooth
field in any coordinates); rotordyn.hopf applies it to eq. 12 in scaled coordinates.
"""

from __future__ import annotations

from typing import Callable

import numpy as np

Vec = np.ndarray


def central_second(f: Callable[[Vec], Vec], x0: Vec, f0: Vec, h: float) -> Callable:
    """u ↦ D²f(x0)[u, u] by the 3-point central difference along û = u/|u| with step h
    (error O(h²)), scaled back by |u|²."""
    def second(u):
        s = float(np.linalg.norm(u))
        if s == 0.0:
            return np.zeros_like(f0)
        e = u / s
        return s * s * (f(x0 + h * e) - 2.0 * f0 + f(x0 - h * e)) / (h * h)
    return second


def central_third(f: Callable[[Vec], Vec], x0: Vec, h: float) -> Callable:
    """u ↦ D³f(x0)[u, u, u] by the 4-point central difference
    (f(x+2hû) − 2f(x+hû) + 2f(x−hû) − f(x−2hû)) / (2h³) (error O(h²)), scaled by |u|³."""
    def third(u):
        s = float(np.linalg.norm(u))
        if s == 0.0:
            return np.zeros(x0.shape)
        e = u / s
        return s ** 3 * (f(x0 + 2 * h * e) - 2.0 * f(x0 + h * e) + 2.0 * f(x0 - h * e)
                         - f(x0 - 2 * h * e)) / (2.0 * h ** 3)
    return third


def fitted_derivatives(f: Callable[[Vec], Vec], x0: Vec, span: float, points: int = 8,
                       degree: int = 6) -> tuple[Callable, Callable]:
    """(second, third): D²f[u, u] and D³f[u, u, u] from one least-squares polynomial of
    ``degree`` in s fitted to f(x0 + s û) at 2·``points`` + 1 equally spaced s in
    [−span, span] (û = u/|u|): 2·c₂ and 6·c₃, scaled by |u|², |u|³. Exact for polynomial
    fields of degree ≤ ``degree``; for a field that is smooth only piecewise (the film force
    with its cavitation set switching at grid nodes) it is the curvature over the span
    instead of at the point. Each direction is sampled once for both derivatives."""
    s = span * np.arange(-points, points + 1) / points
    V = np.vander(s / span, degree + 1, increasing=True)  # scaled for conditioning
    P = np.linalg.pinv(V)  # (degree+1, 2m+1)
    cache: dict = {}

    def coeffs(u):
        nu = float(np.linalg.norm(u))
        if nu == 0.0:
            return nu, None
        e = u / nu
        key = e.tobytes()
        if key not in cache:
            F = np.array([f(x0 + sk * e) for sk in s])  # (2m+1, N)
            cache[key] = P @ F
        return nu, cache[key]

    def second(u):
        nu, c = coeffs(u)
        return np.zeros(x0.shape) if c is None else nu ** 2 * 2.0 * c[2] / span ** 2

    def third(u):
        nu, c = coeffs(u)
        return np.zeros(x0.shape) if c is None else nu ** 3 * 6.0 * c[3] / span ** 3

    return second, third


def _bilinear(second: Callable, u: Vec, w: Vec) -> Vec:
    """B(u, w) for real u, w by polarisation: (B(u+w, u+w) − B(u−w, u−w)) / 4."""
    return 0.25 * (second(u + w) - second(u - w))


def _bilinear_c(second: Callable, u: Vec, w: Vec) -> Vec:
    """B(u, w) for complex u = a + ib, w = c + id: B(a,c) − B(b,d) + i(B(a,d) + B(b,c))."""
    a, b, c, d = u.real, u.imag, w.real, w.imag
    out = _bilinear(second, a, c).astype(complex)
    if np.any(b) and np.any(d):
        out -= _bilinear(second, b, d)
    if np.any(d):
        out += 1j * _bilinear(second, a, d)
    if np.any(b):
        out += 1j * _bilinear(second, b, c)
    return out


def hopf_vectors(A: np.ndarray, omega: float) -> tuple[Vec, Vec]:
    """q, p of the pair ±iω of A (N × N): A q = iω q, Aᵀ p = −iω p, ⟨q, q⟩ = 1,
    ⟨p, q⟩ = 1 (the eigenvalue of A nearest iω, and of Aᵀ nearest −iω)."""
    lam, V = np.linalg.eig(A)
    k = int(np.argmin(np.abs(lam - 1j * omega)))
    q = V[:, k] / np.linalg.norm(V[:, k])
    lt, W = np.linalg.eig(A.T)
    j = int(np.argmin(np.abs(lt + 1j * omega)))
    p = W[:, j]
    p = p / np.conj(np.vdot(p, q))  # ⟨p, q⟩ = p̄ᵀ q = 1
    return q, p


def first_lyapunov(A: np.ndarray, omega: float, second: Callable, third: Callable,
                   q: Vec | None = None, p: Vec | None = None) -> dict:
    """Kuznetsov's l1 (module docstring) for the Jacobian A (N × N) with the Hopf pair ±iω
    (ω > 0, 1/time) and the derivative callables of :func:`central_second` /
    :func:`central_third` (or exact ones). Returns ``l1`` (1/(time·unit²) of the
    coordinates q is measured in), ``c1_real`` = ω l1 (the normal form ż = (α + iω) z +
    c1 z|z|², the cycle |z|² = −α / Re c1), and ``q``, ``p``."""
    if q is None or p is None:
        q, p = hopf_vectors(A, omega)
    N = A.shape[0]
    a, b = q.real, q.imag
    s_a, s_b = second(a), second(b)
    B_qqbar = s_a + s_b                                   # B(q, q̄), real
    B_ab = _bilinear(second, a, b)
    B_qq = (s_a - s_b) + 2j * B_ab                        # B(q, q)
    t_a, t_b = third(a), third(b)
    t_pl, t_mi = third(a + b), third(a - b)
    C_abb = (t_pl + t_mi - 2.0 * t_a) / 6.0
    C_aab = (t_pl - t_mi - 2.0 * t_b) / 6.0
    C_qqqbar = (t_a + C_abb) + 1j * (C_aab + t_b)        # C(q, q, q̄)
    w1 = np.linalg.solve(A, B_qqbar)                      # A⁻¹ B(q, q̄)
    w2 = np.linalg.solve(2j * omega * np.eye(N) - A, B_qq)
    term = (np.vdot(p, C_qqqbar) - 2.0 * np.vdot(p, _bilinear_c(second, q, w1.astype(complex)))
            + np.vdot(p, _bilinear_c(second, np.conj(q), w2)))
    l1 = float(term.real / (2.0 * omega))
    return {"l1": l1, "c1_real": omega * l1, "q": q, "p": p}
