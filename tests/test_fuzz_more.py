"""Property-based fuzzing of issue 21, in the style and under the budget of
tests/test_fuzz.py (same worker process, ROTORDYN_FUZZ_SCALE / ROTORDYN_FUZZ_EXPLORE, same
property): control-law synthesis (``rotordyn.control``: plant, actuator, profiles, LQR/LQG,
PID, controllers closed on the plant, modal and balanced truncation), the sweep spec loader
(mutated built-in specs), and the bearing elements' file paths (a ``[[bearing]]`` table of a
model TOML; ``TableBearing.from_csv``). Cases: tests/fuzz_cases_more.py. In ``make test``:
260 cases (control 80, specs 100, element files 80), 7.7 s on the 2-core machine.
"""

from __future__ import annotations

import math

from hypothesis import given
from hypothesis import strategies as st

from test_fuzz import (SPECIAL, TOML_VALUES, _base_toml, budget, check, edit_line, hostile, integer,  # noqa: F401
                       number, worker)

# -- control-law synthesis (issue 21) ---------------------------------------------------------
ACTUATOR = st.fixed_dictionaries({  # hostile() adds the special values
    "order": st.integers(0, 2), "natural_frequency_hz": number(1.0, 1e3, special=False),
    "damping": number(0.05, 2.0, special=False),
    "time_constant_s": number(1e-4, 0.1, special=False),
    "p_min_pa": st.sampled_from([0.0, -math.inf, 1e5, math.nan]),
    "p_max_pa": st.sampled_from([1e6, math.inf, 0.0, 1e5]),
    "rate_limit_pa_s": st.sampled_from([math.inf, 1e7, 1e-300, 0.0, -1.0, math.nan])})
SQUARE2 = st.one_of(st.lists(st.lists(st.floats(-1e6, 1e6), min_size=2, max_size=2),
                             min_size=2, max_size=2), SPECIAL)


