"""Thread safety: the C++ core releases the GIL and each thread keeps its own solvers (the
assembly cache is thread-local), so operating points computed concurrently in threads equal
the same points computed serially to the equilibrium tolerance (1e-9 c: each solver keeps
its own warm-start cavitation set, so the Newton paths differ at round-off level)."""

from concurrent.futures import ThreadPoolExecutor

import numpy as np

import rotordyn as rd


def _point(pc):
    rig = rd.models.paper_rig()
    e = rd.equilibrium(rig, 50.0, pc, -1.85e-3, warm_start=False)
    st = rd.stability(rig, 50.0, pc, -1.85e-3, warm_start=False)
    return e.r, np.sort_complex(st.eigenvalues)


def test_concurrent_operating_points_equal_serial():
    pcs = [0.05e6, 0.1e6, 0.15e6, 0.2e6, 0.25e6, 0.3e6]
    serial = [_point(p) for p in pcs]
    with ThreadPoolExecutor(max_workers=4) as ex:
        threaded = list(ex.map(_point, pcs))
    for (r1, l1), (r2, l2) in zip(serial, threaded):
        np.testing.assert_allclose(r2, r1, rtol=0, atol=1e-9 * 3e-4)
        np.testing.assert_allclose(l2, l1, rtol=1e-9)


def test_journal_bearing_shared_between_threads():
    """One JournalBearing object used by several threads (one C++ solver per thread)."""
    b = rd.JournalBearing(diameter_m=0.05, length_m=0.04, clearance_m=3e-4,
                          viscosity_pa_s=0.04, n_circ=48, n_axial=12)
    pts = [(1e-4 * np.cos(a), 1e-4 * np.sin(a)) for a in np.linspace(0, 6, 12)]
    serial = [b.forces(x_m=x, y_m=y, speed_hz=50.0) for x, y in pts]
    with ThreadPoolExecutor(max_workers=4) as ex:
        threaded = list(ex.map(lambda p: b.forces(x_m=p[0], y_m=p[1], speed_hz=50.0), pts))
    np.testing.assert_allclose(np.array(threaded), np.array(serial), rtol=1e-10)
