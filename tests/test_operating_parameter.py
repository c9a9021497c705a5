"""An operating variable that acts on nothing in the model is refused, not scanned: on a
compressor without an active journal bearing, a threshold, Hopf point, boundary, branch or
sweep over the chamber pressure p_c (or the active bearing's offset a_y) used to repeat one
point and report e.g. "stable at all 11 scanned points" (found on an overhung pump, not the
paper rig). The CLI's threshold/hopf default to speed there, and ask for its range."""

from pathlib import Path

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.cli import main
from rotordyn.errors import InputError
from rotordyn.results.hopf import HopfResult
from rotordyn.sweep import SweepSpec

MODELS = Path(__file__).parent / "data" / "models"


@pytest.fixture(scope="module")
def plain():
    return rd.System.from_toml(MODELS / "compressor_plain.toml")


@pytest.mark.parametrize("call", [
    lambda s, p: rd.threshold(s, p, bounds=(0.0, 1e-4) if p == "config_ay_m" else (0.0, 5e5)),
    lambda s, p: rd.hopf(s, p, bounds=(0.0, 1e-4) if p == "config_ay_m" else (0.0, 5e5)),
    lambda s, p: rd.continuation(s, p, (0.0, 1e-4) if p == "config_ay_m" else (0.0, 5e5),
                                 start="equilibrium", speed_hz=60.0),
    lambda s, p: rd.stability_boundary(s, p, "speed_hz", values=[60.0, 70.0],
                                       bounds=(0.0, 1e-4)),
], ids=["threshold", "hopf", "equilibrium_branch", "boundary"])
@pytest.mark.parametrize("param", ["chamber_pressure_pa", "config_ay_m"])
def test_no_active_bearing_refuses_the_active_bearings_variables(plain, call, param):
    with pytest.raises(InputError, match=rf"^vary: {param} "):
        call(plain, param)


def test_boundary_along_is_checked_too(plain):
    with pytest.raises(InputError, match=r"^along: config_ay_m "):
        rd.stability_boundary(plain, "speed_hz", "config_ay_m", values=[0.0, 1e-5],
                              bounds=(60.0, 160.0))


def test_the_rig_keeps_both():
    """The paper rig has its active bearing: both variables pass the check (the scan runs:
    n_scan = 2 of a narrow p_c range, no crossing, an honest status)."""
    rig = rd.models.paper_rig()
    t = rd.threshold(rig, "config_ay_m", bounds=(-1.9e-3, -1.8e-3), n_scan=2,
                     chamber_pressure_pa=0.15e6)
    assert t.status in ("ok", "no_crossing")


def _pc_spec(tmp_path, pc: str):
    """A stability sweep of the compressor (no active bearing) with the p_c axis ``pc``."""
    spec = tmp_path / "s.toml"
    spec.write_text(f"""schema = "rotordyn/sweep/1"
name = "pc-on-plain"
model = "{MODELS / 'compressor_plain.toml'}"
analysis = "stability"
[grid]
chamber_pressure_pa = {pc}
speed_hz = 60.0
""")
    return spec


def test_sweep_axis_of_pc_without_an_active_bearing(tmp_path):
    spec = _pc_spec(tmp_path, "[0.0, 1e5]")
    with pytest.raises(InputError, match=r"^grid\.chamber_pressure_pa: acts on an active"):
        SweepSpec.from_toml(spec)


@pytest.mark.parametrize("call", [
    lambda s: rd.equilibrium(s, 60.0, 1e5),
    lambda s: rd.stability(s, 60.0, 1e5),
    lambda s: rd.campbell(s, [50.0, 60.0], chamber_pressure_pa=1e5),
    lambda s: rd.unbalance_response(s, [(3, 1e-4, 0.0)], [60.0], chamber_pressure_pa=1e5),
    lambda s: rd.transient(s, 0.01, 60.0, 1e5),
    lambda s: rd.periodic_orbit(s, 60.0, 1e5, method="harmonic_balance"),
    lambda s: rd.threshold(s, "speed_hz", bounds=(60.0, 160.0), chamber_pressure_pa=1e5),
], ids=["equilibrium", "stability", "campbell", "unbalance", "transient", "orbit",
        "threshold"])
def test_a_fixed_pc_without_an_active_bearing_is_refused(plain, call):
    """A nonzero p_c held fixed on the compressor (no active bearing) acted on nothing while
    the result echoed it ("stable (ok): 60 Hz, p_c = 0.1 MPa"): refused, naming the field
    and the one allowed value; p_c = 0 still runs."""
    with pytest.raises(InputError, match=r"^chamber_pressure_pa: 100000 Pa acts on an active "
                                         r".*\(allowed: 0\)"):
        call(plain)


def test_a_single_nonzero_pc_axis_value_is_refused(tmp_path):
    with pytest.raises(InputError, match=r"^grid\.chamber_pressure_pa: acts on an active"):
        SweepSpec.from_toml(_pc_spec(tmp_path, "1e5"))
    assert SweepSpec.from_toml(_pc_spec(tmp_path, "0.0")) is not None


def test_cli_stability_refuses_pc_without_an_active_bearing(capsys):
    model = str(MODELS / "compressor_plain.toml")
    assert main(["stability", model, "--speed-hz", "60", "--chamber-pressure-pa", "1e5"]) == 2
    assert "chamber_pressure_pa: 100000 Pa acts on an active" in capsys.readouterr().err


def test_cli_threshold_defaults_to_speed_and_asks_for_its_range(capsys):
    model = str(MODELS / "compressor_plain.toml")
    assert main(["threshold", model]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err[-1].startswith("rotordyn: error: --bounds: required with --vary speed_hz")
    assert main(["threshold", model, "--vary", "chamber_pressure_pa"]) == 2
    assert "vary: chamber_pressure_pa acts on an active" in capsys.readouterr().err
    assert main(["threshold", model, "--bounds", "60", "160", "--n-scan", "5", "--json"]) == 0
    out = capsys.readouterr().out
    assert '"speed_hz"' in out and '"status"' in out


def test_degenerate_hopf_repr_does_not_claim_a_stability():
    """A degenerate Hopf point (|l1| < 3 l1_error) used to print 'cycles above (unstable)'
    whenever l1 < 0 was not resolved."""
    r = HopfResult(vary="speed_hz", fixed={}, fd_step=0.05, bearing_names=("a",),
                   clearance_m=np.array([1e-4]),
                   value=165.0, whirl_frequency_hz=78.0, l1=-0.1, l1_error=0.1,
                   type="degenerate", alpha_prime=0.6, stable_side="below",
                   cycle_side="above")
    text = repr(r)
    assert "not resolved" in text and "(unstable)" not in text and "(stable)" not in text