@st.composite
def control_payload(draw):
    call = draw(st.sampled_from(["plant", "actuator", "actuator", "profiles", "profiles",
                                 "transient", "transient",
                                 "lqr", "lqr", "lqg", "pid", "pid", "pid", "controller",
                                 "controller", "modal", "balanced"]))
    if call == "plant":
        args = draw(hostile({"speed_hz": draw(number(-50.0, 150.0, special=False)),
                             "chamber_pressure_pa": draw(number(0.0, 1e6, special=False)),
                             "config_ay_m": draw(st.one_of(st.none(), st.floats(-3e-3, 3e-3))),
                             "measurements": draw(st.sampled_from(
                                 [(("journal", 0),), (("displacement", 6), ("velocity", 2)),
                                  (("journal", 3),), (), "journal", (("speed", 0),)])),
                             "disturbance_stations": draw(st.sampled_from(
                                 [(), (4,), (2, 6), (99,), "4", -1]))}, share=5))
        args["actuator"] = draw(hostile(draw(ACTUATOR), share=5))
        return {"call": call, "args": args}
    if call == "actuator":
        return {"call": call, "args": draw(hostile(draw(ACTUATOR), share=3))}
    if call == "transient":
        act = draw(ACTUATOR)
        act["p_min_pa"] = draw(st.sampled_from([0.0, 0.03e6, -math.inf]))
        act["p_max_pa"] = draw(st.sampled_from([1e6, 0.08e6, math.inf]))
        act["rate_limit_pa_s"] = draw(st.sampled_from([math.inf, 1e7, 1e5, 1e-300]))
        if act["order"] == 0:
            act["rate_limit_pa_s"] = math.inf
        args = {"actuator": draw(hostile(act, share=8)),
                "pressure_pa": draw(st.floats(0.0, 0.2e6)),
                "amplitude_pa": draw(st.sampled_from([0.0, 1e3, 0.05e6, 1e6])),
                "frequency_hz": draw(st.floats(1.0, 2e3)),
                "law": draw(st.sampled_from(["none", "pid", "discrete"])),
                "sample_time_s": draw(st.sampled_from([1e-4, 2.5e-5, 1e-3])),
                "noise_std": draw(st.sampled_from([0.0, 1e-7])),
                "t_end_s": draw(st.floats(1e-3, 0.01))}
        return {"call": call, "args": args}
    if call == "profiles":
        kind = draw(st.sampled_from(["ramp", "table", "time_table", "harmonic"]))
        vals = [draw(number(-1e3, 1e3)) for _ in range(3)]
        if kind in ("table", "time_table"):
            vals = [draw(st.one_of(st.lists(st.floats(-10, 10), max_size=4), SPECIAL)),
                    draw(st.one_of(st.lists(number(-1e6, 1e6), max_size=4), SPECIAL))]
        harm = draw(st.sampled_from([{"frequency_hz": 200.0}, {"order": 1.0},
                                     {"order": -2.0}, {"frequency_hz": math.nan},
                                     {"frequency_hz": 1.0, "order": 1.0}, {},
                                     {"order": 1.0, "phase_deg": 1e300}]))
        return {"call": call, "args": {"kind": kind, "values": vals, "harmonic": harm}}
    if call == "lqr":
        q = draw(st.sampled_from([None, "scalar", "bad"]))
        args = {"kw": draw(hostile({"clearance_m": draw(number(1e-5, 1e-2)),
                                    "pressure_scale_pa": draw(number(1e3, 1e7))}, share=3))}
        if q == "scalar":
            args["R"] = draw(st.one_of(st.floats(1e-6, 1e6), SPECIAL))
        elif q == "bad":
            args["Q"] = draw(SQUARE2)
        return {"call": call, "args": args}
    if call == "lqg":
        kw = draw(hostile({"process_noise": draw(number(1e-3, 1e3)),
                           "measurement_noise_m": draw(number(1e-10, 1e-4)),
                           "disturbance_force_n": draw(number(1e-3, 1e3))}, share=3))
        return {"call": call, "args": {"kw": kw}}
    if call == "pid":
        gains = [draw(number(-1e10, 1e10)), draw(number(-1e7, 1e7)),
                 draw(st.one_of(st.just(0.0), number(-1e10, 1e10)))]
        kw = draw(hostile({"tau_d_s": draw(number(1e-6, 1e-2)),
                           "direction_deg": draw(number(-360.0, 360.0)),
                           "bearing": draw(integer(0, 1))}, share=3))
        args = {"gains": gains, "kw": kw}
        if draw(st.integers(0, 3)) == 0:
            args["freqs_hz"] = draw(st.one_of(st.lists(st.floats(-10, 1e4), max_size=4),
                                              SPECIAL))
        return {"call": call, "args": args}
    if call == "controller":
        n = draw(st.integers(0, 2))
        mat = lambda r, c: st.lists(st.lists(st.floats(-1e8, 1e8), min_size=c, max_size=c),  # noqa: E731
                                    min_size=r, max_size=r)
        args = draw(hostile({"A": draw(mat(n, n)), "B": draw(mat(n, 2)),
                             "C": draw(mat(1, n)), "D": draw(mat(1, 2))}, share=6))
        args["kw"] = draw(hostile({"sample_time_s": draw(st.sampled_from(
            [None, 1e-4, 2.5e-5, 1e-3])), "noise_std": draw(st.sampled_from([0.0, 1e-7, -1.0]))},
            share=4))
        return {"call": call, "args": args}
    if call == "modal":
        return {"call": call, "args": {
            "max_frequency_hz": draw(number(1.0, 5e3)),
            "kw": draw(hostile({"keep_actuator": draw(st.booleans()),
                                "n_check": draw(integer(2, 200))}, share=4))}}
    return {"call": call, "args": {"order": draw(integer(1, 24)),
                                   "kw": draw(hostile({"n_check": draw(integer(2, 200))},
                                                      share=4))}}


@budget(80)
@given(p=control_payload())
def test_fuzz_control(worker, p):
    check(worker, "control", p)


