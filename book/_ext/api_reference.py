"""The API reference: a class's data attributes are documented once, in its docstring.

The library's docstrings follow numpydoc: a class (most are frozen dataclasses) describes its
fields under *Attributes*. The reference pages list members with ``:undoc-members:`` (so that
every public function appears even if a docstring were missing), which would list each field
a second time as a bare, empty entry after the class's own table. This extension skips those:
a member of a class that is neither a routine, a property, a class nor an enumeration's member
is a data attribute, and its documentation is the class docstring's *Attributes* section.
"""

from __future__ import annotations

import enum
import inspect
from typing import Any

from sphinx.application import Sphinx


def _skip_class_data(app: Sphinx, what: str, name: str, obj: Any, skip: bool, options: Any) -> bool | None:
    if what != "class" or skip:
        return None
    if inspect.isroutine(obj) or isinstance(obj, (property, classmethod, staticmethod, type, enum.Enum)):
        return None  # methods, properties, nested classes and an enumeration's members stay
    return True


def setup(app: Sphinx) -> dict[str, Any]:
    app.connect("autodoc-skip-member", _skip_class_data)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
