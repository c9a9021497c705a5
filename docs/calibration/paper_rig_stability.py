"""Stability thresholds and critical speeds of the paper's rig (reference paper §5, §6.2–6.3)
for the model as committed (`rotordyn.models.paper_rig()`), beside the paper's numbers.

1. The threshold at a_y = −1.85 mm, W = 50 Hz (paper: 0.098 MPa), with every crossing of
   max Re λ = 0 in p_c = 0 … 0.6 MPa.
2. Fig. 9: the boundary in (a_y, p_c) at 50 Hz, a_y = −2.5 … 2.5 mm.
3. Fig. 10: the boundary in (speed, p_c) at a_y = 0.
4. Fig. 12: natural frequencies against speed at p_c = 0.4 MPa, a_y = 0 (5–120 Hz), and the
   critical speeds (1× crossings of forward rotor modes; paper: 39 and 90 Hz).
5. Sensitivity of (1) and (4) to the rig's unknown or uncertain parameters (--sensitivity).

Every threshold is `rotordyn.threshold` (bracketing scan, then Brent's method on max Re λ to
1e-6 of the bounds' span) and reports every crossing, not only the first: the rig can be
stable at low p_c, unstable in a band and stable again above it, so a boundary traced from the
first crossing alone (`stability_boundary`'s continuation) would follow the lower edge of such
a band. Figures 9 and 10 shade the scans' max Re λ (the stability map) under the crossings.

Writes docs/figures/paper_rig_fig9_boundary.png, paper_rig_fig10_boundary.png,
paper_rig_fig12_campbell.png and prints every number of docs/paper-rig-stability.md.

Run:  .venv/bin/python docs/calibration/paper_rig_stability.py [--out docs/figures]
      [--sensitivity]   (~20 s in all on 2 shared cores; ~60 s with --sensitivity)
"""

from __future__ import annotations

import argparse
import dataclasses
import hashlib
import os
import subprocess
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rotordyn as rd  # noqa: E402

PAPER_THRESHOLD_PA = 0.098e6      # §6.2, a_y = −1.85 mm, W = 50 Hz (nonlinear: ~0.1 MPa)
PAPER_CRITICAL_HZ = (39.0, 90.0)  # §6.3, linear (nonlinear waterfall: 39 and 91 Hz)
PC_BOUNDS = (0.0, 0.6e6)
N_SCAN = 31                       # 20 kPa between scan points
AY_MM = np.round(np.arange(-2.5, 2.5001, 0.25), 2)
SPEEDS_FIG10 = np.arange(10.0, 120.001, 5.0)
SPEEDS_FIG12 = np.arange(5.0, 120.001, 1.0)


def provenance() -> str:
    here = os.path.dirname(os.path.abspath(__file__))
    try:
        commit = subprocess.run(["git", "-C", here, "rev-parse", "--short", "HEAD"],
                                capture_output=True, text=True, check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", here, "status", "--porcelain", "--",
                                "../../python/rotordyn/model/data/paper_rig.toml"],
                               capture_output=True, text=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        commit, dirty = "unknown", ""
    text = rd.models.paper_rig().to_toml()
    h = hashlib.sha256(text.encode()).hexdigest()[:12]
    return (f"rotordyn {rd.__version__}, git {commit}"
            f"{' (paper_rig.toml modified in the work tree)' if dirty else ''}, "
            f"model hash {h}")


