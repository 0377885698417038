"""Loading the repository's tools (``tools/*.py``, scripts rather than a package) in a test, and
reading what one prints for ``--help``."""

from __future__ import annotations

import importlib.util
import sys
from collections.abc import Callable
from pathlib import Path
from types import ModuleType
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parents[1]


def load_tool(name: str) -> ModuleType:
    """The tool ``tools/<name>.py``, imported under its dotted name ``tools.<name>``, which
    mutation testing's trampolines recognise (``tools/mutation.py``), and registered in
    ``sys.modules`` under it."""
    spec = importlib.util.spec_from_file_location(f"tools.{name}", ROOT / "tools" / f"{name}.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[f"tools.{name}"] = module
    spec.loader.exec_module(module)
    return module


def help_text(main: Callable[[list[str]], Any], capsys: pytest.CaptureFixture[str]) -> str:
    """What a tool's ``main(["--help"])`` prints, its whitespace collapsed; it must exit with 0."""
    with pytest.raises(SystemExit) as exc:
        main(["--help"])
    assert exc.value.code == 0
    return " ".join(capsys.readouterr().out.split())
