"""The coarse-film models the nonlinear tests share: the paper rig with its active bearing's
film on 36 × 6 nodes, and the plain-bearing compressor (tests/data/models/
compressor_plain.toml, the model off the rig) with both films on 36 × 6 nodes."""

import dataclasses
from pathlib import Path

import rotordyn as rd

MODELS = Path(__file__).parent / "data" / "models"


def paper_rig():
    """The paper rig, its first (active) bearing's film on 36 × 6 nodes."""
    rig = rd.models.paper_rig()
    b = rig.bearings[0]
    return dataclasses.replace(rig, bearings=(dataclasses.replace(b, n_circ=36, n_axial=6),)
                               + tuple(rig.bearings[1:]))


def compressor_plain():
    """The compressor on plain bearings, both films on 36 × 6 nodes."""
    s = rd.System.from_toml(MODELS / "compressor_plain.toml")
    return dataclasses.replace(s, bearings=tuple(dataclasses.replace(b, n_circ=36, n_axial=6)
                                                 for b in s.bearings))
