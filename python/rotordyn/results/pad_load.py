"""Tilting pads at the onset of loading: the pads of an equilibrium whose film carries a
pressure, but only a small fraction of their bearing's most loaded pad's (docs/bearings.md,
"A pad at the onset of loading").

Why it is flagged. A pad that just starts to carry load has a tilt stiffness proportional to
its load (→ 0), while the coupling of its tilt with the journal stays finite — the one-sided
derivative of the film at the edge of its pressure-free set. With its tilt stiffness far below
its tilt damping × the whirl frequency the pad's tilt lags the journal by ≈ 90° and feeds back
on the journal as damping of either sign; the linearised verdict then jumps where the pad
starts to carry load (the steam turbine of tests/data/models/steam_turbine_tilting_pad.toml,
48 × 8 per pad: the 26 Hz bending pair's ζ from +0.0100 at 119.5 Hz, top pads unloaded, to
−0.0046 at 119.8 Hz, their peak 1.06 kPa against 2.18 MPa; back above 0 near 130 Hz). It is the
model's behaviour, not a numerical artefact (finite differences agree, the pad equilibrium is
at round-off, a transient agrees, and the band stays under grid refinement), but where it
starts follows the onset of pad loading, which moves with the film grid (119.8 Hz on 48 × 8,
about 115.5 Hz on 96 × 16 and 144 × 24), the load and the preload: such a verdict is
sensitive, and a pad whose load is near zero is named beside it."""

from __future__ import annotations

LIGHT_PAD_REL = 0.05
"""A pad is lightly loaded (at the onset of loading) when its film's peak pressure is above
zero (not an unloaded pad) and below this fraction of the peak pressure of its bearing's most
loaded pad."""


def light_pads(equilibrium) -> list[tuple[str, int, float, float]]:
    """(bearing, pad, peak Pa, bearing's largest peak Pa) of every tilting pad of
    ``equilibrium`` (EquilibriumResult) that carries a pressure below :data:`LIGHT_PAD_REL`
    of its bearing's most loaded pad (pads numbered 0-based in pivot order, as
    ``pads_frame()``); empty without tilting pads or a converged equilibrium."""
    out = []
    for bi, d in (getattr(equilibrium, "pads", None) or {}).items():
        p = [float(x) for x in d.get("pad_p_max_pa", ())]
        top = max(p) if p else 0.0
        for k, (pk, unloaded) in enumerate(zip(p, d.get("pad_unloaded", ()))):
            if top > 0 and not unloaded and pk < LIGHT_PAD_REL * top:
                out.append((str(equilibrium.bearing_names[bi]), k, pk, top))
    return out


def light_pad_note(equilibrium) -> str:
    """One sentence naming the lightly loaded pads of ``equilibrium`` and why a stability
    verdict there is sensitive ("" without any)."""
    pads = light_pads(equilibrium)
    if not pads:
        return ""
    names = "; ".join(f"'{b}' pad {k}: peak {p:.3g} Pa, {100 * p / top:.2g} % of the "
                      f"bearing's most loaded pad" for b, k, p, top in pads)
    return (f"near-zero pad load at {equilibrium.speed_hz:g} Hz ({names}): these pads are at "
            "the onset of loading, where their tilt stiffness vanishes while their coupling "
            "with the journal does not; a stability verdict here is sensitive to the load, "
            "the preload and the film grid (docs/bearings.md, 'A pad at the onset of loading')")


__all__ = ["LIGHT_PAD_REL", "light_pad_note", "light_pads"]
