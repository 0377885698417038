"""Every short cross-reference in the API reference names something the reference documents.

The book's Reference part renders the public API's docstrings with Sphinx in nitpicky mode: a
``:func:`name``` that resolves to nothing fails the strict HTML and PDF builds, minutes into
CI (a docstring once named a helper outside ``__all__`` that way). A reference written without
a module path resolves in its docstring's module (and, for ``:meth:`` and ``:attr:``, in its
class): this test checks those, in a second, on the docstrings the reference renders
(:func:`tests.test_docstring_math.api_docstrings`). References with a module path are left
to Sphinx when they point into navcore, and refused otherwise: the book has no intersphinx
inventory, so a reference to numpy or the standard library resolves to nothing.

Oracle: Sphinx's rule for unqualified Python references, applied by hand; checked on a
hand-written docstring first.
"""

from __future__ import annotations

import builtins
import importlib
import inspect
import re

from tests.test_docstring_math import api_docstrings

_ROLE = re.compile(r":(func|class|meth|data|attr|exc|obj):`~?([A-Za-z_]\w*(?:\.[A-Za-z_]\w*)*)(?:\(\))?`")


def _documented_member(cls: type, name: str, role: str) -> bool:
    """Whether ``name`` is a member of ``cls`` that the reference renders and ``role`` can
    name: a method or property, or (for ``:attr:``) an annotated field, which ``undoc-members``
    renders as an attribute. A field named as a function resolves to nothing (a strict build
    failed on ``:func:`band_too_wide``` for a field of Evaluation once)."""
    for klass in inspect.getmro(cls):
        if name in vars(klass):
            member = vars(klass)[name]
            if isinstance(member, property | staticmethod | classmethod) or inspect.isroutine(member):
                return True
            return role in ("attr", "obj")
        if name in vars(klass).get("__annotations__", {}):
            return role in ("attr", "obj")
    return False


def _owner(qualname: str) -> tuple[object, object | None]:
    """The module of a documented object's name, and the class when the name is a member's."""
    parts = qualname.split(".")
    for cut in range(len(parts), 0, -1):
        try:
            module = importlib.import_module(".".join(parts[:cut]))
        except ImportError:
            continue
        rest = parts[cut:]
        cls = None
        obj: object = module
        for part in rest:
            obj = getattr(obj, part, None)
            if inspect.isclass(obj):
                cls = obj
        return module, cls
    raise ValueError(qualname)


def _automodules() -> set[str]:
    """The modules the reference renders: its pages' ``automodule`` directives."""
    from pathlib import Path

    pages = (Path(__file__).resolve().parents[1] / "book" / "reference").iterdir()
    text = "\n".join(p.read_text(encoding="utf-8") for p in pages if p.suffix in (".rst", ".md"))
    return set(re.findall(r"automodule::\s*(navcore[\w.]*)", text))


def _rendered(target: str, role: str) -> bool:
    """Whether a full path into navcore names something the reference renders: a module it
    documents, a public name of one (its ``__all__``), or a documented member of such a class
    (``navcore.book`` is not in the reference, so ``navcore.book.claims_table`` resolves to
    nothing: a strict build failed on it in December 2026)."""
    modules = _automodules()
    if target in modules:
        return True
    parts = target.split(".")
    for cut in range(len(parts) - 1, 0, -1):
        name = ".".join(parts[:cut])
        if name not in modules:
            continue
        module = importlib.import_module(name)
        head, *rest = parts[cut:]
        if head not in getattr(module, "__all__", ()):
            return False
        if not rest:
            return True
        owner = getattr(module, head, None)
        return len(rest) == 1 and inspect.isclass(owner) and _documented_member(owner, rest[0], role)
    return False


