"""Rotor FE benchmarks (issue 2): assembly + eigen-analysis of a 100-element rotor, and a
50-speed Campbell diagram of the Friswell et al. (2010) Example 5.9.1 rotor.

Baselines measured in the same run: (a) SciPy — the same assembled matrices, state matrix
formed in NumPy and all eigenvalues by scipy.linalg.eig (what a straightforward
implementation does); (b) ROSS (`ross-rotordynamics`, optional extra) on the same rotor, when
importable: `Rotor(...)` + `run_modal(speed, num_modes=12)` and `run_campbell(speeds,
frequencies=6)`. Printed: median times and ratios (baseline / rotordyn).

    .venv/bin/python benchmarks/bench_rotor.py [--repeat 5]
"""

from __future__ import annotations

import argparse
import os
import sys

import numpy as np
import scipy.linalg as sla

sys.path.insert(0, os.path.dirname(__file__))
from _common import fmt, import_ross, median_time  # noqa: E402

import rotordyn as rd  # noqa: E402
import rotordyn._core as core  # noqa: E402

N_EL = 100
L_EL, D_SHAFT = 0.015, 0.05
K_BRG = 1e7
SPEED = 300.0  # rad/s


def rd_system():
    secs = tuple(rd.ShaftSection(L_EL, D_SHAFT) for _ in range(N_EL))
    sups = tuple(rd.Support(s, "linear", kxx_n_per_m=K_BRG, kyy_n_per_m=K_BRG) for s in (0, N_EL))
    steel = rd.Material("steel", 7810.0, 211e9, shear_modulus_pa=81.2e9)
    return rd.System(rotor=rd.Rotor(secs), materials=(steel,), supports=sups,
                     reduction=rd.Reduction(method="none"))


def rd_modal():
    s = rd_system()
    return rd.modes(s, SPEED / (2 * np.pi), reduction="none", n_modes=12)


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
    brgs = [ross.BearingElement(n=n, kxx=K_BRG, kyy=K_BRG, cxx=0, cyy=0) for n in (0, N_EL)]
    return ross.Rotor(shaft, [], brgs)


def ross_friswell(ross):
    steel = ross.Material(name="bench_steel2", rho=7810, E=211e9, G_s=81.2e9)
    shaft = [ross.ShaftElement(L=0.25, idl=0.0, odl=0.05, material=steel, shear_effects=True,
                               rotary_inertia=True, gyroscopic=True) for _ in range(6)]
    disks = [ross.DiskElement.from_geometry(n=2, material=steel, width=0.07, i_d=0.05, o_d=0.28),
             ross.DiskElement.from_geometry(n=4, material=steel, width=0.07, i_d=0.05, o_d=0.35)]
    brgs = [ross.BearingElement(n=n, kxx=1e6, kyy=1e6, cxx=0, cyy=0) for n in (0, 6)]
    return ross.Rotor(shaft, disks, brgs)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args(argv)
    ross = import_ross()
    print(f"rotordyn {rd.__version__}; ROSS: {'ross ' + ross.__version__ if ross else 'not installed'}")

    # -- 1. assembly + eigen-analysis of a 100-element rotor -------------------------------
    ours = rd_modal()
    ref = scipy_modal()
    assert np.allclose(ours.eigenvalues, ref, rtol=1e-6), "rotordyn and SciPy disagree"
    t_rd = median_time(rd_modal, repeat=args.repeat)
    t_sp = median_time(scipy_modal, repeat=max(1, args.repeat // 2))
    print(f"\n1) {N_EL}-element rotor ({4 * (N_EL + 1)} DOF), assembly + 12 modes at {SPEED:g} rad/s")
    print(f"   rotordyn             {fmt(t_rd)}")
    print(f"   SciPy dense eig      {fmt(t_sp)}   ratio {t_sp / t_rd:7.1f}x")
    if ross:
        def ross_modal():
            r = ross_rotor_100(ross)
            return r.run_modal(speed=SPEED, num_modes=12)

        t_ro = median_time(ross_modal, repeat=max(1, args.repeat // 2))
        wd = np.sort(ross_modal().wd)[:6]
        print(f"   ROSS run_modal       {fmt(t_ro)}   ratio {t_ro / t_rd:7.1f}x "
              f"(first ω_d ROSS {wd[:3].round(3)}, rotordyn {ours.eigenvalues.imag[:3].round(3)})")

    # -- 2. 50-speed Campbell of the Friswell rotor ----------------------------------------
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
    t_rd = median_time(rd_camp, repeat=args.repeat)
    t_sp = median_time(sp_camp, repeat=args.repeat)
    print("\n2) Campbell, Friswell Example 5.9.1 rotor, 50 speeds 0–4000 rev/min, 6 modes")
    print(f"   rotordyn             {fmt(t_rd)}")
    print(f"   SciPy dense eig      {fmt(t_sp)}   ratio {t_sp / t_rd:7.1f}x")
    if ross:
        def ross_camp():
            return ross_friswell(ross).run_campbell(speeds_rad, frequencies=6)

        t_ro = median_time(ross_camp, repeat=max(1, args.repeat // 2))
        print(f"   ROSS run_campbell    {fmt(t_ro)}   ratio {t_ro / t_rd:7.1f}x")


if __name__ == "__main__":
    main()
