"""Unbalance response of systems with bearing elements (issue 22): the one C++ call
(``_core.unbalance_sweep``: per speed the continued equilibrium, K_H/D_H, the harmonic solve
and the eigenvalue check, GIL released) against the per-speed Python path it replaced
(equilibrium → linearize → harmonic_response → modal, one speed at a time: the loop of
``unbalance_response`` before the change, reproduced below), measured in the same run.

Both sides start from the concentric state (the system's warm start is cleared before each
call), refine=False, the default eigenvalue check on. Interleaved repeats, medians; wall and
CPU time; BLAS pinned to one thread; load printed before and after. The largest difference
between the two responses (relative to the largest amplitude) is printed beside the times.

    python benchmarks/bench_unbalance.py [--repeat 5] [--speeds 200]
"""

from __future__ import annotations

import argparse

import numpy as np

from _common import footer, header, interleaved

import rotordyn as rd
from rotordyn import _core
from rotordyn.analysis.assembly import assembled
from rotordyn.analysis.linear import continued_linear_models
from rotordyn.results.equilibrium import CONVERGED
from rotordyn.units import hz_to_rad_s

MODELS = "tests/data/models"


def per_speed(system, ub, sp, stations, pc):
    """The per-speed path (unbalance_response's loop before the one-call sweep)."""
    asm = assembled(system)
    F1 = asm.unbalance_load(ub)
    Cout = [asm.station_output_matrix(s) for s in stations]
    X = np.full((sp.size, len(stations)), np.nan + 0j)
    Y = X.copy()
    max_real = np.full(sp.size, np.nan)
    for i, stt, lm in continued_linear_models(system, sp, pc, None, "perturbation",
                                              continue_on=CONVERGED):
        if stt not in CONVERGED:
            continue
        w = hz_to_rad_s(float(sp[i]))
        q = np.asarray(_core.harmonic_response(lm.M, lm.D, lm.K, w, (w**2 * F1)[:, None]))[:, 0]
        for k, Co in enumerate(Cout):
            X[i, k], Y[i, k] = Co @ q
        lam = np.asarray(_core.modal(lm.M, lm.D, lm.K, asm.rotor.xy_pairs(), 0, False,
                                     asm.rotor.rot_pairs()).eigenvalues)
        max_real[i] = float(np.max(lam.real)) if lam.size else np.nan
    return X, Y, max_real


def case(name, system, ub, sp, stations, pc, repeat):
    asm = assembled(system)
    out = {}

    def cold(key, fn):
        def run():
            asm.last_r = None
            out[key] = fn()
        return run

    def old():
        return per_speed(system, ub, sp, stations, pc)

    def one_call():
        u = rd.unbalance_response(system, ub, sp, stations=stations, chamber_pressure_pa=pc,
                                  refine=False)
        return u.x, u.y, u.max_real_1_per_s

    def two_threads():
        u = rd.unbalance_response(system, ub, sp, stations=stations, chamber_pressure_pa=pc,
                                  refine=False, threads=2)
        return u.x, u.y, u.max_real_1_per_s

    t = interleaved({"old": cold("old", old), "one": cold("one", one_call),
                     "two": cold("two", two_threads)},
                    repeat=repeat)
    X0, Y0, m0 = out["old"]
    scale = max(np.nanmax(np.abs(X0)), np.nanmax(np.abs(Y0)))
    print(f"-- {name}: n = {asm.n}, {sp.size} speeds {sp[0]:g}-{sp[-1]:g} Hz, p_c = {pc:g} Pa")
    for k, label in (("old", "per-speed Python path (before)"),
                     ("one", "one C++ call, threads=1"), ("two", "one C++ call, threads=2")):
        X, Y, m = out[k]
        diff = max(np.nanmax(np.abs(X - X0)), np.nanmax(np.abs(Y - Y0))) / scale
        print(f"   {label:34s} {t[k]}  ({1e3 * t[k].cpu / sp.size:.3f} ms CPU/speed; "
              f"max |Δ| / max |x| = {diff:.1e}; "
              f"speed-up wall {t['old'].wall / t[k].wall:.2f}x, CPU {t['old'].cpu / t[k].cpu:.2f}x)")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--speeds", type=int, default=200)
    a = ap.parse_args()
    header("unbalance response with bearing elements: one C++ call vs per-speed path")
    n = a.speeds
    case("compressor, plain journal bearings",
         rd.System.from_toml(f"{MODELS}/compressor_plain.toml"), [(3, 1e-4, 0.0)],
         np.linspace(20.0, 200.0, n), [2, 3, 4], 0.0, a.repeat)
    case("paper rig, active bearing at 0.4 MPa", rd.models.paper_rig(), [(4, 1e-4, 0.0)],
         np.linspace(10.0, 120.0, n), [4, 6], 4e5, a.repeat)
    case("compressor, tilting pads", rd.System.from_toml(f"{MODELS}/compressor_tilting_pad.toml"),
         [(3, 1e-4, 0.0)], np.linspace(30.0, 180.0, max(n // 4, 2)), [1, 3], 0.0, a.repeat)
    footer()


if __name__ == "__main__":
    main()
