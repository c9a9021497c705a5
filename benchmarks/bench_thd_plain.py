"""THD plain journal bearing beside ROSS 2.3's thermal ``PlainJournal`` (issue 20), not a test.

The case of benchmarks/ross_plain_journal.py (two-axial-groove bearing, D = 0.1 m, L = 0.05 m,
c = 0.1 mm, two 150° pads, 20 Hz, 2 kN, ROSS's ISO VG 68 supplied at 40 °C, adiabatic, fresh oil
at every pad, ROSS's laminar range) at an equal grid (``--grid N``: our N intervals around and
``--axial`` along; ROSS N·150/360 volumes per pad and ``--axial`` along). Timed, one thread each
(BLAS/OpenMP/numba threads 1), CPU beside wall time, medians of interleaved repeats, the
machine load printed before and after, the baselines measured in the same run:

* ours, isothermal: equilibrium from the load + K, C at μ(40 °C) (the same grooved film);
* ours, THD: the THD equilibrium from the load (energy equation, μ(T) per node, one C++ call)
  + K, C with the field frozen (``JournalBearing.thermal_equilibrium(model="thd")``);
* ours, THD with the walls' heat paths (rotordyn.bearings.thd_walls: the film's own conduction
  to the walls, the journal's temperature from its heat balance, 1-D conduction through a
  20 mm steel bush, k_b = 50 W/(m K), to its back face at 300 W/(m² K) in oil at the supply
  temperature) + K, C with the field frozen — the cost of the walls beside the adiabatic THD;
* ours, THD + the stiffness with the temperature following the journal (ROSS's definition of
  K: four more THD equilibria under perturbed loads, central differences);
* ROSS, THD: ``PlainJournal(...)`` — its equilibrium from the load (Nelder–Mead over
  eccentricity and attitude, a full THD solve per evaluation) and K, C (eight more THD solves
  at perturbed positions and velocities). Its numba kernels are compiled in an untimed
  warm-up; the bearing is rebuilt every run and ROSS's caches are cleared before it, so no
  result is reused.

Without ROSS the script times ours alone, on our ISO VG 68 (Walther through 68 and 8.6 mm²/s
at 40 and 100 °C, ρ 867 kg/m³, c 1951 J/(kg K): ROSS's lubricant entries) — the walls' cost
beside the adiabatic THD needs no baseline from elsewhere.

Printed after the timings: the comparison on equal inputs (eccentricity, attitude, temperature
field at ROSS's volume centres, pad outlet temperatures, K, C entries in % of the largest).

    .venv/bin/python benchmarks/bench_thd_plain.py [--repeat 21] [--ross-repeat 3] [--grid 72]
        [--axial 16]
"""

from __future__ import annotations

import argparse
import os

for _v in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "NUMBA_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_v, "1")

import dataclasses  # noqa: E402
import statistics  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ross_plain_journal as case  # noqa: E402
from _common import clear_ross_caches, fmt, footer, header, import_ross  # noqa: E402


def timed(fn):
    w0, c0 = time.perf_counter(), time.process_time()
    out = fn()
    return time.perf_counter() - w0, time.process_time() - c0, out


def _row(a: np.ndarray) -> str:
    return np.array2string(np.asarray(a).ravel(), precision=4, max_line_width=200)


def _pct(a: np.ndarray) -> str:
    return ", ".join(f"{100 * x:+.1f}" for x in np.asarray(a).ravel())


WALLS = dict(wall_htc="film", journal_wall="balance", bush_wall="conduction",
             bush_thickness_m=0.02, bush_conductivity_w_per_m_k=50.0, back_htc_w_m2k=300.0)


def ours_without_ross(n_circ: int, n_axial: int):
    """The case's bearing on our ISO VG 68 law (ROSS's density and specific heat)."""
    import rotordyn
    from rotordyn.bearings import Groove, Oil

    oil = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=68.0, t2_c=100.0, nu2_mm2_s=8.6,
              density_kg_m3=867.0, specific_heat_j_per_kg_k=1951.0)
    jb = rotordyn.JournalBearing(
        diameter_m=case.D_M, length_m=case.L_M, clearance_m=case.C_M,
        viscosity_pa_s=oil.viscosity_pa_s(case.SUPPLY_C), n_circ=n_circ, n_axial=n_axial,
        cavitation="gumbel", grooves=[Groove(0.0, case.GROOVE_DEG),
                                      Groove(180.0, case.GROOVE_DEG)])
    return jb, oil