# -- sweep spec loader (issue 21) -------------------------------------------------------------
SPEC_VALUES = st.sampled_from([
    "0", "-1", "1e-300", "1e300", "nan", "inf", "2147483648", "true", '"x"', '""', "[]",
    "[1]", '["a", 2]', "{}", "{start = 0.0, stop = 1.0, num = 3}",
    "{start = 1.0, stop = 100.0, num = 4, scale = \"log\"}",
    "{start = 0.0, stop = 1.0, num = 1e9}", "{start = 0.0, stop = 1.0}",
    "{start = -1.0, stop = 1.0, num = 3, scale = \"log\"}", "[50.0, 1e7]", "[10.0, 20.0]",
    '"paper-rig"', '"friswell-5.9.1"', '"nope"', '"stability"', '"waterfall"',
    '"rotordyn/sweep/1"', "1979-05-27"])
SPEC_KEYS = ["grid.speed_hz", "grid.chamber_pressure_pa", "grid.config_ay_m",
             "grid.bearings.active.viscosity_pa_s", "grid.rotor.n_elements",
             "grid.options.n_modes", "options.n_modes", "options.unbalances",
             "options.t_end_s", "chunk_size", "max_files", "analysis", "model", "schema",
             "name", "bogus", "grid.bogus"]


def _builtin_specs():
    from rotordyn.sweep.spec import builtin_spec_path, builtin_specs

    return {n: builtin_spec_path(n).read_text(encoding="utf-8") for n in builtin_specs()}


@st.composite
def spec_payload(draw):
    texts = _builtin_specs()
    lines = texts[draw(st.sampled_from(sorted(texts)))].splitlines()
    for _ in range(draw(st.integers(1, 3))):
        op = draw(st.sampled_from(["value", "value", "scale", "scale", "add", "add", "delete",
                                   "bytes"]))
        keyed = [i for i, ln in enumerate(lines) if "=" in ln.split("#")[0]
                 and not ln.lstrip().startswith("[")]
        if op == "add":  # a key under its table (created once), or at the top
            key = draw(st.sampled_from(SPEC_KEYS))
            top, _, rest = key.partition(".")
            line = f"{rest or top} = {draw(SPEC_VALUES)}"
            if rest and f"[{top}]" in lines:
                lines.insert(lines.index(f"[{top}]") + 1, line)
            elif rest:
                lines += [f"[{top}]", line]
            else:
                lines.insert(0, line)
            continue
        first_table = next((j for j, ln in enumerate(lines) if ln.startswith("[")), len(lines))
        in_tables = [j for j in keyed if j > first_table]
        if in_tables and draw(st.integers(0, 3)):  # mostly the grid and the options
            keyed = in_tables
        if not keyed:
            continue
        i = draw(st.sampled_from(keyed))
        key, val = (x.strip() for x in lines[i].split("#")[0].split("=", 1))
        if op == "scale":
            try:
                lines[i] = f"{key} = {float(val) * draw(st.floats(-10.0, 10.0))!r}"
            except ValueError:
                lines[i] = f"{key} = {draw(SPEC_VALUES)}"
        elif op == "value":
            lines[i] = f"{key} = {draw(SPEC_VALUES)}"
        elif op == "delete":
            lines[i] = ""
        else:
            lines[i] = draw(st.sampled_from([f"{key} = ", "[[", "= 1", f"{key} = [1,",
                                             f"{key} = {{start = 1"]))
    return {"text": "\n".join(lines) + "\n", "check_model": draw(st.booleans())}


@budget(100)
@given(p=spec_payload())
def test_fuzz_sweep_spec(worker, p):
    check(worker, "spec", p)


