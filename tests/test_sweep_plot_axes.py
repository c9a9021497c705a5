"""Guards issue 18's sweep-plot defects on a model that is not the paper rig: a stability sweep
over speed × a bearing's clearance (a model-field axis) draws as a stability map (it was refused:
"exactly two varying inputs … ['speed_hz']"), ``stability_map_grid`` takes a dotted axis
(KeyError before), the Campbell refuses to average over a second axis (it averaged silently)
unless that axis is fixed with ``--where``, and the dataset's ``units`` metadata has every axis.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.cli import main
from rotordyn.plot.maps import axis_label, axis_scale, stability_map_grid

MODELS = Path(__file__).parent / "data" / "models"


@pytest.fixture(scope="module")
def sweep(tmp_path_factory):
    d = tmp_path_factory.mktemp("sw")
    spec = d / "s.toml"
    spec.write_text(f'''schema = "rotordyn/sweep/1"
name = "speed-clearance"
model = "{(MODELS / 'compressor_plain.toml').as_posix()}"
analysis = "stability"
chunk_size = 4

[grid]
"bearings.*.clearance_m" = [8.0e-5, 1.0e-4, 1.2e-4]
speed_hz = [60.0, 100.0, 140.0]
''')
    out = d / "out"
    assert main(["sweep", str(spec), "--out", str(out), "--threads", "1", "--json"]) == 0
    return d, out


def test_stability_map_over_a_model_field_axis(sweep):
    d, out = sweep
    assert main(["plot", str(out), "--kind", "stability-map", "--out", str(d / "m.png")]) == 0


def test_campbell_refuses_to_average_over_a_second_axis(sweep, capsys):
    d, out = sweep
    assert main(["plot", str(out), "--kind", "campbell", "--out", str(d / "c.png")]) == 2
    assert "bearings.*.clearance_m" in capsys.readouterr().err
    assert main(["plot", str(out), "--kind", "campbell", "--out", str(d / "c.png"),
                 "--where", "bearings.*.clearance_m=1e-4"]) == 0
    assert main(["plot", str(out), "--kind", "campbell", "--out", str(d / "c.png"),
                 "--where", "nosuchaxis=1"]) == 2
    assert main(["plot", str(out), "--kind", "campbell", "--out", str(d / "c.png"),
                 "--where", "speed_hz"]) == 2


def test_units_metadata_has_every_axis(sweep):
    _, out = sweep
    ds = rd.sweep.open(out)
    units = ds.manifest["units"]
    assert units["bearings.*.clearance_m"]["units"] == "m"
    assert units["speed_hz"]["units"] == "Hz"


def test_stability_map_grid_dotted_axis_and_labels():
    ax = stability_map_grid([1e-4, 2e-4], [50.0, 60.0, 70.0], np.array([[-1, -1, 1], [-2, 1, 2]]),
                            xname="bearings.0.clearance_m", yname="speed_hz")
    assert ax.get_xlabel() == "bearings.0.clearance (mm)" and axis_scale("x_m") == 1e3
    assert axis_label("bearings.0.viscosity_pa_s") == "bearings.0.viscosity (Pa·s)"
    assert axis_label("rotor.disks.1.mass_kg") == "rotor.disks.1.mass (kg)"


def test_builtin_specs_load_from_any_directory(tmp_path, monkeypatch):
    """``rotordyn sweep fig9_stability_map`` (and the repository path ``sweeps/…toml``) from a
    directory outside the clone: the specs ship with the package (it worked only from the
    repository root)."""
    from rotordyn.sweep.spec import SweepSpec, builtin_specs

    monkeypatch.chdir(tmp_path)
    assert "fig9_stability_map" in builtin_specs()
    a = SweepSpec.from_toml("fig9_stability_map", check_model=False)
    b = SweepSpec.from_toml("sweeps/fig9_stability_map.toml", check_model=False)
    c = SweepSpec.from_toml("fig9-stability-map", check_model=False)
    assert a.source == b.source == c.source and a.analysis == "stability"
    with pytest.raises(rd.InputError, match="nor a built-in spec .*fig9_stability_map"):
        SweepSpec.from_toml("no_such_spec")
    with pytest.raises(rd.InputError, match="nor a built-in spec"):
        SweepSpec.from_toml("elsewhere/fig9_stability_map.toml")


@pytest.fixture(scope="module")
def sweep3(tmp_path_factory):
    """A three-axis stability sweep of the compressor on plain bearings: clearance × speed ×
    viscosity (2 × 3 × 2 points)."""
    d = tmp_path_factory.mktemp("sw3")
    spec = d / "s.toml"
    spec.write_text(f'''schema = "rotordyn/sweep/1"
name = "speed-clearance-viscosity"
model = "{(MODELS / 'compressor_plain.toml').as_posix()}"
analysis = "stability"
chunk_size = 6

[grid]
"bearings.*.viscosity_pa_s" = [0.012, 0.024]
"bearings.*.clearance_m" = [8.0e-5, 1.2e-4]
speed_hz = [60.0, 100.0, 140.0]
''')
    out = d / "out"
    assert main(["sweep", str(spec), "--out", str(out), "--threads", "1", "--json"]) == 0
    return d, out


def test_stability_map_facets_a_third_axis(sweep3, capsys):
    """``--facet AXIS`` draws one map per value of the third axis (small multiples sharing one
    colour scale); each panel is exactly the two-axis map at that value (never an average);
    without --facet or --where a third axis is refused, pointing at both."""
    import matplotlib.pyplot as plt

    from rotordyn.plot.maps import stability_map
    from rotordyn.sweep import read_dataset

    sys.path.insert(0, str(Path(__file__).parent))
    from figure_checks import overlaps, unlabelled_axes

    d, out = sweep3
    facet = "bearings.*.viscosity_pa_s"
    assert main(["plot", str(out), "--kind", "stability-map", "--out", str(d / "m.png")]) == 2
    err = capsys.readouterr().err
    assert "--facet AXIS" in err and "--where" in err
    assert main(["plot", str(out), "--kind", "stability-map", "--facet", facet,
                 "--out", str(d / "f.png")]) == 0
    assert (d / "f.png").stat().st_size > 20000
    assert main(["plot", str(out), "--kind", "campbell", "--facet", facet,
                 "--out", str(d / "c.png")]) == 2
    assert main(["plot", str(out), "--kind", "stability-map", "--facet", "speed_hz",
                 "--where", "bearings.*.clearance_m=8e-5", "--out", str(d / "g.png")]) == 2
    df = read_dataset(out)
    ax = stability_map(df, facet=facet)
    fig = ax.figure
    panels = [a for a in fig.axes if a.get_visible() and hasattr(a, "_rotordyn_mesh")]
    assert [a.get_title() for a in panels] == ["bearings.*.viscosity = 0.012 Pa·s",
                                               "bearings.*.viscosity = 0.024 Pa·s"]
    norms = {(a._rotordyn_mesh.norm.vmin, a._rotordyn_mesh.norm.vmax) for a in panels}
    assert len(norms) == 1  # one shared colour scale
    for a, v in zip(panels, (0.012, 0.024)):
        one = stability_map(df, where={facet: v})
        np.testing.assert_array_equal(np.asarray(a._rotordyn_mesh.get_array()),
                                      np.asarray(one._rotordyn_mesh.get_array()))
        plt.close(one.figure)
    # the two viscosities give different maps: nothing was averaged over them
    assert not np.allclose(np.asarray(panels[0]._rotordyn_mesh.get_array()),
                           np.asarray(panels[1]._rotordyn_mesh.get_array()))
    fig.set_dpi(200)
    assert overlaps(fig) == [] and unlabelled_axes(fig) == []
    plt.close(fig)
