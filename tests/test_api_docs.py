"""The API reference is complete (issue 19, item 1).

- Every public name (each module's ``__all__`` in the model subpackages and the ledger) has
  a docstring, and its module is on a page of the book's Reference part
  (``book/reference/*.rst``), so every public name is documented there.
- A function's numpydoc ``Parameters`` section names exactly the parameters of its signature.
- A public function has a ``Parameters`` section (if it takes any) and a ``Returns`` section.
  The functions that do not yet are listed in ``tests/api_docs_todo.txt``: a function missing
  from that list must be documented, and a listed function that gains both sections must be
  removed from it, so the list only shrinks.
- A public function has an ``Examples`` section (a doctest, run by ``--doctest-modules``).
  The functions that do not yet are listed in ``tests/api_examples_todo.txt``, which may
  likewise only shrink.
- Every field of a public dataclass or named tuple is documented in its ``Attributes`` (or
  ``Parameters``) section; the classes that are not yet complete are listed in
  ``tests/api_fields_todo.txt``, which may only shrink.
"""

from __future__ import annotations

import dataclasses
import importlib
import inspect
import pkgutil
import re
import warnings
from pathlib import Path

import pytest
from numpydoc.docscrape import ClassDoc, FunctionDoc

ROOT = Path(__file__).resolve().parents[1]
SUBPACKAGES = (
    "units",
    "frames",
    "gravity",
    "estimation",
    "inertial",
    "gnss",
    "integration",
    "detection",
    "location",
    "claims",
    "ledger",
)
TODO = ROOT / "tests" / "api_docs_todo.txt"
EXAMPLES_TODO = ROOT / "tests" / "api_examples_todo.txt"
FIELDS_TODO = ROOT / "tests" / "api_fields_todo.txt"


def _modules() -> list:
    mods = []
    for sub in SUBPACKAGES:
        pkg = importlib.import_module(f"navcore.{sub}")
        if not hasattr(pkg, "__path__"):
            mods.append(pkg)
            continue
        for info in pkgutil.iter_modules(pkg.__path__):
            mod = importlib.import_module(f"navcore.{sub}.{info.name}")
            if getattr(mod, "__all__", None):
                mods.append(mod)
    return mods


def _public() -> list[tuple[str, object]]:
    out = []
    for mod in _modules():
        for name in mod.__all__:
            obj = getattr(mod, name)
            if (inspect.isfunction(obj) or inspect.isclass(obj)) and getattr(
                obj, "__module__", ""
            ) == mod.__name__:
                out.append((f"{mod.__name__}.{name}", obj))
    return out


PUBLIC = _public()
FUNCTIONS = [(n, o) for n, o in PUBLIC if inspect.isfunction(o)]


def _doc(func: object) -> FunctionDoc:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # numpydoc warns on sections it does not know
        return FunctionDoc(func)


def _documented_names(doc: FunctionDoc) -> set[str]:
    names: set[str] = set()
    for param in doc["Parameters"]:
        names |= {n.strip().lstrip("*") for n in param.name.split(",") if n.strip()}
    return names


def _lacks_sections(func: object) -> bool:
    doc = _doc(func)
    params = [p for p in inspect.signature(func).parameters.values() if p.name != "self"]
    return (bool(params) and not doc["Parameters"]) or not (doc["Returns"] or doc["Yields"])


def test_every_public_name_has_a_docstring():
    missing = [name for name, obj in PUBLIC if not inspect.getdoc(obj)]
    assert not missing, f"public names without a docstring: {missing}"


def test_every_public_module_is_on_a_reference_page():
    pages = "\n".join(p.read_text() for p in (ROOT / "book" / "reference").glob("*.rst"))
    on_pages = set(re.findall(r"\.\. automodule:: (navcore[\w.]*)\n   :members:", pages))
    missing = [m.__name__ for m in _modules() if m.__name__ not in on_pages]
    assert not missing, f"modules with public names but no reference page: {missing}"


