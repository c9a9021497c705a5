"""Built-in models: the reference paper's three-bearing test rig and textbook rotors.

Each is a TOML file under ``rotordyn/model/data/`` (read with :meth:`System.from_toml`), so the
values and their sources are in one hand-readable place.
"""

from __future__ import annotations

from importlib import resources

from rotordyn.errors import InputError
from rotordyn.model.system import System

BUILTIN = {
    "paper-rig": "paper_rig.toml",
    "paper-rig-hs": "paper_rig_hs.toml",
    "friswell-5.9.1": "friswell_5_9_1.toml",
}


def _load(filename: str) -> System:
    text = resources.files("rotordyn.model.data").joinpath(filename).read_text(encoding="utf-8")
    return System.from_toml(text, is_text=True)


def paper_rig() -> System:
    """The three-bearing test rig of the reference paper (§6); see docs/paper-rig.md."""
    return _load(BUILTIN["paper-rig"])


def paper_rig_hs() -> System:
    """The paper's rig with the half-Sommerfeld (Gümbel) film, its sleeve and chamber fitted to
    Table 1 and the instability threshold 0.098 MPa together (docs/paper-rig.md, "Cavitation
    model"): reproduces the threshold, misses Table 1 by up to ~0.035 c. ``paper_rig()``
    (Swift–Stieber) is the other choice: Table 1 within 0.01 c, threshold 0.057 MPa."""
    return _load(BUILTIN["paper-rig-hs"])


def friswell_5_9_1() -> System:
    """Friswell, Penny, Garvey & Lees (2010), Dynamics of Rotating Machines, Example 5.9.1:
    1.5 m shaft, two disks, isotropic 1 MN/m bearings."""
    return _load(BUILTIN["friswell-5.9.1"])


def load(name_or_path: str) -> System:
    """A built-in model by name (``paper-rig``, ``paper-rig-hs``, ``friswell-5.9.1``) or a TOML
    file path."""
    if name_or_path in BUILTIN:
        return _load(BUILTIN[name_or_path])
    if name_or_path.endswith(".toml"):
        return System.from_toml(name_or_path)
    raise InputError(
        f"model: expected a TOML path or one of {sorted(BUILTIN)}, got {name_or_path!r}")
