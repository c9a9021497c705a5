"""Rotor FE benchmarks (issues 2 and 11): eigen-analysis of a 100-element rotor, a 50-speed
Campbell diagram of Friswell et al. (2010) Example 5.9.1, and the unbalance response of the
100-element rotor at 50 frequencies.

    .venv/bin/python benchmarks/bench_rotor.py [--repeat 5] [--no-ross] [--only repeat]

Protocol (benchmarks/_common.py): every side on one BLAS/OpenMP thread (threadpoolctl) unless
a row says otherwise, the sides of each ratio timed in interleaved repeats, medians of wall and
CPU time, machine load before and after. Ratios are baseline / rotordyn in wall time.

Baselines in the same run:
(a) SciPy — the same assembled matrices, the state matrix formed in NumPy and all its
    eigenvalues by scipy.linalg.eig (what a straightforward implementation does);
(b) ROSS (``ross-rotordynamics``, optional extra) on the same rotor, when importable:
    ``Rotor(...)`` + ``run_modal(speed, num_modes=12)``, ``run_campbell(speeds, frequencies=6)``
    and ``run_unbalance_response``. ROSS memoises run_modal/run_campbell (functools.lru_cache):
    every cache is cleared before each timed call, so no call is a dictionary look-up;
(c) unbalance: the dense complex LU (numpy.linalg.solve) of the same dynamic stiffness, which is
    what rotordyn did before issue 11, on one thread and — one row — with the default threads.
"""

from __future__ import annotations

import argparse
import os
import sys

import numpy as np
import scipy.linalg as sla

sys.path.insert(0, os.path.dirname(__file__))
from _common import (clear_ross_caches, fmt, footer, header, import_ross,  # noqa: E402
                     interleaved)

import rotordyn as rd  # noqa: E402
import rotordyn._core as core  # noqa: E402

N_EL = 100
L_EL, D_SHAFT = 0.015, 0.05
K_BRG, C_BRG = 1e7, 200.0
SPEED = 300.0  # rad/s
UB_STATION, UB_ME = 30, 1e-4
UB_SPEEDS_HZ = np.linspace(5.0, 400.0, 50)


def rd_system():
    secs = tuple(rd.ShaftSection(L_EL, D_SHAFT) for _ in range(N_EL))
    sups = tuple(rd.Support(s, "linear", kxx_n_per_m=K_BRG, kyy_n_per_m=K_BRG,
                            cxx_n_s_per_m=C_BRG, cyy_n_s_per_m=C_BRG) for s in (0, N_EL))
    steel = rd.Material("steel", 7810.0, 211e9, shear_modulus_pa=81.2e9)
    # No gravity: a free linear response (the unbalance response does not depend on it).
    return rd.System(rotor=rd.Rotor(secs), materials=(steel,), supports=sups,
                     reduction=rd.Reduction(method="none"), gravity_m_s2=0.0)


def rd_modal():
    return rd.modes(rd_system(), SPEED / (2 * np.pi), reduction="none", n_modes=12)


def scipy_modal():
    c = core.constrain(rd_system().to_core())
    n = len(c.M)
    A = np.block([[np.zeros((n, n)), np.eye(n)],
                  [-np.linalg.solve(c.M, c.K), -np.linalg.solve(c.M, c.C + SPEED * c.G)]])
    w = sla.eig(A, right=True)[0]
    w = w[w.imag > 0]
    return w[np.argsort(w.imag)][:12]


def ross_rotor_100(ross):
    steel = ross.Material(name="bench_steel", rho=7810, E=211e9, G_s=81.2e9)
    shaft = [ross.ShaftElement(L=L_EL, idl=0.0, odl=D_SHAFT, material=steel, shear_effects=True,
                               rotary_inertia=True, gyroscopic=True) for _ in range(N_EL)]
    brgs = [ross.BearingElement(n=n, kxx=K_BRG, kyy=K_BRG, cxx=C_BRG, cyy=C_BRG)
            for n in (0, N_EL)]
    return ross.Rotor(shaft, [], brgs)


