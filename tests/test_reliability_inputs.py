"""Bad input is an InputError naming the field (API) or exit code 2 with one line naming it
(CLI), before any solve and without a traceback (issue 13). Each case is a call of the issue
text; resource limits (memory estimated before allocating) are checked here too."""

import re
from importlib import resources

import numpy as np
import pytest

import rotordyn as rd
from rotordyn.cli import main as cli_main

BASE = resources.files("rotordyn.model.data").joinpath("paper_rig.toml").read_text()


@pytest.fixture(scope="module")
def rig():
    return rd.models.paper_rig()


def _sub(pattern, repl):
    out, n = re.subn(pattern, repl, BASE, count=1, flags=re.M)
    assert n == 1, pattern
    return out


# -- API ------------------------------------------------------------------------------------
API_CASES = [
    ("threshold bounds text", lambda s: rd.threshold(s, bounds="ab"), "bounds"),
    ("threshold bounds None", lambda s: rd.threshold(s, bounds=None), "bounds"),
    ("threshold bounds length", lambda s: rd.threshold(s, bounds=(1, 2, 3)), "bounds"),
    ("threshold n_scan 2**31", lambda s: rd.threshold(s, bounds=(0, 1e5), n_scan=2**31),
     "n_scan"),
    # issue 13: returned no_crossing
    ("threshold negative fixed p_c",
     lambda s: rd.threshold(s, vary="speed_hz", bounds=(10, 50), chamber_pressure_pa=-1e5),
     "chamber_pressure_pa"),
    ("disturbance None", lambda s: rd.transient(s, 0.01, disturbance_m=None), "disturbance_m"),
    ("disturbance text", lambda s: rd.transient(s, 0.01, disturbance_m="ab"), "disturbance_m"),
    ("disturbance length", lambda s: rd.transient(s, 0.01, disturbance_m=(1, 2, 3)),
     "disturbance_m"),
    ("transient unbalances [1]", lambda s: rd.transient(s, 0.01, unbalances=[1]),
     "unbalances"),
    ("transient unbalances None", lambda s: rd.transient(s, 0.01, unbalances=None),
     "unbalances"),
    ("transient r0 text", lambda s: rd.transient(s, 0.01, r0="abc"), "r0"),
    ("unbalance [1]", lambda s: rd.unbalance_response(s, [1], [10, 20]), "unbalances"),
    ("unbalance None", lambda s: rd.unbalance_response(s, None, [10, 20]), "unbalances"),
    ("unbalance station 2**31", lambda s: rd.unbalance_response(s, [(2**31, 1e-5, 0)],
                                                                [10, 20]), "station"),
    ("r0 text", lambda s: rd.equilibrium(s, 50, r0="abc"), "r0"),
    ("r0 length", lambda s: rd.equilibrium(s, 50, r0=[1, 2]), "r0"),
    ("speed text", lambda s: rd.equilibrium(s, "50"), "speed_hz"),
    ("speed None", lambda s: rd.equilibrium(s, None), "speed_hz"),
    ("speed 10**400", lambda s: rd.equilibrium(s, 10**400), "speed_hz"),
    ("max_iter 2**31", lambda s: rd.equilibrium(s, 50, max_iter=2**31), "max_iter"),
    # issue 13: marked every point "error" with exit 0
    ("campbell config_ay_m nan", lambda s: rd.campbell(s, [10, 20], config_ay_m=float("nan")),
     "config_ay_m"),
    ("campbell speeds text", lambda s: rd.campbell(s, "abc"), "speeds_hz"),
    ("campbell speeds None", lambda s: rd.campbell(s, None), "speeds_hz"),
    ("stability n_modes 2**31", lambda s: rd.stability(s, 50, n_modes=2**31), "n_modes"),
    ("stability n_modes 0", lambda s: rd.stability(s, 50, n_modes=0), "n_modes"),
    ("stability n_modes text", lambda s: rd.stability(s, 50, n_modes="x"), "n_modes"),
    ("modes n_modes 2**31", lambda s: rd.modes(s, n_modes=2**31, without_bearings=True), "n_modes"),
    ("statespace inputs None", lambda s: rd.statespace(s, inputs=None), "inputs"),
    ("boundary values text", lambda s: rd.stability_boundary(s, values="ab", bounds=(0, 1e5)),
     "values"),
    ("boundary bounds None", lambda s: rd.stability_boundary(s, values=[0.0], bounds=None),
     "bounds"),
    # resources: estimated before allocating (issue 13)
    ("transient n_out 10**7", lambda s: rd.transient(s, 0.01, n_out=10**7), "n_out"),
]


