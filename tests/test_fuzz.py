"""Property-based fuzzing (issue 13) of the bearing, the system analyses, the TOML loader and
the CLI, and of the bearing elements (rotordyn.bearings), as a careless or hostile user
would call them.

Property: every call ends in a rotordyn exception whose message starts with the field it
names (CLI: exit code 2 and one such line), or in a result that is finite and whose status is
truthful (only converged equilibria are linearised, classified or integrated from; ``stable``
agrees with the eigenvalues; "contact" iff a converged film is thin). Never another exception
(a traceback), a hang (per-case timeout) or a crash: each case runs in a worker process
(tests/fuzz_cases.py), so a segfault or a hang fails the case, not the run.

Budget: derandomized (a fixed seed: CI is reproducible), ``max_examples`` per test scaled by
ROTORDYN_FUZZ_SCALE (1 in ``make test``: 540 cases, ~60 s on 2 cores; ``make fuzz`` runs 20x
with a random seed and prints the failing example's reproduction blob).

The film items of issue 13 (non-finite forces at extreme velocities/speeds/groove
pressures, degenerate finite-difference steps, tiny loads, meaningless rtol) are fixed in the
film core and fuzzed here without restriction.
"""

from __future__ import annotations

import math
import os

import pytest
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

from fuzz_cases import Worker

SCALE = float(os.environ.get("ROTORDYN_FUZZ_SCALE", "1"))
EXPLORE = os.environ.get("ROTORDYN_FUZZ_EXPLORE") == "1"  # make fuzz: random seed


def budget(n: int):
    return settings(max_examples=max(1, int(n * SCALE)), deadline=None,
                    derandomize=not EXPLORE, database=None, print_blob=EXPLORE,
                    suppress_health_check=[HealthCheck.too_slow,
                                           HealthCheck.function_scoped_fixture,
                                           HealthCheck.data_too_large])


@pytest.fixture(scope="module")
def worker():
    w = Worker()
    yield w
    w.close()


def check(worker, kind, payload):
    r = worker.run(kind, payload)
    event(f"{r['outcome']}: {r['detail'][:int(os.environ.get('ROTORDYN_FUZZ_EVENT_CHARS', '40'))]}")
    shown = repr(payload)
    shown = shown if len(shown) < 600 else shown[:300] + " ... " + shown[-300:]
    assert r["outcome"] in ("result", "rotordyn"), (r["outcome"], shown, r["violations"])
    assert not r["violations"], (shown, r["violations"], r["detail"])
    return r


# -- value strategies -----------------------------------------------------------------------
SPECIAL = st.sampled_from([0, 0.0, -0.0, -1.0, 1e-300, -1e-300, 1e300, -1e300, math.nan,
                           math.inf, -math.inf, 2**31, 2**63, 10**400, True, None, "50",
                           "", [1.0], (), {"a": 1}])


def number(lo, hi, *, special=True):
    base = st.floats(lo, hi, allow_nan=False)
    return st.one_of(base, base, base, SPECIAL) if special else base


def integer(lo, hi):
    return st.one_of(st.integers(lo, hi), st.integers(lo, hi), SPECIAL)


# -- bearing --------------------------------------------------------------------------------
GEOMETRY = st.fixed_dictionaries({
    "diameter_m": number(1e-3, 1.0, special=False),
    "length_m": number(1e-3, 1.0, special=False),
    "clearance_m": number(1e-6, 1e-3, special=False),
    "viscosity_pa_s": number(1e-4, 1.0, special=False),
    "n_circ": st.integers(12, 96),
    "n_axial": st.integers(2, 16),
    "cavitation": st.sampled_from(["gumbel", "reynolds", "jfo"]),
})


@st.composite
def hostile(draw, values: dict, share: int = 4) -> dict:
    """``values`` with, in one case out of ``share``, one entry replaced by a special value
    (NaN, inf, 1e300, 2**63, text, None, a list, ...)."""
    out = dict(values)
    if out and draw(st.integers(0, share - 1)) == 0:
        key = draw(st.sampled_from(sorted(out)))
        out[key] = draw(st.one_of(SPECIAL, st.sampled_from(["Reynolds", 5, -72, 2**31])))
    return out