def unresolved(qualname: str, doc: str) -> list[str]:
    """The short references of ``doc`` (the docstring of ``qualname``) that resolve to nothing
    the reference documents: not in the module's ``__all__``, not a member of the class."""
    module, cls = _owner(qualname)
    public = set(getattr(module, "__all__", ()))
    out = []
    for role, target in _ROLE.findall(doc):
        head, _, member = target.partition(".")
        if head == "navcore":  # a full path into navcore: a module the reference renders
            if _rendered(target, role):
                continue
            out.append(f":{role}:`{target}`")
            continue
        if member:  # Class.member: a public class of this module and one of its members
            owner = getattr(module, head, None)
            if "." not in member and head in public and inspect.isclass(owner):
                if _documented_member(owner, member, role):
                    continue
            # anything else with a dot (numpy.random.default_rng, np.log) is outside the
            # reference, and the book has no intersphinx inventory to resolve it (no network)
        elif target in public or (cls is not None and _documented_member(cls, target, role)):
            continue
        if role == "exc" and hasattr(builtins, target):
            continue
        out.append(f":{role}:`{target}`")
    return out


def test_the_check_finds_a_reference_to_a_helper_outside_all():
    doc = "Uses :func:`quote_math` and :func:`~quote_below`; see :func:`tex_text`."
    found = unresolved("navcore.ledger.text.quote_text", doc)
    assert found == [":func:`quote_below`"]


def test_the_check_finds_a_member_of_another_module_and_a_field_named_as_a_function():
    """Sphinx resolves ``Class.member`` in the docstring's module only, and a dataclass field
    is an attribute, not a function (both failed a strict build once, after a module split)."""
    doc = (
        "See :meth:`Tolerance.loose`, :meth:`~Evaluation.deviation`, :attr:`Evaluation.sensitivity`, "
        ":attr:`readings` and :func:`band_too_wide`; :func:`np.log` is numpy's."
    )
    found = unresolved("navcore.claims.evaluation.Evaluation", doc)
    assert found == [":meth:`Tolerance.loose`", ":func:`band_too_wide`", ":func:`np.log`"]
    # the same field named from the module that holds the verdict rule, not the Evaluation
    assert unresolved("navcore.claims.verdict.additive_envelope", doc) == [
        ":meth:`Tolerance.loose`",
        ":meth:`Evaluation.deviation`",
        ":attr:`Evaluation.sensitivity`",
        ":attr:`readings`",
        ":func:`np.log`",
    ]


def test_the_check_finds_a_reference_outside_navcore():
    """The book has no intersphinx inventory (CI has no network), so a reference to numpy's or
    the standard library's functions resolves to nothing and fails the strict build; a full
    path into navcore is left to Sphinx (a strict build failed on both kinds in December 2026)."""
    doc = (
        "Seed of :func:`numpy.random.default_rng`; copies (:func:`dataclasses.replace`); "
        "see :func:`navcore.claims.quotes.with_quotes` and :class:`Evaluation`."
    )
    assert unresolved("navcore.claims.evaluation.Evaluation", doc) == [
        ":func:`numpy.random.default_rng`",
        ":func:`dataclasses.replace`",
    ]


def test_the_check_finds_a_full_path_to_something_the_reference_does_not_render():
    """A full path resolves only to what the reference renders: ``navcore.book`` (the pages'
    helpers) is not in it, nor a private helper of a module that is (a strict build failed on
    ``navcore.book.claims_table`` in a Claim docstring, December 2026)."""
    doc = (
        ":func:`navcore.book.claims_table`, :func:`navcore.claims.quotes._no_such_helper`, "
        ":mod:`navcore.claims.quotes`, :attr:`navcore.claims.declarations.Claim.table`, "
        ":class:`navcore.claims.declarations.Claim`, :meth:`navcore.claims.declarations.Claim.nope`"
    )
    assert unresolved("navcore.claims.evaluation.Evaluation", doc) == [
        ":func:`navcore.book.claims_table`",
        ":func:`navcore.claims.quotes._no_such_helper`",
        ":meth:`navcore.claims.declarations.Claim.nope`",
    ]


def test_short_references_in_the_api_reference_resolve():
    bad = [(name, ref) for name, doc in api_docstrings() for ref in unresolved(name, doc)]
    assert not bad, "references Sphinx cannot resolve (qualify them, or name them as code):\n" + "\n".join(
        f"{name}: {ref}" for name, ref in bad
    )
