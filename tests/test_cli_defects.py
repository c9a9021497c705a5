"""Defects found by a new user (issue 10), each guarded: a model written by ``to_toml`` is
accepted by every command; comparison marks come from stated tolerances; negative numbers in
scientific notation are values; every CLI error is one line with exit code 2; ``--json`` is
strict JSON; the sweep's refusal names the CLI flag; every option has help; unit slips warn."""

import json
import subprocess
import sys
import warnings

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.cli import build_parser
from rotordyn.errors import UnitWarning
from cli_output import error_lines


def run(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "rotordyn.cli", *args], capture_output=True,
                          text=True, cwd=cwd)


def _strict(text):
    """json.loads that refuses NaN/Infinity (RFC 8259)."""
    def bad(c):
        raise ValueError(f"non-standard JSON constant {c}")
    return json.loads(text, parse_constant=bad)


@pytest.fixture(scope="module")
def readme_rotor(tmp_path_factory):
    """The README's own rotor (no reduction given) written with to_toml."""
    steel = rd.Material("steel", density_kg_m3=7810.0, young_pa=211e9, shear_modulus_pa=81.2e9)
    shaft = tuple(rd.ShaftSection(length_m=0.25, outer_diameter_m=0.05) for _ in range(6))
    disks = (rd.Disk.from_geometry(2, steel, width_m=0.07, outer_diameter_m=0.28,
                                   inner_diameter_m=0.05),)
    sup = tuple(rd.Support(s, "linear", kxx_n_per_m=1e6, kyy_n_per_m=1e6) for s in (0, 6))
    s = rd.System(rotor=rd.Rotor(shaft, disks), materials=(steel,), supports=sup)
    path = tmp_path_factory.mktemp("model") / "my_rotor.toml"
    s.to_toml(path)
    return s, path


def test_written_model_round_trips_and_every_command_accepts_it(readme_rotor, tmp_path):
    s, path = readme_rotor
    assert 'method = "none"' in path.read_text()
    back = rd.System.from_toml(path)
    assert back == s
    assert len(rd.modes(back, without_bearings=True).eigenvalues) > 0
    assert run("modes", str(path), "--speed-hz", "66.7").returncode == 0
    assert run("validate", str(path)).returncode == 0
    p = run("report", str(path), "--out", str(tmp_path / "rep"))
    assert p.returncode == 0, p.stderr


def test_reduction_without_masters_is_refused_naming_the_field():
    with pytest.raises(rd.InputError, match="reduction.master_stations"):
        rd.Reduction(method="guyan")
    assert rd.Reduction().method == "none" and rd.Reduction((1, 2)).method == "guyan"


def test_comparison_marks_come_from_a_stated_tolerance():
    from rotordyn.report import mark

    assert mark(0.057e6, 0.098e6, rtol=0.10) == "OFF by 42 % (tolerance 10 %)"
    assert mark(10.427, 10.43, rtol=0.01) == "ok (±1 %)"
    assert mark(0.0077, 0.0, atol=0.01) == "ok (±0.01)"
    assert mark(np.nan, 1.0, rtol=0.1) == "n/a"


def test_negative_scientific_numbers_are_values():
    p = run("bearing", "--diameter-m", "0.05", "--length-m", "0.04", "--clearance-m", "3e-4",
            "--viscosity-pa-s", "0.04", "--speed-hz", "50", "--load-n", "0", "-5e2", "--json")
    assert p.returncode == 0, p.stderr
    assert _strict(p.stdout)["equilibrium"]["load_n"] == [0.0, -500.0]
    assert _strict(p.stdout)["friction_torque_n_m"] > 0  # N·m spelt _n_m (issue 18)
    a = build_parser().parse_args(["threshold", "paper-rig", "--bounds", "-2E-3", "-1.5e-3",
                                   "--config-ay-m", "-.5e-3"])
    assert a.bounds == [-2e-3, -1.5e-3] and a.config_ay_m == -0.5e-3


SPEC = """schema = "rotordyn/sweep/1"
name = "{name}"
model = "paper-rig"
analysis = "stability"
chunk_size = 4
[grid]
speed_hz = {speeds}
chamber_pressure_pa = 0.4e6
config_ay_m = 0.0
"""


