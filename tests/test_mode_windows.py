"""Guards issue 18's "mode windows" and output defects: the per-mode ``mode_stable`` beside the
point's ``point_stable`` (the ``stable`` column was the point's verdict on every mode row);
round-off log decrements (−4e-12) are 0, not a sign; tables of a model without an active bearing
carry no ``chamber_pressure_pa`` / ``config_ay_m``; the CLI's ``stability`` and ``campbell``
take a mode window (``--n-modes``, ``--max-freq-hz``) and a table shows 12 modes by default
instead of all 66 up to tens of kHz. On the compressor models of tests/data/models."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.cli import main
from rotordyn.results.modes import damping_ratio, log_dec, mode_stable, settled_real

MODELS = Path(__file__).parent / "data" / "models"


def test_round_off_real_parts_are_zero_damping_and_stable():
    lam = np.array([-4e-12 + 2000j, 4e-12 + 2000j, -1.0 + 2000j, 1e-3 + 10j])
    np.testing.assert_array_equal(settled_real(lam), [0.0, 0.0, -1.0, 1e-3])
    assert log_dec(lam)[0] == 0.0 and log_dec(lam)[1] == 0.0
    assert damping_ratio(lam)[1] == 0.0
    assert list(mode_stable(lam)) == [True, True, True, False]


def test_stability_frame_per_mode_and_per_point_verdicts():
    s = rd.System.from_toml(MODELS / "compressor_plain.toml")
    st = rd.stability(s, 150.0)  # above the whip onset: unstable
    df = st.to_frame()
    assert not st.stable and not df["point_stable"].any()
    assert df["mode_stable"].sum() == len(df) - (st.eigenvalues.real > 0).sum()
    assert df["mode_stable"].any() and not df["mode_stable"].all()
    assert "stable" not in df and "chamber_pressure_pa" not in df and "config_ay_m" not in df
    e = rd.equilibrium(s, 150.0).to_frame()
    assert "chamber_pressure_pa" not in e and "config_ay_m" in e


def test_rig_frames_keep_the_active_bearing_inputs():
    rig = rd.models.paper_rig()
    df = rd.stability(rig, 50.0, 0.15e6, -1.85e-3).to_frame()
    assert (df["chamber_pressure_pa"] == 0.15e6).all()
    assert np.allclose(df["config_ay_m"], -1.85e-3)
    assert "chamber_pressure_pa" in rd.equilibrium(rig, 50.0, 0.15e6, -1.85e-3).to_frame()


def test_cli_stability_window(capsys, tmp_path):
    import dataclasses

    s = rd.System.from_toml(MODELS / "compressor_tilting_pad.toml")
    full = dataclasses.replace(s, reduction=rd.Reduction(method="none"))  # 76 DOF + pads
    path = str(tmp_path / "full.toml")
    full.to_toml(path)
    assert main(["stability", path, "--speed-hz", "150"]) == 0
    out = capsys.readouterr()
    rows = [r for r in out.out.splitlines()[1:] if r.strip()]
    assert len(rows) == 12 and "12 of" in out.err and "stable: largest Re" in out.err
    assert main(["stability", path, "--speed-hz", "150", "--max-freq-hz", "200"]) == 0
    out = capsys.readouterr()
    freqs = [float(r.split()[2]) for r in out.out.splitlines()[1:] if r.strip()]
    assert freqs and max(freqs) <= 200.0
    assert main(["stability", path, "--speed-hz", "150", "--n-modes", "4", "--json"]) == 0
    import json

    rec = json.loads(capsys.readouterr().out)
    assert len(rec["modes"]["mode"]) == 4 and len(rec["modes"]["mode_stable"]) == 4
    assert main(["stability", path, "--max-freq-hz", "-1"]) == 2


def test_cli_campbell_window(tmp_path):
    path = str(MODELS / "compressor_tilting_pad.toml")
    assert main(["campbell", path, "--speeds-hz", "50:150:50", "--n-modes", "6",
                 "--max-freq-hz", "400", "--plot", str(tmp_path / "c.png")]) == 0


def test_output_labels_and_units(capsys, tmp_path):
    """Coordinates of a full model are named by station (they were dof8, dof56); CLI tables show
    small lengths in µm with 6 significant digits (0.000069 m before); a mode's figure title
    gives its table number and the index it was asked for."""
    import dataclasses

    s = rd.System.from_toml(MODELS / "compressor_plain.toml")
    full = dataclasses.replace(s, reduction=rd.Reduction(method="none"))
    bc = rd.linearize(full, 100.0).bearing_coefficients()
    assert set(bc["row"]) == {"station1.x", "station1.y", "station5.x", "station5.y"}
    assert len(bc) == 8  # 2 × 2 per bearing; the zeros between the bearings left out
    assert main(["unbalance", str(MODELS / "compressor_linear.toml"), "--unbalance", "3,1e-4,0",
                 "--speeds-hz", "100:200:5", "--station", "3"]) == 0
    out = capsys.readouterr().out
    assert "peak_um" in out and "0.0000" not in out
    st = rd.stability(rd.models.paper_rig(), 50.0, 0.15e6, -1.85e-3)
    assert st.plot(mode=5).get_title().startswith("mode 6 (index 5):")
    r = rd.modes(rd.models.friswell_5_9_1(), 0.0, reduction="none", n_modes=4)
    with pytest.raises(rd.InputError, match="frequency_errors"):
        r.frequency_errors()
