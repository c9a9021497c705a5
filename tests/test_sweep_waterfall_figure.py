"""A waterfall batch through the sweep store, read back with pandas and drawn by
``rotordyn plot --kind waterfall`` (the compressor of tests/data/models on plain bearings, not
the paper rig; 2026-12-05).

Before, ``plot_dataset`` saved the figure without the paper style's tight bounding box (the
style's rc applies while drawing, not at the save), so the 3-D cascade's "frequency (Hz)"
label, which hangs ~11 pt below the figure, was cut off in every file (docs/figures/
fig13_waterfall.png too). Now the saved image spans every axis label."""

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
import pytest  # noqa: E402

from rotordyn.plot.cascade import waterfall  # noqa: E402
from rotordyn.plot.dataset import plot_dataset  # noqa: E402
from rotordyn.sweep import run_sweep  # noqa: E402

MODEL = (Path(__file__).parent / "data" / "models" / "compressor_plain.toml").resolve()


@pytest.fixture(scope="module")
def frame(tmp_path_factory):
    d = tmp_path_factory.mktemp("wf")
    spec = d / "wf.toml"
    spec.write_text(f'schema = "rotordyn/sweep/1"\nname = "wf"\nmodel = "{MODEL}"\n'
                    'analysis = "waterfall"\nchunk_size = 2\n[grid]\n'
                    'speed_hz = [40.0, 70.0, 100.0]\n[options]\n'
                    'unbalances = [[3, 2.0e-4, 0.0]]\nrevolutions = 12\n'
                    'samples_per_revolution = 32\nmax_frequency_hz = 300.0\n'
                    'bearing = "DE bearing"\n')
    run_sweep(spec, d / "out", threads=1, progress=False)
    return pd.read_parquet(d / "out")


def test_waterfall_rows_read_back(frame):
    assert (frame["status"] == "ok").all()
    assert set(frame["journal_bearing"]) == {"DE bearing"}
    # below the threshold the unbalance response is synchronous: each speed's largest line at
    # order 1 (the spectrum's lines are the speed's multiples over the run's last half)
    top = frame.loc[frame.groupby("speed_hz")["amplitude_x_m"].idxmax()]
    assert np.allclose(top["order"], 1.0) and np.allclose(top["freq_hz"], top["speed_hz"])
    assert (frame["freq_hz"] <= 300.0 + 1e-9).all()


def test_saved_waterfall_keeps_its_axis_labels(frame, tmp_path):
    dpi = 100
    out = plot_dataset(frame, "waterfall", str(tmp_path / "wf.png"), dpi=dpi)
    # where the labels are on the drawn figure (points; the figure spans 0..height)
    ax = waterfall(frame)
    fig = ax.figure
    fig.set_dpi(dpi)
    fig.canvas.draw()
    r = fig.canvas.get_renderer()
    ext = [lab.get_window_extent(r) for lab in (ax.xaxis.label, ax.yaxis.label,
                                               ax.zaxis.label)]
    low, top = min(e.y0 for e in ext), fig.bbox.height
    plt.close(fig)
    assert low < 0  # the frequency label hangs below the figure: the case of the defect
    h = mpimg.imread(out).shape[0]
    assert h >= top - low, (h, top - low)
