"""Plain state-space systems for the margins and the exports: (A, B, C, D, dt) with the
states scaled by an exact diagonal similarity (powers of two, LAPACK ``gebal`` on
[[A, B], [C, 0]]: inputs and outputs keep their units), frequency responses with their
derivative, series connections and the loops of a plant and a controller.

Conventions: a controller is rotordyn's positive-feedback law u = K y (:class:`Controller`);
a *loop* L(s) is SISO in the negative-feedback convention (closed loop 1 + L), so the loop
broken at the actuator input is L = −K G and the loops broken at the measurements are
L_o = −G K (n_y × n_y). ``dt`` None: continuous (s = iω); a sample time: discrete
(z = e^{iωT}).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rotordyn._common import validate as v
from rotordyn._common.balance import scaled, state_scaling
from rotordyn.errors import InputError

BATCH = 256  # frequencies per batched solve


@dataclass(frozen=True)
class SS:
    """x' = A x + B u, y = C x + D u (continuous, ``dt`` None) or x⁺ = … (discrete).
    ``scale``: the state scaling T applied (x_original = T x, T diagonal powers of two)."""

    A: np.ndarray
    B: np.ndarray
    C: np.ndarray
    D: np.ndarray
    dt: float | None = None
    scale: np.ndarray | None = None

    @property
    def n(self) -> int:
        return self.A.shape[0]

    @property
    def shape(self) -> tuple:
        return self.D.shape

    def poles_s(self) -> np.ndarray:
        """Eigenvalues mapped to the s-plane (discrete: ln z / T), 1/s."""
        lam = np.linalg.eigvals(self.A).astype(complex) if self.n else np.zeros(0, complex)
        if self.dt is None:
            return lam
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.log(lam) / self.dt


def as_ss(field: str, value, dt=None) -> SS:
    """An :class:`SS` from an SS, a python-control StateSpace/TransferFunction or a tuple
    (A, B, C, D); entries finite (InputError naming ``field`` otherwise)."""
    if isinstance(value, SS):
        return value
    try:
        import control
    except ImportError:  # pragma: no cover - python-control is a dependency
        control = None
    if control is not None and isinstance(value, (control.StateSpace, control.TransferFunction)):
        sysd = value.dt
        if isinstance(value, control.TransferFunction):
            value = control.ss(value)
        if sysd is True:
            raise InputError(f"{field}: a discrete system with an unspecified sample time "
                             f"(dt=True); give dt > 0")
        dt = None if sysd in (None, 0) else float(sysd)
        value = (value.A, value.B, value.C, value.D)
    if not isinstance(value, (tuple, list)) or len(value) != 4:
        raise InputError(f"{field}: expected a state space (A, B, C, D), a python-control "
                         f"system or a rotordyn SS, got {type(value).__name__}")
    D = v.matrix(f"{field}.D", value[3])
    ny, nu = D.shape
    A = np.asarray(value[0], float)
    n = A.shape[0] if A.size else 0
    A = v.matrix(f"{field}.A", A, (n, n)) if n else np.zeros((0, 0))
    B = v.matrix(f"{field}.B", value[1], (n, nu)) if n else np.zeros((0, nu))
    C = v.matrix(f"{field}.C", value[2], (ny, n)) if n else np.zeros((ny, 0))
    if dt is not None:
        dt = v.positive(f"{field}.dt", dt)
    return SS(A, B, C, D, dt)


def balanced(ss: SS) -> SS:
    """The same system with states scaled x = T x̃ (:func:`rotordyn._common.balance.state_scaling`:
    T diagonal powers of two, so Ã = T⁻¹AT, B̃ = T⁻¹B, C̃ = CT are exact in floating point and
    the transfer function is unchanged)."""
    t = state_scaling(ss.A, ss.B, ss.C)
    A, B, C = scaled(ss.A, ss.B, ss.C, t)
    base = ss.scale if ss.scale is not None else np.ones(ss.n)
    return SS(A, B, C, ss.D.copy(), ss.dt, base * t)


def points(w: np.ndarray, dt) -> tuple[np.ndarray, np.ndarray]:
    """(s or z, d(s or z)/dω) at angular frequencies ω (rad/s)."""
    if dt is None:
        return 1j * w, np.full(w.shape, 1j)
    z = np.exp(1j * w * dt)
    return z, 1j * dt * z


def freqresp(ss: SS, w, derivative: bool = False):
    """G(iω) (or G(e^{iωT})) of shape (n_f, n_y, n_u) for ω in rad/s, and with
    ``derivative`` also dG/dω = −C (sI − A)⁻² B ds/dω. Batched dense solves."""
    w = np.atleast_1d(np.asarray(w, float))
    ny, nu = ss.shape
    G = np.empty((w.size, ny, nu), complex)
    dG = np.empty_like(G) if derivative else None
    if ss.n == 0:
        G[:] = ss.D
        if derivative:
            dG[:] = 0
        return (G, dG) if derivative else G
    eye = np.eye(ss.n)
    s_all, ds_all = points(w, ss.dt)
    for i0 in range(0, w.size, BATCH):
        s = s_all[i0:i0 + BATCH]
        M = s[:, None, None] * eye - ss.A
        Z = np.linalg.solve(M, np.broadcast_to(ss.B, (s.size,) + ss.B.shape))
        G[i0:i0 + s.size] = ss.C @ Z + ss.D
        if derivative:
            Z2 = np.linalg.solve(M, Z)
            dG[i0:i0 + s.size] = -(ss.C @ Z2) * ds_all[i0:i0 + s.size, None, None]
    return (G, dG) if derivative else G


def dc_value(ss: SS):
    """G at ω = 0 (s = 0 or z = 1), or None when A (or A − I) is singular there."""
    if ss.n == 0:
        return ss.D.copy()
    M = -ss.A if ss.dt is None else np.eye(ss.n) - ss.A
    try:
        if np.linalg.cond(M) > 1e14:
            return None
        return ss.C @ np.linalg.solve(M, ss.B) + ss.D
    except np.linalg.LinAlgError:
        return None


def feedback_A(P: SS, K: SS) -> np.ndarray:
    """Closed-loop state matrix of x_p, x_k for y = P u, u = K y (positive feedback, any
    feedthrough: the algebraic loop (I − D_k D_p) u = … solved; InputError when singular)."""
    Dp, Dk = P.D, K.D
    nu = Dp.shape[1]
    W = np.eye(nu) - Dk @ Dp
    if np.linalg.cond(W) > 1e14:
        raise InputError("controller: the loop is ill-posed (I − D_k D_p is singular: an "
                         "algebraic loop without a solution)")
    Wi = np.linalg.inv(W)
    Ux = Wi @ np.hstack([Dk @ P.C, K.C])  # u = Ux [x_p; x_k]
    top = np.hstack([P.A, np.zeros((P.n, K.n))]) + P.B @ Ux
    bot = np.hstack([K.B @ P.C, K.A]) + K.B @ Dp @ Ux
    return np.vstack([top, bot])


def stable(A: np.ndarray, dt) -> tuple[bool, float]:
    """(stable, max Re λ in 1/s) of x' = A x (discrete: |z| < 1, Re ln z / T)."""
    if A.shape[0] == 0:
        return True, -np.inf
    lam = np.linalg.eigvals(A)
    if dt is None:
        m = float(lam.real.max())
    else:
        with np.errstate(divide="ignore"):
            m = float(np.log(np.abs(lam)).max() / dt)
    return bool(m < 0), m


