"""TOML model files (``schema = "rotordyn/model/1"``): hand-writable, SI, unit-suffixed keys.

Reading rejects unknown keys (with the key's path in the message); writing emits the same
layout, so ``System.from_toml(system.to_toml(), is_text=True) == system``.
"""

from __future__ import annotations

import dataclasses
import math
import re
import tomllib
import warnings

import numpy as np
from pathlib import Path

from rotordyn.bearings import BEARING_TYPES, FlexibleSleeve, Groove, Oil, ThermalFilm, ThermalModel
from rotordyn.errors import InputError, RotordynDeprecationWarning
from rotordyn.model.rotor import STEEL, Disk, Material, Reduction, Rotor, ShaftSection, Support
from rotordyn.model.stage import Stage

SCHEMA = "rotordyn/model/1"
RENAMED_KEYS = {"tilt_stiffness_nm_per_rad": "tilt_stiffness_n_m_per_rad"}
"""Keys of ``[[bearing]]`` tables that were renamed: still read (with a
:class:`~rotordyn.errors.RotordynDeprecationWarning` naming the path), written new."""


def _fields(cls) -> list[str]:
    return [f.name for f in dataclasses.fields(cls)]


def _check_keys(where: str, table: dict, allowed) -> None:
    if not isinstance(table, dict):
        raise InputError(f"{where}: expected a table, got {type(table).__name__}")
    for k in table:
        if k not in allowed:
            raise InputError(f"{where}.{k}: unknown key (allowed: {', '.join(sorted(allowed))})")


def _array_of_tables(where: str, value) -> list[dict]:
    if not isinstance(value, list) or not all(isinstance(t, dict) for t in value):
        raise InputError(f"{where}: expected an array of tables ([[{where}]])")
    return value


def _build(cls, where: str, table: dict, **extra):
    try:
        return cls(**table, **extra)
    except TypeError as exc:  # missing required key
        raise InputError(f"{where}: {exc}") from None
    except InputError as exc:  # a self-checking element: name the file's path, not its kind
        raise type(exc)(at_path(where, str(exc), table)) from None


_HEAD = re.compile(r"^([A-Za-z_]\w*)(\[\d+\])?(?=[.:\[ ])")


def at_path(where: str, message: str, table: dict) -> str:
    """``message`` of an element's own check with its field path rewritten to the model
    file's (``tilting_pad_bearing.n_pads: …`` → ``bearing[0].n_pads: …``, ``speeds_hz: …``
    → ``bearing[1].speeds_hz: …``, ``sleeve.x`` → ``bearing[0].sleeve.x``)."""
    if message.startswith(where):
        return message
    m = _HEAD.match(message)
    if m is None:
        return f"{where}: {message}"
    head = m.group(1)
    if head in table:  # a field of this table (or a nested one) named without the element
        return f"{where}.{message}"
    if message[m.end():].startswith("."):  # the element's kind in place of its path
        return where + message[m.end():]
    return f"{where}: {message}"


def read_text(path, field: str = "model") -> str:
    """The UTF-8 text of a file; InputError naming ``field`` when it is missing, unreadable
    or not UTF-8 (issue 13: a non-UTF-8 model file gave a traceback)."""
    if not isinstance(path, (str, Path)):
        raise InputError(f"{field}: expected a file path, got {type(path).__name__}")
    p = Path(path)
    if not p.is_file():
        raise InputError(f"{field}: no such file {str(p)!r}")
    try:
        return p.read_text(encoding="utf-8")
    except UnicodeDecodeError as exc:
        raise InputError(f"{field}: {str(p)!r} is not UTF-8 text (byte {exc.start})") from None
    except OSError as exc:
        raise InputError(f"{field}: cannot read {str(p)!r}: {exc.strerror}") from None


def parse_toml(text: str, src: str, field: str = "model") -> dict:
    """``tomllib.loads`` with a syntax error as InputError naming ``field`` and the source."""
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"{field}: {src} is not valid TOML: {exc}") from None