def test_meaningless_mode_counts_are_capped(rig):
    """Issue 13: ``rotor_campbell(n_modes=10**6)`` returned a 10^6-column NaN array; more
    modes than coordinates are capped at the model's size (6 for the Guyan-reduced rig)."""
    c = rd.rotor_campbell(rig, [0, 10], n_modes=10**6, without_bearings=True)
    assert c.eigenvalues.shape == (2, 6) and np.all(np.isfinite(c.eigenvalues))
    st = rd.stability(rig, 50.0, 0.15e6, -1.85e-3, n_modes=10**6)
    assert len(st.eigenvalues) <= 9


@pytest.mark.parametrize(("call", "field"), [c[1:] for c in API_CASES],
                         ids=[c[0] for c in API_CASES])
def test_api_bad_input_is_an_input_error_naming_the_field(rig, call, field):
    with pytest.raises(rd.InputError, match=re.escape(field)):
        call(rig)


def test_nan_in_r0_names_the_problem(rig):
    """Issue 13: the message read "expected shape (9, 1), got (9, 1)"."""
    with pytest.raises(rd.InputError) as exc:
        rd.equilibrium(rig, 50, r0=[np.nan] * 9)
    assert "finite" in str(exc.value) and "shape" not in str(exc.value)
    # the C++ core's own message (reached when Python validation is bypassed)
    asm = rd.analysis.assembly.assembled(rig)
    with pytest.raises(rd.InputError, match="r0: expected finite values"):
        asm.solver.equilibrium(1.0, 0.0, np.zeros(asm.n), np.full(asm.n, np.nan),
                               rd._core.EquilibriumOptions())


def test_bearing_batches_name_the_field():
    b = rd.JournalBearing(diameter_m=0.05, length_m=0.04, clearance_m=3e-4,
                          viscosity_pa_s=0.04, n_circ=24, n_axial=4)
    with pytest.raises(rd.InputError, match="x_m"):
        b.forces_batch(x_m="a", y_m=[0], speed_hz=50)
    with pytest.raises(rd.InputError, match="x_m"):
        b.forces_batch(x_m=[0, 1e-5, 2e-5], y_m=[0, 0], speed_hz=50)
    with pytest.raises(rd.InputError, match="n_threads"):
        b.forces_batch(x_m=[0], y_m=[0], speed_hz=50, n_threads=2**31)


def test_too_many_elements_refused_with_an_estimate():
    """Issue 13: ``n_elements = 10000`` ended in std::bad_alloc (dense 40004² matrices)."""
    s = rd.System.from_toml(_sub(r"^n_elements = \d+", "n_elements = 10000"), is_text=True)
    with pytest.raises(rd.InputError, match=r"rotor.n_elements.*GiB"):
        rd.modes(s, without_bearings=True)


# -- model (Python and TOML) ----------------------------------------------------------------
TOML_CASES = [
    ("grooves = 5", _sub(r"^grooves = .*$", "grooves = 5"), "grooves"),
    ("material = 5", _sub(r"^\[material\.steel\]", "material = 5\n[rotor.x]"), "material"),
    ("description = [1]", _sub(r"^description = .*$", "description = [1]"), "description"),
    ("name = 5", _sub(r"^name = \"paper-rig\"$", "name = 5"), "name"),
    ("reduction.master_stations = 5", _sub(r"^master_stations = \[2, 4, 6\]",
                                           "master_stations = 5"), "master_stations"),
    ("sleeve.master_stations = 5", _sub(r"^master_stations = \[7, 14, 20\]",
                                        "master_stations = 5"), "sleeve.master_stations"),
    # issue 13: not checked
    ("sleeve inside the journal", _sub(r"^radius_m = 0.0278.*$", "radius_m = 0.02"),
     "sleeve.radius_m"),
    ("two rigid supports at a station", BASE + "\n[[support]]\nstation = 1\n", "support[2]"),
    ("rigid + linear at a station",
     BASE + '\n[[support]]\nstation = 7\ntype = "linear"\nkxx_n_per_m = 1e6\n', "support[2]"),
]


@pytest.mark.parametrize(("text", "field"), [c[1:] for c in TOML_CASES],
                         ids=[c[0] for c in TOML_CASES])
def test_toml_bad_value_names_the_field(text, field):
    with pytest.raises(rd.InputError, match=re.escape(field)):
        rd.System.from_toml(text, is_text=True)


