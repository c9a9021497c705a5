"""The report's note on tilting pads at the onset of loading (docs/bearings.md, "A pad at the
onset of loading"): over the equilibria the report already solved (the bearing coefficients'
speeds), every pad that carries near-zero load (:func:`rotordyn.results.pad_load.light_pads`)
and every pad that starts (or stops) carrying load between two of those speeds. A stability
verdict at such speeds sits at the onset of pad loading and is sensitive to the load, the
preload and the film grid; the report says so beside the stability screen."""

from __future__ import annotations

from rotordyn._common.status import CONVERGED
from rotordyn.results.pad_load import LIGHT_PAD_REL, light_pads

HEAD = ("tilting pads at the onset of loading (at the bearing coefficients' speeds; a pad is "
        f"lightly loaded below {100 * LIGHT_PAD_REL:g} % of its bearing's most loaded pad's peak "
        "pressure): a stability verdict at and near these speeds is sensitive to the load, the "
        "preload and the film grid — a pad that just carries load has a vanishing tilt "
        "stiffness but a finite coupling with the journal, and can turn a lightly damped mode "
        "unstable (docs/bearings.md, 'A pad at the onset of loading')")


def _loaded(eq) -> dict:
    """{(bearing, pad): loaded?} of a converged equilibrium's tilting pads."""
    out = {}
    for bi, d in (getattr(eq, "pads", None) or {}).items():
        for k, unloaded in enumerate(d.get("pad_unloaded", ())):
            out[(str(eq.bearing_names[bi]), k)] = not bool(unloaded)
    return out


def pad_onset_items(equilibria) -> list[str]:
    """The note's items: each speed's lightly loaded pads, and each pad whose loaded state
    changes between consecutive speeds (empty when none, or without tilting pads).
    ``equilibria``: EquilibriumResults, or the (speed, status, EquilibriumResult or None)
    triples :func:`rotordyn.analysis.bearing_coefficients.bearing_coefficients` collects."""
    eqs = [e[-1] if isinstance(e, tuple) else e for e in equilibria]
    eqs = sorted((e for e in eqs if e is not None and e.status in CONVERGED),
                 key=lambda e: e.speed_hz)
    items = []
    for e in eqs:
        pads = light_pads(e)
        if pads:
            items.append(f"at {e.speed_hz:.4g} Hz " + ", ".join(
                f"'{b}' pad {k} carries {p:.3g} Pa ({100 * p / top:.2g} %)"
                for b, k, p, top in pads))
    for a, b in zip(eqs, eqs[1:]):
        la, lb = _loaded(a), _loaded(b)
        for key in sorted(set(la) & set(lb)):
            if la[key] != lb[key]:
                what = "starts" if lb[key] else "stops"
                items.append(f"'{key[0]}' pad {key[1]} {what} to carry load between "
                             f"{a.speed_hz:.4g} and {b.speed_hz:.4g} Hz")
    return items


def pad_onset_lines(equilibria) -> list[str]:
    """The text report's lines ([] without any item)."""
    items = pad_onset_items(equilibria)
    return ["", HEAD] + [f"  {x}" for x in items] if items else []


def pad_onset_html(equilibria) -> str:
    """The HTML report's paragraph ("" without any item)."""
    import html

    items = pad_onset_items(equilibria)
    if not items:
        return ""
    return (f"<p>{html.escape(HEAD[0].upper() + HEAD[1:])}: "
            + "; ".join(html.escape(x) for x in items) + ".</p>")


__all__ = ["HEAD", "pad_onset_html", "pad_onset_items", "pad_onset_lines"]