def ross_friswell(ross):
    steel = ross.Material(name="bench_steel2", rho=7810, E=211e9, G_s=81.2e9)
    shaft = [ross.ShaftElement(L=0.25, idl=0.0, odl=0.05, material=steel, shear_effects=True,
                               rotary_inertia=True, gyroscopic=True) for _ in range(6)]
    disks = [ross.DiskElement.from_geometry(n=2, material=steel, width=0.07, i_d=0.05, o_d=0.28),
             ross.DiskElement.from_geometry(n=4, material=steel, width=0.07, i_d=0.05, o_d=0.35)]
    brgs = [ross.BearingElement(n=n, kxx=1e6, kyy=1e6, cxx=0, cyy=0) for n in (0, 6)]
    return ross.Rotor(shaft, disks, brgs)


# Issue 22: the 100-element rotor with three disks (stations 25, 50, 75), the same on both
# sides; a repeated analysis of one model (a design loop, a sweep of speeds).
DISKS = ((25, 12.0, 0.040, 0.022), (50, 20.0, 0.080, 0.045), (75, 12.0, 0.040, 0.022))
UB_500_HZ = np.linspace(5.0, 400.0, 500)


def rd_system_3disks():
    s = rd_system()
    disks = tuple(rd.Disk(st, m, ip_kg_m2=ip, id_kg_m2=i_d) for st, m, ip, i_d in DISKS)
    return rd.System(rotor=rd.Rotor(s.rotor.sections, disks=disks), materials=s.materials,
                     supports=s.supports, reduction=s.reduction, gravity_m_s2=0.0)


def ross_rotor_3disks(ross):
    steel = ross.Material(name="bench_steel3", rho=7810, E=211e9, G_s=81.2e9)
    shaft = [ross.ShaftElement(L=L_EL, idl=0.0, odl=D_SHAFT, material=steel, shear_effects=True,
                               rotary_inertia=True, gyroscopic=True) for _ in range(N_EL)]
    disks = [ross.DiskElement(n=st, m=m, Id=i_d, Ip=ip) for st, m, ip, i_d in DISKS]
    brgs = [ross.BearingElement(n=n, kxx=K_BRG, kyy=K_BRG, cxx=C_BRG, cyy=C_BRG)
            for n in (0, N_EL)]
    return ross.Rotor(shaft, disks, brgs)