@st.composite
def bearing_payload(draw):
    geom = draw(hostile(draw(GEOMETRY), share=5))
    c = geom["clearance_m"] if isinstance(geom["clearance_m"], float) and \
        geom["clearance_m"] > 0 else 3e-4
    if isinstance(geom["diameter_m"], float) and geom["diameter_m"] > 0:
        c = min(c, 0.05 * geom["diameter_m"])
        if isinstance(geom["clearance_m"], float):
            geom["clearance_m"] = c
    if geom["cavitation"] == "jfo":
        import rotordyn as rd

        geom["grooves"] = [rd.Groove(center_deg=draw(st.floats(-720, 720)),
                                     width_deg=draw(st.floats(0, 60)),
                                     pressure_pa=draw(st.floats(0, 1e9)))]
    call = draw(st.sampled_from(["forces", "coefficients", "solve", "static_equilibrium"]))
    frac = st.floats(-1.2, 1.2)
    if call == "static_equilibrium":
        ang = draw(st.floats(0, 2 * math.pi))
        w = draw(st.one_of(st.floats(1e-3, 1e5),
                           st.sampled_from([0.0, math.nan, -1.0, 1e-200, 1e-12, 1e300])))
        args = {"load_n": (w * math.cos(ang), w * math.sin(ang)),
                "speed_hz": draw(number(-1e4, 1e4, special=False)),
                "rtol": draw(st.sampled_from([1e-10, 1e-6, 1e-12, 0.0, -1.0, 1e300]))}
        args = draw(hostile(args, share=5))
    else:
        args = {"x_m": draw(frac) * c, "y_m": draw(frac) * c,
                "speed_hz": draw(number(-1e4, 1e4, special=False))}
        if call in ("forces", "solve"):
            args["vx_m_s"] = draw(number(-10.0, 10.0, special=False))
            args["vy_m_s"] = draw(number(-10.0, 10.0, special=False))
        args = draw(hostile(args, share=5))
        if call == "coefficients" and draw(st.booleans()):
            args["method"] = "finite_difference"
            args["rel_step"] = draw(st.sampled_from([1e-6, 1e-4, 1e-8, 1e-300, 0.5]))
    return {"geometry": geom, "call": call, "args": args}


@budget(150)
@given(p=bearing_payload())
def test_fuzz_bearing(worker, p):
    check(worker, "bearing", p)


# -- bearing elements (rotordyn.bearings) -----------------------------------------------------
FILM = {"station": 0, "diameter_m": 0.1, "length_m": 0.05, "clearance_m": 1e-4,
        "viscosity_pa_s": 0.03, "n_circ": 36, "n_axial": 6}


@st.composite
def element_payload(draw):
    kind = draw(st.sampled_from(["fixed_geometry", "tilting_pad", "tilting_pad",
                                 "squeeze_film_damper", "table"]))
    if kind == "fixed_geometry":
        f = dict(FILM, kind=draw(st.sampled_from(["partial_arc", "two_axial_groove", "elliptical",
                                                  "offset_halves", "three_lobe", "four_lobe",
                                                  "pressure_dam"])),
                 preload=draw(st.one_of(st.none(), st.floats(0, 0.9))),
                 cavitation=draw(st.sampled_from(["reynolds", "gumbel"])))
    elif kind == "tilting_pad":
        f = dict(FILM, n_pads=draw(st.integers(2, 8)), pad_arc_deg=draw(st.floats(20, 100)),
                 pivot_offset=draw(st.floats(0.05, 0.95)), preload=draw(st.floats(0, 0.8)),
                 load=draw(st.sampled_from(["between", "on"])),
                 pivot_stiffness_n_per_m=draw(st.sampled_from([0.0, 1e5, 1e8, 1e12])),
                 pad_mass_kg=0.5)
        if f["n_pads"] * f["pad_arc_deg"] > 340:
            f["pad_arc_deg"] = 340 / f["n_pads"]
    elif kind == "squeeze_film_damper":
        f = dict(FILM, cavitation=draw(st.sampled_from(["none", "gumbel", "reynolds"])),
                 centring_spring_n_per_m=draw(st.sampled_from([0.0, 1e6])),
                 end_seal_conductance_m3_per_pa_s_per_m=draw(st.sampled_from(
                     [None, 1e-12, 1e-9, 1e-6, 0.0, math.inf])))
    else:
        n = draw(st.integers(1, 4))
        sp = draw(st.lists(st.floats(1, 300), min_size=n, max_size=n, unique=True))
        if draw(st.integers(0, 3)):
            sp = sorted(sp)
        col = st.lists(st.floats(-1e9, 1e9), min_size=n, max_size=n).map(tuple)
        f = {"station": 0, "speeds_hz": tuple(sp), "kxx_n_per_m": draw(col),
             "kyy_n_per_m": draw(col), "cxx_n_s_per_m": draw(col),
             "extrapolate": draw(st.booleans())}
        if draw(st.booleans()):
            f.update(mxx_kg=draw(col), mxy_kg=draw(col), myx_kg=draw(col), myy_kg=draw(col))
    f = draw(hostile(f, share=6))
    return {"kind": kind, "fields": f, "speed_hz": draw(st.floats(0.5, 400)),
            "eps": draw(st.one_of(st.floats(0.01, 0.95), SPECIAL)),
            "speeds_hz": draw(st.lists(st.floats(1, 300), min_size=1, max_size=3)),
            "load_n": (draw(st.floats(-2e3, 2e3)), draw(st.floats(-2e4, -1.0)))}


