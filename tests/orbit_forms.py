"""Closed forms shared by the periodic-orbit and continuation tests (issue 19).

A rotor on linear supports forced by unbalances [(station, m·e kg·m, phase deg)] at Ω = 2πf has
the periodic orbit r(t) = K⁻¹(Q − K a) + Re(X e^{iΩt}) with
(K − Ω² M + iΩ(C + ΩG)) X = Ω² (u_c − i u_s)."""

import numpy as np

from rotordyn.analysis.assembly import assembled


def forced_orbit(system, f, t, unbalances):
    """The closed-form orbit at the times ``t`` (s), shape (n_t, n), and max |X| (m)."""
    asm = assembled(system)
    m = asm.model
    w = 2 * np.pi * f
    M, K, C, G = (np.asarray(x) for x in (m.M, m.K, m.C, m.G))
    n = M.shape[0]
    uc, us = np.zeros(n), np.zeros(n)
    for st, me, ph in unbalances:
        L = asm.station_load_matrix(st)
        p = np.radians(ph)
        uc += me * (L[:, 0] * np.cos(p) + L[:, 1] * np.sin(p))
        us += me * (-L[:, 0] * np.sin(p) + L[:, 1] * np.cos(p))
    rs = np.linalg.solve(K, np.asarray(m.Q) - K @ asm.config_vector(None))
    X = np.linalg.solve(K - w**2 * M + 1j * w * (C + w * G), w**2 * (uc - 1j * us))
    t = np.asarray(t)
    return rs[None, :] + np.real(X[None, :] * np.exp(1j * w * t[:, None])), np.abs(X).max()
