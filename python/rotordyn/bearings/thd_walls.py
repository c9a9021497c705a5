"""The THD film's heat paths to its walls (issue 20; docs/film-physics.md "Heat paths to the
journal and through the bush or pad"; C++ ``thd_walls.hpp``).

Options (keywords of every THD entry point and keys of the model file's ``[thermal]``):

* ``wall_htc``: ``"given"`` (the film-side heat-transfer coefficients ``journal_htc_w_m2k``,
  ``bush_htc_w_m2k``) or ``"film"`` (the film's own conduction across its thickness h: per
  cell q_J = θ k/h (6 T − 4 T_J − 2 T_w), q_B = θ k/h (6 T − 2 T_J − 4 T_w), the parabolic
  cross-film profile of a uniform viscous heat source; k the oil's
  ``conductivity_w_per_m_k``; the given coefficients must then be 0; a turbulent film,
  ``turbulence = "ng_pan"``, raises the symmetric part 6 θ k/h and the across-film part
  θ k/h by its eddy conductivity at each cell's Re_h and Prandtl number (with the film's
  transition, ``turbulence_onset_re``/``turbulence_full_re``, the factors' excess takes its
  weight: exactly the laminar film's coefficients below the onset): C++
  ``thd_wall_turbulence.hpp``, docs/film-physics.md "The turbulent film's wall heat
  transfer");
* ``journal_wall``: ``"fixed"`` (the journal at ``journal_temperature_c``, None: the supply
  temperature) or ``"balance"`` (the journal's temperature from its own heat balance: zero net
  heat into it over the whole bearing, all its pads; iterated with the film);
* ``bush_wall``: ``"fixed"`` (the bush or pad surface at ``bush_temperature_c``) or
  ``"conduction"`` (1-D conduction through the bush or pad, ``bush_thickness_m`` t,
  ``bush_conductivity_w_per_m_k`` k_b, to its back face, which convects to the surrounding oil
  at ``back_temperature_c`` T_o (None: the supply temperature) with ``back_htc_w_m2k`` h_o:
  q_B = U (T_w − T_o), 1/U = t/k_b + 1/h_o, per film cell; the bush's conduction along its
  surface and its deformation are neglected).
"""

from __future__ import annotations

from rotordyn._common import validate as v
from rotordyn.errors import InputError

WALL_HTC = ("given", "film")
JOURNAL_WALLS = ("fixed", "balance")
BUSH_WALLS = ("fixed", "conduction")
WALL_NUMBERS = ("bush_thickness_m", "bush_conductivity_w_per_m_k", "back_htc_w_m2k")
WALL_OPTIONS = ("wall_htc", "journal_wall", "bush_wall", *WALL_NUMBERS, "back_temperature_c")
"""The wall options beyond the heat-transfer coefficients and wall temperatures."""
WALL_DEFAULTS = {"wall_htc": "given", "journal_wall": "fixed", "bush_wall": "fixed",
                 "bush_thickness_m": 0.0, "bush_conductivity_w_per_m_k": 0.0,
                 "back_htc_w_m2k": 0.0, "back_temperature_c": None}


def check_walls(values: dict, prefix: str = "") -> dict:
    """The wall options ``values`` (names of :data:`WALL_OPTIONS`, missing ones at their
    defaults) checked: choices, numbers >= 0, a finite back temperature or None; the
    combinations the core refuses (an option of the other choice) named here too.
    InputError naming the field (``prefix`` before it, e.g. ``"thermal."``)."""
    out = dict(WALL_DEFAULTS)
    for k, x in values.items():
        if k not in WALL_DEFAULTS:
            raise InputError(f"{prefix}{k}: not a wall option of the THD film "
                             f"({', '.join(WALL_OPTIONS)})")
        out[k] = x
    out["wall_htc"] = v.choice(f"{prefix}wall_htc", out["wall_htc"], WALL_HTC)
    out["journal_wall"] = v.choice(f"{prefix}journal_wall", out["journal_wall"], JOURNAL_WALLS)
    out["bush_wall"] = v.choice(f"{prefix}bush_wall", out["bush_wall"], BUSH_WALLS)
    for f in WALL_NUMBERS:
        x = v.finite(f"{prefix}{f}", out[f])
        if x < 0.0:
            raise InputError(f"{prefix}{f}: expected a value >= 0, got {x}")
        out[f] = x
        if out["bush_wall"] != "conduction" and x != 0.0:
            raise InputError(f"{prefix}{f}: used only with bush_wall = 'conduction', got {x}")
    if out["back_temperature_c"] is not None:
        out["back_temperature_c"] = v.finite(f"{prefix}back_temperature_c",
                                             out["back_temperature_c"])
        if out["bush_wall"] != "conduction":
            raise InputError(f"{prefix}back_temperature_c: used only with bush_wall = "
                             f"'conduction', got {out['back_temperature_c']}")
    return out


def set_walls(o, walls: dict) -> None:
    """Put the checked wall options (:func:`check_walls`) on the core's ``ThdOptions``."""
    o.film_htc = walls["wall_htc"] == "film"
    o.journal_balance = walls["journal_wall"] == "balance"
    o.bush_conduction = walls["bush_wall"] == "conduction"
    for f in WALL_NUMBERS:
        setattr(o, f, float(walls[f]))
    if walls["back_temperature_c"] is not None:
        o.back_temperature_c = float(walls["back_temperature_c"])


def walls_of(o) -> dict:
    """The wall options of a core ``ThdOptions`` (the inverse of :func:`set_walls`)."""
    import math

    return {"wall_htc": "film" if o.film_htc else "given",
            "journal_wall": "balance" if o.journal_balance else "fixed",
            "bush_wall": "conduction" if o.bush_conduction else "fixed",
            **{f: getattr(o, f) for f in WALL_NUMBERS},
            "back_temperature_c": None if math.isnan(o.back_temperature_c)
            else o.back_temperature_c}


__all__ = ["BUSH_WALLS", "JOURNAL_WALLS", "WALL_DEFAULTS", "WALL_HTC", "WALL_OPTIONS",
           "check_walls", "set_walls", "walls_of"]