def system_fields_from_toml(path_or_text, *, is_text: bool = False) -> dict:
    """Parse a model (path or, with ``is_text=True``, the TOML text) into the keyword arguments
    of ``System`` (which builds and validates itself: :meth:`rotordyn.System.from_toml`)."""
    if is_text:
        if not isinstance(path_or_text, str):
            raise InputError(f"model: expected TOML text, got {type(path_or_text).__name__}")
        doc = parse_toml(path_or_text, "<text>")
    else:
        doc = parse_toml(read_text(path_or_text), str(path_or_text))

    top = {"schema", "name", "description", "material", "rotor", "disk", "support", "reduction",
           "bearing", "gravity_m_s2", "stage", "thermal"}
    _check_keys("model", doc, top)
    if doc.get("schema") != SCHEMA:
        raise InputError(f"schema: expected {SCHEMA!r}, got {doc.get('schema')!r}")

    mats = []
    mat_t = doc.get("material", {})
    _check_keys("material", mat_t, set(mat_t) if isinstance(mat_t, dict) else ())
    for name, t in mat_t.items():
        _check_keys(f"material.{name}", t, set(_fields(Material)) - {"name"})
        mats.append(_build(Material, f"material.{name}", t, name=name))

    rotor_t = doc.get("rotor")
    if rotor_t is None:
        raise InputError("rotor: missing table [rotor] with [[rotor.section]] entries")
    rotor_keys = {"damping_alpha_1_per_s", "damping_beta_s", "damping_rotating"}
    _check_keys("rotor", rotor_t, {"section"} | rotor_keys)
    sections = []
    for i, t in enumerate(_array_of_tables("rotor.section", rotor_t.get("section", []))):
        _check_keys(f"rotor.section[{i}]", t, _fields(ShaftSection))
        sections.append(_build(ShaftSection, f"rotor.section[{i}]", t))
    disks = []
    for i, t in enumerate(_array_of_tables("disk", doc.get("disk", []))):
        _check_keys(f"disk[{i}]", t, _fields(Disk))
        disks.append(_disk_from_table(f"disk[{i}]", t, mats))
    supports = []
    for i, t in enumerate(_array_of_tables("support", doc.get("support", []))):
        _check_keys(f"support[{i}]", t, _fields(Support))
        supports.append(_build(Support, f"support[{i}]", t))
    red_t = doc.get("reduction", {})
    _check_keys("reduction", red_t, _fields(Reduction))
    reduction = _build(Reduction, "reduction", red_t)
    if reduction.n_modes and reduction.method != "craig-bampton":
        # (the Python API keeps n_modes for modes(..., reduction="craig-bampton"); a file
        # that sets it for another method would have it silently ignored)
        raise InputError(f"reduction.n_modes: only method \"craig-bampton\" adds fixed-"
                         f"interface modes; got n_modes = {reduction.n_modes} with method "
                         f"{reduction.method!r} (set method = \"craig-bampton\" or drop n_modes)")

    bearings = [_bearing_from_table(f"bearing[{i}]", t)
                for i, t in enumerate(_array_of_tables("bearing", doc.get("bearing", [])))]

    stages = []
    for i, t in enumerate(_array_of_tables("stage", doc.get("stage", []))):
        _check_keys(f"stage[{i}]", t, _fields(Stage))
        stages.append(_build(Stage, f"stage[{i}]", t))

    kwargs = {}
    if "thermal" in doc:
        kwargs["thermal"] = _thermal_from_table(doc["thermal"])
    if stages:
        kwargs["stages"] = tuple(stages)
    if "gravity_m_s2" in doc:
        kwargs["gravity_m_s2"] = doc["gravity_m_s2"]
    if mats:
        kwargs["materials"] = tuple(mats)
    # (Rotor's own messages name rotor.damping_* and disk[i] already)
    rotor = Rotor(tuple(sections), tuple(disks),
                  **{k: rotor_t[k] for k in rotor_keys if k in rotor_t})
    return dict(rotor=rotor, supports=tuple(supports),
                reduction=reduction, bearings=tuple(bearings), name=doc.get("name", ""),
                description=doc.get("description", ""), **kwargs)