def section_repeat(ross, repeat, n_ub, ross_ub_repeat):
    """Repeated modal calls (6 and 12 frequencies) and one unbalance response of n_ub
    frequencies on one model, against ROSS on the same model object with its caches cleared
    before every call (ROSS's run_modal(num_modes=2k) returns k frequencies)."""
    from rotordyn.analysis.modes import clear_cache

    s = rd_system_3disks()
    w = SPEED / (2 * np.pi)
    rr = ross_rotor_3disks(ross) if ross else None
    print(f"\n5) {N_EL}-element rotor with 3 disks ({4 * (N_EL + 1)} DOF), repeated calls on one "
          f"model at {SPEED:g} rad/s (issue 22)")
    for k in (6, 12):
        warm = rd.modes(s, w, reduction="none", n_modes=k)

        def cold(k=k):  # the set-up included: cache dropped, a new System object
            clear_cache()
            return rd.modes(rd_system_3disks(), w, reduction="none", n_modes=k)

        c = cold()
        fresh = np.asarray(c.eigenvalues)
        same = np.array_equal(fresh, warm.eigenvalues)
        fns = {"warm": lambda k=k: rd.modes(s, w, reduction="none", n_modes=k), "cold": cold}
        if rr is not None:
            def ross_modal(k=k):
                clear_ross_caches(rr)
                return rr.run_modal(speed=SPEED, num_modes=2 * k)
            m = ross_modal()
            nf = len(m.wd)
            fns["ross"] = ross_modal
        t = interleaved(fns, repeat=repeat)
        print(f"   {k} frequencies: cached and fresh call identical: {same}")
        row(f"rd.modes, {k} freq., model cached", t["warm"])
        row(f"rd.modes, {k} freq., set-up included", t["cold"], t["warm"])
        if rr is not None:
            rd_w = np.sort(warm.eigenvalues.imag)
            ro_w = np.sort(np.asarray(m.wd))
            # ROSS 2.3's nodes have 6 DOF (axial, torsion): its lowest k may hold modes a
            # lateral model has not; match each ROSS frequency to the nearest of ours
            rel = np.array([np.min(np.abs(rd_w - x)) / x for x in ro_w])
            print(f"   ROSS run_modal(num_modes={2 * k}) returned {nf} frequencies "
                  f"({rr.ndof} DOF); {int(np.sum(rel < 1e-6))} equal ours within 1e-6 "
                  f"(largest difference among them {np.max(rel[rel < 1e-6]):.1e}), the others "
                  f"are ROSS's axial/torsional modes: {np.round(ro_w[rel >= 1e-6], 1).tolist()} "
                  "rad/s")
            row(f"ROSS run_modal({2 * k}), caches cleared", t["ross"], t["warm"])
            print(f"   ratio ROSS/rotordyn CPU: {t['ross'].cpu / t['warm'].cpu:.1f}x cached, "
                  f"{t['ross'].cpu / t['cold'].cpu:.1f}x set-up included (goal >= 50x)")
    sp = UB_500_HZ if n_ub == 500 else np.linspace(5.0, 400.0, n_ub)
    ub = [(UB_STATION, UB_ME, 0.0)]

    def rd_ub():
        return rd.unbalance_response(s, ub, sp, stations=[UB_STATION], refine=False)

    from rotordyn.analysis.assembly import assembled
    asm = assembled(s)
    F1 = asm.unbalance_load(ub)
    O = asm.station_output_matrix(UB_STATION)

    def rd_ub_loop():  # the former per-speed path: linearise, then one sparse solve per speed
        out = []
        for f in sp:
            lm = rd.linearize(s, f)
            w = 2 * np.pi * f
            q = core.harmonic_response(lm.M, lm.D, lm.K, w, (w**2 * F1)[:, None])
            out.append(O @ np.asarray(q)[:, 0])
        return np.array(out)

    a, b = rd_ub(), rd_ub_loop()
    d = np.max(np.abs(a.x[:, 0] - b[:, 0])) / np.max(np.abs(b[:, 0]))
    t = interleaved({"rd": rd_ub, "loop": rd_ub_loop}, repeat=repeat)
    print(f"   unbalance, {len(sp)} frequencies {sp[0]:g}-{sp[-1]:g} Hz (refine=False): one C++ "
          f"call vs the per-speed loop: largest difference {d:.1e} of the peak")
    row(f"rd.unbalance_response, {len(sp)} freq.", t["rd"])
    row("per-speed loop (linearize + sparse LU)", t["loop"], t["rd"])
    if rr is not None:
        def ross_ub():
            clear_ross_caches(rr)
            return rr.run_unbalance_response(UB_STATION, UB_ME, 0.0, 2 * np.pi * sp)
        tr = interleaved({"ross": ross_ub, "rd": rd_ub}, repeat=ross_ub_repeat, warmup=0)
        row(f"ROSS run_unbalance_response, {len(sp)} freq.", tr["ross"], tr["rd"])
        print(f"   ratio ROSS/rotordyn CPU: {tr['ross'].cpu / tr['rd'].cpu:.1f}x (goal >= 50x; "
              f"{ross_ub_repeat} ROSS repeat(s), no warm-up)")


def row(name, t, ref=None):
    ratio = f"   ratio {t.wall / ref.wall:7.1f}x" if ref is not None else ""
    print(f"   {name:<34} {t}{ratio}")


