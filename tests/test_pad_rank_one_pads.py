"""A pad whose film carries pressure on one node does not stall the pad assembly (C++
``pad_equilibrium.cpp``, ``pad_block_solve``).

The case: the compressor of tests/data/models on 5-pad spherical-pivot bearings misaligned by
0.3 mrad (the case of tests/test_pad_fallback_solves.py before this fix). At 5 and 20 Hz the top
pads sit at the boundary of their pressure-free set with 1e-9 … 1e-7 Pa on 1 of 165 nodes: the
pad's tilt and pitch moments are two multiples of that node's pressure, so its 2×2 block of
J_pp has rank 1 (smallest singular value 5e-19 against ~10). The reduced Newton's LU gave NaN,
the minimum-norm fallback a zero step, the line search failed (residual 1.3e-3 at 5 Hz, 3.7e-5
at 20 Hz of the load scale) and the tilt homotopy ran: 36 866 and 40 886 Reynolds solves, against
174 at 60 Hz. Checks:
* 5 and 20 Hz converge through the pad assembly, with at most 4× the Reynolds solves of the
  60 Hz equilibrium (measured 450 and 386 against 174), residual below the tolerance 1e-10;
* at 20 Hz the answer is the homotopy's (homotopy start, then plain Newton on the same model
  without pad groups, as tests/test_tilting_pad_equilibrium.py builds it) to 1e-8 of the
  clearance on the journal, 1e-7 C on the pad tilts, 1e-7 of C/(L/2) on the pitches (measured
  4.4e-9 C, 3.9e-8 C, 5.5e-9: the plain Newton's tolerance), except the top pads, whose
  tilt and pitch their one-node film does not fix (any pose that keeps that node's film
  carries the same ~0 force);
* at 5 Hz the homotopy's answer is another equilibrium: there pad 1 of each bearing is
  pressure-free (0 of 165 nodes) on its pressure-free continuum, a branch the pad assembly
  excludes by construction; the pad assembly's answer has every side pad pressured on every
  node and is mirror-symmetric (pads 1 and 3 tilt alike), as at 20 Hz.
"""

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn import _core
from rotordyn.analysis.assembly import assembled
from rotordyn.analysis.equilibrium import equilibrium_options

MODEL = Path(__file__).parent / "data" / "models" / "compressor_tilting_pad.toml"
C, L = 1e-4, 0.05  # the bearings' radial clearance and length, m


@pytest.fixture(scope="module")
def system():
    s0 = rd.System.from_toml(MODEL)
    return dataclasses.replace(s0, bearings=tuple(
        dataclasses.replace(b, tilt=True, config_theta_y_rad=3e-4, pivot_type="spherical")
        for b in s0.bearings))


def _pads(asm):
    """Per pad (film index), its (tilt, pitch) coordinates."""
    return [list(g) for g in asm.model.pad_coords]


def test_low_speeds_converge_by_the_pad_assembly(system):
    e60 = rd.equilibrium(system, speed_hz=60.0, warm_start=False)
    assert e60.status == "ok" and e60.path == "pad_assembly"
    for hz in (5.0, 20.0):
        e = rd.equilibrium(system, speed_hz=hz, warm_start=False)
        assert e.status == "ok" and e.path == "pad_assembly", (hz, e.path, e.message)
        assert e.residual < 1e-10
        assert e.reynolds_solves <= 4 * e60.reynolds_solves, (hz, e.reynolds_solves)


def test_the_answer_is_the_homotopys_where_that_is_on_the_loaded_branch(system):
    asm = assembled(system)
    m, opt = asm.model, equilibrium_options()
    a = asm.config_vector(None, None)
    pads = _pads(asm)
    n = m.K.shape[0]
    for hz in (20.0, 5.0):
        w = 2 * math.pi * hz
        e = _core.SystemSolver(m).equilibrium(w, 0.0, a, np.zeros(0), opt)
        assert e.status == "ok" and e.path == "pad_assembly"
        s = _core.SystemSolver(m)
        s.film_forces(np.asarray(e.r), np.zeros(n), w)
        peak = [float(np.asarray(s.last_pressure(k)).max()) for k in range(len(pads))]
        nodes = [int((np.asarray(s.last_pressure(k)) > 0).sum()) for k in range(len(pads))]
        # the top pad of each bearing: pressure on one node, ~0 Pa (measured 7e-5 Pa)
        top = [k for k in range(len(pads)) if nodes[k] <= 1]
        assert len(top) == 2 and all(peak[k] < 1e-3 for k in top), (nodes, peak)
        # every other pad is pressured on every node but the cavitated ones of the loaded pads
        assert all(nodes[k] >= 160 for k in range(len(pads)) if k not in top), nodes
        # mirror symmetry of each bearing: pads 1 and 3 (and 0 and 4) tilt alike
        r = np.asarray(e.r)
        for b0 in (0, 5):
            for i, j in ((1, 3), (0, 4)):
                ti, tj = r[pads[b0 + i][0]], r[pads[b0 + j][0]]
                assert abs(ti - tj) < 1e-2 * abs(ti), (hz, b0, i, j, ti, tj)
        if hz != 20.0:
            continue
        start = _core.homotopy_start(m, w, 0.0, a, np.zeros(0), opt, asm.pad_penalty)
        mh = _core.SystemModel()  # the same model without pad groups: the plain Newton path
        for f in ("M", "K", "C", "G", "Q", "chamber", "films", "tables"):
            setattr(mh, f, getattr(m, f))
        eh = _core.SystemSolver(mh).equilibrium(w, 0.0, a, start, opt)
        assert eh.status == "ok"
        # the homotopy's answer is converged to the tolerance (residual 1.5e-11 of the load
        # scale), the pad assembly's to round-off (2e-14): per coordinate the tolerance its
        # stiffness allows — journal and rotor 1e-8 C (measured 4.4e-9 C), pad tilts 1e-7 C
        # (3.9e-8 C; their film stiffness is ~30× softer), pitches 1e-7 of C/(L/2) (5.5e-9)
        assert e.residual < 1e-2 * eh.residual
        atol = np.full(n, 1e-8 * C)
        for k, (tilt, pitch) in enumerate(pads):
            atol[tilt], atol[pitch] = 1e-7 * C, 1e-7 * C / (0.5 * L)
            if k in top:
                atol[tilt] = atol[pitch] = np.inf
        d = np.abs(np.asarray(e.r) - np.asarray(eh.r))
        assert (d <= atol).all(), [(i, d[i], atol[i]) for i in np.flatnonzero(d > atol)]