def crossings_table(system, th, speed_hz, ay_m, vary="chamber_pressure_pa"):
    """One row per crossing: value, whirl frequency of the mode crossing, which way."""
    rows = []
    for x in th.crossings:
        p = dict(speed_hz=speed_hz, chamber_pressure_pa=x, config_ay_m=ay_m)
        st = rd.stability(system, p["speed_hz"], p["chamber_pressure_pa"], p["config_ay_m"])
        i = int(np.argmax(st.eigenvalues.real))
        # Direction: max Re λ just below and above the crossing (1 % of the bound span).
        d = 0.01 * (th.bounds[1] - th.bounds[0])
        lo = dict(p, **{vary: max(th.bounds[0], x - d)})
        hi = dict(p, **{vary: min(th.bounds[1], x + d)})
        re_lo = rd.stability(system, lo["speed_hz"], lo["chamber_pressure_pa"],
                             lo["config_ay_m"]).max_real_1_per_s
        re_hi = rd.stability(system, hi["speed_hz"], hi["chamber_pressure_pa"],
                             hi["config_ay_m"]).max_real_1_per_s
        rows.append({"value": x, "whirl_hz": st.eigenvalues[i].imag / (2 * np.pi),
                     "whirl": st.whirl[i], "kind": st.kind[i],
                     "becomes": "stable" if re_hi < 0 < re_lo else
                                "unstable" if re_lo < 0 < re_hi else "?"})
    return rows


def threshold_185(system):
    th = rd.threshold(system, "chamber_pressure_pa", bounds=PC_BOUNDS, speed_hz=50.0,
                      config_ay_m=-1.85e-3, n_scan=N_SCAN)
    rows = crossings_table(system, th, 50.0, -1.85e-3)
    return th, rows


def fig9(system):
    out = []
    for ay in AY_MM:
        th = rd.threshold(system, "chamber_pressure_pa", bounds=PC_BOUNDS, speed_hz=50.0,
                          config_ay_m=float(ay) * 1e-3, n_scan=N_SCAN)
        out.append((float(ay), th, crossings_table(system, th, 50.0, float(ay) * 1e-3)))
    return out


def fig10(system):
    out = []
    for sp in SPEEDS_FIG10:
        th = rd.threshold(system, "chamber_pressure_pa", bounds=PC_BOUNDS, speed_hz=float(sp),
                          config_ay_m=0.0, n_scan=N_SCAN)
        out.append((float(sp), th, crossings_table(system, th, float(sp), 0.0)))
    return out


def upper_boundary(th):
    """The pressure above which the scan stays stable: the last crossing to 'stable above',
    NaN when unstable at the top of the bounds, 0 when stable everywhere."""
    re = th.scan["max_real_1_per_s"].to_numpy()
    if re[-1] > 0:
        return np.nan
    if not th.crossings:
        return 0.0 if np.all(re < 0) else np.nan
    return th.crossings[-1]


def print_boundary(name, along, results, unit_scale, unit):
    print(f"\n{name}")
    print(f"  {along:>10}  crossings p_c MPa (+: becomes unstable, -: stable; whirl Hz)"
          f"        stable for p_c above")
    for x, th, rows in results:
        cr = ", ".join(f"{r['value'] / 1e6:.4f}{'+' if r['becomes'] == 'unstable' else '-'}"
                       f"({r['whirl_hz']:.1f}{r['whirl'][0].upper()})" for r in rows) or "-"
        wf = ""
        ub = upper_boundary(th)
        re0 = th.scan["max_real_1_per_s"].iloc[0]
        state0 = "stable" if re0 < 0 else "unstable"
        ubs = ("never (unstable at 0.6 MPa)" if np.isnan(ub) else
               "every p_c (no crossing)" if not th.crossings else f"{ub / 1e6:.4f} MPa")
        bad = set(th.scan["status"]) - {"ok"}
        extra = f"  statuses {sorted(bad)}" if bad else ""
        print(f"  {x * unit_scale:10.2f}  {cr:44s}{wf}  {ubs:28s} (p_c = 0: {state0}){extra}")


def on_grid(scan, grid, vary="chamber_pressure_pa"):
    """max Re λ of a threshold scan at the regular scan points (the scan also holds the
    refinement points threshold() adds where a parabola dips through zero)."""
    x = scan[vary].to_numpy()
    re = scan["max_real_1_per_s"].to_numpy()
    return np.array([re[np.argmin(np.abs(x - g))] for g in grid])


