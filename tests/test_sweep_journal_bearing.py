"""Which journal a sweep's rows describe. On a three-bearing motor-fan train (no active
bearing; found in an engineer's pass, not on the paper rig) the stability rows' journal_x_m,
journal_y_m and config_ay_m were the first bearing's, unnamed, while the swept offset was the
middle bearing's: the config_ay_m column read 0 at every point. The rows now name the bearing
(``journal_bearing``) and ``options.bearing`` picks it; the waterfall used bearing 0 whatever
the model (the run-up used the active one): both follow the same rule."""

from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
import rotordyn.sweep as sw
from rotordyn.errors import InputError
from rotordyn.model.paths import set_field
from rotordyn.sweep import SweepSpec, run_sweep

MODELS = Path(__file__).parent / "data" / "models"
TRAIN = MODELS / "motor_fan_train.toml"


def _spec(tmp_path, model, analysis, grid, options):
    spec = tmp_path / f"{analysis}.toml"
    spec.write_text(f'schema = "rotordyn/sweep/1"\nname = "jb"\nmodel = "{model}"\n'
                    f'analysis = "{analysis}"\n[grid]\n{grid}\n[options]\n{options}\n')
    return spec


@pytest.mark.parametrize("bearing", [None, "B2", "B3"])
def test_stability_rows_name_their_journal(tmp_path, bearing):
    opt = "n_modes = 1" + (f'\nbearing = "{bearing}"' if bearing else "")
    spec = _spec(tmp_path, TRAIN, "stability",
                 '"bearings.B2.config_ay_m" = [0.0, 1.0e-4]\nspeed_hz = 25.0', opt)
    df = (run_sweep(spec, tmp_path / "out", threads=1), sw.open(tmp_path / "out").frame)[1]
    name = bearing or "B1"  # no active bearing: the first
    assert (df.journal_bearing == name).all()
    k = ("B1", "B2", "B3").index(name)
    for ay, row in df.groupby("bearings.B2.config_ay_m"):
        s = set_field(rd.System.from_toml(TRAIN), "bearings.B2.config_ay_m", float(ay))
        e = rd.equilibrium(s, 25.0, warm_start=False)
        # the row's journal against the equilibrium of that bearing (same solver, 1e-9 m)
        assert row.journal_x_m.iloc[0] == pytest.approx(e.journal_x_m[k], abs=1e-9)
        assert row.journal_y_m.iloc[0] == pytest.approx(e.journal_y_m[k], abs=1e-9)
        # config_ay_m is that bearing's offset (B2's follows the axis)
        assert row.config_ay_m.iloc[0] == (ay if name == "B2" else 0.0)


def test_waterfall_follows_the_named_bearing(tmp_path):
    """compressor_plain: the DE bearing's spectrum, not bearing 0's (8 revolutions, 1×
    line against rd.transient's spectrum of bearing 1 at equal settings, 1e-12 m)."""
    model = MODELS / "compressor_plain.toml"
    opts = ('unbalances = [[2, 1.0e-4, 0.0]]\nrevolutions = 8\nsamples_per_revolution = 32\n'
            'bearing = "DE bearing"')
    run_sweep(_spec(tmp_path, model, "waterfall", "speed_hz = 60.0", opts),
                   tmp_path / "out", threads=1)
    df = sw.open(tmp_path / "out").frame
    assert (df.journal_bearing == "DE bearing").all()
    s = rd.System.from_toml(model)
    tr = rd.transient(s, 8 / 60.0, 60.0, unbalances=[(2, 1e-4, 0.0)], n_out=8 * 32 + 1,
                      r0=rd.equilibrium(s, 60.0, warm_start=False).r)
    f, ax = tr.spectrum(1, last_fraction=0.5, axis="x")
    _, ax0 = tr.spectrum(0, last_fraction=0.5, axis="x")
    i = int(np.argmin(np.abs(f - 60.0)))
    row = df.iloc[int(np.argmin(np.abs(df.freq_hz.to_numpy() - 60.0)))]
    assert row.amplitude_x_m == pytest.approx(ax[i], rel=1e-6, abs=1e-12)
    assert abs(ax[i] - ax0[i]) > 1e-3 * ax[i]  # the two journals differ: the test can fail


def test_unknown_bearing_is_refused_with_the_names(tmp_path):
    spec = _spec(tmp_path, TRAIN, "stability", "speed_hz = 25.0", 'bearing = "B9"')
    with pytest.raises(InputError, match=r"^options\.bearing: 'B9' is not a bearing of the "
                                         r"model \(allowed: 'B1', 'B2', 'B3'\)"):
        SweepSpec.from_toml(spec).check_against(rd.System.from_toml(TRAIN))
