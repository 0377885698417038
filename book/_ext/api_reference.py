"""The API reference: a class's data attributes are documented once, in its docstring.

The library's docstrings follow numpydoc: a class (most are frozen dataclasses) describes its
fields under *Attributes*. The reference pages list members with ``:undoc-members:`` (so that
every public function appears even if a docstring were missing), which would list each field
a second time as a bare, empty entry after the class's own table. This extension skips those:
a member of a class that is neither a routine, a property, a class nor an enumeration's member
is a data attribute, and its documentation is the class docstring's *Attributes* section.

A docstring that refers to such a field (``:attr:`readings``` inside a method of the class, or
``:attr:`Evaluation.readings```) then links to the class, where the field is described.
"""

from __future__ import annotations

import enum
import importlib
import inspect
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


def setup(app: Sphinx) -> dict[str, Any]:
    app.connect("autodoc-skip-member", _skip_class_data)
    app.connect("missing-reference", _field_reference)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