def _sweep(tmp, name, speeds):
    """A small stability sweep over ``speeds`` (threads in this process, no dask)."""
    from rotordyn.sweep import run_sweep

    spec = tmp / f"{name}.toml"
    spec.write_text(SPEC.format(name=name, speeds=speeds))
    run_sweep(spec, tmp / name, threads=1)
    return spec, tmp / name


@pytest.fixture(scope="module")
def datasets(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("sweeps")
    return {"two": _sweep(tmp, "two", "[20.0, 40.0]"), "one": _sweep(tmp, "one", "50.0")}


@pytest.mark.parametrize(("which", "kind", "needle"), [
    ("two", "waterfall", "waterfall: the dataset has no spectra"),
    ("one", "campbell", "campbell: needs a sweep over 2 or more speeds"),
    ("one", "stability-map", "stability-map: expected exactly two varying axes"),
    ("two", "equilibrium", "equilibrium: the dataset has no journal positions"),
])
def test_plot_kind_mismatch_is_one_line_exit_2(datasets, tmp_path, which, kind, needle):
    p = run("plot", str(datasets[which][1]), "--kind", kind, "--out", str(tmp_path / "f.png"))
    assert p.returncode == 2
    assert len(error_lines(p.stderr)) == 1 and needle in p.stderr, p.stderr
    assert "Traceback" not in p.stderr


def test_plot_campbell_from_a_speed_sweep(datasets, tmp_path):
    p = run("plot", str(datasets["two"][1]), "--kind", "campbell", "--out",
            str(tmp_path / "c.png"))
    assert p.returncode == 0, p.stderr
    assert (tmp_path / "c.png").stat().st_size > 5000


def test_json_has_null_not_nan():
    from rotordyn.cli.common import json_text

    out = json_text({"a": np.nan, "b": [1.0, np.inf], "c": np.array([np.nan, 2.0])})
    assert _strict(out) == {"a": None, "b": [1.0, None], "c": [None, 2.0]}


def test_sweep_refusal_names_the_cli_flag(datasets, tmp_path):
    from rotordyn.sweep import run_sweep

    spec, out = datasets["two"]
    other = tmp_path / "other.toml"
    other.write_text(spec.read_text().replace("chunk_size = 4", "chunk_size = 3"))
    with pytest.raises(rd.InputError, match="--no-resume") as exc:
        run_sweep(other, out, threads=1)
    assert "resume=False" not in str(exc.value)


def _options(parser):
    import argparse

    for a in parser._actions:
        if isinstance(a, argparse._SubParsersAction):
            for name, sub in a.choices.items():
                yield from ((f"{name} {o}", h, d) for o, h, d in _options(sub))
        elif a.option_strings and a.dest != "help":
            yield a.option_strings[0], a.help, a.default


def test_every_cli_option_has_help_and_states_its_default():
    p = build_parser()
    opts = list(_options(p))
    assert len(opts) > 40
    missing = [o for o, h, _ in opts if not h]
    assert not missing, missing
    text = run("unbalance", "--help").stdout
    # --speeds-hz: its default depends on --operating-speed-hz (API 684), stated in its help
    assert "else 5:120:1)" in text and "(default: 0.0)" in text


def test_unit_slips_warn_naming_the_field():
    with pytest.warns(UnitWarning, match=r"material.soft.young_pa = 211 Pa .* GPa"):
        rd.Material("soft", density_kg_m3=7850.0, young_pa=211.0)
    with pytest.warns(UnitWarning, match=r"density_kg_m3 = 7.85 .* g/cm³"):
        rd.Material("s", density_kg_m3=7.85, young_pa=2.1e11)
    with pytest.warns(UnitWarning, match=r"rotor.section\[0\].outer_diameter_m = 50 m"):
        s = rd.ShaftSection(length_m=0.25, outer_diameter_m=50.0)
        s.check("rotor.section[0]")
    rig = rd.models.paper_rig()
    import dataclasses

    b = dataclasses.replace(rig.bearings[0], config_ay_m=-1.85)
    with pytest.warns(UnitWarning, match=r"bearing\[0\].config_ay_m = -1.85 m .* millimetres"):
        dataclasses.replace(rig, bearings=(b,) + rig.bearings[1:])
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the shipped models are plausible
        rd.models.paper_rig(), rd.models.load("friswell-5.9.1")


def test_cli_unit_slip_warnings_are_one_line_naming_the_flag():
    p = run("bearing", "--diameter-m", "50", "--length-m", "0.04", "--clearance-m", "3e-4",
            "--viscosity-pa-s", "0.04", "--speed-hz", "50", "--x-m", "0", "--y-m", "-1e-4")
    assert p.returncode == 0, p.stderr
    assert "rotordyn: warning: --diameter-m = 50 m" in p.stderr and "millimetres" in p.stderr
    p = run("stability", "paper-rig", "--config-ay-m", "-1.85", "--speed-hz", "50",
            "--chamber-pressure-pa", "0")
    assert "rotordyn: warning: --config-ay-m = -1.85 m is 6167 times" in p.stderr


def test_reprs_are_short_and_informative():
    rig = rd.models.paper_rig()
    res = [rd.modes(rig, 0.0, reduction="guyan", without_bearings=True),
           rd.equilibrium(rig, 50.0, 0.15e6, -1.85e-3),
           rd.stability(rig, 50.0, 0.15e6, -1.85e-3),
           rd.statespace(rig, inputs=["chamber_pressure"], outputs=[("journal", 0)],
                         speed_hz=50.0, chamber_pressure_pa=0.15e6, config_ay_m=-1.85e-3),
           rd.campbell(rig, [30.0, 40.0], 0.4e6, 0.0),
           rd.unbalance_response(rig, [(4, 1e-4, 0.0)], [30.0, 40.0], chamber_pressure_pa=4e5),
           rd.rotor_campbell(rig, [0.0, 10.0], n_modes=4, without_bearings=True)]
    res.append(res[2].linear)
    for r in res:
        text = repr(r)
        assert "\n" not in text and len(text) < 400, text
        assert text.startswith(f"<{type(r).__name__}")
    assert "Hz" in repr(res[0]) and "states" in repr(res[3])


def test_one_whirl_rule_planar_at_rest():
    """At 0 Hz the paper rig's isotropic supports give degenerate, near-planar pairs (whirl
    index |(|F|²−|B|²)/(|F|²+|B|²)| ≤ 0.03): the full and the reduced model, the figure
    legend and the JSON all say planar (tolerance WHIRL_PLANAR_TOL = 0.05)."""
    from rotordyn.results.modes import WHIRL_PLANAR_TOL, whirl_index, whirl_label

    r = rd.modes(rd.models.paper_rig(), 0.0, reduction="guyan", without_bearings=True)
    assert set(r.whirl) == {"planar"} and set(r.full.whirl) == {"planar"}
    idx = whirl_index(r.full.shapes[:, 0, :], r.full.shapes[:, 1, :], axis=0)
    assert list(whirl_label(idx)) == list(r.full.whirl)
    assert WHIRL_PLANAR_TOL == 0.05
    assert list(whirl_label([0.049, -0.049, 0.051, -0.051])) == \
        ["planar", "planar", "forward", "backward"]
    p = run("modes", "paper-rig", "--json", "--without-bearings")
    assert set(_strict(p.stdout)["whirl"]) == {"planar"}


def test_campbell_without_crossings_says_so(capsys):
    """The three-bearing train has no 1× crossing of a forward mode over 20–30 Hz: the text
    output said pandas' "(no rows)"; it names what was looked for and where."""
    from pathlib import Path

    from rotordyn.cli import main

    model = str(Path(__file__).parent / "data" / "models" / "motor_fan_train.toml")
    assert main(["campbell", model, "--speeds-hz", "20:30:10", "--n-modes", "4"]) == 0
    out = capsys.readouterr().out
    assert "no 1× crossing of a forward mode between 20 and 30 Hz" in out
    assert "(no rows)" not in out