def plot_boundary(results, along_label, scale, path, title, paper_point=None):
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    xs = np.array([x * scale for x, _, _ in results])
    grid = np.linspace(*PC_BOUNDS, N_SCAN)
    ps = grid / 1e6
    re = np.array([on_grid(th.scan, grid) for _, th, _ in results]).T
    lim = np.nanmax(np.abs(re))
    im = ax.pcolormesh(xs, ps, np.sign(re) * np.sqrt(np.abs(re) / lim), cmap="RdBu_r",
                       vmin=-1, vmax=1, shading="nearest", alpha=0.55)
    cb = fig.colorbar(im, ax=ax)
    cb.set_label("sign(max Re λ)·√(|max Re λ| / max)   (red: unstable)")
    first = True
    for x, th, _ in results:
        for c in th.crossings:
            ax.plot(x * scale, c / 1e6, "ko", ms=4, label="threshold (Brent)" if first else None)
            first = False
    if paper_point is not None:
        ax.plot(*paper_point, "r*", ms=12, label="paper: 0.098 MPa at −1.85 mm")
    ax.set_xlabel(along_label)
    ax.set_ylabel("chamber pressure p_c (MPa)")
    ax.set_ylim(ps[0], ps[-1])
    ax.set_title(title, fontsize=10)
    ax.legend(fontsize="small", loc="upper right")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def fig12(system):
    c = rd.campbell(system, SPEEDS_FIG12, chamber_pressure_pa=0.4e6, config_ay_m=0.0)
    return c


def campbell_summary(c):
    crit = c.critical_speeds(harmonic=1.0, whirl="forward")
    back = c.critical_speeds(harmonic=1.0, whirl="backward")
    return crit, back


def plot_campbell(c, crit, path):
    fig, ax = plt.subplots(figsize=(6.4, 5.0))
    f = np.where(c.rotor_mask(), c.frequencies_hz, np.nan)
    s = c.speeds_hz
    for j in range(f.shape[1]):
        if not np.any(np.isfinite(f[:, j])):
            continue
        fw = np.where(c.whirl[:, j] > 0, f[:, j], np.nan)
        bw = np.where(c.whirl[:, j] < 0, f[:, j], np.nan)
        ax.plot(s, fw, ".", ms=2.5, color="C0")
        ax.plot(s, bw, ".", ms=2.5, color="C1")
    ax.plot([], [], ".", color="C0", label="forward")
    ax.plot([], [], ".", color="C1", label="backward")
    ax.plot(s, s, "k:", lw=1, label="Im = W (1×)")
    for _, r in crit.iterrows():
        ax.plot(r["speed_hz"], r["freq_hz"], "ks", mfc="none", ms=8)
        ax.annotate(f"{r['speed_hz']:.1f} Hz", (r["speed_hz"], r["freq_hz"]),
                    textcoords="offset points", xytext=(6, -12), fontsize=8)
    for p in PAPER_CRITICAL_HZ:
        ax.plot(p, p, "r*", ms=10)
    ax.plot([], [], "r*", label="paper: 39, 90 Hz")
    ax.set_ylim(0, 200)
    ax.set_xlabel("speed W (Hz)")
    ax.set_ylabel("damped natural frequency (Hz)")
    ax.set_title("rig, p_c = 0.4 MPa, a_y = 0: rotor modes (sleeve modes omitted, as in the paper)",
                 fontsize=9)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small", loc="upper left")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


# -- sensitivity --------------------------------------------------------------------------
def variant(system, **bearing_changes):
    b = system.bearings[0]
    sleeve_changes = {k[7:]: v for k, v in bearing_changes.items() if k.startswith("sleeve_")}
    bc = {k: v for k, v in bearing_changes.items() if not k.startswith("sleeve_")}
    if sleeve_changes:
        bc["sleeve"] = dataclasses.replace(b.sleeve, **sleeve_changes)
    return dataclasses.replace(system, bearings=(dataclasses.replace(b, **bc),))