def _disk_from_table(where: str, t: dict, mats: list):
    """A disk by its inertias, or by its geometry and material (inertias computed)."""
    inertia = {"mass_kg", "ip_kg_m2", "id_kg_m2"}
    if "station" not in t:
        raise InputError(f"{where}.station: missing (the station the disk sits at)")
    if inertia & set(t):
        if inertia - set(t):
            raise InputError(f"{where}: the inertias come as all of mass_kg, ip_kg_m2, "
                             f"id_kg_m2 (missing {sorted(inertia - set(t))}), or give the "
                             "geometry (outer_diameter_m, width_m, material) instead")
        return _build(Disk, where, t)
    need = {"outer_diameter_m", "width_m", "material"} - set(t)
    if need:
        raise InputError(f"{where}: expected mass_kg, ip_kg_m2, id_kg_m2, or the geometry "
                         f"(outer_diameter_m, width_m, material; missing {sorted(need)})")
    known = {m.name: m for m in mats} or {STEEL.name: STEEL}
    mat = known.get(t["material"])
    if mat is None:
        raise InputError(f"{where}.material: expected one of {sorted(known)}, got "
                         f"{t['material']!r}")
    try:
        return Disk.from_geometry(t["station"], mat, t["width_m"], t["outer_diameter_m"],
                                  t.get("inner_diameter_m", 0.0), t.get("name", ""))
    except InputError as exc:  # "disk.width_m: …" → "disk[2].width_m: …"
        raise type(exc)(at_path(where, str(exc), t)) from None


def _thermal_from_table(t: dict) -> ThermalModel:
    """``[thermal]`` (the oil system), ``[thermal.oil]`` and ``[[thermal.film]]`` entries."""
    _check_keys("thermal", t, (set(_fields(ThermalModel)) - {"films"}) | {"film"})
    t = dict(t)
    if "supply_temperature_c" not in t:
        raise InputError("thermal.supply_temperature_c: missing (the oil's supply "
                         "temperature, degC)")
    if "oil" in t:
        _check_keys("thermal.oil", t["oil"], _fields(Oil))
        t["oil"] = _build(Oil, "thermal.oil", t["oil"])
    films = []
    for i, f in enumerate(_array_of_tables("thermal.film", t.pop("film", []))):
        _check_keys(f"thermal.film[{i}]", f, _fields(ThermalFilm))
        films.append(_build(ThermalFilm, f"thermal.film[{i}]", f))
    return _build(ThermalModel, "thermal", t, films=tuple(films))


def _bearing_from_table(where: str, t: dict):
    t = dict(t)
    kind = t.pop("type", None)
    if not isinstance(kind, str) or kind not in BEARING_TYPES:
        raise InputError(f"{where}.type: expected one of {sorted(BEARING_TYPES)}, got {kind!r}")
    cls = BEARING_TYPES[kind]
    _check_keys(where, t, _fields(cls))
    for old, new in RENAMED_KEYS.items():
        if old in t:
            if new in t:
                raise InputError(f"{where}.{old}: the old name of {new}; give one of them")
            warnings.warn(f"{where}.{old} is renamed {new} (N·m/rad; 'nm' reads as "
                          "nanometres); the old key is read for now", RotordynDeprecationWarning,
                          stacklevel=2)
            t[new] = t.pop(old)
    grooves = []
    for j, g in enumerate(_array_of_tables(f"{where}.grooves", t.pop("grooves", []))):
        _check_keys(f"{where}.grooves[{j}]", g, _fields(Groove))
        grooves.append(_build(Groove, f"{where}.grooves[{j}]", g))
    if "sleeve" in t:
        st = t.pop("sleeve")
        _check_keys(f"{where}.sleeve", st, _fields(FlexibleSleeve))
        if "master_stations" in st:
            ms = st["master_stations"]
            if not isinstance(ms, list):
                raise InputError(f"{where}.sleeve.master_stations: expected a list of "
                                 f"integers, got {ms!r}")
            st = dict(st, master_stations=tuple(ms))
        t["sleeve"] = _build(FlexibleSleeve, f"{where}.sleeve", st)
    if "grooves" in _fields(cls):
        return _build(cls, where, t, grooves=tuple(grooves))
    if grooves:
        raise InputError(f"{where}.grooves: type {kind!r} has no grooves")
    return _build(cls, where, t)


