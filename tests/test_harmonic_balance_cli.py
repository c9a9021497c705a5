"""``rotordyn periodic-orbit --method harmonic_balance`` (python/rotordyn/cli/nonlinear.py)
against ``rd.periodic_orbit(..., method="harmonic_balance")`` with the same inputs, and the
validation of the HB flags (docs/nonlinear.md "Harmonic balance (AFT)").

The model: the compressor on plain bearings (tests/data/models/compressor_plain.toml) on a
36 × 6 film grid, so that each orbit takes about a second.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

import rotordyn as rd
from rotordyn.cli import main

MODELS = Path(__file__).parent / "data" / "models"

HB = "harmonic_balance"


@pytest.fixture(scope="module")
def coarse_compressor(tmp_path_factory):
    """The plain-bearing compressor with n_circ = 36, n_axial = 6 on both bearings (TOML)."""
    text = (MODELS / "compressor_plain.toml").read_text()
    text = re.sub(r"^(viscosity_pa_s = .*)$", r"\1\nn_circ = 36\nn_axial = 6", text,
                  flags=re.M)
    path = tmp_path_factory.mktemp("hbcli") / "compressor_plain_36x6.toml"
    path.write_text(text)
    s = rd.models.load(str(path))
    assert [(b.n_circ, b.n_axial) for b in s.bearings] == [(36, 6), (36, 6)]
    return str(path), s


def _json_run(capsys, argv):
    rc = main(argv + ["--json"])
    return rc, json.loads(capsys.readouterr().out)


def test_cli_forced_orbit_equals_api(coarse_compressor, capsys):
    """A forced orbit (100 Hz, 2e-2 kg·m at the middle impeller: 63 µm, second harmonic 10 %
    of the first, so nonlinear) with H = 6, M = 20: period and amplitude equal the API's to
    1e-12 relative; the JSON names the method and its settings, a shooting run names its."""
    path, s = coarse_compressor
    api = rd.periodic_orbit(s, 100.0, kind="forced", unbalances=[(3, 2e-2, 30.0)], method=HB,
                            harmonics=6, time_points=20)
    assert api.ok, api.message
    rc, out = _json_run(capsys, ["periodic-orbit", path, "--kind", "forced", "--speed-hz",
                                 "100", "--unbalance", "3,2e-2,30", "--method", HB,
                                 "--harmonics", "6", "--samples", "20"])
    assert rc == 0 and out["status"] == "ok"
    assert (out["method"], out["harmonics"], out["time_points"], out["floquet"]) == (
        HB, 6, 20, "samples")
    assert "start_amplitude_c" not in out  # not used by a forced orbit
    assert out["period_s"] == pytest.approx(api.period_s, rel=1e-12, abs=0)
    assert out["amplitude_m"] == pytest.approx(api.amplitude(), rel=1e-12, abs=0)
    assert out["multipliers_real"] == pytest.approx(api.multipliers.real, rel=1e-10,
                                                    abs=1e-12)
    rc, out = _json_run(capsys, ["periodic-orbit", path, "--kind", "forced", "--speed-hz",
                                 "100", "--unbalance", "3,2e-3,30"])
    assert rc == 0 and out["method"] == "shooting" and "harmonics" not in out


def test_cli_limit_cycle_from_the_equilibrium_equals_api(coarse_compressor, capsys):
    """The self-excited cycle at 150 Hz (96 µm whirl at 74.6 Hz) by HB from the equilibrium
    plus its least-damped mode (no settling transient: the HB default) at 0.5 c, H = 8:
    the CLI's period and amplitude equal the API's to 1e-12 and so do its Newton iterations
    (12; 25 from the default 0.3 c: the flag reaches the solver); the text output names the
    method with H, M, the Floquet method and the start amplitude."""
    path, s = coarse_compressor
    api = rd.periodic_orbit(s, 150.0, method=HB, start_amplitude_c=0.5)
    assert api.ok, api.message
    rc, out = _json_run(capsys, ["periodic-orbit", path, "--speed-hz", "150", "--method", HB,
                                 "--start-amplitude-c", "0.5"])
    assert rc == 0 and out["status"] == "ok" and out["kind"] == "autonomous"
    assert out["start_amplitude_c"] == 0.5 and out["time_points"] == 32
    assert out["period_s"] == pytest.approx(api.period_s, rel=1e-12, abs=0)
    assert out["amplitude_m"] == pytest.approx(api.amplitude(), rel=1e-12, abs=0)
    assert out["stats"]["iterations"] == api.stats["iterations"]
    assert main(["periodic-orbit", path, "--speed-hz", "150", "--method", HB,
                 "--start-amplitude-c", "0.5", "--floquet", "none"]) == 0
    text = capsys.readouterr().out
    assert ("method: harmonic_balance (harmonics = 8, time_points = 32, floquet = none, "
            "start_amplitude_c = 0.5)") in text


@pytest.mark.parametrize("flags, named, allowed", [
    (["--harmonics", "4"], "--harmonics", "--method harmonic_balance"),
    # shooting takes --floquet flow, samples or none since 2026-12-06
    (["--floquet", "hill"], "--floquet", "--method shooting expected one of flow, samples"),
    (["--method", HB, "--harmonics", "0"], "--harmonics", "1..1000"),
    (["--method", HB, "--harmonics", "4", "--samples", "8"], "--samples", "9"),
    (["--method", HB, "--samples", "200000"], "--samples", "100000"),
    (["--method", HB, "--start-amplitude-c", "1.5"], "--start-amplitude-c", "0.99"),
    (["--method", HB, "--kind", "forced", "--unbalance", "3,1e-3,0",
      "--start-amplitude-c", "0.2"], "--start-amplitude-c", "--kind autonomous"),
    (["--method", HB, "--floquet", "magnus"], "--floquet", "samples"),
    (["--method", "hill"], "--method", "harmonic_balance"),
])
def test_cli_bad_hb_flags_exit_2_naming_the_flag(flags, named, allowed, capsys):
    """Every bad HB flag exits 2 before any solve, naming the flag and what is allowed (an HB
    flag with --method shooting included; argparse's choices through the same InputError)."""
    model = str(MODELS / "compressor_plain.toml")
    assert main(["periodic-orbit", model] + flags) == 2
    err = capsys.readouterr().err
    assert named in err and allowed in err, err


def test_cli_help_lists_the_method(capsys):
    """``periodic-orbit --help`` lists --method with both methods and every HB flag with its
    default."""
    with pytest.raises(SystemExit) as e:
        main(["periodic-orbit", "--help"])
    assert e.value.code == 0
    text = " ".join(capsys.readouterr().out.split())
    assert "--method {shooting,harmonic_balance}" in text
    for flag in ("--harmonics H", "--samples M", "--floquet {samples,hill,flow,none}",
                 "--start-amplitude-c F"):
        assert flag in text
    assert "(default 8)" in text and "(default 4H)" in text and "(default: 0.3, then 0.6, then 0.9" in text


def test_cli_failed_hb_start_says_what_to_try(coarse_compressor, capsys):
    """An HB limit cycle from the equilibrium that does not converge (130 Hz: the 0.9 c whip
    far from a 0.05 c start, H = 2): exit 1 with the result, and a line naming --settle-s and
    --start-amplitude-c; a settled start or a forced orbit gets no such line (their start is
    not the equilibrium's mode)."""
    path, _ = coarse_compressor
    from rotordyn.cli import nonlinear
    args = type("A", (), {"method": HB, "kind": "autonomous"})()
    assert "--settle-s 1" in nonlinear._start_hint(args, None)
    assert nonlinear._start_hint(args, object()) == ""  # a settled start: nothing to add
    args.kind = "forced"
    assert nonlinear._start_hint(args, None) == ""
    rc = main(["periodic-orbit", path, "--speed-hz", "130", "--method", HB,
               "--start-amplitude-c", "0.05", "--harmonics", "2"])
    out = capsys.readouterr().out
    assert rc == 1 and "not_converged" in out
    assert "--settle-s 1" in out and "--start-amplitude-c" in out
