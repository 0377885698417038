"""Every function, class and constant a paper module defines is used somewhere.

A claim that is reworked can leave its old oracle or helper behind: code that no claim, page,
test or tool runs, which a reader takes for evidence and mutation testing counts as untested
(twenty such functions were found by the first mutation run of the paper modules). Oracle: the
name's whole-word occurrences in the project's sources (navcore, the book's pages and
extensions, the tests, the tools, the nox file); its own definition is one of them.
"""

from __future__ import annotations

import ast
import re
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
#: names a module defines for the machinery that reads every paper module (the registry)
_PROTOCOL = {"IN", "CLAIMS", "ERRATA", "__all__"}


def _words(text: str) -> Counter[str]:
    """How often each identifier-like word occurs in ``text`` (a whole-word count)."""
    return Counter(re.findall(r"\w+", text))


def _sources() -> str:
    files = [
        *ROOT.glob("navcore/**/*.py"),
        *ROOT.glob("tests/*.py"),
        *ROOT.glob("tools/*.py"),
        *ROOT.glob("book/**/*.md"),
        *ROOT.glob("book/**/*.py"),
        ROOT / "noxfile.py",
    ]
    return "\n".join(p.read_text(encoding="utf-8") for p in files if "_build" not in p.parts)


def _defined(path: Path) -> list[str]:
    names = []
    for node in ast.parse(path.read_text(encoding="utf-8")).body:
        if isinstance(node, ast.FunctionDef | ast.ClassDef):
            names.append(node.name)
        elif isinstance(node, ast.Assign):
            names += [t.id for t in node.targets if isinstance(t, ast.Name)]
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names.append(node.target.id)
    return [n for n in names if n not in _PROTOCOL]


def test_every_name_a_paper_module_defines_is_used():
    words = _words(_sources())
    unused = [
        f"{path.stem}.{name}"
        for path in sorted(ROOT.glob("navcore/papers/*.py"))
        for name in _defined(path)
        if words[name] <= 1
    ]
    assert not unused, f"defined in a paper module and used nowhere: {unused}"


def test_the_scan_finds_an_unused_function(tmp_path):
    """The check itself: a module with one used and one unused function."""
    module = tmp_path / "m.py"
    module.write_text("def used():\n    return 1\n\n\ndef unused():\n    return used()\n")
    words = _words(module.read_text() + "\nused()\n# unused_not_this_one\n")
    names = _defined(module)
    assert names == ["used", "unused"]
    assert [n for n in names if words[n] <= 1] == ["unused"]
