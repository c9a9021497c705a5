"""Guards the package layout (issue 23): the import graph of ``python/rotordyn`` has no circle,
no module imports the package root, and no import runs against the layer order of the rooms
written in docs/architecture.md (the table between ``<!-- layers`` and ``<!-- /layers -->``).

The graph is built from the sources with ``ast``: every ``import`` and ``from ... import``,
at module level or inside a function (a lazy import is still a dependency), relative imports
resolved; ``from pkg import name`` is an edge to ``pkg.name`` when that is a module of the tree,
else to ``pkg``. Importing ``pkg.sub`` also runs ``pkg/__init__``, but that is Python's order of
execution, not a dependency of the importer, so it is not an edge. The checker is tested on
small synthetic trees (a circle, an upward import, an import of the root) so that it can fail.

Also guards that every public name of the package before the re-layout is still importable
where it was (the one name that moved says where it went)."""

from __future__ import annotations

import ast
import importlib
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "python" / "rotordyn"
ARCHITECTURE = ROOT / "docs" / "architecture.md"
EXTENSIONS = ("_core",)  # compiled modules of the package (no .py source)


def module_files(pkg_dir: Path) -> dict[str, Path]:
    """Dotted module name -> file for every .py under ``pkg_dir`` (packages by __init__)."""
    name = pkg_dir.name
    out = {}
    for f in sorted(pkg_dir.rglob("*.py")):
        parts = (name,) + f.relative_to(pkg_dir).with_suffix("").parts
        if parts[-1] == "__init__":
            parts = parts[:-1]
        out[".".join(parts)] = f
    return out


def import_graph(pkg_dir: Path, extensions=EXTENSIONS) -> dict[str, set[str]]:
    """module -> the package modules it imports (all imports, lazy ones included)."""
    files = module_files(pkg_dir)
    pkg = pkg_dir.name
    known = set(files) | {f"{pkg}.{e}" for e in extensions}
    graph: dict[str, set[str]] = {}
    for mod, f in files.items():
        is_pkg = f.name == "__init__.py"
        deps: set[str] = set()
        for node in ast.walk(ast.parse(f.read_text(encoding="utf-8"), str(f))):
            if isinstance(node, ast.Import):
                for a in node.names:
                    if a.name == pkg or a.name.startswith(pkg + "."):
                        deps.add(a.name)
            elif isinstance(node, ast.ImportFrom):
                if node.level:
                    base = mod.split(".") if is_pkg else mod.split(".")[:-1]
                    base = base[:len(base) - (node.level - 1)]
                    src = ".".join(base + ([node.module] if node.module else []))
                else:
                    src = node.module or ""
                if not (src == pkg or src.startswith(pkg + ".")):
                    continue
                for a in node.names:
                    sub = f"{src}.{a.name}"
                    deps.add(sub if sub in known else src)
        unknown = {d for d in deps if d not in known}
        assert not unknown, f"{mod} imports modules that do not exist: {sorted(unknown)}"
        graph[mod] = deps - {mod}
    return graph


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components with more than one module (Tarjan), sorted."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on: set[str] = set()
    out: list[list[str]] = []
    counter = [0]

    def visit(v: str) -> None:
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return sorted(out)


def read_layers(text: str) -> dict[str, int]:
    """room -> layer from the markdown table between the layer markers."""
    m = re.search(r"<!-- layers.*?-->(.*?)<!-- /layers -->", text, re.S)
    assert m, "docs/architecture.md: no <!-- layers --> table"
    layers = {}
    for line in m.group(1).splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) < 2 or not cells[0].isdigit():
            continue
        for room in re.findall(r"`([A-Za-z_][A-Za-z0-9_]*)`", cells[1]):
            layers[room] = int(cells[0])
    return layers


def room_of(module: str) -> str | None:
    """The room of ``pkg.room...``; None for the package root."""
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else None


def violations(graph: dict[str, set[str]], layers: dict[str, int], pkg: str) -> list[str]:
    """Imports of the root, modules outside every room, and imports against the layers."""
    bad = []
    for mod, deps in sorted(graph.items()):
        src = room_of(mod)
        if src is not None and src not in layers:
            bad.append(f"{mod}: room {src!r} is not in the layer table")
            continue
        for d in sorted(deps):
            dst = room_of(d)
            if dst is None:
                bad.append(f"{mod} imports the package root {pkg!r} (a table of contents)")
            elif src is not None and dst in layers and layers[dst] > layers[src]:
                bad.append(f"{mod} (room {src}, layer {layers[src]}) imports {d} (room {dst}, "
                           f"layer {layers[dst]})")
    return bad


# -- the package -----------------------------------------------------------------------------
@pytest.fixture(scope="module")
def graph():
    return import_graph(PACKAGE)


def test_no_import_circle(graph):
    found = cycles(graph)
    assert not found, "import circles:\n" + "\n".join(" <-> ".join(c) for c in found)