def loop_at_input(P: SS, K: SS) -> SS:
    """SISO loop broken at the (single) actuator input: L = −K P (realisation of the series
    P then K, states [x_p; x_k])."""
    if P.shape[1] != 1:
        raise InputError(f"plant: the input loop needs one actuator input, got {P.shape[1]}")
    A = np.block([[P.A, np.zeros((P.n, K.n))], [K.B @ P.C, K.A]])
    B = np.vstack([P.B, K.B @ P.D])
    C = -np.hstack([K.D @ P.C, K.C])
    D = -K.D @ P.D
    return SS(A, B, C, D, P.dt)


def loop_at_output(P: SS, K: SS, i: int) -> SS:
    """SISO loop broken at measurement ``i`` with every other measurement fed back:
    L_i = −(v → y_i) where the controller reads v instead of y_i."""
    ny, nu = P.shape
    e = np.zeros((ny, 1))
    e[i] = 1.0
    Pi = np.eye(ny) - e @ e.T
    W = np.eye(nu) - K.D @ Pi @ P.D
    if np.linalg.cond(W) > 1e14:
        raise InputError(f"controller: the loop broken at measurement {i} is ill-posed")
    Wi = np.linalg.inv(W)
    Ux = Wi @ np.hstack([K.D @ Pi @ P.C, K.C])
    Uv = Wi @ K.D @ e
    top = np.hstack([P.A, np.zeros((P.n, K.n))]) + P.B @ Ux
    bot = np.hstack([K.B @ Pi @ P.C, K.A]) + K.B @ Pi @ P.D @ Ux
    A = np.vstack([top, bot])
    B = np.vstack([P.B @ Uv, K.B @ Pi @ P.D @ Uv + K.B @ e])
    C = e.T @ (np.hstack([P.C, np.zeros((ny, K.n))]) + P.D @ Ux)
    D = e.T @ P.D @ Uv
    return SS(A, B, -C, -D, P.dt)


