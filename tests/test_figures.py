"""Every figure kind renders (Agg) with units on its axes and colour bars and a legend that
explains its line styles (issue 10); the unbalance grid is refined so a peak is not missed."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
import pytest  # noqa: E402

import rotordyn as rd  # noqa: E402
from rotordyn import plot  # noqa: E402

UNIT = ("(Hz)", "(µm", "(m)", "(mm)", "(MPa)", "(1/s)", "(–", "(deg)", "(rpm)")


@pytest.fixture(autouse=True)
def _close():
    yield
    plt.close("all")


def legend_texts(ax):
    leg = ax.get_legend() or (ax.figure.legends[0] if ax.figure.legends else None)
    assert leg is not None, "figure without legend"
    return [t.get_text() for t in leg.get_texts()]


def has_unit(label):
    return any(u in label for u in UNIT)


def colorbar_labels(fig):
    return [a.get_ylabel() for a in fig.axes if a.get_label() == "<colorbar>"]


@pytest.fixture(scope="module")
def rig():
    return rd.models.paper_rig()


@pytest.fixture(scope="module")
def rig_campbell(rig):
    return rd.campbell(rig, np.arange(10.0, 121.0, 3.0), 0.4e6, 0.0)


def test_campbell_diagram(rig_campbell, tmp_path):
    ax = rig_campbell.plot()
    assert ax.get_xlabel() == "rotor speed (Hz)"
    assert ax.get_ylabel() == "damped natural frequency (Hz)"
    cb = colorbar_labels(ax.figure)
    assert cb == ["logarithmic decrement δ (–)"]
    leg = legend_texts(ax)
    for entry in ("0.5× running speed", "1× running speed", "2× running speed",
                  "critical speed (1×, forward or planar)"):
        assert entry in leg
    assert any("whirl" in t for t in leg)
    # the critical speeds are labelled on the figure with their speed
    crit = rig_campbell.critical_speeds()["speed_hz"]
    texts = " ".join(t.get_text() for t in ax.texts)
    for s in crit:
        assert f"{s:.1f} Hz" in texts
    ax.figure.savefig(tmp_path / "c.svg")
    with pytest.raises(rd.InputError, match="at least 2 speeds"):
        rd.campbell(rd.models.paper_rig(), [50.0], 0.4e6, 0.0).plot()


def test_campbell_unstable_region_visible():
    """A stretch with δ < 0 is drawn red and explained in the legend (synthetic data)."""
    sp = np.linspace(0, 100, 21)
    f = np.column_stack([np.full(21, 40.0), 0.5 * sp + 10])
    d = np.column_stack([np.linspace(0.3, -0.2, 21), np.full(21, 0.1)])
    w = np.column_stack([np.ones(21), -np.ones(21)])
    ax = plot.campbell_arrays(sp, f, d, w, harmonics=(1.0,))
    leg = legend_texts(ax)
    assert "unstable (δ < 0, growing)" in leg and "backward whirl" in leg


def test_rotor_campbell_plot():
    r = rd.rotor_campbell(rd.models.load("friswell-5.9.1"), np.linspace(0, 100, 11), n_modes=4, without_bearings=True)
    ax = r.plot(color_by="damping_ratio")
    assert colorbar_labels(ax.figure) == ["damping ratio ζ (–)"]


def test_unbalance_bode_and_polar(rig):
    u = rd.unbalance_response(rig, [(4, 1e-4, 0.0)], np.arange(10.0, 121.0, 2.0),
                              chamber_pressure_pa=4e5, config_ay_m=0.0,
                              operating_speed_hz=(50.0, 60.0))
    a1, a2 = u.plot()
    assert a1.get_ylabel() == "amplitude (µm, 0-peak)" and a2.get_ylabel() == "phase lag (deg)"
    assert a2.get_xlabel() == "rotor speed (Hz)"
    leg = [t.get_text() for t in a1.figure.legends[0].get_texts()]
    assert "operating speed range" in leg and "critical speed N_c (peak)" in leg
    assert any("half-power band" in t for t in leg)
    notes = " ".join(t.get_text() for t in a1.texts)
    assert "AF = " in notes and "SM = " in notes and "API" in notes
    ax = u.plot(kind="polar")
    assert "amplitude (µm)" in ax.get_xlabel() and len(legend_texts(ax)) == 3


def test_unbalance_grid_refined_at_peaks():
    """A lightly damped Jeffcott-like rotor (one disk on a massless-shaft span on isotropic
    damped supports, analytic response |X| = m e Ω² / |k − Ω² M + iΩ c|): on a 1 Hz grid the
    sharp peak is read off by the refined grid within 1 % of a 2 mHz reference grid, and its
    x and y peaks agree (isotropic), which a plain 1 Hz grid does not achieve."""
    steel = rd.Material("steel", density_kg_m3=7850.0, young_pa=2.1e11)
    shaft = (rd.ShaftSection(0.3, 0.03), rd.ShaftSection(0.3, 0.03))
    disk = (rd.Disk(1, 10.0, 0.05, 0.025),)
    sup = tuple(rd.Support(s, "linear", kxx_n_per_m=5e6, kyy_n_per_m=5e6, cxx_n_s_per_m=30.0,
                           cyy_n_s_per_m=30.0) for s in (0, 2))
    s = rd.System(rotor=rd.Rotor(shaft, disk), materials=(steel,), supports=sup)
    ub = [(1, 1e-4, 0.0)]
    coarse = rd.unbalance_response(s, ub, np.arange(5.0, 101.0, 1.0), refine=False)
    fine = rd.unbalance_response(s, ub, np.arange(5.0, 101.0, 1.0))
    pk = coarse.peaks(1, amplitude="x")
    nc = float(pk["critical_speed_hz"].iloc[0])
    ref = rd.unbalance_response(s, ub, np.arange(nc - 1.0, nc + 1.0, 0.002), refine=False)
    ref_peak = np.nanmax(np.abs(ref.x[:, 0]))
    got = np.nanmax(np.abs(fine.x[:, 0]))
    raw = np.nanmax(np.abs(coarse.x[:, 0]))
    assert abs(got - ref_peak) / ref_peak < 0.01
    assert abs(raw - ref_peak) / ref_peak > 0.05  # the plain grid misses the peak
    assert abs(np.nanmax(np.abs(fine.y[:, 0])) - got) / got < 0.01
    assert len(fine.speeds_hz) > len(coarse.speeds_hz)


def test_mode_shape_3d_and_2d(rig):
    m = rd.modes(rig, 30.0, reduction="none", n_modes=6, without_bearings=True)
    ax = m.plot(1, system=rig)
    assert ax.name == "3d"
    assert ax.get_xlabel() == "axial position (m)"
    assert "normalised" in ax.get_ylabel() and "normalised" in ax.get_zlabel()
    leg = legend_texts(ax)
    assert any(t.endswith("orbit") or "orbit (" in t for t in leg)
    assert "rotor outline, disks, bearings (not to scale)" in leg
    assert m.whirl[1] in ax.get_title()
    ax2 = m.plot([0, 2])
    assert "(–, normalised)" in ax2.get_ylabel() and len(legend_texts(ax2)) == 2


def test_stability_mode_and_deflected_shape(rig):
    st = rd.stability(rig, 50.0, 0.15e6, -1.85e-3)
    ax = st.plot(system=rig)
    assert "log dec" in ax.get_title()
    u = rd.unbalance_response(rig, [(4, 1e-4, 0.0)], [30.0, 40.0], stations=[0, 2, 4, 6, 8],
                              chamber_pressure_pa=4e5, config_ay_m=0.0)
    ax = u.plot(kind="deflected", speed_hz=40.0, system=rig)
    assert "(µm)" in ax.get_ylabel() and "(µm)" in ax.get_zlabel()
    assert "40 Hz" in ax.get_title()


def test_rotor_drawing(rig):
    ax = plot.rotor_drawing(rig)
    assert ax.get_xlabel() == "axial position (mm)" and ax.get_ylabel() == "radius (mm)"
    leg = legend_texts(ax)
    assert "shaft section (to scale)" in leg and "station (number)" in leg
    assert "active journal bearing" in leg and any("ball bearing" in t for t in leg)
    assert any("disk" in t for t in leg)


def _grid_df():
    rows = []
    for ay in (-2e-3, -1e-3, 0.0):
        for pc in (0.0, 0.1e6, 0.2e6, 0.3e6):
            for k in (1, 2):
                rows.append({"config_ay_m": ay, "chamber_pressure_pa": pc, "speed_hz": 50.0,
                             "eig_real_1_per_s": (0.15e6 - pc) * 1e-5 * (1 + ay * 100) - k,
                             "kind": "rotor", "status": "ok" if pc > 0 or ay < 0 else "contact",
                             "x_over_c": 0.1 * k + pc * 1e-6, "y_over_c": -0.5 + ay * 100,
                             "bearing": "active"})
    return pd.DataFrame(rows)


def test_stability_map_has_units_boundary_and_hatching():
    ax = plot.stability_map(_grid_df())
    assert ax.get_xlabel() == "housing offset a_y (mm)"
    assert ax.get_ylabel() == "chamber pressure p_c (MPa)"
    assert colorbar_labels(ax.figure) == ["largest real part of the eigenvalues, max Re λ (1/s)"]
    leg = legend_texts(ax)
    assert "stability boundary, Re λ = 0" in leg and "unstable side (Re λ > 0)" in leg
    assert "no equilibrium / contact" in leg
    assert any(h for c in ax.collections for h in (getattr(c, "hatches", None) or [None]))


def test_equilibrium_loci_in_units_of_c():
    ax = plot.equilibrium_loci(_grid_df())
    assert "x / c" in ax.get_xlabel() and "y / c" in ax.get_ylabel()
    leg = legend_texts(ax)
    assert "clearance circle (e = c)" in leg and "a_y = -2 mm" in leg
    assert "increasing p_c (MPa)" in leg


def _waterfall_df():
    rows = []
    for s in np.linspace(10, 100, 10):
        f = np.linspace(0, 4 * 100, 161)
        a = 1e-6 * np.exp(-((f - s) / 2) ** 2) + 2e-7 * np.exp(-((f - 40) / 2) ** 2) + 1e-9
        rows.append(pd.DataFrame({"speed_hz": s, "freq_hz": f[f <= 4 * s],
                                  "amplitude_x_m": a[f <= 4 * s], "amplitude_y_m": a[f <= 4 * s],
                                  "status": "ok"}))
    return pd.concat(rows, ignore_index=True)


@pytest.mark.parametrize("style", ["cascade", "map"])
@pytest.mark.parametrize("scale", ["linear", "log"])
def test_waterfall(style, scale):
    df = _waterfall_df()
    ax = plot.waterfall(df, style=style, scale=scale)
    assert ax.get_xlabel() == "frequency (Hz)" and ax.get_ylabel() == "rotor speed (Hz)"
    leg = legend_texts(ax)
    assert {"0.5× running speed", "1× running speed", "2× running speed"} <= set(leg)
    if style == "map":
        assert "µm" in colorbar_labels(ax.figure)[0]
    else:
        assert "µm" in ax.get_zlabel()
    # every trace over the same frequency span: the lowest speed's 40 Hz
    assert ax.get_xlim()[1] == pytest.approx(40.0)


def test_runup_waterfall():
    """A run-up 10 → 60 Hz: the 1× line of the short-time spectra follows the speed."""
    t = np.arange(0, 4.0, 1 / 2000)
    sp = 10 + 12.5 * t
    phase = 2 * np.pi * np.cumsum(sp) / 2000
    z = 1e-5 * np.cos(phase)
    df = plot.runup_spectra(t, z, sp, window_s=0.5, fmax_hz=150)
    peak = df.loc[df.groupby("speed_hz")["amplitude_m"].idxmax()]
    np.testing.assert_allclose(peak["freq_hz"], peak["speed_hz"], atol=2.5)
    ax = plot.waterfall(df, axis=None, style="map")
    assert "journal amplitude (µm)" in colorbar_labels(ax.figure)[0]


def test_threshold_boundary_equilibrium_transient_statespace_plots(rig):
    t = rd.threshold(rig, "chamber_pressure_pa", bounds=(0.02e6, 0.3e6), speed_hz=50.0,
                     config_ay_m=-1.85e-3, n_scan=6)
    ax = t.plot()
    assert ax.get_ylabel() == "max Re λ (1/s)" and "(MPa)" in ax.get_xlabel()
    assert "unstable (Re λ > 0)" in legend_texts(ax)
    e = rd.equilibrium(rig, 50.0, 0.15e6, -1.85e-3)
    ax = e.plot()
    assert "x / c" in ax.get_xlabel() and "clearance circle (e = c)" in legend_texts(ax)
    ss = rd.statespace(rig, inputs=["chamber_pressure"], outputs=[("journal", 0)],
                       speed_hz=50.0, chamber_pressure_pa=0.15e6, config_ay_m=-1.85e-3)
    ax = ss.plot()
    assert ax.get_xlabel() == "frequency (Hz)" and "/Pa" in legend_texts(ax)[0]