def section_modal(ross, repeat):
    ours = rd_modal()
    ref = scipy_modal()
    assert np.allclose(ours.eigenvalues, ref, rtol=1e-6), "rotordyn and SciPy disagree"
    fns = {"rd": rd_modal, "scipy": scipy_modal}
    if ross:
        def ross_modal():  # a new rotor each call: nothing memoised
            return ross_rotor_100(ross).run_modal(speed=SPEED, num_modes=12)
        fns["ross"] = ross_modal
    t = interleaved(fns, repeat=repeat)
    print(f"\n1) {N_EL}-element rotor ({4 * (N_EL + 1)} DOF), assembly + 12 modes at {SPEED:g} rad/s")
    row("rotordyn.modes", t["rd"])
    row("SciPy dense eig (state matrix)", t["scipy"], t["rd"])
    if ross:
        wd = np.sort(fns["ross"]().wd)[:3]
        row("ROSS Rotor + run_modal", t["ross"], t["rd"])
        print(f"   (first ω_d: ROSS {wd.round(3)}, rotordyn {ours.eigenvalues.imag[:3].round(3)} rad/s)")


def section_campbell(ross, repeat):
    fr = rd.models.friswell_5_9_1()
    speeds_rad = np.linspace(0, 4000 * 2 * np.pi / 60, 50)

    def rd_camp():
        return rd.rotor_campbell(rd.models.friswell_5_9_1(), speeds_rad / (2 * np.pi),
                                 reduction="none", n_modes=6)

    def sp_camp():
        c = core.constrain(fr.to_core())
        n = len(c.M)
        out = []
        for w in speeds_rad:
            A = np.block([[np.zeros((n, n)), np.eye(n)],
                          [-np.linalg.solve(c.M, c.K), -np.linalg.solve(c.M, c.C + w * c.G)]])
            ev = sla.eig(A)[0]
            ev = ev[ev.imag > 0]
            out.append(np.sort(ev.imag)[:6])
        return np.array(out)

    cr = rd_camp()
    assert np.allclose(np.sort(cr.eigenvalues.imag, axis=1), sp_camp(), rtol=1e-8)
    fns = {"rd": rd_camp, "scipy": sp_camp}
    if ross:
        def ross_camp():  # a new rotor each call: nothing memoised
            return ross_friswell(ross).run_campbell(speeds_rad, frequencies=6)
        fns["ross"] = ross_camp
    t = interleaved(fns, repeat=repeat)
    print("\n2) Campbell, Friswell Example 5.9.1 rotor, 50 speeds 0–4000 rev/min, 6 modes")
    row("rotordyn.rotor_campbell", t["rd"])
    row("SciPy dense eig per speed", t["scipy"], t["rd"])
    if ross:
        row("ROSS Rotor + run_campbell", t["ross"], t["rd"])


def section_unbalance(ross, repeat):
    s = rd_system()
    ub = [(UB_STATION, UB_ME, 0.0)]
    sp = UB_SPEEDS_HZ
    lms = [rd.linearize(s, f) for f in sp]  # the matrices of each frequency (linear rotor)
    from rotordyn.analysis.assembly import assembled
    asm = assembled(s)
    F1 = asm.station_load_matrix(UB_STATION) @ (UB_ME * np.array([1.0, -1j]))
    n = asm.n

    def solves_sparse():
        return [core.harmonic_response(lm.M, lm.D, lm.K, 2 * np.pi * f,
                                       ((2 * np.pi * f) ** 2 * F1)[:, None])
                for lm, f in zip(lms, sp)]

    def solves_dense():
        out = []
        for lm, f in zip(lms, sp):
            w = 2 * np.pi * f
            out.append(np.linalg.solve(lm.K - w**2 * lm.M + 1j * w * lm.D, w**2 * F1))
        return out

    def full_api():
        return rd.unbalance_response(s, ub, sp, stations=[UB_STATION])

    a, b = solves_sparse(), solves_dense()
    err = max(np.abs(x[:, 0] - y).max() / np.abs(y).max() for x, y in zip(a, b))
    assert err < 1e-9, err
    fns = {"sparse": solves_sparse, "dense": solves_dense, "api": full_api}
    if ross:
        rr = ross_rotor_100(ross)

        def ross_ub():
            clear_ross_caches(rr)
            return rr.run_unbalance_response(UB_STATION, UB_ME, 0.0, 2 * np.pi * sp)
        fns["ross"] = ross_ub
    t = interleaved(fns, repeat=repeat)
    print(f"\n3) Unbalance response, {N_EL}-element rotor ({n} DOF after constraints), "
          f"{len(sp)} frequencies {sp[0]:g}-{sp[-1]:g} Hz")
    row("rotordyn sparse LU (C++), 50 solves", t["sparse"])
    row("dense complex LU (NumPy), 50 solves", t["dense"], t["sparse"])
    print(f"   per frequency: sparse {fmt(t['sparse'].wall / len(sp))}, dense "
          f"{fmt(t['dense'].wall / len(sp))}; max relative difference {err:.1e}")
    row("rd.unbalance_response (whole API)", t["api"])
    if ross:
        row("ROSS run_unbalance_response", t["ross"], t["api"])
    # The one row with the default BLAS threads (what the former code did on a shared machine).
    from threadpoolctl import threadpool_limits
    with threadpool_limits(limits=os.cpu_count()):
        td = interleaved({"dense": solves_dense}, repeat=repeat)["dense"]
    row(f"dense LU, {os.cpu_count()} BLAS threads (row)", td, t["sparse"])


