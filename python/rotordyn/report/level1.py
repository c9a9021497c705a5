"""The report's API 617 Level I section (text and HTML): evaluated at the maximum continuous
speed with the model's ``[[stage]]`` data; "not evaluated (no stage data)" without any, and
"not evaluated (no operating speed)" without the operating range — never invented. Inputs
(stages, where Q acts, the judged mode) are echoed beside the result."""

from __future__ import annotations

import html

import numpy as np

from rotordyn import analysis
from rotordyn.results.level1 import MODE_TEXT, NO_STAGE_DATA, NOT_RESOLVED

NO_SPEED = "not evaluated (no operating speed: --operating-speed-hz)"
CRITERIA = ("API 617 (8th ed., Part 1 §4.8.5) / API 684 (2nd ed., §2.9) Level I: Level II is "
            "required when Q_0/Q_A < 2, or δ_A < 0.1, or 2 ≤ Q_0/Q_A < 10 with the critical "
            "speed ratio in Region B of the standard's screening figure.")


def evaluate(system, operating_speed_hz, chamber_pressure_pa: float = 0.0, config_ay_m=None,
             **options):
    """(Level1Result or None, why-not text): Level I at the top of the operating range;
    ``options`` go to :func:`rotordyn.level1` (``gas_density_kg_m3``, ``csr_limit``)."""
    if not system.stages:
        return None, NO_STAGE_DATA
    if not operating_speed_hz:
        return None, NO_SPEED
    return analysis.level1(system, float(operating_speed_hz[1]), chamber_pressure_pa,
                           config_ay_m, **options), ""


def _stage_rows(r) -> list[tuple]:
    return [(st["name"] or f"stage {i + 1}", st["station"], st["type"],
             f"{st['power_w'] / 1e3:.4g}", f"{st['diameter_m'] * 1e3:.4g}",
             f"{st['height_m'] * 1e3:.4g}",
             "–" if st["density_ratio"] is None else f"{st['density_ratio']:.4g}",
             f"{st['q_a_n_per_m'] / 1e6:.4g}") for i, st in enumerate(r.stages)]


STAGE_HEADER = ["stage", "station", "type", "P (kW)", "D (mm)", "H (mm)", "ρ_d/ρ_s",
                "q_A (MN/m)"]


def text_lines(r, why: str) -> list[str]:
    """The text report's section."""
    out = ["API 617 Level I stability analysis"]
    if r is None:
        return out + [f"  {why}"]
    out.append(f"  at {r.speed_hz:.4g} Hz ({60 * r.speed_hz:.0f} rpm); Q acts {r.placement_why}")
    out.append(f"  judged mode: the {MODE_TEXT[r.mode]}, {r.freq_0_hz:.4g} Hz, δ = "
               f"{r.log_dec_0:.3g} at Q = 0")
    out.append("  " + " | ".join(STAGE_HEADER))
    out += ["  " + " | ".join(str(c) for c in row) for row in _stage_rows(r)]
    for name, crit, val, v in r.checks():
        out.append(f"  {name}: {val} [{crit}] "
                   + ({True: "PASS", False: "FAIL"}.get(v, v) if v is not None else "n/a"))
    out.append(f"  verdict: {r.verdict()}")
    return out


def add_checks(r, why: str, checks) -> None:
    """Level I's criteria into the report's ``checks`` (PASS/FAIL only where they apply; ``r``
    None: one row saying why it was not evaluated)."""
    if r is None:
        checks.add("API 617 Level I", "Q_0/Q_A ≥ 2 and δ_A ≥ 0.1", why, why)
        return
    for name, crit, val, v in r.checks():
        checks.add(name, crit, val, v)


def html_section(r, why: str, checks, svg, table) -> str:
    """The HTML section; the criteria go into ``checks`` (:func:`add_checks`)."""
    head = "<h2>5b. API 617 Level I stability analysis</h2>"
    add_checks(r, why, checks)
    if r is None:
        return head + f"<p class=\"na\">{html.escape(why)}. Give the stages as [[stage]] tables " \
            "in the model file (docs/model-file.md) and the operating speed range.</p>"
    if r.status != "ok":
        return head + f"<p class=\"nr\">{NOT_RESOLVED}: {html.escape(r.message)}</p>"
    q0 = (f"{r.q0_n_per_m / 1e6:.4g} MN/m" if np.isfinite(r.q0_n_per_m)
          else f"not reached up to {r.q_max_n_per_m / 1e6:.4g} MN/m")
    rows = [("speed (maximum continuous)", f"{r.speed_hz:.4g} Hz ({60 * r.speed_hz:.0f} rpm)"),
            ("where Q acts", r.placement_why),
            ("judged mode", f"the {MODE_TEXT[r.mode]}, {r.freq_0_hz:.4g} Hz, δ = "
                            f"{r.log_dec_0:.3g} at Q = 0"),
            ("Q_A (sum of the stages)", f"{r.q_a_n_per_m / 1e6:.4g} MN/m"),
            ("Q_0 (δ = 0, root-found)", q0),
            ("Q_0/Q_A", f"{r.ratio:.3g}"), ("δ_A (δ at Q_A)", f"{r.log_dec_a:.3g}"),
            ("critical speed ratio CSR", f"{r.csr:.3g} (first critical on rigid supports "
                                         f"{r.first_critical_hz:.4g} Hz)"),
            ("average gas density", "not given" if not np.isfinite(r.gas_density_kg_m3)
             else f"{r.gas_density_kg_m3:.4g} kg/m³"),
            ("Region B boundary CSR (from the standard's figure)",
             "not given" if not np.isfinite(r.csr_limit) else f"{r.csr_limit:.3g}"),
            ("verdict", r.verdict())]
    return (head + f"<p>{html.escape(CRITERIA)} q_A = B·C·P·(ρ_d/ρ_s)/(D·H·N), B_c = 3 "
            "(axial B_t = 1.5, no density ratio), C = 9.55 (P in W, D and H in m, N in rpm, "
            "q_A in N/m).</p>"
            + table(["stage"] + STAGE_HEADER[1:], [tuple(html.escape(str(c)) for c in row)
                                                   for row in _stage_rows(r)])
            + table(["item", "value"], [(html.escape(a), html.escape(b)) for a, b in rows])
            + f"<figure>{svg(r.plot().figure)}<figcaption>Log decrement of the judged mode "
            "against the applied cross-coupled stiffness at the operating speed.</figcaption>"
            "</figure>")