@budget(40)
@given(p=element_payload())
def test_fuzz_bearing_elements(worker, p):
    check(worker, "element", p)


# -- system analyses ------------------------------------------------------------------------
@st.composite
def system_payload(draw):
    a = draw(st.sampled_from(["equilibrium", "equilibrium", "stability", "stability",
                              "linearize", "transient", "campbell", "threshold", "unbalance",
                              "statespace"]))
    speed = draw(number(-100.0, 300.0, special=False))
    pc = draw(number(0.0, 2e6, special=False))
    ay = draw(st.one_of(st.none(), number(-6e-3, 6e-3, special=False)))
    kw = {}
    if draw(st.integers(0, 3)) == 0:  # a quarter of the cases: one hostile operating value
        bad = draw(SPECIAL)
        which = draw(st.integers(0, 2))
        speed, pc, ay = [bad if i == which else x for i, x in enumerate((speed, pc, ay))]
    if a == "equilibrium":
        if draw(st.booleans()):
            kw["method"] = draw(st.sampled_from(["newton", "successive", "magic"]))
        if draw(st.booleans()):
            kw["tol"] = draw(st.sampled_from([1e-10, 1e-6, 0.0, 1e-2, 1.0]))
        if draw(st.booleans()):
            kw["contact_fraction"] = draw(st.sampled_from([0.0, 0.02, 0.5, 0.9, 1.0]))
        if draw(st.booleans()):
            kw["warm_start"] = draw(st.sampled_from([True, False, 1]))
        return {"analysis": a, "op": [speed, pc, ay], "kw": kw}
    if a in ("stability", "linearize"):
        if draw(st.booleans()):
            kw["method"] = draw(st.sampled_from(["perturbation", "finite_difference", "x"]))
        if a == "linearize" and draw(st.booleans()):
            kw["rel_step"] = draw(st.sampled_from([1e-6, 1e-9, 1e-300, 0.5]))
        if a == "stability" and draw(st.booleans()):
            kw["n_modes"] = draw(integer(1, 12))
        return {"analysis": a, "op": [speed, pc, ay], "kw": kw}
    if a == "transient":
        kw = {"n_out": draw(integer(2, 50)),
              "disturbance_m": draw(st.one_of(
                  st.tuples(st.floats(-1e-4, 1e-4), st.floats(-1e-4, 1e-4)), SPECIAL)),
              "rtol": draw(st.sampled_from([1e-6, 1e-4, 1e-300, 0.5]))}
        if draw(st.booleans()):
            kw["unbalances"] = draw(st.one_of(
                st.lists(st.tuples(integer(0, 8), number(0, 1e-3), number(-360, 360)),
                         max_size=2), SPECIAL))
        t_end = draw(st.one_of(st.floats(1e-4, 0.01), SPECIAL))
        return {"analysis": a, "op": [t_end, speed, pc, ay], "kw": kw}
    if a == "unbalance":
        speeds = draw(st.lists(st.floats(1.0, 200.0), min_size=1, max_size=3,
                               unique=True).map(sorted))
        ub = draw(st.lists(st.tuples(st.integers(0, 8), st.floats(0, 1e-3),
                                     st.floats(-360, 360)), min_size=1, max_size=2))
        args = draw(hostile({"unbalances": ub, "speeds_hz": speeds}))
        kw = {"chamber_pressure_pa": pc, "config_ay_m": ay}
        return {"analysis": a, "op": [args["unbalances"], args["speeds_hz"]], "kw": kw}
    if a == "statespace":
        kw = {"inputs": draw(st.sampled_from([("chamber_pressure",), (("force", 2),),
                                             (("force", 1),), ("magic",), None]))}
        return {"analysis": a, "op": [speed, pc, ay], "kw": kw}
    if a == "campbell":
        speeds = draw(st.one_of(
            st.lists(st.floats(-50, 300), min_size=1, max_size=3, unique=True).map(sorted),
            SPECIAL))
        if draw(st.booleans()):
            kw["n_modes"] = draw(integer(1, 12))
        return {"analysis": a, "op": [speeds, pc, ay], "kw": kw}
    vary = draw(st.sampled_from(["chamber_pressure_pa", "config_ay_m", "speed_hz", "rpm"]))
    lo = draw(number(-1e5, 5e5))
    hi = draw(st.one_of(st.floats(-1e5, 5e5), SPECIAL))
    kw = {"bounds": (lo, hi), "n_scan": draw(integer(2, 3)), "speed_hz": speed,
          "chamber_pressure_pa": pc, "config_ay_m": ay}
    return {"analysis": a, "op": [vary], "kw": kw}


