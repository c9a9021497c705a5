"""The package version and the versions of the libraries the C++ core was built with
(recorded in every sweep manifest)."""

from __future__ import annotations

from rotordyn import _core

__version__ = "0.1.0"
DESCRIPTION = ("rotordyn: vibration analysis and control-law synthesis of multi-bearing rotors on "
               "fluid-film and active journal bearings (C++ core, Python API).")


def build_info() -> dict[str, str]:
    """Versions of rotordyn and of the Eigen, SUNDIALS and SuiteSparse it was built with."""
    info = dict(_core.build_info())
    info["python_package"] = __version__
    return info