def test_two_linear_supports_at_one_station_add_up():
    text = BASE.replace("[[support]]", '[[support]]\nstation = 3\ntype = "linear"\n'
                        'kxx_n_per_m = 1e6\n\n[[support]]\nstation = 3\ntype = "linear"\n'
                        'kyy_n_per_m = 1e6\n\n[[support]]', 1)
    s = rd.System.from_toml(text, is_text=True)
    assert sum(sp.station == 3 for sp in s.supports) == 2


# -- CLI -------------------------------------------------------------------------------------
def _cli(capsys, *argv):
    code = cli_main(list(argv))
    err = capsys.readouterr().err.strip()
    return code, err


@pytest.fixture()
def files(tmp_path):
    out = {}
    for name, text in [("grooves", TOML_CASES[0][1]), ("material", TOML_CASES[1][1]),
                       ("description", TOML_CASES[2][1])]:
        out[name] = tmp_path / f"{name}.toml"
        out[name].write_text(text)
    out["latin1"] = tmp_path / "latin1.toml"
    out["latin1"].write_bytes(BASE.encode().replace(b'name = "paper-rig"',
                                                    'name = "Prüfstand"'.encode("latin-1")))
    out["invalid"] = tmp_path / "invalid.toml"
    out["invalid"].write_text("[sleeve\nradius_m = 1\n")
    out["tmp"] = tmp_path
    return out


@pytest.mark.parametrize(("argv", "field"), [
    (("validate", "{grooves}"), "grooves"),
    (("validate", "{material}"), "material"),
    (("validate", "{description}"), "description"),
    (("validate", "{latin1}"), "UTF-8"),
    (("modes", "{invalid}", "--part", "sleeve"), "not valid TOML"),
    (("modes", "{latin1}", "--part", "sleeve"), "UTF-8"),
    (("campbell", "friswell-5.9.1", "--speeds-hz", "5:1e9:1e-9"), "--speeds-hz"),
    (("campbell", "friswell-5.9.1", "--speeds-hz", "5:10:5", "--plot", "{tmp}/no/dir/c.png"),
     "--plot"),
    (("campbell", "friswell-5.9.1", "--speeds-hz", "5:10:5", "--plot", "{tmp}/c.xyz"),
     "--plot"),
    (("plot", "{tmp}", "--kind", "campbell", "--out", "{tmp}/no/dir/c.png"), "--out"),
    (("plot", "{tmp}", "--kind", "campbell", "--out", "{tmp}/c.xyz"), "--out"),
    (("report", "paper-rig", "--out", "{grooves}"), "--out"),
])
def test_cli_bad_input_exits_2_with_one_line(capsys, files, argv, field):
    argv = [a.format(**{k: str(v) for k, v in files.items()}) for a in argv]
    code, err = _cli(capsys, *argv)
    assert code == 2, err
    assert len(err.splitlines()) == 1 and field in err and "Traceback" not in err


def test_speeds_beyond_any_rotor_are_refused(capsys):
    """Found by `make fuzz` (20x budget) after the merge: `campbell --speeds-hz 1e308` overflowed
    ω to inf (LAPACK DGEBAL complained, exit 0 with garbage) and a transient at 2^63 Hz
    returned NaN states. Speeds are |f| <= 1e5 Hz everywhere, as in the film solver."""
    code, err = _cli(capsys, "campbell", "friswell-5.9.1", "--speeds-hz", "1e308")
    assert code == 2 and "speeds_hz" in err and "1e+308" in err and "\n" not in err
    rig = rd.models.paper_rig()
    with pytest.raises(rd.InputError, match=r"speed_hz: expected a speed in \[-100000, 100000\]"):
        rd.transient(rig, 0.01, 9223372036854775808, 0.15e6, -1.85e-3, n_out=2)
    for call in (lambda: rd.equilibrium(rig, 2e5, 0.15e6, -1.85e-3),
                 lambda: rd.modes(rig, speed_hz=-1e6, without_bearings=True),
                 lambda: rd.campbell(rig, [10.0, 1e6])):
        with pytest.raises(rd.InputError, match="speed"):
            call()


def test_bearing_table_speed_range_is_counted_before_allocating(capsys):
    """The coefficient-table CLI had its own START:STOP:STEP parser without the count check
    (issue 13's campbell 5:1e9:1e-9 MemoryError, again): one parser for every --speeds-hz."""
    code, err = _cli(capsys, "bearing", "--diameter-m", "0.05", "--length-m", "0.025",
                     "--clearance-m", "1e-4", "--viscosity-pa-s", "0.03", "--load-n", "0", "-500",
                     "--speeds-hz", "5:1e9:1e-9")
    assert code == 2 and "--speeds-hz: expected at most" in err and "\n" not in err
