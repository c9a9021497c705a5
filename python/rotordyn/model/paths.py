"""Any model field as a sweep axis: a dotted path into the frozen :class:`System`, validated
against the model when the spec loads, and applied by rebuilding the dataclasses along the
path (:func:`dataclasses.replace`, so every ``__post_init__``/``check`` runs again).

Path grammar: ``<field>(.<field> | .<index> | .<name> | .*)*``. Tuple fields (``bearings``,
``rotor.disks``, ``rotor.sections``, ``supports``, ``materials``) take an integer index, an
element's ``name`` (spaces may be written as ``_``), ``active`` for the active journal
bearing(s), or ``*`` for every element. Examples: ``bearings.active.clearance_m``,
``bearings.*.config_ay_m``, ``rotor.disks.1.mass_kg``, ``gravity_m_s2``.
"""

from __future__ import annotations

import dataclasses
import math

from rotordyn.errors import ClosedFilmError, FieldCombinationError, InputError


def _fields(obj) -> list[str]:
    return [f.name for f in dataclasses.fields(obj)]


# an empty ``thermal.films``: the [thermal] table gives every film its values, and a bearing's
# own values need an entry of its own (a film by its bearing's name is not made up: its other
# keys would take the class defaults, not the [thermal] values)
_NO_FILMS = (" (the model's [thermal] has no [[thermal.film]] entry: add one, bearing = "
             "\"<the bearing's name>\", to give that bearing's film values of its own, or sweep "
             "the [thermal] value for every film, e.g. thermal.carry_over)")


def _select(seq: tuple, key: str, where: str, starred: bool = False) -> list[int]:
    """Indices of the elements of tuple ``seq`` addressed by ``key``. An empty ``seq`` is an
    InputError ('*' too: a path that sets nothing would be an axis that varies nothing),
    except for '*' under a parent '*' (``starred``: ``bearings.*.grooves.*`` over a bearing
    without grooves selects none of its grooves; :func:`set_field` refuses a path whose
    every selection is empty)."""
    if not seq and key == "*" and starred:
        return []
    if not seq:
        raise InputError(f"{where}: no element {key!r}: the model has none here"
                         + (_NO_FILMS if ".films." in f".{where}." else ""))
    if key == "*":
        return list(range(len(seq)))
    if key.lstrip("-").isdigit():
        i = int(key)
        if not 0 <= i < len(seq):
            raise InputError(f"{where}: index {i} out of range (0..{len(seq) - 1})")
        return [i]
    if key == "active":
        from rotordyn.bearings import ActiveJournalBearing

        idx = [i for i, b in enumerate(seq) if isinstance(b, ActiveJournalBearing)]
        if idx:
            return idx
    names = [getattr(e, "name", "") for e in seq]
    idx = [i for i, n in enumerate(names) if n and (n == key or n.replace(" ", "_") == key)]
    if not idx:
        listed = ", ".join(repr(n) for n in names if n)
        raise InputError(f"{where}: no element {key!r} (an index 0..{len(seq) - 1}, '*', "
                         f"'active' or a name: {listed})")
    return idx


# Fields that hold an array when set (None by default) and are never a sweep axis.
_ARRAY_FIELDS = {"viscosity_field_pa_s": "a frozen viscosity per film node, set by a thermal "
                                         "equilibrium"}


def declared_type(obj, name: str) -> str:
    """The annotation of the dataclass field ``name`` of ``obj`` as text ("" if none)."""
    if dataclasses.is_dataclass(obj):
        for f in dataclasses.fields(obj):
            if f.name == name:
                return f.type if isinstance(f.type, str) else getattr(f.type, "__name__",
                                                                      str(f.type))
    return ""


