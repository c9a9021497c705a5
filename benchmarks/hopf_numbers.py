"""Every number of docs/nonlinear.md's section on Hopf points (issue 19): rotordyn.hopf on
the paper rig (as built and on a 36 × 6 film grid) at a_y = −1.85 mm, 50 Hz over p_c, and
on the compressor on plain bearings over the speed; l1 against the width of the film-force
fits; the leading-order amplitude against cycles shot from it near the Hopf point."""

from __future__ import annotations

import dataclasses
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from _common import footer, header  # noqa: E402

import rotordyn as rd  # noqa: E402
from rotordyn.analysis.hopf import hopf_cycle  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
SPANS = (0.01, 0.02, 0.05, 0.1, 0.2)


def coarse(s):
    return dataclasses.replace(s, bearings=tuple(
        dataclasses.replace(b, n_circ=36, n_axial=6) if hasattr(b, "n_circ") else b
        for b in s.bearings))


def spans(s, vary, at, **kw):
    for sp in SPANS:
        h = rd.hopf(s, vary, at=at, fd_step=sp, **kw)
        print(f"    fit ±{sp:<5g} l1 {h.l1:+.5f} ± {h.l1_error:.2g} 1/s  {h.type:<13s} "
              f"κ = A²/|p − p_H| {h.amplitude_coefficient[0]:.4g} m²/unit")


def shots(s, h, dists):
    sgn = 1 if h.cycle_side == "above" else -1
    for d in dists:
        t = time.process_time()
        o = hopf_cycle(s, h, h.value + sgn * d, rtol=1e-7, tol=1e-5)
        if not o.ok:
            print(f"    {d:g} from p_H: {o.status}: {o.message}")
            continue
        a = o.amplitude(0)
        print(f"    {d:g} from p_H: shot A = {a * 1e6:.3f} µm (A/c {a / h.clearance_m[0]:.4f}), "
              f"A²/d = {a * a / d:.4g}, κ·d predicts {h.amplitude(h.value + sgn * d) * 1e6:.3f}"
              f" µm (A²/d / κ = {a * a / d / h.amplitude_coefficient[0]:.4f}); period "
              f"{o.period_s * 1e3:.4f} ms (1/whirl {1e3 / h.whirl_frequency_hz:.4f}); "
              f"stable {o.stable}, |μ_c| {abs(o.critical_multiplier):.4f}  "
              f"[{time.process_time() - t:.1f} s CPU]")


def main():
    header("hopf_numbers: first Lyapunov coefficients of docs/nonlinear.md")
    rig = rd.models.paper_rig()
    op = dict(speed_hz=50.0, config_ay_m=-1.85e-3)
    for name, s, d in (("rig, 36 × 6 film grid", coarse(rig), (12.0, 25.0, 100.0, 400.0)),
                       ("rig as built", rig, (12.0, 84.0))):
        h = rd.hopf(s, bounds=(0.04e6, 0.08e6), **op)
        print(f"{name}: {h!r}")
        spans(s, "chamber_pressure_pa", h.value, **op)
        shots(s, h, d)
    comp = rd.System.from_toml(ROOT / "tests" / "data" / "models" / "compressor_plain.toml")
    for name, s in (("compressor_plain, 36 × 6 film grid", coarse(comp)),
                    ("compressor_plain as built", comp)):
        h = rd.hopf(s, "speed_hz", bounds=(100.0, 150.0))
        print(f"{name}: {h!r}")
        spans(s, "speed_hz", h.value)
    footer()


if __name__ == "__main__":
    main()
