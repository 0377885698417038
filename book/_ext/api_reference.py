"""The API reference: a class's data attributes are documented once, in its docstring.

The library's docstrings follow numpydoc: a class (most are frozen dataclasses) describes its
fields under *Attributes*. The reference pages list members with ``:undoc-members:`` (so that
every public function appears even if a docstring were missing), which would list each field
a second time as a bare, empty entry after the class's own table. This extension skips those:
a member of a class that is neither a routine, a property, a class nor an enumeration's member
is a data attribute, and its documentation is the class docstring's *Attributes* section.

A docstring that refers to such a field (``:attr:`readings``` inside a method of the class, or
``:attr:`Evaluation.readings```) then links to the class, where the field is described.

A reference of a *References* section whose text begins with an author's initial and fits on
one line (``.. [2] P. S. Maybeck, Stochastic Models ...``) would be read by docutils as a list
enumerated "P.", "S." (the PDF printed "P.   S. Maybeck"): the initial's dot is escaped
(:func:`escape_citation_initials`), so that the reference reads as written.
"""

from __future__ import annotations

import enum
import importlib
import inspect
import re
from typing import Any

from docutils import nodes
from sphinx.application import Sphinx
from sphinx.util.nodes import make_refnode


def _skip_class_data(app: Sphinx, what: str, name: str, obj: Any, skip: bool, options: Any) -> bool | None:
    if what != "class" or skip:
        return None
    if inspect.isroutine(obj) or isinstance(obj, (property, classmethod, staticmethod, type, enum.Enum)):
        return None  # methods, properties, nested classes and an enumeration's members stay
    return True


def _class_fields(path: str) -> set[str]:
    """Names of the fields of the class at ``path`` (dataclass fields, named-tuple fields,
    annotations), or an empty set if it cannot be imported."""
    module_name, _, qualname = path.rpartition(".")
    while module_name:
        try:
            obj: Any = importlib.import_module(module_name)
        except ImportError:
            module_name, _, head = module_name.rpartition(".")
            qualname = f"{head}.{qualname}"
            continue
        for part in qualname.split("."):
            obj = getattr(obj, part, None)
        if not inspect.isclass(obj):
            return set()
        return (
            set(getattr(obj, "__dataclass_fields__", {}))
            | set(getattr(obj, "_fields", ()))
            | set(getattr(obj, "__annotations__", {}))
        )
    return set()


def _field_reference(app: Sphinx, env: Any, node: Any, contnode: nodes.Element) -> nodes.Element | None:
    """Resolve ``:attr:`` references to a skipped class field to the class's own entry."""
    if node.get("refdomain") != "py" or node.get("reftype") != "attr":
        return None
    target, module, cls = node["reftarget"], node.get("py:module"), node.get("py:class")
    owner, _, attr = target.rpartition(".")
    if owner:
        candidates = [owner, f"{module}.{owner}"] if module else [owner]
    elif cls:
        candidates = [f"{module}.{cls}" if module else cls]
    else:
        return None
    objects = env.get_domain("py").objects
    for path in candidates:
        entry = objects.get(path)
        if entry is not None and entry.objtype in ("class", "exception") and attr in _class_fields(path):
            return make_refnode(app.builder, node["refdoc"], entry.docname, entry.node_id, contnode, path)
    return None


_CITATION_INITIAL = re.compile(r"^(\s*\.\. \[[^\]]+\][ \t]+)([A-Z][a-z]?)\.(?=\s)")


def escape_citation_initials(lines: list[str]) -> None:
    r"""Escape the dot of an initial that begins a reference, in place: ``.. [2] P. S. Maybeck``
    becomes ``.. [2] P\. S. Maybeck``, which docutils reads as text, not as a list item "P.".

    Examples
    --------
    >>> lines = [".. [2] P. S. Maybeck, Stochastic Models (1979).", "   P. S. Maybeck"]
    >>> escape_citation_initials(lines)
    >>> lines
    ['.. [2] P\\. S. Maybeck, Stochastic Models (1979).', '   P. S. Maybeck']
    """
    for i, line in enumerate(lines):
        lines[i] = _CITATION_INITIAL.sub(r"\1\2\\.", line)


def _process_docstring(app: Sphinx, what: str, name: str, obj: Any, options: Any, lines: list[str]) -> None:
    escape_citation_initials(lines)


def setup(app: Sphinx) -> dict[str, Any]:
    # after numpydoc (priority 500), which writes the References section as citations
    app.connect("autodoc-process-docstring", _process_docstring, priority=600)
    app.connect("autodoc-skip-member", _skip_class_data)
    app.connect("missing-reference", _field_reference)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
