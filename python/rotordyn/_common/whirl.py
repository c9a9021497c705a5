"""Whirl of an orbit or a mode: forward, backward or planar (one rule for tables, figures and
JSON; the C++ modal solver, cpp/src/modal.cpp ``whirl_direction``, applies the same)."""

from __future__ import annotations

import numpy as np

WHIRL_NAMES = {1: "forward", -1: "backward", 0: "planar"}
WHIRL_PLANAR_TOL = 0.05
"""A mode (or orbit) is planar when its whirl index (|F|² − |B|²)/(|F|² + |B|²) — F, B the
forward and backward circular components of its (x, y) motion, summed over stations — is
below this in magnitude (orbit minor/major axis ratio below about 2.5 %). The C++ modal
solver (cpp/src/modal.cpp, ``whirl_direction``) applies the same rule; figures, tables and
JSON take the label from there."""


def whirl_index(x: np.ndarray, y: np.ndarray, axis=None) -> np.ndarray:
    """(|F|² − |B|²)/(|F|² + |B|²) of complex amplitudes x, y (x = Re(X e^{iωt})): +1 circular
    forward, −1 circular backward, 0 a straight line. Summed over ``axis`` (e.g. stations)."""
    area = np.sum(np.imag(x * np.conj(y)), axis=axis)
    scale = np.sum(np.abs(x) ** 2 + np.abs(y) ** 2, axis=axis)
    return np.where(scale > 0, 2 * area / np.where(scale > 0, scale, 1.0), 0.0)


def whirl_label(index) -> np.ndarray:
    """"forward"/"backward"/"planar" from :func:`whirl_index` with :data:`WHIRL_PLANAR_TOL`."""
    i = np.asarray(index, dtype=float)
    return np.where(np.abs(i) < WHIRL_PLANAR_TOL, "planar",
                    np.where(i > 0, "forward", "backward")).astype(object)


def driven_by_unbalance(whirl) -> np.ndarray:
    """True where a mode's whirl (a label or the index code 1/0/−1) is one an unbalance — a
    force rotating forward with the shaft — drives: forward, and planar (a straight-line orbit
    is half forward, half backward circular whirl). On anisotropic supports the lowest bending
    modes are planar at low speed (a generator on tilting pads loaded between and on pads:
    kyy ≈ 1.6–3.3 kxx; its first bending pair, 22.2 and 22.5 Hz, is planar up to its 1×
    crossing, tests/test_generator_system.py); its 1× crossing is a critical speed."""
    w = np.asarray(whirl)
    if w.dtype.kind in "biuf":
        return w >= 0
    return (w == "forward") | (w == "planar")
