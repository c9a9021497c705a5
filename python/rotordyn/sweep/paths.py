"""Model fields as sweep axes: the dotted paths of :mod:`rotordyn.model.paths` (moved there so
that the analyses — a continuation over a model field — use them without importing the sweep
room)."""

from rotordyn.model.paths import get_field, set_field, set_fields  # noqa: F401

__all__ = ["get_field", "set_field", "set_fields"]