def sensitivity(system):
    b = system.bearings[0]
    g0 = b.grooves[0]
    E, rho = b.sleeve.young_pa, b.sleeve.density_kg_m3
    cases = [
        ("as committed", {}),
        ("sleeve E x0.8 (rho x0.8: same frequencies)", dict(sleeve_young_pa=0.8 * E,
                                                          sleeve_density_kg_m3=0.8 * rho)),
        ("sleeve E x1.25 (rho x1.25)", dict(sleeve_young_pa=1.25 * E,
                                           sleeve_density_kg_m3=1.25 * rho)),
        (f"chamber arc -10 deg ({b.chamber_start_deg - 10:.0f}-{b.chamber_end_deg - 10:.0f})", dict(chamber_start_deg=b.chamber_start_deg - 10,
                                               chamber_end_deg=b.chamber_end_deg - 10)),
        ("chamber = whole sleeve (195-355)", dict(chamber_start_deg=None, chamber_end_deg=None)),
        ("groove at 60 deg", dict(grooves=(dataclasses.replace(g0, center_deg=60.0),))),
        ("groove at 120 deg", dict(grooves=(dataclasses.replace(g0, center_deg=120.0),))),
        ("viscosity x0.8", dict(viscosity_pa_s=0.8 * b.viscosity_pa_s)),
        ("viscosity x1.25", dict(viscosity_pa_s=1.25 * b.viscosity_pa_s)),
        ("clearance x1.1", dict(clearance_m=1.1 * b.clearance_m)),
        ("cavitation gumbel", dict(cavitation="gumbel")),
        ("film grid 144 x 32", dict(n_circ=144, n_axial=32)),
        ("rotor shaft E x1.2 (rotor free freqs +9.5 %)", "rotor_E"),
    ]
    print("\nSensitivity (threshold at a_y = -1.85 mm, 50 Hz; critical speeds at 0.4 MPa, a_y = 0):")
    print(f"  {'variant':44s} crossings p_c (MPa)          critical speeds (Hz)")
    for name, ch in cases:
        if ch == "rotor_E":  # stiffer shaft: not a candidate, an illustration (see the doc)
            s = dataclasses.replace(system, materials=tuple(
                dataclasses.replace(m, young_pa=1.2 * m.young_pa) for m in system.materials))
        else:
            s = variant(system, **ch) if ch else system
        t0 = time.perf_counter()
        try:
            th = rd.threshold(s, "chamber_pressure_pa", bounds=PC_BOUNDS, speed_hz=50.0,
                              config_ay_m=-1.85e-3, n_scan=N_SCAN)
            cr = ", ".join(f"{c / 1e6:.4f}" for c in th.crossings) or \
                ("none (" + ("stable" if "stable)" in th.message and "unstable" not in
                             th.message else "unstable") + ")")
            c = rd.campbell(s, np.arange(20.0, 120.001, 1.0), chamber_pressure_pa=0.4e6,
                            config_ay_m=0.0)
            cs = ", ".join(f"{v:.1f}" for v in c.critical_speeds()["speed_hz"])
        except rd.RotordynError as exc:
            cr, cs = f"error: {exc}", ""
        print(f"  {name:44s} {cr:28s} {cs:20s} ({time.perf_counter() - t0:.1f} s)")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=os.path.join(os.path.dirname(__file__), "..", "figures"))
    ap.add_argument("--sensitivity", action="store_true",
                    help="also vary the rig's unknown parameters (~40 s more)")
    args = ap.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    system = rd.models.paper_rig()
    print(provenance())
    t_all = time.perf_counter()

    # 1. threshold at a_y = -1.85 mm, 50 Hz
    t0 = time.perf_counter()
    th, rows = threshold_185(system)
    print(f"\n1) Threshold at a_y = -1.85 mm, W = 50 Hz, p_c in [0, 0.6] MPa "
          f"({th.evaluations} operating points, {time.perf_counter() - t0:.2f} s)")
    print(f"   status {th.status}; {len(rows)} crossing(s); paper 0.098 MPa (stable above)")
    for r in rows:
        print(f"   p_c = {r['value'] / 1e6:.5f} MPa: becomes {r['becomes']} with increasing p_c; "
              f"crossing mode {r['kind']} {r['whirl']}, {r['whirl_hz']:.2f} Hz "
              f"(whirl ratio {r['whirl_hz'] / 50.0:.3f})")
    ub = upper_boundary(th)
    if np.isfinite(ub):
        print(f"   stable for every p_c above {ub / 1e6:.5f} MPa: "
              f"{100 * (ub / PAPER_THRESHOLD_PA - 1):+.1f} % against the paper")
    fig11 = [(p, rd.stability(system, 50.0, p, -1.85e-3)) for p in (0.05e6, 0.10e6, 0.15e6)]
    print("   Fig. 11 pressures (paper, nonlinear: limit cycle, slow decay, fast decay): "
          + "; ".join(f"{p / 1e6:.2f} MPa max Re λ {st.max_real_1_per_s:+.2f} 1/s "
                      f"({'stable' if st.stable else 'unstable'})" for p, st in fig11))
    grid = np.linspace(*PC_BOUNDS, N_SCAN)
    print("   scan: " + "  ".join(f"{p / 1e6:.2f}:{r:+.1f}" for p, r in
                                   zip(grid, on_grid(th.scan, grid))))

    # 2. Fig. 9
    t0 = time.perf_counter()
    r9 = fig9(system)
    print_boundary(f"2) Fig. 9: boundary in (a_y, p_c) at 50 Hz "
                   f"({time.perf_counter() - t0:.1f} s)", "a_y (mm)", r9, 1.0, "mm")
    plot_boundary(r9, "a_y (mm)", 1.0, os.path.join(args.out, "paper_rig_fig9_boundary.png"),
                  "Fig. 9: stability boundary at W = 50 Hz (model)",
                  paper_point=(-1.85, PAPER_THRESHOLD_PA / 1e6))

    # 3. Fig. 10
    t0 = time.perf_counter()
    r10 = fig10(system)
    print_boundary(f"3) Fig. 10: boundary in (speed, p_c) at a_y = 0 "
                   f"({time.perf_counter() - t0:.1f} s)", "W (Hz)", r10, 1.0, "Hz")
    plot_boundary(r10, "speed W (Hz)", 1.0, os.path.join(args.out, "paper_rig_fig10_boundary.png"),
                  "Fig. 10: stability boundary at a_y = 0 (model)")
    for pc in (0.0, 0.1e6, 0.2e6, 0.4e6):
        ts = rd.threshold(system, "speed_hz", bounds=(10.0, 120.0), chamber_pressure_pa=pc,
                          config_ay_m=0.0, n_scan=23)
        cr = ", ".join(f"{v:.2f}" for v in ts.crossings) or "none"
        print(f"   threshold speed at p_c = {pc / 1e6:.1f} MPa, a_y = 0 (10-120 Hz): {cr} Hz"
              + (f"; whirl {ts.whirl_frequency_hz:.2f} Hz, ratio {ts.whirl_ratio:.3f}, stable "
                 f"{ts.stable_side}" if ts.status == "ok" else f" ({ts.message})"))

    # 4. Fig. 12
    t0 = time.perf_counter()
    c = fig12(system)
    dt = time.perf_counter() - t0
    crit, back = campbell_summary(c)
    print(f"\n4) Fig. 12: Campbell at p_c = 0.4 MPa, a_y = 0, {len(SPEEDS_FIG12)} speeds "
          f"5-120 Hz ({dt:.2f} s); statuses {sorted(set(c.point_status))}")
    for k, (_, r) in enumerate(crit.iterrows()):
        ref = PAPER_CRITICAL_HZ[k] if k < len(PAPER_CRITICAL_HZ) else np.nan
        print(f"   forward critical speed {k + 1}: {r['speed_hz']:.2f} Hz (mode {r['mode']}); "
              f"paper {ref:g} Hz ({100 * (r['speed_hz'] / ref - 1):+.1f} %)")
    for _, r in back.iterrows():
        print(f"   backward 1x crossing: {r['speed_hz']:.2f} Hz (mode {r['mode']})")
    f = np.where(c.rotor_mask(), c.frequencies_hz, np.nan)
    for sp in (5.0, 40.0, 90.0, 120.0):
        i = int(np.argmin(np.abs(c.speeds_hz - sp)))
        fr = f[i][np.isfinite(f[i])]
        wh = c.whirl[i][np.isfinite(f[i])]
        re = c.eigenvalues[i].real[np.isfinite(f[i])]
        desc = ", ".join(f"{x:.1f}{'F' if w > 0 else 'B' if w < 0 else 'P'}({r:+.0f})"
                         for x, w, r in zip(fr, wh, re) if x < 250)
        print(f"   rotor modes at {sp:5.1f} Hz: {desc}   [Hz, whirl, Re λ 1/s]")
    sl = np.where(~c.rotor_mask(), c.frequencies_hz, np.nan)
    print(f"   sleeve modes: {np.nanmin(sl):.0f}-{np.nanmax(sl):.0f} Hz over the speeds")
    m0 = rd.modes(system, 0.0, without_bearings=True)
    print("   rotor alone on its ball bearings (condensed, 0 Hz): "
          + ", ".join(f"{x:.2f}" for x in m0.eigenvalues.imag[::2] / (2 * np.pi)) + " Hz")
    # The rotor with its journal pinned (a rigid support at the bearing station, no film):
    # what the critical speeds tend to when the film is much stiffer than the rotor.
    st4 = system.bearings[0].station
    pinned = dataclasses.replace(
        system, bearings=(), supports=system.supports + (rd.Support(st4),),
        reduction=rd.Reduction(tuple(m for m in system.reduction.master_stations if m != st4),
                               system.reduction.method))
    pg = rd.modes(pinned, 0.0, without_bearings=True)
    pf = rd.modes(pinned, 0.0, reduction="none", n_modes=4, without_bearings=True)
    print("   rotor pinned at the journal (no film, 0 Hz): condensed "
          + ", ".join(f"{x:.2f}" for x in pg.eigenvalues.imag[::2] / (2 * np.pi))
          + " Hz; full " + ", ".join(f"{x:.2f}" for x in pf.eigenvalues.imag[::2] / (2 * np.pi))
          + " Hz")
    e = rd.linearize(system, 40.0, 0.4e6, 0.0)
    j = [e.labels.index(f"station{st4}.x"), e.labels.index(f"station{st4}.y")]
    n_r = 2 * len(system.reduction.master_stations)  # rotor coordinates come first
    kr = np.linalg.inv(np.linalg.inv(e.K_structure[:n_r, :n_r])[np.ix_(j, j)])
    cl = e.equilibrium.clearance_m[0]
    print(f"   at 40 Hz, 0.4 MPa: film K_H at the journal {np.abs(e.KH[np.ix_(j, j)]).max():.3g} N/m "
          f"(largest entry), rotor stiffness there {np.abs(kr).max():.3g} N/m; h_min/c "
          f"{e.equilibrium.h_min_m[0] / cl:.3f}, journal x/c, y/c "
          f"{e.equilibrium.journal_x_m[0] / cl:+.3f}, {e.equilibrium.journal_y_m[0] / cl:+.3f}")
    plot_campbell(c, crit, os.path.join(args.out, "paper_rig_fig12_campbell.png"))

    if args.sensitivity:
        sensitivity(system)
    print(f"\ntotal {time.perf_counter() - t_all:.1f} s; figures in {os.path.normpath(args.out)}")


if __name__ == "__main__":
    main()
