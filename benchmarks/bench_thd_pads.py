"""THD tilting-pad benchmark (issue 20), not a test.

ROSS 2.3's TiltingPad example (5 pads of 60°, preload 0.5, D = 101.6 mm, c = 74.9 µm,
L = 50.8 mm, 3000 rpm, ISO VG 32 at 40 °C, adiabatic film, hot-oil carry-over 0) at an equal
grid (``--grid`` volumes per pad around and along in ROSS; the same number of intervals per pad
and axially here). Timed, one thread each (OMP/OpenBLAS/numba threads 1), CPU and wall time,
medians of interleaved repeats, machine load printed before and after:

* ours, isothermal: equilibrium (journal and pads) + synchronous reduced K, C at μ(40 °C);
* ours, THD: the thermal equilibrium (energy equation per pad, inlet mixing, pad equilibrium,
  one C++ call) + K, C with the field frozen (``TiltingPadBearing.thermal_equilibrium``);
* ours, THD with the pads' and the journal's heat paths (rotordyn.bearings.thd_walls: the
  film's own conduction to the walls, k = 0.13 W/(m K), one journal temperature from its heat
  balance over the five pads, 1-D conduction through the 12.7 mm steel pads, k_b = 50 W/(m K),
  to their backs at 300 W/(m² K) in oil at the supply temperature) + K, C with the field
  frozen — the walls' cost beside the adiabatic THD of the same run;
* ROSS, THD: ``equilibrium_type="match_eccentricity"`` at ε = 0.35, 287.5° (it balances only
  the pads at the given journal position — less work than our full equilibrium) and its K, C;
  ROSS's caches (numba's compiled kernels are warmed up once before timing; the bearing object
  is rebuilt every run, so no result is reused).

Ours is given the load ROSS's film carries at that position, so both describe the same
operating point; the printed figures compare them (eccentricity, attitude, pad outlet
temperatures, K, C). Without ROSS, ours alone under the load of docs/calibration/
pad_effective_vs_thd.py, (864.9, −2611.2) N, on our ISO VG 32 Walther law at 40 °C.

    .venv/bin/python benchmarks/bench_thd_pads.py [--repeat 5] [--ross-repeat 3] [--grid 12]
"""

from __future__ import annotations

import argparse
import os

for _v in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "NUMBA_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_v, "1")

import contextlib  # noqa: E402
import dataclasses  # noqa: E402
import io  # noqa: E402
import statistics  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
import warnings  # noqa: E402

import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(__file__))
from _common import fmt, import_ross  # noqa: E402

from rotordyn.bearings import Oil, TiltingPadBearing  # noqa: E402

D, C, L = 101.6e-3, 74.9e-6, 50.8e-3
PIVOTS = [18.0, 90.0, 162.0, 234.0, 306.0]


def timed(fn):
    w0, c0 = time.perf_counter(), time.process_time()
    out = fn()
    return time.perf_counter() - w0, time.process_time() - c0, out


def load() -> str:
    return " ".join(f"{x:.2f}" for x in os.getloadavg())


def ross_bearing(ross, grid):
    Q_ = ross.Q_
    with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()):
        warnings.simplefilter("ignore")
        return ross.TiltingPad(
            n=1, frequency=Q_([3000], "RPM"), equilibrium_type="match_eccentricity",
            journal_diameter=D, radial_clearance=C, pad_thickness=12.7e-3,
            pivot_angle=Q_(PIVOTS, "deg"), pad_arc=Q_([60] * 5, "deg"),
            pad_axial_length=Q_([L] * 5, "m"), pre_load=[0.5] * 5, offset=[0.5] * 5,
            lubricant="ISOVG32", oil_supply_temperature=Q_(40, "degC"), eccentricity=0.35,
            attitude_angle=Q_(287.5, "deg"), load=[884.05, -2670.4],
            thermal_type="adiabatic", nx=grid, nz=grid, hot_oil_carry_over=0.0)