def section_large_campbell(ross, repeat):
    """Campbell of the 100-element rotor (shift-invert Arnoldi per speed) for several requests;
    the 6-mode request is where the first Krylov basis used to fail and restart (issue 11)."""
    s = rd_system()
    sp = np.linspace(5.0, 400.0, 100)
    fns = {k: (lambda k=k: rd.rotor_campbell(s, sp, reduction="none", n_modes=k))
           for k in (2, 4, 6, 8, 12)}
    if ross:
        rr = ross_rotor_100(ross)

        def ross_camp():
            clear_ross_caches(rr)
            return rr.run_campbell(2 * np.pi * sp, frequencies=6)
        fns["ross"] = ross_camp
    t = interleaved(fns, repeat=max(1, repeat // 2))
    print(f"\n4) Campbell, {N_EL}-element rotor ({4 * (N_EL + 1)} DOF), 100 speeds "
          f"{sp[0]:g}-{sp[-1]:g} Hz, rotordyn.rotor_campbell by number of modes")
    for k in (2, 4, 6, 8, 12):
        row(f"{k:2d} modes", t[k])
    if ross:
        row("ROSS run_campbell, 6 frequencies", t["ross"], t[6])


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--no-ross", action="store_true")
    ap.add_argument("--only", choices=("modal", "campbell", "unbalance", "large-campbell",
                                       "repeat"))
    ap.add_argument("--ub-freqs", type=int, default=500, help="section 5's unbalance frequencies")
    ap.add_argument("--ross-ub-repeat", type=int, default=1,
                    help="ROSS repeats of section 5's unbalance (each ~1 min, GBs of memory)")
    args = ap.parse_args(argv)
    header("bench_rotor: 100-element rotor and Friswell 5.9.1")
    ross = None if args.no_ross else import_ross()
    print(f"rotordyn {rd.__version__}; ROSS: {'ross ' + ross.__version__ if ross else 'not used'}"
          f"; {args.repeat} interleaved repeats, medians")
    if ross:
        print("   ROSS memoises run_modal/run_campbell per rotor (methodtools lru_cache): each timed "
              "ROSS call builds its rotor or has its caches cleared first")
    if args.only in (None, "modal"):
        section_modal(ross, args.repeat)
    if args.only in (None, "campbell"):
        section_campbell(ross, args.repeat)
    if args.only in (None, "unbalance"):
        section_unbalance(ross, args.repeat)
    if args.only in (None, "large-campbell"):
        section_large_campbell(ross, args.repeat)
    if args.only in (None, "repeat"):
        section_repeat(ross, args.repeat, args.ub_freqs, args.ross_ub_repeat)
    footer()


if __name__ == "__main__":
    main()
