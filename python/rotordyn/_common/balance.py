"""Exact state scaling of a state-space model for export (issue 24): the rotor's states are
metres and metres per second beside the valve's pascals, so entries of A span 1e-8 .. 1e8 and
tools that reduce A to Hessenberg form without balancing it first (python-control through
SLICOT's TB05AD, job 'NG') lose up to all digits of G(iω). LAPACK's ``gebal`` (no permutation)
on the square [[A, B, 0], [0, 0, 0], [C, 0, 0]] gives a diagonal T of powers of two: the model
in x̃ = T⁻¹ x is (T⁻¹AT, T⁻¹B, CT, D), exact in floating point (only exponents change), with
the same transfer function and the inputs and outputs in their own units (their rows and
columns are zero on one side, so gebal leaves them alone)."""

from __future__ import annotations

import numpy as np


def state_scaling(A: np.ndarray, B: np.ndarray, C: np.ndarray) -> np.ndarray:
    """T (n,) powers of two: x = T x̃ (see the module docstring)."""
    from scipy.linalg import matrix_balance

    n, nu, ny = A.shape[0], B.shape[1], C.shape[0]
    if n == 0:
        return np.ones(0)
    M = np.zeros((n + nu + ny, n + nu + ny))
    M[:n, :n], M[:n, n:n + nu], M[n + nu:, :n] = A, B, C
    _, (t, _) = matrix_balance(M, permute=False, separate=True)
    return np.asarray(t[:n], float)


def scaled(A, B, C, t):
    """(T⁻¹AT, T⁻¹B, CT) for the scaling ``t`` of :func:`state_scaling`."""
    return A * (1 / t)[:, None] * t[None, :], B / t[:, None], C * t[None, :]


def scaled_state_names(names, t) -> list[str]:
    """State names that state the scaling: ``name·2^-e`` for x̃ = x / 2^e (e = 0: the name)."""
    out = []
    for nm, ti in zip(names, t):
        e = int(round(np.log2(ti)))
        out.append(str(nm) if e == 0 else f"{nm}·2^{-e}")
    return out
