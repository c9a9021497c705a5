"""Guards the build: the C++ core imports and reports the library versions it was built with."""

import subprocess
import sys

import rotordyn


def test_build_info_has_library_versions():
    info = rotordyn.build_info()
    assert info["eigen"].startswith("3.4")
    assert info["sundials"].split(".")[0] in {"6", "7"}
    assert info["suitesparse"].startswith("5.") or info["suitesparse"].startswith("7.")
    assert info["rotordyn"] == rotordyn.__version__


def test_cli_info_prints_versions():
    out = subprocess.run(
        [sys.executable, "-m", "rotordyn.cli", "info"], capture_output=True, text=True, check=True
    ).stdout
    assert "rotordyn" in out and "eigen" in out and "sundials" in out and "suitesparse" in out


def test_errors_form_one_hierarchy():
    assert issubclass(rotordyn.InputError, rotordyn.RotordynError)
    assert issubclass(rotordyn.InputError, ValueError)
    assert issubclass(rotordyn.ConvergenceError, rotordyn.RotordynError)
    assert issubclass(rotordyn.ContactError, RuntimeError)