def _coerce(old, value, where: str, declared: str = ""):
    """The new value in the type of the field it replaces (ints stay ints, unless the field
    is declared a float: a TOML integer such as ``mass_kg = 30`` takes 30.5)."""
    name = where.rsplit(".", 1)[-1]
    if name in _ARRAY_FIELDS:
        raise InputError(f"{where}: not a numeric field ({_ARRAY_FIELDS[name]}); "
                         "only numbers can be swept")
    if isinstance(old, bool) or not isinstance(old, (int, float)) and old is not None:
        raise InputError(f"{where}: not a numeric field (holds {type(old).__name__}); "
                         "only numbers can be swept")
    if isinstance(old, int) and "float" not in declared:
        if not float(value).is_integer():
            raise InputError(f"{where}: expected an integer, got {value!r}")
        return int(value)
    return float(value)


def _set(obj, parts: list[str], value, where: str, hits: list, starred: bool = False):
    head, rest = parts[0], parts[1:]
    here = f"{where}.{head}" if where else head
    if not dataclasses.is_dataclass(obj):
        raise InputError(f"{here}: {where or 'model'} has no fields")
    if head not in _fields(obj):
        raise InputError(f"unknown field {here!r} (allowed here: {', '.join(_fields(obj))})")
    cur = getattr(obj, head)
    if isinstance(cur, tuple):
        if not rest:
            raise InputError(f"{here}: a list; address one element (index, name or '*')")
        idx = _select(cur, rest[0], f"{here}.{rest[0]}", starred)
        below = starred or rest[0] == "*"
        new = list(cur)
        for i in idx:
            if len(rest) == 1:
                new[i] = _coerce(new[i], value, f"{here}.{i}")
                hits.append(i)
            else:
                new[i] = _set(new[i], rest[1:], value, f"{here}.{rest[0]}", hits, below)
        return dataclasses.replace(obj, **{head: tuple(new)})
    if rest:
        return dataclasses.replace(obj, **{head: _set(cur, rest, value, here, hits, starred)})
    hits.append(head)
    return dataclasses.replace(obj, **{head: _coerce(cur, value, here,
                                                     declared_type(obj, head))})


def set_fields(system, items, where: str = "grid"):
    """A copy of ``system`` with every (dotted path, value) of ``items`` set (each by
    :func:`set_field`). A fault of a combination of fields met on the way — an intermediate
    model, e.g. a transition's onset set above the full Re_h the next item raises — is
    retried after the others, so the order of the items does not matter; the first such
    fault is raised only when no item can be set any more."""
    pending, s = list(items), system
    while pending:
        left, first = [], None
        for path, value in pending:
            try:
                s = set_field(s, path, value, where)
            except FieldCombinationError as exc:
                left.append((path, value))
                first = first or exc
        if len(left) == len(pending):
            raise first
        pending = left
    return s


def set_field(system, path: str, value, where: str = "grid"):
    """A copy of ``system`` with the field at dotted ``path`` set to ``value`` (validated by
    the model's own checks; an InputError names ``where``.path)."""
    if not isinstance(value, (int, float)) or isinstance(value, bool) or not math.isfinite(value):
        raise InputError(f"{where}.{path}: expected a finite number, got {value!r}")
    hits: list = []
    try:
        out = _set(system, path.split("."), value, "", hits)
        if not hits:  # every '*' selected an empty list: an axis that would vary nothing
            raise InputError("no element: every list its '*' selects is empty in this model"
                             + (_NO_FILMS if ".films." in f".{path}." else ""))
        return out
    except InputError as exc:  # a combination's fault stays one (a sweep point's row)
        cls = (ClosedFilmError if isinstance(exc, ClosedFilmError) else FieldCombinationError
               if isinstance(exc, FieldCombinationError) else InputError)
        raise cls(f"{where}.{path}: {exc}") from None
    except (TypeError, ValueError) as exc:
        raise InputError(f"{where}.{path}: {exc}") from None


def get_field(system, path: str):
    """The current value(s) of dotted ``path`` (a list when ``*`` selects several)."""
    def get(obj, parts, starred=False):
        if not parts:
            return [obj]
        head, rest = parts[0], parts[1:]
        cur = getattr(obj, head)
        if isinstance(cur, tuple):
            out = []
            for i in _select(cur, rest[0], head, starred):
                out += get(cur[i], rest[1:], starred or rest[0] == "*")
            return out
        return get(cur, rest, starred)
    return get(system, path.split("."))