def test_imports_follow_the_layers(graph):
    layers = read_layers(ARCHITECTURE.read_text(encoding="utf-8"))
    assert layers["_common"] < layers["bearings"] < layers["model"] < layers["analysis"] \
        < layers["sweep"] < layers["cli"]
    bad = violations(graph, layers, PACKAGE.name)
    assert not bad, "imports against docs/architecture.md:\n" + "\n".join(bad)


def test_every_room_is_in_the_table():
    """A new room (sub-package or top-level module) must be given its layer in the docs."""
    layers = read_layers(ARCHITECTURE.read_text(encoding="utf-8"))
    rooms = {p.name for p in PACKAGE.iterdir() if p.is_dir() and (p / "__init__.py").exists()}
    rooms |= {p.stem for p in PACKAGE.glob("*.py") if p.name != "__init__.py"}
    rooms |= set(EXTENSIONS)
    assert rooms == set(layers), f"rooms {sorted(rooms ^ set(layers))} differ from the table"


def test_root_holds_only_the_table_of_contents():
    """The root has the re-exports, the base modules and the ``python -m`` entry point (which
    imports the CLI only); no feature module."""
    tops = sorted(p.name for p in PACKAGE.glob("*.py"))
    assert tops == ["__init__.py", "__main__.py", "errors.py", "units.py"]
    main_graph = import_graph(PACKAGE)["rotordyn.__main__"]
    assert main_graph == {"rotordyn.cli"}, main_graph
    tree = ast.parse((PACKAGE / "__init__.py").read_text(encoding="utf-8"))
    defs = [n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))]
    assert defs == [], f"the root defines {defs}: define them in a room and re-export"


# -- the checker itself can fail --------------------------------------------------------------
def _tree(tmp_path, files: dict[str, str]) -> Path:
    pkg = tmp_path / "pk"
    for rel, text in files.items():
        f = pkg / rel
        f.parent.mkdir(parents=True, exist_ok=True)
        f.write_text(text)
    return pkg


LAYERS = "<!-- layers -->\n| 0 | `low` | x |\n| 1 | `high` | y |\n<!-- /layers -->"


def test_checker_finds_a_lazy_circle(tmp_path):
    pkg = _tree(tmp_path, {
        "__init__.py": "",
        "low/__init__.py": "",
        "low/a.py": "def f():\n    from pk.low.b import g\n",
        "low/b.py": "from pk.low import a\n",
    })
    assert cycles(import_graph(pkg, ())) == [["pk.low.a", "pk.low.b"]]


def test_checker_finds_an_upward_import_and_a_root_import(tmp_path):
    pkg = _tree(tmp_path, {
        "__init__.py": "from pk.high import h\n",
        "low/__init__.py": "",
        "low/a.py": "def f():\n    from ..high.h import x\n",
        "low/b.py": "import pk\n",
        "high/__init__.py": "",
        "high/h.py": "from pk.low import a\nx = 1\n",
    })
    g = import_graph(pkg, ())
    assert g["pk.low.a"] == {"pk.high.h"}  # the relative, lazy import resolved
    bad = violations(g, read_layers(LAYERS), "pk")
    assert any(b.startswith("pk.low.a (room low, layer 0) imports pk.high.h") for b in bad)
    assert any(b.startswith("pk.low.b imports the package root") for b in bad)
    assert len(bad) == 2  # high -> low and the root's re-export are allowed