@pytest.mark.parametrize(("name", "func"), FUNCTIONS, ids=[n for n, _ in FUNCTIONS])
def test_parameters_section_matches_signature(name, func):
    doc = _doc(func)
    if not doc["Parameters"]:
        return
    params = inspect.signature(func).parameters.values()
    signature = {p.name for p in params if p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD)}
    variadic = {p.name for p in params if p.kind in (p.VAR_POSITIONAL, p.VAR_KEYWORD)}
    documented = _documented_names(doc)
    allowed = signature | variadic | {"args", "kwargs"}
    assert documented <= allowed, f"{name} documents {sorted(documented - allowed)}"
    assert signature <= documented, f"{name} does not document {sorted(signature - documented)}"


def _lacks_examples(func: object) -> bool:
    return not "".join(_doc(func)["Examples"]).strip()


def _todo(path: Path) -> set[str]:
    lines = path.read_text().splitlines()
    return {line.strip() for line in lines if line.strip() and not line.startswith("#")}


def test_undocumented_functions_only_shrink():
    todo = _todo(TODO)
    lacking = {name for name, func in FUNCTIONS if _lacks_sections(func)}
    new = sorted(lacking - todo)
    done = sorted(todo - lacking)
    assert not new, f"public functions without Parameters/Returns sections (document them): {new}"
    assert not done, f"documented now, remove from {TODO.name}: {done}"


def test_functions_without_examples_only_shrink():
    todo = _todo(EXAMPLES_TODO)
    lacking = {name for name, func in FUNCTIONS if _lacks_examples(func)}
    new = sorted(lacking - todo)
    done = sorted(todo - lacking)
    assert not new, f"public functions without an Examples section (add a doctest): {new}"
    assert not done, f"have examples now, remove from {EXAMPLES_TODO.name}: {done}"


def _undocumented_fields(cls: type) -> list[str]:
    if dataclasses.is_dataclass(cls):
        fields = [f.name for f in dataclasses.fields(cls) if not f.name.startswith("_")]
    else:
        fields = list(getattr(cls, "_fields", ()))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        doc = ClassDoc(cls, config={"show_class_members": False})
    documented: set[str] = set()
    for section in ("Parameters", "Attributes"):
        for param in doc[section]:
            documented |= {n.strip() for n in param.name.split(",")}
    return [f for f in fields if f not in documented]


def test_class_fields_documented_only_shrink():
    todo = _todo(FIELDS_TODO)
    classes = [(n, c) for n, c in PUBLIC if inspect.isclass(c)]
    lacking = {name for name, cls in classes if _undocumented_fields(cls)}
    new = sorted(lacking - todo)
    done = sorted(todo - lacking)
    assert not new, f"public classes with undocumented fields (add Attributes): {new}"
    assert not done, f"fields documented now, remove from {FIELDS_TODO.name}: {done}"


def test_no_reference_entry_opens_with_an_initial():
    """A References entry that opens with an initial ("N. E. Wu and ...") is read by reST as an
    enumerated list item labelled "N." (the PDF printed "N." apart from "E. Wu"): the surname
    goes first. Oracle: docutils' own reading of such a line, checked on a hand-written case."""
    from docutils.core import publish_doctree

    tree = publish_doctree('N. E. Wu and M. L. Fowler, "A title".', settings_overrides={"report_level": 5})
    assert tree.children[0].tagname == "enumerated_list"  # what the check below guards against
    opens_with_initial = re.compile(r"^\s*[A-Z]\. ")
    found = []
    for path in sorted((ROOT / "navcore").rglob("*.py")):
        lines = path.read_text().splitlines()
        for i, line in enumerate(lines[:-2]):
            if line.strip() == "References" and set(lines[i + 1].strip()) == {"-"}:
                entry = lines[i + 2]
                if opens_with_initial.match(entry):
                    found.append(f"{path.relative_to(ROOT)}:{i + 3}: {entry.strip()}")
    assert not found, found