@budget(100)
@given(p=system_payload())
def test_fuzz_system_analyses(worker, p):
    check(worker, "system", p)


# -- TOML loader ----------------------------------------------------------------------------
def _base_toml():
    from importlib import resources

    return resources.files("rotordyn.model.data").joinpath("paper_rig.toml").read_text()


def edit_line(draw, line: str, key: str, val: str, op: str, lo: float = 0.1) -> str:
    """One fuzzed edit of a ``key = val`` TOML line: ``scale`` (a number scaled by [lo, 10], an
    integer shifted by ±3), ``value`` (a hostile value), ``delete``, ``unknown`` (a key added)."""
    if op == "scale":  # a plausible edit: a number scaled, an integer shifted
        try:
            return f"{key} = {int(val) + draw(st.integers(-3, 3))}"
        except ValueError:
            try:
                return f"{key} = {float(val) * draw(st.floats(lo, 10.0))!r}"
            except ValueError:
                return f"{key} = {draw(TOML_VALUES)}"
    if op == "value":
        return f"{key} = {draw(TOML_VALUES)}"
    if op == "delete":
        return ""
    return line + f"\n{key}_x = 1"


TOML_VALUES = st.sampled_from([
    "0", "-1", "1e-300", "1e300", "nan", "inf", "-inf", "2147483648", "9223372036854775807",
    "true", '"x"', '""', "[]", "[1]", '["a", 2]', "{}", "{a = 1}", "[[1, 2], [3]]",
    "1979-05-27", "0.5", "3", "[2, 4, 6]", "[7, 14, 20]", '"rigid"', '"linear"', '"steel"',
    '"guyan"', '"none"', '"jfo"', "[{center_deg = 90.0}]"])


@st.composite
def toml_payload(draw):
    lines = _base_toml().splitlines()
    for _ in range(draw(st.integers(1, 3))):
        keyed = [i for i, ln in enumerate(lines) if "=" in ln.split("#")[0]]
        op = draw(st.sampled_from(["scale", "scale", "scale", "value", "value", "delete",
                                   "unknown", "bytes"]))
        i = draw(st.sampled_from(keyed))
        key, val = (x.strip() for x in lines[i].split("#")[0].split("=", 1))
        if op == "bytes":
            lines[i] = draw(st.sampled_from([f"{key} = ", "[[", "= 1", f"{key} = [1,"]))
        else:
            lines[i] = edit_line(draw, lines[i], key, val, op)
    return {"text": "\n".join(lines) + "\n", "modes": draw(st.booleans())}