# -- bearing elements through their files (issue 21) ------------------------------------------
ELEMENT_TOML = {
    "fixed_geometry": ('type = "fixed_geometry"\nname = "fg"\nstation = 2\ndiameter_m = 0.05\n'
                       'length_m = 0.04\nclearance_m = 1e-4\nviscosity_pa_s = 0.03\n'
                       'kind = "elliptical"\npreload = 0.5\nn_circ = 36\nn_axial = 6\n'),
    "tilting_pad": ('type = "tilting_pad"\nname = "tp"\nstation = 2\ndiameter_m = 0.05\n'
                    'length_m = 0.04\nclearance_m = 1e-4\nviscosity_pa_s = 0.03\nn_pads = 4\n'
                    'pad_arc_deg = 70.0\npivot_offset = 0.5\npreload = 0.3\nn_circ = 36\n'
                    'n_axial = 6\n'),
    "squeeze_film_damper": ('type = "squeeze_film_damper"\nname = "sfd"\nstation = 2\n'
                            'diameter_m = 0.05\nlength_m = 0.02\nclearance_m = 1e-4\n'
                            'viscosity_pa_s = 0.01\ncentring_spring_n_per_m = 1e6\n'
                            'n_circ = 36\nn_axial = 6\n'),
    "table": ('type = "table"\nname = "tab"\nstation = 2\nspeeds_hz = [10.0, 50.0]\n'
              'kxx_n_per_m = [1e7, 2e7]\nkyy_n_per_m = [1e7, 2e7]\n'
              'cxx_n_s_per_m = [1e3, 1e3]\ncyy_n_s_per_m = [1e3, 1e3]\n'
              'mxx_kg = [0.1, 0.1]\nmxy_kg = [0.0, 0.0]\nmyx_kg = [0.0, 0.0]\n'
              'myy_kg = [0.1, 0.1]\n'),
}
CSV_CELLS = st.sampled_from(["1e7", "-1e7", "0", "nan", "inf", "", "x", "1e400", "50",
                             "10", "ok", "contact", "no_equilibrium", " 2e3 ", "1,5"])
CSV_COLUMNS = ["speed_hz", "kxx_n_per_m", "kxy_n_per_m", "kyy_n_per_m", "cxx_n_s_per_m",
               "cyy_n_s_per_m", "mxx_kg", "mxy_kg", "myx_kg", "myy_kg", "status", "other"]


@st.composite
def element_file_payload(draw):
    if draw(st.booleans()):
        cols = draw(st.lists(st.sampled_from(CSV_COLUMNS), min_size=1, max_size=7))
        if draw(st.integers(0, 3)):
            cols = ["speed_hz"] + [c for c in cols if c != "speed_hz"]
        rows = [",".join(cols)]
        for i in range(draw(st.integers(0, 4))):
            rows.append(",".join(str(10.0 * (i + 1)) if c == "speed_hz" and draw(
                st.integers(0, 3)) else draw(CSV_CELLS) for c in cols))
        data = ("\n".join(rows) + "\n").encode()
        if draw(st.integers(0, 9)) == 0:
            data = draw(st.sampled_from([b"\xff\xfe", b"", b"\x00" * 8])) + data
        return {"path": "csv", "data": data, "station": draw(integer(0, 8)),
                "extrapolate": draw(st.booleans()), "speed_hz": draw(st.floats(1.0, 200.0))}
    kind = draw(st.sampled_from(sorted(ELEMENT_TOML)))
    lines = ELEMENT_TOML[kind].splitlines()
    for _ in range(draw(st.integers(1, 2))):
        keyed = [j for j, ln in enumerate(lines) if j and "=" in ln]
        i = draw(st.sampled_from(keyed))
        key, val = (x.strip() for x in lines[i].split("\n")[0].split("=", 1))
        op = draw(st.sampled_from(["scale", "value", "delete", "unknown"]))
        lines[i] = edit_line(draw, lines[i], key, val, op, lo=0.0)
    text = _base_toml() + "\n[[bearing]]\n" + "\n".join(lines) + "\n"
    return {"path": "toml", "text": text, "solve": draw(st.integers(0, 3)) == 0,
            "speed_hz": draw(st.floats(5.0, 100.0))}


@budget(80)
@given(p=element_file_payload())
def test_fuzz_bearing_element_files(worker, p):
    check(worker, "element_file", p)
