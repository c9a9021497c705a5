"""rotordyn exceptions; every error raised by rotordyn subclasses :class:`RotordynError`.

``InputError`` (also a ``ValueError``) names the offending field and its allowed range;
``ConvergenceError``, ``ContactError`` and ``SundialsError`` (also ``RuntimeError``) come from
the solvers. The classes are created by the C++ core so that C++ exceptions map onto them.
"""

from rotordyn._core import (  # noqa: F401
    ContactError,
    ConvergenceError,
    InputError,
    RotordynError,
    SundialsError,
)

__all__ = ["RotordynError", "InputError", "ConvergenceError", "ContactError", "SundialsError"]