# -- public names --------------------------------------------------------------------------
# Every public name (the ``__all__`` of the root and of each sub-package) before the
# re-layout of issue 23, and the module paths the docs and README name.
PUBLIC = """
rotordyn.__version__ rotordyn.build_info rotordyn.set_blas_threads rotordyn.get_blas_threads
rotordyn.RotordynError rotordyn.InputError rotordyn.ConvergenceError rotordyn.ContactError
rotordyn.SundialsError rotordyn.Material rotordyn.STEEL rotordyn.ShaftSection rotordyn.Disk
rotordyn.Support rotordyn.Rotor rotordyn.Reduction rotordyn.System rotordyn.FluidFilmBearing
rotordyn.ActiveJournalBearing rotordyn.FlexibleSleeve rotordyn.paper_rig_sleeve rotordyn.models
rotordyn.JournalBearing rotordyn.Groove rotordyn.BearingEquilibrium rotordyn.FilmResult
rotordyn.PressureField rotordyn.modes rotordyn.rotor_campbell rotordyn.campbell
rotordyn.equilibrium rotordyn.linearize rotordyn.stability rotordyn.threshold
rotordyn.stability_boundary rotordyn.unbalance_response rotordyn.statespace rotordyn.transient
rotordyn.ModesResult rotordyn.LinearModel rotordyn.StabilityResult rotordyn.CampbellResult
rotordyn.EquilibriumResult rotordyn.SleeveResult
rotordyn.analysis.campbell rotordyn.analysis.modes rotordyn.analysis.rotor_campbell
rotordyn.analysis.equilibrium rotordyn.analysis.linearize rotordyn.analysis.stability
rotordyn.analysis.threshold rotordyn.analysis.stability_boundary
rotordyn.analysis.unbalance_response rotordyn.analysis.statespace rotordyn.analysis.transient
rotordyn.analysis.RotorMatrices
rotordyn.bearings.CoefficientTable rotordyn.bearings.FixedGeometryBearing
rotordyn.bearings.SqueezeFilmDamper rotordyn.bearings.TableBearing
rotordyn.bearings.TiltingPadBearing rotordyn.bearings.end_plate_seal_conductance
rotordyn.bearings.long_damper_orbit_forces rotordyn.bearings.short_damper_orbit_forces
rotordyn.bearings.to_ross_bearing
rotordyn.control.Actuator rotordyn.control.Controller rotordyn.control.PressureSchedule
rotordyn.control.SpeedProfile rotordyn.control.measurement_matrix
rotordyn.model.FluidFilmBearing rotordyn.model.ActiveJournalBearing rotordyn.model.Material
rotordyn.model.STEEL rotordyn.model.ShaftSection rotordyn.model.Disk rotordyn.model.Support
rotordyn.model.Rotor rotordyn.model.Reduction rotordyn.model.System
rotordyn.plot.KINDS rotordyn.plot.AXIS_LABEL rotordyn.plot.AXIS_SCALE rotordyn.plot.COLUMN_IN
rotordyn.plot.PAGE_IN rotordyn.plot.RC rotordyn.plot.plot_dataset rotordyn.plot.stability_map
rotordyn.plot.stability_map_grid rotordyn.plot.equilibrium_loci rotordyn.plot.boundary_curve
rotordyn.plot.campbell rotordyn.plot.campbell_arrays rotordyn.plot.campbell_diagram
rotordyn.plot.waterfall rotordyn.plot.runup_spectra rotordyn.plot.bode rotordyn.plot.polar
rotordyn.plot.rotor_drawing rotordyn.plot.mode_shape rotordyn.plot.mode_shapes_2d
rotordyn.plot.orbits_3d rotordyn.plot.deflected_shape
rotordyn.results.ModesResult rotordyn.results.CampbellResult rotordyn.results.EquilibriumResult
rotordyn.results.LinearModel rotordyn.results.StabilityResult rotordyn.results.ThresholdResult
rotordyn.results.BoundaryResult rotordyn.results.UnbalanceResult
rotordyn.results.StateSpaceResult rotordyn.results.TransientResult
rotordyn.sweep.SweepSpec rotordyn.sweep.SweepResult rotordyn.sweep.SweepDataset
rotordyn.sweep.SweepInterrupted rotordyn.sweep.run_sweep rotordyn.sweep.read_dataset
rotordyn.sweep.open rotordyn.sweep.open_dataset
rotordyn.errors.RotordynWarning rotordyn.errors.UnitWarning
rotordyn.units.hz_to_rad_s rotordyn.units.rad_s_to_hz rotordyn.units.rpm_to_rad_s
rotordyn.units.rad_s_to_rpm
rotordyn.control.plant.plant rotordyn.control.reduction.modal_truncation
rotordyn.control.closedloop.closed_loop rotordyn.control.lqr.lqr rotordyn.control.lqr.lqg
rotordyn.control.pid.tune_pd rotordyn.control.pid.pid rotordyn.control.schedule.pressure_schedule
rotordyn.control.synchronous.synchronous_bound rotordyn.control.threshold.closed_loop_threshold
rotordyn.control.hinf.hinf rotordyn.analysis.assembly.assembled
rotordyn.analysis.tracking.track_modes rotordyn.sweep.paths.set_field
rotordyn.results.equilibrium.CONVERGED rotordyn.results.modes.WHIRL_PLANAR_TOL
rotordyn.results.modes.whirl_index rotordyn.results.modes.whirl_label
rotordyn.cli.main rotordyn.report.run rotordyn.report.mark
""".split()

MOVED = {
    # a whole-system converter, so it lives with the model (a bearing element cannot import
    # the System without a circle: the System holds the elements)
    "rotordyn.bearings.system_from_ross": "rotordyn.model.system_from_ross",
}


def _resolve(dotted: str):
    mod, _, name = dotted.rpartition(".")
    return getattr(importlib.import_module(mod), name)


@pytest.mark.parametrize("dotted", PUBLIC)
def test_public_name_is_importable(dotted):
    assert _resolve(dotted) is not None


@pytest.mark.parametrize("old,new", sorted(MOVED.items()))
def test_moved_name_is_at_its_new_place(old, new):
    assert callable(_resolve(new))
    assert _resolve("rotordyn." + new.rpartition(".")[2]) is _resolve(new)