def zpk(ss: SS, ref_hz: float | None = None):
    """(zeros, poles, gain) of a SISO system, for tools that evaluate a transfer function
    from its factors (SciPy's ``freqresp`` converts a state space to polynomial coefficients,
    which for the rig's 20-odd states loses every digit). Poles: eig(Ã); zeros: the finite
    generalized eigenvalues of the Rosenbrock pencil ([[Ã, b̃], [c̃, d]], diag(I, 0)), both on
    the balanced realisation; gain matched to G at ``ref_hz`` (default: the geometric mean
    of the poles' magnitudes, off any pole), real for a real system. Continuous: s-plane
    factors; discrete: z-plane."""
    from scipy.linalg import eig

    if ss.shape != (1, 1):
        raise InputError(f"system: zpk() needs one input and one output, got {ss.shape}")
    b = balanced(ss)
    n = b.n
    poles = np.linalg.eigvals(b.A).astype(complex) if n else np.zeros(0, complex)
    if n:
        M = np.block([[b.A, b.B], [b.C, b.D]])
        N = np.zeros_like(M)
        N[:n, :n] = np.eye(n)
        al, be = eig(M, N, right=False, homogeneous_eigvals=True)
        big = 1e8 * max(1.0, float(np.abs(poles).max()))
        with np.errstate(divide="ignore", invalid="ignore"):
            z = al / be
        zeros = z[np.isfinite(z) & (np.abs(z) < big)]
    else:
        zeros = np.zeros(0, complex)
    if ref_hz is None:
        mags = np.abs(poles[np.abs(poles) > 0])
        w0 = float(np.exp(np.log(mags).mean())) * 1.0123 if mags.size else 1.0
        if ss.dt is not None:
            w0 = min(w0, 0.5 * np.pi / ss.dt)
    else:
        w0 = 2 * np.pi * v.positive("ref_hz", ref_hz)
    s0 = points(np.array([w0]), ss.dt)[0][0]
    g0 = freqresp(b, [w0])[0, 0, 0]
    k = g0 * np.prod(s0 - poles) / np.prod(s0 - zeros)
    return zeros, poles, float(k.real)