WALLS = dict(wall_htc="film", journal_wall="balance", bush_wall="conduction",
             bush_thickness_m=12.7e-3, bush_conductivity_w_per_m_k=50.0, back_htc_w_m2k=300.0)


def _ours_lines(med, r, rw, head: bool = True) -> None:
    """Our timings: isothermal, adiabatic THD, THD with the walls."""
    if head:
        print(f"  ours isothermal equilibrium + K, C : cpu {fmt(med['iso'][1])}, wall "
              f"{fmt(med['iso'][0])}")
        print(f"  ours THD equilibrium + K, C        : cpu {fmt(med['thd'][1])}, wall "
              f"{fmt(med['thd'][0])}  ({med['thd'][1] / med['iso'][1]:.1f}x the isothermal "
              f"CPU; {r.iterations} outer steps)")
    print(f"  ours THD with the walls + K, C     : cpu {fmt(med['thd_walls'][1])}, wall "
          f"{fmt(med['thd_walls'][0])}  ({med['thd_walls'][1] / med['thd'][1]:.2f}x the "
          f"adiabatic THD CPU; {rw.iterations} outer steps)")
    print(f"    adiabatic: T_max {r.max_temperature_c_total:.2f} degC, eps "
          f"{r.eccentricity_ratio:.4f}; walls: T_max {rw.max_temperature_c_total:.2f} degC, "
          f"pad surface max {rw.max_wall_temperature_c_total:.2f} degC, journal "
          f"{rw.journal_temperature_c[0]:.2f} degC, to the pads {rw.heat_to_bush_w.sum():.1f} W "
          f"of {rw.power_loss_w_total:.1f} W, eps {rw.eccentricity_ratio:.4f}")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--ross-repeat", type=int, default=3)
    ap.add_argument("--grid", type=int, default=12)
    args = ap.parse_args(argv)
    print(f"load average before: {load()}  (2-core shared machine: noisy; CPU time is the "
          "figure)")
    with contextlib.redirect_stdout(io.StringIO()), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ross = import_ross()
    if ross is None:
        print("ROSS not installed: ours only (pip install ross-rotordynamics 'plotly<7' for "
              "the baseline)")
        f = -np.array([864.9, -2611.2])
        oil = Oil(viscosity_law="walther", t1_c=40.0, nu1_mm2_s=32.0, t2_c=100.0,
                  nu2_mm2_s=5.4, density_kg_m3=870.0, specific_heat_j_per_kg_k=2000.0)
    else:
        rb = ross_bearing(ross, args.grid)  # warm-up: numba compiles; the load to give ours
        f = np.array([float(np.ravel(rb.force_x_total_list[-1])[0]),
                      float(np.ravel(rb.force_y_total_list[-1])[0])])
        a, b = float(rb.a_a), float(rb.b_b)
        oil = Oil(viscosity_law="exponential", mu_ref_pa_s=a * np.exp(b * 40.0), t_ref_c=40.0,
                  beta_1_per_k=-b, density_kg_m3=float(rb.rho),
                  specific_heat_j_per_kg_k=float(rb.cp))
    n_circ = int(round(args.grid * 360.0 / 60.0))
    tp = TiltingPadBearing(station=0, diameter_m=D, length_m=L, clearance_m=C,
                           viscosity_pa_s=oil.viscosity_pa_s(40.0), n_pads=5, pad_arc_deg=60.0,
                           pivot_offset=0.5, preload=0.5, orientation_deg=PIVOTS[0],
                           pad_thickness_m=12.7e-3, n_circ=n_circ, n_axial=args.grid)

    def iso():
        return tp.coefficient_table([50.0], -f)

    def thd():
        return tp.thermal_equilibrium(load_n=-f, speed_hz=50.0, oil=oil,
                                      supply_temperature_c=40.0, carry_over=0.0)

    def thd_walls():
        return tp.thermal_equilibrium(load_n=-f, speed_hz=50.0,
                                      oil=dataclasses.replace(oil, conductivity_w_per_m_k=0.13),
                                      supply_temperature_c=40.0, carry_over=0.0, **WALLS)

    iso()
    thd()
    thd_walls()
    t = {"iso": [], "thd": [], "thd_walls": [], "ross": []}
    for k in range(max(args.repeat, args.ross_repeat if ross is not None else 0)):
        if k < args.repeat:
            t["iso"].append(timed(iso)[:2])
            t["thd"].append(timed(thd)[:2])
            t["thd_walls"].append(timed(thd_walls)[:2])
        if ross is not None and k < args.ross_repeat:
            w, cpu, rb = timed(lambda: ross_bearing(ross, args.grid))
            t["ross"].append((w, cpu))
    med = {k: (statistics.median(x[0] for x in v), statistics.median(x[1] for x in v))
           for k, v in t.items() if v}
    r = thd()
    rw = thd_walls()
    it = iso()
    if ross is None:
        print(f"ours only: 5 x 60 deg pads, {args.grid} intervals per pad x {args.grid} "
              f"axially, 3000 rpm, load {np.array2string(-f, precision=1)} N, one thread, "
              f"medians of {args.repeat} interleaved runs")
        _ours_lines(med, r, rw)
        print(f"load average after: {load()}")
        return 0
    print(f"ROSS {ross.__version__} TiltingPad example, adiabatic THD, carry-over 0, grid "
          f"{args.grid} x {args.grid} per pad; ours {args.grid} intervals per pad x "
          f"{args.grid} axially; one thread each; medians of {args.repeat} (ours) and "
          f"{args.ross_repeat} (ROSS) interleaved runs")
    print(f"  ours isothermal equilibrium + K, C : cpu {fmt(med['iso'][1])}, wall "
          f"{fmt(med['iso'][0])}")
    print(f"  ours THD equilibrium + K, C        : cpu {fmt(med['thd'][1])}, wall "
          f"{fmt(med['thd'][0])}  ({med['thd'][1] / med['iso'][1]:.1f}x the isothermal CPU; "
          f"{r.iterations} outer steps)")
    _ours_lines(med, r, rw, head=False)
    print(f"  ROSS THD match_eccentricity + K, C : cpu {fmt(med['ross'][1])}, wall "
          f"{fmt(med['ross'][0])}")
    print(f"  -> ours THD is {med['ross'][1] / med['thd'][1]:.0f}x faster in CPU time "
          f"({med['ross'][0] / med['thd'][0]:.0f}x wall)")
    att = np.degrees(np.arctan2(r.y_m, r.x_m)) % 360
    print(f"  operating point: ROSS eps 0.35 at 287.50 deg, film force ({f[0]:.1f}, "
          f"{f[1]:.1f}) N; ours under that load: eps {r.eccentricity_ratio:.4f} at "
          f"{att:.2f} deg (isothermal: eps "
          f"{np.hypot(it.x_m[0], it.y_m[0]) / C:.4f})")
    print(f"  pad outlet T (degC): ROSS {np.array2string(np.asarray(rb.T_outlet), precision=2)}"
          f"  ours {np.array2string(r.outlet_temperature_c, precision=2)}")
    print(f"  pad max T (degC): ours {np.array2string(r.max_temperature_c, precision=2)}; "
          f"power loss ours {r.power_loss_w_total:.1f} W")
    kr = np.array([[rb.kxx[0], rb.kxy[0]], [rb.kyx[0], rb.kyy[0]]], dtype=float)
    cr = np.array([[rb.cxx[0], rb.cxy[0]], [rb.cyx[0], rb.cyy[0]]], dtype=float)
    print(f"  K [N/m]   ROSS {np.array2string(kr.ravel(), precision=4)}\n"
          f"            ours {np.array2string(r.K.ravel(), precision=4)}")
    print(f"  C [N s/m] ROSS {np.array2string(cr.ravel(), precision=4)}\n"
          f"            ours {np.array2string(r.C.ravel(), precision=4)}")
    print(f"load average after: {load()}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