def _ours_lines(med, res, rw, head: bool = True) -> None:
    """Our timings: isothermal, adiabatic THD, THD with the walls, field-following K."""
    if head:
        print(f"  ours isothermal equilibrium + K, C          : cpu {fmt(med['iso'][1])}, wall "
              f"{fmt(med['iso'][0])}")
        print(f"  ours THD equilibrium + K, C (field frozen)  : cpu {fmt(med['thd'][1])}, wall "
              f"{fmt(med['thd'][0])}  ({med['thd'][1] / med['iso'][1]:.1f}x the isothermal "
              f"CPU; {res.iterations} outer steps)")
    print(f"  ours THD with the walls + K, C              : cpu {fmt(med['thd_walls'][1])}, "
          f"wall {fmt(med['thd_walls'][0])}  ({med['thd_walls'][1] / med['thd'][1]:.2f}x the "
          f"adiabatic THD CPU, {med['thd_walls'][1] / med['iso'][1]:.1f}x the isothermal; "
          f"{rw.iterations} outer steps)")
    print(f"    adiabatic: T_max {res.max_temperature_c:.2f} degC, eps "
          f"{res.eccentricity_ratio:.4f}; walls: T_max {rw.max_temperature_c:.2f} degC, bush "
          f"surface max {rw.max_wall_temperature_c:.2f} degC, journal "
          f"{rw.journal_temperature_c:.2f} degC, to the bush {rw.heat_to_bush_w:.1f} W of "
          f"{rw.power_loss_w:.1f} W, eps {rw.eccentricity_ratio:.4f}")
    print(f"  ours THD + field-following K (4 more THD)   : cpu {fmt(med['thd_ff'][1])}, wall "
          f"{fmt(med['thd_ff'][0])}")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=21)
    ap.add_argument("--ross-repeat", type=int, default=3)
    ap.add_argument("--grid", type=int, default=72)
    ap.add_argument("--axial", type=int, default=16)
    args = ap.parse_args(argv)
    header("THD plain journal bearing beside ROSS's thermal PlainJournal (issue 20)")
    ross = import_ross()
    n, k = args.grid, args.axial
    if ross is None:
        print("ROSS not installed: ours only, on our ISO VG 68 law (pip install "
              "ross-rotordynamics 'plotly<7' for the baseline)")
        jb, oil = ours_without_ross(n, k)
    else:
        w, cpu, rb = timed(lambda: case.ross_bearing(ross, n, k))  # warm-up: numba compiles
        print(f"ROSS warm-up (numba compilation included): {fmt(cpu)} CPU, {fmt(w)} wall")
        ro = case.ross_outputs(rb)
        jb, oil, dev = case.ours(ro, n, k)
    mu_s = oil.viscosity_pa_s(case.SUPPLY_C)

    def iso():
        e = jb.static_equilibrium(load_n=case.LOAD_N, speed_hz=case.SPEED_HZ)
        return e, jb.coefficients(x_m=e.x_m, y_m=e.y_m, speed_hz=case.SPEED_HZ)

    def thd():
        return case.thd(jb, oil)

    def thd_walls():
        return jb.thermal_equilibrium(load_n=case.LOAD_N, speed_hz=case.SPEED_HZ,
                                      oil=dataclasses.replace(oil, conductivity_w_per_m_k=0.13),
                                      supply_temperature_c=case.SUPPLY_C, carry_over=0.0,
                                      model="thd", **WALLS)

    def thd_ff():
        return case.thd(jb, oil), case.field_following_stiffness(jb, oil)

    cleared = []

    def ross_run():
        cleared.append(clear_ross_caches(rb))  # PlainJournal memoises nothing in ROSS 2.3
        return case.ross_bearing(ross, n, k)

    for fn in (iso, thd, thd_walls, thd_ff):
        fn()
    t = {"iso": [], "thd": [], "thd_walls": [], "thd_ff": [], "ross": []}
    for r in range(max(args.repeat, args.ross_repeat if ross is not None else 0)):
        if r < args.repeat:
            for key, fn in (("iso", iso), ("thd", thd), ("thd_walls", thd_walls),
                            ("thd_ff", thd_ff)):
                t[key].append(timed(fn)[:2])
        if ross is not None and r < args.ross_repeat:
            t["ross"].append(timed(ross_run)[:2])
    med = {key: (statistics.median(x[0] for x in v), statistics.median(x[1] for x in v))
           for key, v in t.items() if v}
    res = thd()
    rw = thd_walls()
    if ross is None:
        print(f"ours only ({n} x {k} intervals, {case.SPEED_HZ:g} Hz, load {case.LOAD_N} N, "
              f"one thread, medians of {args.repeat} interleaved runs):")
        _ours_lines(med, res, rw)
        footer()
        return 0
    k_ff = case.field_following_stiffness(jb, oil)
    e_iso, _ = iso()
    cmp_ = case.compare(res, ro, k_ff)
    n_pad_vol = int(round(n * case.PAD_ARC_DEG / 360.0))
    print(f"ROSS {ross.__version__} PlainJournal, 2 pads x 150 deg, ISO VG 68 at "
          f"{case.SUPPLY_C:g} degC, {case.SPEED_HZ:g} Hz, load {case.LOAD_N} N, flooded, "
          f"groove_factor 1; grid: ROSS {n_pad_vol} x {k} volumes per pad, ours {n} x {k} "
          f"intervals; one thread each; medians of {args.repeat} (ours) and {args.ross_repeat} "
          f"(ROSS) interleaved runs")
    print(f"  ours isothermal equilibrium + K, C          : cpu {fmt(med['iso'][1])}, wall "
          f"{fmt(med['iso'][0])}")
    print(f"  ours THD equilibrium + K, C (field frozen)  : cpu {fmt(med['thd'][1])}, wall "
          f"{fmt(med['thd'][0])}  ({med['thd'][1] / med['iso'][1]:.1f}x the isothermal CPU, "
          f"{med['thd'][0] / med['iso'][0]:.1f}x wall; goal <= 5x; {res.iterations} outer "
          f"steps)")
    _ours_lines(med, res, rw, head=False)
    print(f"  ROSS THD equilibrium + K, C                 : cpu {fmt(med['ross'][1])}, wall "
          f"{fmt(med['ross'][0])}  (bearing rebuilt each run; ROSS caches cleared before it: "
          f"{max(cleared, default=0)} found)")
    print(f"  -> ours THD is {med['ross'][1] / med['thd'][1]:.0f}x faster in CPU time "
          f"({med['ross'][0] / med['thd'][0]:.0f}x wall; goal >= 50x); with the field-following "
          f"K {med['ross'][1] / med['thd_ff'][1]:.0f}x CPU "
          f"({med['ross'][0] / med['thd_ff'][0]:.0f}x wall)")
    print("comparison on equal inputs (ROSS's force differences = -dF/dq of its own _forces at "
          "its perturbed positions):")
    print(f"  ROSS's largest Reynolds number {ro['re_max']:.0f} (< 500: its eddy viscosity off); "
          f"our law ({oil.viscosity_law}) within {dev:.1e} of its power law a T^b (a "
          f"{ro['mu_a']:.5g}, b {ro['mu_b']:.4f}) over {case.SUPPLY_C:g}.."
          f"{ro['temperature_c'].max():.2f} degC (mu_s {mu_s:.5g} Pa s)")
    print(f"  eccentricity: ROSS {ro['eps']:.4f}, ours {res.eccentricity_ratio:.4f} "
          f"(isothermal {e_iso.eccentricity_ratio:.4f}); attitude ROSS "
          f"{ro['attitude_deg']:.2f} deg, ours {cmp_['attitude_deg']:.2f} deg")
    fm = ro["force_midpoint_n"] - ro["force_n"]
    print(f"  ROSS's film force at its equilibrium {_row(ro['force_n'])} N (trapezoid over its "
          f"volume centres, across the grooves); the midpoint rule over its volumes differs "
          f"by {_row(fm)} N")
    print(f"  max T: ROSS {ro['temperature_c'].max():.3f} degC (volume centre), ours "
          f"{res.max_temperature_c:.3f} degC (node); rise {cmp_['rise_k']:.3f} K")
    print(f"  field at ROSS's centres: max |dT| {cmp_['d_field_max_k']:.3f} K "
          f"({100 * cmp_['d_field_rel']:.1f} % of the rise); per pad (15..165, 195..345 deg) "
          f"{', '.join(f'{x:.3f}' for x in cmp_['d_field_pad_max_k'])} K; without the end rows "
          f"{cmp_['d_field_inner_max_k']:.3f} K")
    print(f"  pad outlet T (axial mean of the last volume): ROSS "
          f"{_row(cmp_['outlet_ross_c'])}, ours {_row(cmp_['outlet_ours_c'])} degC")
    print(f"  K [N/m] ROSS reported          {_row(ro['K'])}")
    print(f"          ROSS force differences {_row(ro['K_force_differences'])}  (reported / "
          f"differences: {_row(ro['K'] / ro['K_force_differences'])})")
    print(f"          ours, field frozen     {_row(res.K)}  ({_pct(cmp_['dK_frozen'])} % of "
          f"the largest)")
    print(f"          ours, field following  {_row(k_ff)}  ({_pct(cmp_['dK_following'])} %)")
    print(f"  C [N s/m] ROSS reported          {_row(ro['C'])}")
    print(f"            ROSS force differences {_row(ro['C_force_differences'])}  (reported / "
          f"differences: {_row(ro['C'] / ro['C_force_differences'])})")
    print(f"            ours, field frozen     {_row(res.C)}  ({_pct(cmp_['dC'])} % of the "
          f"largest)")
    footer()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
