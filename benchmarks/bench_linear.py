"""Benchmark: the linear toolchain on the paper's rig (issue 5).

Run ``python benchmarks/bench_linear.py [--repeat 7] [--wall] [--no-ross]``.

1. **One full operating point** of the rig (W = 50 Hz, a_y = −1.85 mm, p_c from ``params``:
   Table 1's pressures): static equilibrium + K_H, D_H + eigen-analysis with whirl, kind and
   mode shapes, i.e. ``rotordyn.stability``, from a **warm start** (the equilibrium at
   0.99 p_c is solved, untimed, just before; a sweep or continuation step). Broken down into
   the equilibrium alone, the linearisation alone (``SystemSolver.linearize``) and the
   eigen-analysis alone (``_core.modal``). Baselines in the same run: the same operating point
   with the paper's finite-difference K_H, D_H (eq. 20, ``method="finite_difference"``), and
   the eigen-step done by ``scipy.linalg.eig`` on the NumPy state matrix (eigenvalues and
   right eigenvectors; no whirl or kind classification). Goal: < 3 ms on one core.
2. **A 100-speed Campbell diagram** of the rig (5–120 Hz, p_c = 0.4 MPa, a_y = 0; the
   equilibrium continued from speed to speed, K_H(Ω), D_H(Ω) and all 9 modes at each speed):
   ``rotordyn.campbell``. Baselines: the same with finite-difference K_H, D_H; a Python loop
   over ``rotordyn.linearize`` + ``scipy.linalg.eig``; and ROSS's ``Rotor.run_campbell``
   (``ross-rotordynamics``, when importable) on a rotor of the same size: the rig's
   26-element shaft and two disks on linear bearings in place of the ball bearings and the
   film (ROSS has no film equilibrium; it solves its full 108-DOF model at each speed), next
   to ``rotordyn.rotor_campbell`` on the same full rotor. Goal: < 0.5 s.

Protocol (benchmarks/_common.py): one BLAS/OpenMP thread for every side (threadpoolctl),
wall and CPU time of the process side by side (medians of ``--repeat`` runs after one
warm-up), the machine load before and after, and the rotordyn/ROSS sides of the Campbell
ratio timed in interleaved repeats. ROSS memoises ``Rotor.run_modal`` (which run_campbell
calls at each speed) per rotor with an lru_cache: every cache is cleared before each timed
ROSS call (a warm-up on the same rotor and speeds otherwise makes every timed call a
dictionary look-up, which is where an earlier "6.4x slower than ROSS" came from). Ratios are
in wall time. Structure as asv (``params`` × ``param_names``).
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import time

import numpy as np  # noqa: E402
import scipy.linalg as sla  # noqa: E402

sys.path.insert(0, os.path.dirname(__file__))
from _common import (Timing, clear_ross_caches, fmt, footer, header, import_ross,  # noqa: E402
                     interleaved, quiet_fds)

import rotordyn as rd  # noqa: E402
from rotordyn import _core  # noqa: E402
from rotordyn.analysis.assembly import assembled  # noqa: E402

params = ([0.10e6, 0.15e6, 0.20e6, 0.25e6],)
param_names = ("chamber_pressure_pa",)
SPEED_HZ, AY_M = 50.0, -1.85e-3
CAMPBELL_SPEEDS = np.linspace(5.0, 120.0, 100)


def median_of(repeat, setup, fn):
    """Median wall and CPU time (a Timing) over ``repeat`` runs of fn() after an untimed
    setup(); plus the last result. One untimed warm-up round first."""
    setup()
    out = fn()
    ws, cs = [], []
    for _ in range(repeat):
        setup()
        w0, c0 = time.perf_counter(), time.process_time()
        out = fn()
        ws.append(time.perf_counter() - w0)
        cs.append(time.process_time() - c0)
    return Timing(statistics.median(ws), statistics.median(cs), ws, cs), out


def wc(t: Timing) -> str:
    """``wall/CPU`` in a table cell."""
    return f"{fmt(t.wall).strip()}/{fmt(t.cpu).strip()}"


# -- 1. operating point ---------------------------------------------------------------------
def bench_operating_point(rig, repeat):
    asm = assembled(rig)
    xy = asm.rotor.xy_pairs()
    w = 2 * np.pi * SPEED_HZ
    print(f"\n1) Rig operating point, W = {SPEED_HZ:g} Hz, a_y = {AY_M * 1e3:g} mm, warm start "
          f"(equilibrium at 0.99 p_c just before), {asm.n} coordinates, film "
          f"{rig.bearings[0].n_circ}x{rig.bearings[0].n_axial}")
    print("   (each cell: median wall / CPU time)")
    print(f"   {'p_c (MPa)':>9} | {'stability()':>19} | {'equilibrium':>19} | {'linearize':>19} | "
          f"{'modal (C++)':>19} || {'FD K_H stab.':>19} | {'FD linearize':>19} | "
          f"{'SciPy eig':>19}")
    totals = []
    for pc in params[0]:
        def setup(pc=pc):
            rd.equilibrium(rig, SPEED_HZ, 0.99 * pc, AY_M)

        t_st, st = median_of(repeat, setup, lambda: rd.stability(rig, SPEED_HZ, pc, AY_M))
        t_fd, st_fd = median_of(repeat, setup, lambda: rd.stability(
            rig, SPEED_HZ, pc, AY_M, method="finite_difference"))
        t_eq, e = median_of(repeat, setup, lambda: rd.equilibrium(rig, SPEED_HZ, pc, AY_M))
        assert e.status == "ok", e.message
        t_lin, lin = median_of(repeat, lambda: None,
                               lambda: asm.solver.linearize(e.r, np.zeros(asm.n), w))
        t_lfd, _ = median_of(repeat, lambda: None,
                             lambda: asm.solver.linearize_fd(e.r, w, 1e-5))
        lm = st.linear
        t_mod, mod = median_of(repeat, lambda: None,
                               lambda: _core.modal(lm.M, lm.D, lm.K, xy, asm.n, True))

        def scipy_eig():
            return sla.eig(lm.state_matrix(), right=True)

        t_sp, (ev, _) = median_of(repeat, lambda: None, scipy_eig)
        # same eigenvalues by both paths, and FD vs perturbation within 1e-6
        ev = np.sort_complex(ev[ev.imag > 1e-9])
        ours = np.sort_complex(st.eigenvalues[st.eigenvalues.imag > 1e-9])
        assert np.allclose(ev, ours, rtol=1e-8), (ev, ours)
        assert np.allclose(st_fd.eigenvalues, st.eigenvalues, rtol=1e-6)
        totals.append(t_st)
        print(f"   {pc / 1e6:9.2f} | {wc(t_st):>19} | {wc(t_eq):>19} | {wc(t_lin):>19} | "
              f"{wc(t_mod):>19} || {wc(t_fd):>19} | {wc(t_lfd):>19} | {wc(t_sp):>19}")
    med_w = statistics.median(t.wall for t in totals)
    med_c = statistics.median(t.cpu for t in totals)
    print(f"   median over the pressures: {fmt(med_w).strip()} wall, {fmt(med_c).strip()} CPU per "
          f"full operating point (goal < 3 ms): {'met' if med_w < 3e-3 else 'NOT met'} (wall)")


# -- 2. Campbell ----------------------------------------------------------------------------
def ross_rig_like(ross, rig):
    """The rig's 26-element shaft and disks in ROSS, linear bearings instead of the ball
    bearings (1e9 N/m) and the film (1e6 N/m, 1e3 N s/m): same size, not the same physics."""
    m = rig.materials[0]
    steel = ross.Material(name="bench_rig_steel", rho=m.density_kg_m3, E=m.young_pa,
                          Poisson=m.poisson)
    shaft = []
    for s in rig.rotor.sections:
        for _ in range(s.n_elements):
            shaft.append(ross.ShaftElement(L=s.length_m / s.n_elements, idl=0.0,
                                           odl=s.outer_diameter_m, material=steel,
                                           shear_effects=True, rotary_inertia=True,
                                           gyroscopic=True))
    nodes = rig.rotor.station_nodes()
    disks = [ross.DiskElement(n=int(nodes[d.station]), m=d.mass_kg, Id=d.id_kg_m2, Ip=d.ip_kg_m2)
             for d in rig.rotor.disks]
    brgs = [ross.BearingElement(n=int(nodes[s.station]), kxx=1e9, kyy=1e9, cxx=0, cyy=0)
            for s in rig.supports]
    brgs.append(ross.BearingElement(n=int(nodes[rig.bearings[0].station]), kxx=1e6, kyy=1e6,
                                    cxx=1e3, cyy=1e3))
    return ross.Rotor(shaft, disks, brgs)


def rd_rig_like(rig):
    """The same linear-bearing rotor in rotordyn, full FE model (no reduction)."""
    sups = [rd.Support(s.station, "linear", kxx_n_per_m=1e9, kyy_n_per_m=1e9)
            for s in rig.supports]
    sups.append(rd.Support(rig.bearings[0].station, "linear", kxx_n_per_m=1e6, kyy_n_per_m=1e6,
                           cxx_n_s_per_m=1e3, cyy_n_s_per_m=1e3))
    return rd.System(rotor=rig.rotor, materials=rig.materials, supports=tuple(sups),
                     reduction=rd.Reduction(method="none"))


def bench_campbell(rig, repeat, use_ross):
    sp = CAMPBELL_SPEEDS
    pc, ay = 0.4e6, 0.0
    print(f"\n2) Campbell of the rig, {len(sp)} speeds {sp[0]:g}-{sp[-1]:g} Hz, p_c = "
          f"{pc / 1e6:g} MPa, a_y = {ay:g} (equilibrium continued, K_H(Ω), D_H(Ω), all modes)")
    t_rd, c = median_of(repeat, lambda: None, lambda: rd.campbell(rig, sp, pc, ay))
    crit = c.critical_speeds()["speed_hz"].to_numpy()
    print(f"   rotordyn.campbell                 {t_rd}   ({1e3 * t_rd.wall / len(sp):.2f} ms "
          f"per speed; critical speeds {np.round(crit, 2)} Hz) goal < 0.5 s: "
          f"{'met' if t_rd.wall < 0.5 else 'NOT met'}")
    t_fd, cfd = median_of(max(1, repeat // 2), lambda: None,
                          lambda: rd.campbell(rig, sp, pc, ay, method="finite_difference"))
    fin = np.isfinite(c.eigenvalues)
    dev = np.max(np.abs(cfd.eigenvalues[fin] - c.eigenvalues[fin]) / np.abs(c.eigenvalues[fin]))
    assert dev < 1e-2, dev
    print(f"   same, finite-difference K_H, D_H  {t_fd}   ratio {t_fd.wall / t_rd.wall:6.2f}x "
          f"(max |Δλ|/|λ| {dev:.1e})")

    def python_loop():
        out = []
        for s in sp:
            lm = rd.linearize(rig, float(s), pc, ay)
            ev = sla.eigvals(lm.state_matrix())
            ev = ev[ev.imag > 0]
            out.append(np.sort(ev.imag))
        return out

    t_py, py = median_of(max(1, repeat // 2), lambda: None, python_loop)
    ours = [np.sort(row[np.isfinite(row) & (row.imag > 0)].imag) for row in c.eigenvalues]
    assert all(np.allclose(a, b, rtol=1e-7) for a, b in zip(py, ours))
    print(f"   loop: linearize + scipy eigvals   {t_py}   ratio {t_py.wall / t_rd.wall:6.2f}x")

    like = rd_rig_like(rig)
    n_dof = 4 * (rig.rotor.n_elements + 1)
    ross = import_ross() if use_ross else None
    print(f"   same-size linear rotor ({n_dof} free-free DOF, 6 modes, no film), interleaved:")

    def rd_camp():
        return rd.rotor_campbell(like, sp, reduction="none", n_modes=6, without_bearings=True)

    fns = {"rd": rd_camp}
    if ross is not None:
        with quiet_fds():
            rr = ross_rig_like(ross, rig)
        sp_rad = 2 * np.pi * sp

        def ross_camp():
            n = clear_ross_caches(rr)  # run_modal is memoised per rotor and speed
            assert n >= 1
            with quiet_fds():
                return rr.run_campbell(sp_rad, frequencies=6)

        fns["ross"] = ross_camp
    t = interleaved(fns, repeat=max(1, repeat // 2))
    rc = rd_camp()
    print(f"     rotordyn.rotor_campbell         {t['rd']}")
    if ross is None:
        print("     ROSS run_campbell               not installed")
        return
    res = fns["ross"]()
    wd_ross = np.sort(np.asarray(res.wd)[0])[:4] / (2 * np.pi)
    wd_rd = np.sort(rc.frequencies_hz[0])[:4]
    print(f"     ROSS {ross.__version__} run_campbell         {t['ross']}   ROSS / rotor_campbell = "
          f"{t['ross'].wall / t['rd'].wall:.1f}x; ROSS / the rig's campbell = "
          f"{t['ross'].wall / t_rd.wall:.2f}x (wall)")
    print(f"     (ROSS's caches cleared before every timed call; first ω_d at 5 Hz: ROSS "
          f"{np.round(wd_ross, 2)}, rotordyn {np.round(wd_rd, 2)} Hz)")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=7)
    ap.add_argument("--no-ross", action="store_true")
    args = ap.parse_args(argv)
    header("bench_linear: the rig's operating point and Campbell diagram")
    rig = rd.models.paper_rig()
    print(f"rotordyn {rd.__version__}; repeat {args.repeat}")
    bench_operating_point(rig, args.repeat)
    bench_campbell(rig, args.repeat, not args.no_ross)
    footer()


if __name__ == "__main__":
    main()