# -- writing ----------------------------------------------------------------------------
def _val(x) -> str:
    if isinstance(x, (bool, np.bool_)):
        return "true" if x else "false"
    if isinstance(x, (int, np.integer)):
        return str(int(x))
    if isinstance(x, (float, np.floating)):
        x = float(x)
        if math.isnan(x) or math.isinf(x):
            raise InputError(f"to_toml: cannot write non-finite value {x!r}")
        return repr(x)
    if isinstance(x, str):
        return '"' + x.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'
    if isinstance(x, (tuple, list)):
        return "[" + ", ".join(_val(e) for e in x) + "]"
    raise InputError(f"to_toml: cannot write value {x!r}")


def _table_lines(obj, skip=(), defaults_too=False) -> list[str]:
    out = []
    for f in dataclasses.fields(obj):
        if f.name in skip:
            continue
        val = getattr(obj, f.name)
        if val is None:
            continue
        if not defaults_too and f.default is not dataclasses.MISSING and val == f.default \
                and f.name not in ("type",):
            continue
        out.append(f"{f.name} = {_val(val)}")
    return out


def system_to_toml(system) -> str:
    """TOML text of a ``System`` in the layout :func:`system_fields_from_toml` reads."""
    lines = [f'schema = "{SCHEMA}"']
    if system.name:
        lines.append(f"name = {_val(system.name)}")
    if system.description:
        lines.append(f"description = {_val(system.description)}")
    for m in system.materials:
        lines += ["", f"[material.{m.name}]"] + _table_lines(m, skip=("name",), defaults_too=True)
    lines += ["", "[rotor]"] + _table_lines(system.rotor, skip=("sections", "disks"))
    for s in system.rotor.sections:
        lines += ["", "[[rotor.section]]"] + _table_lines(s)
    for d in system.rotor.disks:
        lines += ["", "[[disk]]"] + _table_lines(d)
    for s in system.supports:
        lines += ["", "[[support]]"] + _table_lines(s)
    # n_modes only where the file's method uses it (the reader refuses it elsewhere)
    lines += ["", "[reduction]"] + _table_lines(
        system.reduction, defaults_too=True,
        skip=() if system.reduction.method == "craig-bampton" else ("n_modes",))
    kinds = {cls: name for name, cls in BEARING_TYPES.items()}
    for b in system.bearings:
        lines += ["", "[[bearing]]", f"type = {_val(kinds[type(b)])}"]
        lines += _table_lines(b, skip=("grooves", "sleeve"))
        if getattr(b, "grooves", ()):
            gs = ", ".join("{" + ", ".join(f"{f.name} = {_val(getattr(g, f.name))}"
                                           for f in dataclasses.fields(g)) + "}"
                           for g in b.grooves)
            lines.append(f"grooves = [{gs}]")
        if getattr(b, "sleeve", None) is not None:
            lines += ["", "[bearing.sleeve]"] + _table_lines(b.sleeve, defaults_too=True)
    for st in getattr(system, "stages", ()):
        lines += ["", "[[stage]]"] + _table_lines(st)
    th = getattr(system, "thermal", None)
    if th is not None:
        lines += ["", "[thermal]"] + _table_lines(th, skip=("oil", "films"), defaults_too=True)
        lines += ["", "[thermal.oil]"] + _table_lines(th.oil, defaults_too=True)
        for f in th.films:
            lines += ["", "[[thermal.film]]"] + _table_lines(f, defaults_too=True)
    if system.gravity_m_s2 != 9.81:
        lines.insert(1, f"gravity_m_s2 = {_val(system.gravity_m_s2)}")
    return "\n".join(lines) + "\n"
