"""Guards issue 18's figure-output defects: CLI PNGs at the style's 200 dpi (they were written
at matplotlib's 100: the rc context was gone when the file was saved) with ``--dpi`` to choose;
``unbalance --station 4 --station 6 --plot FIG`` writes a figure per station (only the first
was written)."""

from __future__ import annotations

from pathlib import Path

import pytest
from PIL import Image

from rotordyn.cli import main

MODELS = Path(__file__).parent / "data" / "models"
MODEL = str(MODELS / "compressor_linear.toml")


def _dpi(path) -> float:
    with Image.open(path) as im:
        return float(im.info["dpi"][0])


@pytest.mark.parametrize("cmd", [
    ["validate", MODEL],
    ["modes", MODEL, "--n-modes", "4"],
    ["static", MODEL, "--speed-hz", "100"],
    ["campbell", MODEL, "--speeds-hz", "20:200:60"],
    ["unbalance", MODEL, "--unbalance", "3,1e-4,0", "--speeds-hz", "100:200:20"],
])
def test_cli_figures_at_200_dpi_and_dpi_flag(tmp_path, cmd):
    fig = tmp_path / "f.png"
    assert main([*cmd, "--plot", str(fig)]) == 0
    assert _dpi(fig) == pytest.approx(200, abs=0.5)
    assert main([*cmd, "--plot", str(fig), "--dpi", "300"]) == 0
    assert _dpi(fig) == pytest.approx(300, abs=0.5)
    assert main([*cmd, "--plot", str(fig), "--dpi", "5"]) == 2


def test_unbalance_plot_per_station(tmp_path):
    fig = tmp_path / "u.png"
    assert main(["unbalance", MODEL, "--unbalance", "3,1e-4,0", "--speeds-hz", "100:200:20",
                 "--station", "1", "--station", "3", "--plot", str(fig)]) == 0
    assert (tmp_path / "u_station1.png").stat().st_size > 10000
    assert (tmp_path / "u_station3.png").stat().st_size > 10000
    assert not fig.exists()


def test_bode_phase_is_an_unwrapped_lag():
    """A single-degree-of-freedom response: the lag rises from 0 through 90° at resonance to
    180°, continuously (the wrapped phase jumped by 360°, read as a resonance)."""
    import numpy as np

    from rotordyn.plot.response import phase_lag_deg

    r = np.linspace(0.1, 3.0, 200)
    z = 1.0 / (1 - r**2 + 2j * 0.05 * r)
    sdof = np.degrees(np.arctan2(2 * 0.05 * r, 1 - r**2))  # 0 → 90° at r = 1 → 180°
    lag = phase_lag_deg(z * np.exp(-3j))  # 172° more: the wrapped phase jumps by 360°
    np.testing.assert_allclose(lag, sdof + np.degrees(3.0), atol=1e-9)
    assert np.all(np.abs(np.diff(lag)) < 60)
    gap = np.array([1 + 0j, np.nan, -1 + 0j])
    assert np.isnan(phase_lag_deg(gap)[1])


def test_results_display_in_jupyter():
    import rotordyn as rd

    s = rd.System.from_toml(MODELS / "compressor_linear.toml")
    for r in (rd.stability(s, 100.0), rd.static(s), rd.equilibrium(rd.models.paper_rig(), 50.0,
                                                                   0.15e6, -1.85e-3)):
        h = r._repr_html_()
        assert h.startswith("<pre>&lt;") and "<table" in h
