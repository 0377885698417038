"""The layer map of ARCHITECTURE.md holds for navcore's imports (tools/import_layers.py).

Oracle for the checker itself: small synthetic packages written here, whose arrows and cycles
are known by construction.
"""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent


def _load_tool():
    spec = importlib.util.spec_from_file_location("import_layers", ROOT / "tools" / "import_layers.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules["import_layers"] = module
    spec.loader.exec_module(module)
    return module


layers_tool = _load_tool()


def _package(tmp_path: Path, files: dict[str, str], table: str) -> tuple[Path, Path]:
    """Write a package ``navcore`` under tmp_path with these files and a map with this table."""
    for rel, text in files.items():
        path = tmp_path / "navcore" / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    arch = tmp_path / "ARCHITECTURE.md"
    arch.write_text("| layer | modules | what |\n| --- | --- | --- |\n" + table)
    return tmp_path / "navcore", arch


def _kinds(findings) -> list[tuple[str, str]]:
    return [(f.kind, f.text) for f in findings]


def test_navcore_imports_follow_the_layer_map():
    findings, _ = layers_tool.check(ROOT / "navcore", ROOT / "ARCHITECTURE.md")
    assert not findings, "\n".join(f"{f.kind}: {f.text}" for f in findings)


def test_a_clean_synthetic_package_has_no_finding(tmp_path):
    pkg, arch = _package(
        tmp_path,
        {"__init__.py": "", "low.py": "", "high/__init__.py": "from navcore import low\n"},
        "| 0 | `navcore`, `navcore.low` | |\n| 1 | `navcore.high` | |\n",
    )
    findings, packages = layers_tool.check(pkg, arch)
    assert findings == []
    assert packages == {"navcore.high": {"navcore.low"}}


def test_an_upward_import_inside_a_function_is_found(tmp_path):
    pkg, arch = _package(
        tmp_path,
        {"__init__.py": "", "low.py": "def f():\n    from navcore.high import g\n", "high.py": ""},
        "| 0 | `navcore`, `navcore.low` | |\n| 1 | `navcore.high` | |\n",
    )
    findings, _ = layers_tool.check(pkg, arch)
    assert _kinds(findings) == [("upward", "navcore.low (layer 0) imports navcore.high (layer 1)")]


def test_relative_imports_resolve_to_their_modules(tmp_path):
    pkg, arch = _package(
        tmp_path,
        {
            "__init__.py": "",
            "low/__init__.py": "",
            "low/a.py": "from ..high import b\n",
            "high/__init__.py": "",
            "high/b.py": "from . import c\n",
            "high/c.py": "",
        },
        "| 0 | `navcore`, `navcore.low` | |\n| 1 | `navcore.high` | |\n",
    )
    findings, _ = layers_tool.check(pkg, arch)
    assert _kinds(findings) == [("upward", "navcore.low.a (layer 0) imports navcore.high.b (layer 1)")]


def test_cycles_between_files_and_between_packages_are_found(tmp_path):
    pkg, arch = _package(
        tmp_path,
        {
            "__init__.py": "",
            "p/__init__.py": "",
            "p/a.py": "import navcore.q.b\n",
            "q/__init__.py": "",
            "q/b.py": "",
            "q/c.py": "from navcore.p import d\n",
            "p/d.py": "",
            "x.py": "import navcore.y\n",
            "y.py": "import navcore.x\n",
        },
        "| 0 | `navcore`, `navcore.p`, `navcore.q`, `navcore.x`, `navcore.y` | |\n",
    )
    findings, _ = layers_tool.check(pkg, arch)
    assert _kinds(findings) == [
        ("file cycle", "files import each other: navcore.x, navcore.y"),
        ("package cycle", "packages import each other: navcore.p, navcore.q"),
        ("package cycle", "packages import each other: navcore.x, navcore.y"),
    ]


def test_a_module_without_a_row_and_a_row_without_a_module_are_found(tmp_path):
    pkg, arch = _package(
        tmp_path,
        {"__init__.py": "", "new.py": ""},
        "| 0 | `navcore`, `navcore.gone` | |\n",
    )
    findings, _ = layers_tool.check(pkg, arch)
    assert _kinds(findings) == [
        ("unplaced", "navcore.new has no layer in the map"),
        ("stale", "the map places navcore.gone, which does not exist"),
    ]


def test_a_name_placed_twice_is_an_error(tmp_path):
    _, arch = _package(tmp_path, {"__init__.py": ""}, "| 0 | `navcore` | |\n| 1 | `navcore` | |\n")
    with pytest.raises(ValueError, match="navcore is placed twice"):
        layers_tool.read_layers(arch)


def test_the_command_line_exits_1_on_a_finding(capsys):
    code = layers_tool.main([])
    out = capsys.readouterr().out
    findings, _ = layers_tool.check(ROOT / "navcore", ROOT / "ARCHITECTURE.md")
    assert code == (1 if findings else 0)
    assert out.rstrip().endswith(f"{len(findings)} finding(s)")
