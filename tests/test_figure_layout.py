"""Guards issue 18's figure defects: on every figure kind, drawn for models that are not only
the paper rig, no two text boxes (titles, axis labels, legends, annotations, free texts)
overlap — the Campbell legend covered its x label, polar speed labels piled up, the rotor
drawing's bearing labels and station numbers ran into each other — and every data axis has a
label with its unit. Checked on the rendered figure's bounding boxes (tests/figure_checks.py),
at the style's 200 dpi."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
import rotordyn.plot

sys.path.insert(0, str(Path(__file__).parent))
from figure_checks import overlaps, unlabelled_axes  # noqa: E402

MODELS = Path(__file__).parent / "data" / "models"


@pytest.fixture(scope="module")
def systems():
    return {"rig": rd.models.paper_rig(),
            "tp": rd.System.from_toml(MODELS / "compressor_tilting_pad.toml"),
            "lin": rd.System.from_toml(MODELS / "compressor_linear.toml"),
            "table": rd.System.from_toml(MODELS / "compressor_table.toml")}


NAMES = ["campbell rig", "campbell tilting pad", "bode rig", "polar rig", "bode compressor",
         "polar compressor", "mode shape rig", "mode shapes compressor", "rotor drawing rig",
         "rotor drawing tp", "rotor drawing table", "static compressor", "equilibrium rig",
         "stability map", "level1 compressor", "bearing coefficients tp",
         "critical mode shape compressor"]


@pytest.fixture(scope="module")
def figures(systems):
    s = systems
    rig, tp, lin = s["rig"], s["tp"], s["lin"]
    u_rig = rd.unbalance_response(rig, [(6, 1e-4, 0)], np.arange(5, 121, 1.0), stations=[6],
                                  operating_speed_hz=(45, 55))
    u_lin = rd.unbalance_response(lin, [(3, 1e-4, 0)], np.linspace(20, 250, 60), stations=[3],
                                  operating_speed_hz=(140, 170))
    from rotordyn.analysis.bearing_coefficients import bearing_coefficients
    from rotordyn.plot.coefficients import bearing_coefficients as coefficient_figure
    from rotordyn.report.sections import critical_mode_shapes

    return {
        "bearing coefficients tp": lambda: coefficient_figure(
            bearing_coefficients(tp, np.linspace(20, 200, 5))).axes[0],
        "critical mode shape compressor": lambda: critical_mode_shapes(
            lin, [157.9], 0.0, None)[0].figure.axes[0],
        "campbell rig": lambda: rd.campbell(rig, np.arange(5, 121, 5.0), 0.4e6, 0.0).plot(),
        "campbell tilting pad": lambda: rd.campbell(tp, np.linspace(20, 200, 10)).plot(),
        "bode rig": lambda: u_rig.plot()[0],
        "polar rig": lambda: u_rig.plot(kind="polar"),
        "bode compressor": lambda: u_lin.plot()[0],
        "polar compressor": lambda: u_lin.plot(kind="polar"),
        "mode shape rig": lambda: rd.stability(rig, 50, 0.15e6, -1.85e-3).plot(system=rig),
        "mode shapes compressor": lambda: rd.modes(lin, 0, reduction="none", n_modes=6).plot(),
        "rotor drawing rig": lambda: rd.plot.rotor_drawing(rig),
        "rotor drawing tp": lambda: rd.plot.rotor_drawing(tp),
        "rotor drawing table": lambda: rd.plot.rotor_drawing(s["table"]),
        "static compressor": lambda: rd.static(lin).plot(system=lin)[0],
        "equilibrium rig": lambda: rd.equilibrium(rig, 50, 0.15e6, -1.85e-3).plot(),
        "stability map": lambda: rd.plot.stability_map_grid(
            [8e-5, 1e-4, 1.2e-4], [60.0, 100.0, 140.0],
            np.array([[-3.0, -1.0, 2.0], [-2.0, 1.0, 3.0], [-1.0, 2.0, 4.0]]),
            xname="bearings.*.clearance_m", yname="speed_hz"),
        "level1 compressor": lambda: rd.level1(tp, 150.0, stages=[
            rd.Stage(station=k, power_w=1.5e6, diameter_m=0.4, height_m=0.02,
                     density_ratio=1.3) for k in (2, 3, 4)]).plot(),
    }


@pytest.mark.parametrize("name", NAMES)
def test_no_overlapping_text_and_units_on_every_axis(figures, name, tmp_path):
    import matplotlib.pyplot as plt

    fig = figures[name]().figure
    fig.set_dpi(200)
    try:
        assert overlaps(fig) == []
        assert unlabelled_axes(fig) == []
        fig.savefig(tmp_path / "f.png", dpi=200)
    finally:
        plt.close(fig)


def test_the_checker_sees_an_overlap():
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    ax.plot([0, 1], [0, 1])
    ax.set_xlabel("speed (Hz)")
    ax.set_ylabel("amplitude")
    ax.legend(["a very long legend entry"], loc="lower center", bbox_to_anchor=(0.5, -0.14))
    assert any("overlaps" in b for b in overlaps(fig))
    assert unlabelled_axes(fig) == ["ax0 y: no unit in 'amplitude'"]
    plt.close(fig)
