"""K_H does not jump with the round-off of the state (DESIGN §5: same inputs, same answer,
whatever ran before). The compressor on 5-pad tilting-pad bearings has an unloaded top pad whose
equilibrium tilt sits at the edge of its pressure-free branch: its film is a degenerate
Swift–Stieber state (p = 0 and A p − b = 0 together, to round-off). A warm-started Campbell
diagram reached an equilibrium differing from the cold one by 5.5e-16 m in that pad's
coordinate, the film then had p = 0 everywhere instead of ~1e-8 Pa on 15 nodes, and K_H moved
by 3.6e-4 of its largest entry (the rotor modes by 1.5e-3: tests/test_mode_window_pads.py
failed depending on the tests run before it in the same process). Degenerate nodes are now
judged against the film's own scales (1e-12 of μ|ω|(R/c)² and of the cell's Couette flux), so
both round-off states are the same degenerate state and K_H is continuous there.

Check: K_H at the cold equilibrium against K_H with each pad coordinate moved by ±1.5e-16 and
±6e-16 m (equilibrium-tolerance sizes): relative 1e-9 of the largest entry (was 3.6e-4)."""

from pathlib import Path

import numpy as np

import rotordyn as rd
from rotordyn.analysis.assembly import assembled

MODELS = Path(__file__).parent / "data" / "models"


def test_kh_is_continuous_at_an_unloaded_pad():
    s = rd.System.from_toml(MODELS / "compressor_tilting_pad.toml")
    e = rd.equilibrium(s, 40.0, warm_start=False)
    assert e.status == "ok"
    asm = assembled(s)
    w = 2 * np.pi * 40.0
    zero = np.zeros(asm.n)
    k0 = np.asarray(asm.solver.linearize(e.r, zero, w).KH)
    pads = [i for bc in asm.bearings for i in bc.extra]
    assert len(pads) == 10
    worst = 0.0
    for i in pads:
        for dx in (-6e-16, -1.5e-16, 1.5e-16, 6e-16):
            r = e.r.copy()
            r[i] += dx
            k = np.asarray(asm.solver.linearize(r, zero, w).KH)
            worst = max(worst, np.max(np.abs(k - k0)) / np.max(np.abs(k0)))
    assert worst < 1e-9, worst


def test_campbell_after_other_calls_equals_a_fresh_one():
    """The failing sequence in one process: Campbell diagrams warm-started from each other's
    last equilibrium give the modes of a cold one (relative 1e-8, the warm-start contract of
    tests/test_call_order.py)."""
    sp = np.array([20.0, 40.0, 60.0])
    ref = None
    for _ in range(5):
        s = rd.System.from_toml(MODELS / "compressor_tilting_pad.toml")
        for n_modes in (None, 4):
            f = rd.campbell(s, sp, n_modes=n_modes).frequencies_hz[:, :4]
            if ref is None:
                ref = f
            np.testing.assert_allclose(f, ref, rtol=1e-8)
