"""The stability map's boundary on a rotor without material damping (a 4.3 t steam-turbine
rotor on two turbulent two-axial-groove bearings, no reduction).

Its free bending modes near 9 kHz keep max Re λ ≈ -0.01 1/s on the whole stable side, so the
linear zero of max Re λ between the last stable and the first unstable speed hugged the stable
one (60.01 Hz drawn for a threshold of 61.58 Hz at c = 0.3 mm on a 10 Hz grid, 60.02 for 65.68 Hz at 0.25 mm; now 61.30 and 65.90 Hz). The boundary is
now the zero of the unstable modes' own Re λ (``rotordyn.plot.maps.critical_field``), which has
the sign of max Re λ at every point; checked against ``rotordyn.threshold`` (bisection to
``xtol``) on each line. The colour bar ticks both halves of its two-slope scale.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import rotordyn as rd
from rotordyn.cli import main
from rotordyn.model.paths import set_field
from rotordyn.plot.maps import critical_field

TURBINE = Path(__file__).parent / "data" / "models" / "turbine_two_axial_groove.toml"
CLEARANCES = (2.5e-4, 3.0e-4)
STEP_HZ = 10.0


@pytest.fixture(scope="module")
def sweep(tmp_path_factory):
    d = tmp_path_factory.mktemp("turbine")
    spec = d / "s.toml"
    spec.write_text(f'''schema = "rotordyn/sweep/1"
name = "turbine-speed-clearance"
model = "{TURBINE.as_posix()}"
analysis = "stability"
chunk_size = 6

[grid]
"bearings.*.clearance_m" = [{CLEARANCES[0]}, {CLEARANCES[1]}]
speed_hz = {{start = 40.0, stop = 90.0, num = 6}}
''')
    out = d / "out"
    assert main(["sweep", str(spec), "--out", str(out), "--threads", "1", "--json"]) == 0
    return d, out


def _zero(x, f):
    """The linear zero of f on the first sign change (stable → unstable) along x."""
    i = int(np.argmax(f > 0))
    assert i > 0 and f[i - 1] < 0
    return x[i - 1] + (x[i] - x[i - 1]) * (-f[i - 1]) / (f[i] - f[i - 1])


def test_boundary_follows_the_modes_that_cross(sweep):
    _, out = sweep
    df = pd.read_parquet(out)
    d = df[(df["status"] == "ok") & (df["kind"] == "rotor")]
    axes = ["bearings.*.clearance_m", "speed_hz"]
    xs, ys = np.sort(d[axes[0]].unique()), np.sort(d[axes[1]].unique())
    mx = d.groupby(axes)["eig_real_1_per_s"].max().unstack().reindex(index=xs, columns=ys)
    mx = mx.to_numpy(dtype=float)
    f = critical_field(d, axes, xs, ys)
    assert f is not None
    np.testing.assert_array_equal(np.sign(f), np.sign(mx))  # the same verdict at every point
    s = rd.System.from_toml(TURBINE)
    for k, c in enumerate(xs):
        th = rd.threshold(set_field(s, "bearings.*.clearance_m", float(c)), "speed_hz",
                          bounds=(40.0, 90.0), xtol=1e-3)
        assert th.status == "ok"
        # the premise: max Re λ's zero sits within a tenth of a step of the last stable speed
        old = _zero(ys, mx[k])
        assert old - ys[ys < th.value].max() < 0.1 * STEP_HZ < th.value - old
        # the critical modes' zero: within a fifth of a grid step of the bisected threshold
        assert abs(_zero(ys, f[k]) - th.value) < 0.2 * STEP_HZ


def test_map_draws_and_ticks_both_halves(sweep):
    import matplotlib

    matplotlib.use("Agg")
    from rotordyn.plot.maps import stability_map

    _, out = sweep
    ax = stability_map(pd.read_parquet(out))
    cb = ax.collections[0].colorbar
    ticks = np.asarray(cb.get_ticks())
    assert (ticks < 0).any() and (ticks > 0).any() and (ticks == 0).any()


def test_one_signed_map_ticks_only_its_half():
    import matplotlib

    matplotlib.use("Agg")
    from rotordyn.plot.maps import stability_map_grid

    ax = stability_map_grid([1.0, 2.0], [50.0, 60.0], np.array([[1.0, 2.0], [3.0, 4.0]]),
                            xname="bearings.*.clearance_m", yname="speed_hz")
    ticks = np.asarray(ax.collections[0].colorbar.get_ticks())
    assert not (ticks < 0).any()  # the -1e-9 padding of an unstable map is not labelled


def test_units_of_thermal_fields():
    from rotordyn.units import split_unit

    assert split_unit("thermal.supply_temperature_c") == ("thermal.supply_temperature", "°C")
    assert split_unit("thermal.oil.t1_c") == ("thermal.oil.t1", "°C")
    assert split_unit("bearing[0].oil.beta_1_per_k") == ("bearing[0].oil.beta", "1/K")
    assert split_unit("thermal.tol_k") == ("thermal.tol", "K")
    for clearance_units in ("x_over_c", "amplitude_c", "disturbance_c", "amplitudes_c", "p_c"):
        assert split_unit(clearance_units)[1] == "1"