@budget(150)
@given(p=toml_payload())
def test_fuzz_toml_loader(worker, p):
    check(worker, "toml", p)


# -- CLI ------------------------------------------------------------------------------------
ARG_VALUES = st.sampled_from(["50", "-1", "0", "nan", "inf", "1e308", "-1.85e-3", "x", "",
                              "5:10:5", "5:1e9:1e-9", "1,2,3", "10:5:1", "2147483648",
                              "0.15e6", "1e-6", "out.png", "out.xyz", "nodir/out.png"])
COMMANDS = {
    "validate": ([], []),
    "modes": (["--speed-hz", "--n-modes", "--reduction", "--part"], ["--json"]),
    "equilibrium": (["--speed-hz", "--chamber-pressure-pa", "--config-ay-m", "--method"],
                    ["--json"]),
    "stability": (["--speed-hz", "--chamber-pressure-pa", "--config-ay-m"], ["--json"]),
    "campbell": (["--speeds-hz", "--chamber-pressure-pa", "--config-ay-m", "--harmonic",
                  "--plot"], ["--json", "--all-whirl"]),
    "threshold": (["--vary", "--n-scan", "--speed-hz", "--chamber-pressure-pa"], ["--json"]),
    "unbalance": (["--unbalance", "--speeds-hz", "--station"], ["--json"]),
}


PLAUSIBLE = {
    "--speed-hz": ["50", "20", "1e-6", "-30"], "--chamber-pressure-pa": ["0", "0.15e6", "4e5"],
    "--config-ay-m": ["-1.85e-3", "0", "5e-3"], "--n-modes": ["4", "2"],
    "--reduction": ["guyan", "none", "irs"], "--part": ["rotor", "sleeve"],
    "--method": ["newton", "successive"], "--speeds-hz": ["5:30:25", "10,20", "10"],
    "--harmonic": ["1", "2"], "--plot": ["out.png", "out.svg"],
    "--vary": ["chamber_pressure_pa", "speed_hz", "config_ay_m"], "--n-scan": ["2"],
    "--unbalance": ["4,1e-5,0", "2,1e-5,90"], "--station": ["2", "4"],
}


@st.composite
def cli_payload(draw):
    cmd = draw(st.sampled_from(sorted(COMMANDS) * 4 + ["nope"]))
    flags, switches = COMMANDS.get(cmd, ([], []))
    model = draw(st.sampled_from(["paper-rig"] * 3 + ["friswell-5.9.1"] * 3 +
                                 ["missing", "nofile.toml", "bad.toml"]))
    argv = [cmd, model]
    for f in draw(st.lists(st.sampled_from(flags), max_size=3, unique=True)) if flags else []:
        hostile_value = draw(st.integers(0, 3)) == 0
        argv += [f, draw(ARG_VALUES if hostile_value else st.sampled_from(PLAUSIBLE[f]))]
    if switches and draw(st.booleans()):
        argv.append(draw(st.sampled_from(switches)))
    if cmd in ("campbell", "unbalance") and "--speeds-hz" not in argv:
        argv += ["--speeds-hz", draw(st.sampled_from(["5:30:25", "10", "5:1e9:1e-9", "x"]))]
    if cmd == "unbalance" and "--unbalance" not in argv and draw(st.integers(0, 4)):
        argv += ["--unbalance", "4,1e-5,0"]
    if cmd == "threshold" and draw(st.booleans()):
        argv += ["--bounds", draw(ARG_VALUES), draw(ARG_VALUES)]
    if cmd == "threshold" and "--n-scan" not in argv:
        argv += ["--n-scan", "2"]
    return argv


@pytest.fixture(scope="module")
def cli_dir(tmp_path_factory):
    d = tmp_path_factory.mktemp("cli")
    (d / "bad.toml").write_bytes(b'schema = "rotordyn/model/1"\n\xff = 1\n')
    return d


@budget(100)
@given(argv=cli_payload())
def test_fuzz_cli(worker, cli_dir, argv):
    check(worker, "cli", {"argv": argv, "cwd": str(cli_dir)})
