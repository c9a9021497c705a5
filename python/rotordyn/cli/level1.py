"""``rotordyn level1 MODEL --speed-hz HZ``: API 617 Level I stability analysis (the applied
cross-coupling sweep, Q_0, Q_A from the stages, δ_A and the criteria)."""

from __future__ import annotations

import sys

import numpy as np

from rotordyn import analysis
from rotordyn.analysis.level1 import MODES, PLACEMENTS
from rotordyn.cli.common import (JSON_HELP, MODEL_HELP, add_dpi, add_operating_point,
                                 check_figure, json_text, save_figure, table_text)
from rotordyn.errors import InputError
from rotordyn.model import builtin as models
from rotordyn.results.equilibrium import CONVERGED

STAGE_HELP = ("a stage: STATION,POWER_W,DIAMETER_M,HEIGHT_M,DENSITY_RATIO (centrifugal) or "
              "STATION,POWER_W,DIAMETER_M,HEIGHT_M (axial, with --axial); repeat per stage; "
              "replaces the model's [[stage]] tables")


def register(sub) -> None:
    """``level1`` on the ``rotordyn`` parser's subparsers ``sub``."""
    s = sub.add_parser("level1", help="API 617 Level I stability analysis (Q_A, Q_0, δ_A)")
    s.add_argument("model", help=MODEL_HELP)
    add_operating_point(s)
    s.add_argument("--stage", action="append", default=None, metavar="SPEC", help=STAGE_HELP)
    s.add_argument("--axial", action="store_true",
                   help="the --stage entries are axial stages (B_t = 1.5, no density ratio)")
    s.add_argument("--at", default="auto", metavar="WHERE",
                   help=f"where Q acts: {', '.join(PLACEMENTS)} or a station number "
                        "(default auto: mid-span, or the stages' centroid when overhung)")
    s.add_argument("--mode", default="first_forward", choices=MODES,
                   help="the judged mode (default first_forward, the standard's)")
    s.add_argument("--max-freq-hz", type=float, default=None, metavar="HZ",
                   help="judge only forward modes at most HZ")
    s.add_argument("--gas-density-kg-m3", type=float, default=None, metavar="RHO",
                   help="average gas density (first-stage suction, last-stage discharge)")
    s.add_argument("--csr-limit", type=float, default=None, metavar="CSR",
                   help="the Region B boundary CSR of the standard's screening figure at that "
                        "density (then the screening criterion is judged)")
    s.add_argument("--plot", default=None, metavar="FIG",
                   help="write the log decrement against Q (PNG/SVG/PDF)")
    add_dpi(s)
    s.add_argument("--json", action="store_true", help=JSON_HELP)
    s.set_defaults(func=_cmd_level1)


def _stage(text: str, axial: bool) -> dict:
    parts = text.split(",")
    want = 4 if axial else 5
    try:
        vals = [float(x) for x in parts]
    except ValueError:
        vals = []
    if len(vals) != want or not float(vals[0]).is_integer():
        form = "STATION,POWER_W,DIAMETER_M,HEIGHT_M" + ("" if axial else ",DENSITY_RATIO")
        raise InputError(f"--stage: expected {form}, got {text!r}")
    d = dict(station=int(vals[0]), power_w=vals[1], diameter_m=vals[2], height_m=vals[3],
             type="axial" if axial else "centrifugal")
    if not axial:
        d["density_ratio"] = vals[4]
    return d


def _cmd_level1(args) -> int:
    check_figure(args.plot)
    s = models.load(args.model)
    stages = None if args.stage is None else [_stage(t, args.axial) for t in args.stage]
    at = int(args.at) if args.at.lstrip("-").isdigit() else args.at
    r = analysis.level1(s, args.speed_hz, args.chamber_pressure_pa, args.config_ay_m,
                        stages=stages, at=at, mode=args.mode, max_freq_hz=args.max_freq_hz,
                        gas_density_kg_m3=args.gas_density_kg_m3, csr_limit=args.csr_limit)
    checks = r.checks()
    if args.json:
        print(json_text({"status": r.status, "message": r.message, "speed_hz": r.speed_hz,
                         "verdict": r.verdict(), "q_a_n_per_m": r.q_a_n_per_m,
                         "q0_n_per_m": r.q0_n_per_m, "ratio": r.ratio,
                         "log_dec_a": r.log_dec_a, "log_dec_0": r.log_dec_0,
                         "csr": r.csr, "first_critical_hz": r.first_critical_hz,
                         "placement": [list(p) for p in r.placement],
                         "stages": list(r.stages),
                         "checks": [{"name": c[0], "criterion": c[1], "value": c[2],
                                     "verdict": c[3]} for c in checks],
                         "curve": r.to_frame().drop(columns="status").to_dict("list")}))
    else:
        df = r.to_frame()
        df.insert(1, "applied_q_mn_per_m", df.pop("applied_q_n_per_m") / 1e6)
        mark = np.where(df["is_q_a"], "Q_A", np.where(df["is_q0"], "Q_0", ""))
        df = df.drop(columns=["is_q_a", "is_q0", "status"]).assign(at=mark)
        print(table_text(df))
        print(repr(r), file=sys.stderr)
        print(f"Q acts {r.placement_why}", file=sys.stderr)
        for st in r.stages:
            print(f"stage at station {st['station']}: P = {st['power_w']:.4g} W, D = "
                  f"{st['diameter_m']:.4g} m, H = {st['height_m']:.4g} m, ρ_d/ρ_s = "
                  f"{st['density_ratio'] if st['density_ratio'] is not None else '–'}: "
                  f"q_A = {st['q_a_n_per_m']:.4g} N/m", file=sys.stderr)
        for name, crit, val, verdict in checks:
            v = {True: "PASS", False: "FAIL"}.get(verdict, verdict) if verdict is not None \
                else "–"
            print(f"{name}: {val} [{crit}] {v}", file=sys.stderr)
    if args.plot and r.status in CONVERGED:
        save_figure(r.plot(), args.plot, args.dpi)
    if r.status not in CONVERGED:
        print(f"rotordyn: failed: {r.status}: {r.message}", file=sys.stderr)
        return 1
    return 0
