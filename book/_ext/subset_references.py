"""In a subset build, a reference to a page outside the subset reads as plain text.

``tools/build_book.py --only kzl`` builds one chapter (or the API reference, or the
verification reports) strictly, for a quick check. Its pages link to the other chapters, the
front and back matter and the API reference, which that build does not contain; without this
extension each such link is a broken reference and the strict build fails. The build tool
loads this extension in a subset build only (the full book never loads it, so a broken
reference there still fails the build).

A reference is set as plain text (its own words, or for a page named without them the page's
title) only when its target is known to exist outside the subset:

- a page (``{doc}`` role, Markdown link to a ``.md`` file): the page's source is in the book
  folder and not in this build;
- a label (``{ref}``, ``{numref}``, ``{eq}``, ``{prf:ref}``, ``[text](#label)``): a page
  outside the subset defines it (``(label)=``, ``:name: label``, ``:label: label``, a
  display equation's ``$$ (label)``, or reST's ``.. _label:``);
- an API object (``{py:func}`` and the other roles of the Python domain): a public navcore
  object that Python can import, of a module that a page outside the subset documents
  (``automodule`` or ``py:module``);
- a glossary term (``{term}``): the glossary page is outside the subset and lists it.

Any other unresolved reference (a label no page defines, a misspelt page) is left alone, and
the strict subset build fails on it as the full build would. When the build finishes, the log
says how many references were set as plain text, by kind.
"""

from __future__ import annotations

import importlib
import re
from collections import Counter
from pathlib import Path
from typing import Any

from docutils import nodes
from sphinx import addnodes
from sphinx.application import Sphinx
from sphinx.environment import BuildEnvironment
from sphinx.transforms.post_transforms import SphinxPostTransform
from sphinx.util import docname_join

SOURCE_SUFFIXES = (".md", ".ipynb", ".rst")
LABEL_PATTERNS = (
    re.compile(r"^\((?P<label>[^()\s]+)\)=\s*$", re.M),  # MyST target
    re.compile(r"^\s*:(?:name|label):\s*(?P<label>\S+)\s*$", re.M),  # directive option
    re.compile(r"\$\$\s*\((?P<label>[^()\s]+)\)\s*$", re.M),  # dollarmath equation label
    re.compile(r"^\.\.\s+_(?P<label>[^:\s]+):\s*$", re.M),  # reStructuredText target
)
GLOSSARY_DOCNAME = "glossary"


def _outside_sources(env: BuildEnvironment) -> dict[str, Path]:
    """The book's page sources that this build does not contain, by docname."""
    srcdir = Path(env.srcdir)
    found = set(env.found_docs)
    out: dict[str, Path] = {}
    for path in sorted(srcdir.rglob("*")):
        rel = path.relative_to(srcdir)
        if path.suffix not in SOURCE_SUFFIXES or any(part.startswith(("_", ".")) for part in rel.parts):
            continue
        docname = rel.with_suffix("").as_posix()
        if docname not in found:
            out.setdefault(docname, path)
    return out


class _Outside:
    """What the pages outside the subset define: their titles, labels and glossary terms."""

    def __init__(self, env: BuildEnvironment) -> None:
        self.sources = _outside_sources(env)
        self.labels: set[str] = set()
        self.titles: dict[str, str] = {}
        self.terms: set[str] = set()
        self.modules: set[str] = set()
        for docname, path in self.sources.items():
            try:
                text = path.read_text()
            except (OSError, UnicodeDecodeError):
                continue
            for pattern in LABEL_PATTERNS:
                self.labels.update(m.group("label").lower() for m in pattern.finditer(text))
            self.modules.update(re.findall(r"^\s*\.\. (?:automodule|py:module|module)::\s*(\S+)", text, re.M))
            self.modules.update(re.findall(r"^[`:]{3,}\s*\{(?:automodule|py:module)\}\s*(\S+)", text, re.M))
            title = re.search(r"^#\s+(.+?)\s*$", text, re.M) or re.search(
                r"^(?!\.\.)(\S.*?)\s*\n[=]{3,}\s*$", text, re.M
            )
            if title:
                self.titles[docname] = title.group(1)
            if docname == GLOSSARY_DOCNAME:
                self.terms = _glossary_terms(text)


def _glossary_terms(text: str) -> set[str]:
    """The term lines (unindented, non-blank) inside the page's ``glossary`` directives."""
    terms: set[str] = set()
    inside = False
    for line in text.splitlines():
        stripped = line.strip()
        if re.match(r"^(`{3,}|:{3,})\s*\{glossary\}", stripped):
            inside = True
            continue
        if inside and re.match(r"^(`{3,}|:{3,})\s*$", stripped):
            inside = False
            continue
        if inside and line and not line[0].isspace() and not stripped.startswith((":", "%")):
            terms.add(stripped.lower())
    return terms


def _outside(app: Sphinx) -> _Outside:
    found = getattr(app, "_subset_outside", None)
    if found is None:
        found = _Outside(app.env)
        app._subset_outside = found  # type: ignore[attr-defined]
    return found


def _documented(name: str, modules: set[str]) -> bool:
    """Whether ``name`` is a public navcore object of a module that a page outside documents.

    ``modules``: the modules named by ``automodule`` (or ``py:module``) directives outside the
    subset (their public members are documented there); the object must import and no part of its name after
    the module may start with an underscore.
    """
    if not (name == "navcore" or name.startswith("navcore.")):
        return False
    parts = name.split(".")
    for split in range(len(parts), 0, -1):
        module = ".".join(parts[:split])
        try:
            obj: Any = importlib.import_module(module)
        except ImportError:
            continue
        try:
            for attr in parts[split:]:
                obj = getattr(obj, attr)
        except AttributeError:
            return False
        return module in modules and not any(attr.startswith("_") for attr in parts[split:])
    return False


def _plain(app: Sphinx, kind: str, contnode: nodes.Node, text: str | None = None) -> nodes.inline:
    app._subset_counts[kind] += 1  # type: ignore[attr-defined]
    node = nodes.inline("", "", classes=["xref-outside-subset"])
    if text is not None:
        node += nodes.Text(text)
    else:
        node += contnode.deepcopy()
    return node


def _doc_outside(app: Sphinx, refdoc: str, target: str) -> str | None:
    """The docname of ``target`` (relative to ``refdoc``) if that page is outside the subset."""
    docname = docname_join(refdoc, target.removesuffix(".md"))
    if docname in app.env.found_docs:
        return None
    return docname if docname in _outside(app).sources else None


def missing_reference(
    app: Sphinx, env: BuildEnvironment, node: addnodes.pending_xref, contnode: nodes.Node
) -> nodes.Node | None:
    """Set a reference to something outside the subset as plain text; leave the rest broken."""
    domain, reftype = node.get("refdomain") or "", node.get("reftype") or ""
    target = node.get("reftarget") or ""
    refdoc = node.get("refdoc") or env.docname
    outside = _outside(app)
    if domain == "std" and reftype == "doc":
        docname = _doc_outside(app, refdoc, target)
        if docname is None:
            return None
        explicit = node.get("refexplicit")
        return _plain(app, "page", contnode, None if explicit else outside.titles.get(docname, target))
    if (domain, reftype) in (("std", "ref"), ("std", "numref"), ("math", "eq"), ("prf", "ref")):
        return _plain(app, "label", contnode) if target.lower() in outside.labels else None
    if domain == "std" and reftype == "term":
        return _plain(app, "term", contnode) if target.lower() in outside.terms else None
    if domain == "py":
        module = node.get("py:module") or ""
        names = [target, *([f"{module}.{target}"] if module else [])]
        documented = any(_documented(n, outside.modules) for n in names)
        return _plain(app, "API", contnode) if documented else None
    return None


class MystLinksOutside(SphinxPostTransform):
    """Markdown links (``[text](../wf/01-page.md)``, ``[text](#label)``) to what lies outside.

    MyST resolves its own links before Sphinx's reference resolver runs (and never asks the
    ``missing-reference`` event), so this runs just before MyST's resolver.
    """

    default_priority = 8

    def run(self, **kwargs: Any) -> None:
        std = self.env.get_domain("std")
        for node in list(self.document.findall(addnodes.pending_xref)):
            if node.get("reftype") != "myst":
                continue
            target = node.get("reftarget") or ""
            if node.get("refdomain") == "doc":
                if target in self.env.all_docs:
                    continue
                docname = _doc_outside(self.app, node.get("refdoc") or self.env.docname, "/" + target)
                if docname is None:
                    continue
                text = None if node.get("refexplicit") else _outside(self.app).titles.get(docname, target)
                node.replace_self(_plain(self.app, "page", node[0], text))
            elif target.lower() in _outside(self.app).labels and target not in std.labels:  # type: ignore[attr-defined]
                if target not in std.anonlabels:  # type: ignore[attr-defined]
                    node.replace_self(_plain(self.app, "label", node[0]))


def _report(app: Sphinx, exception: Exception | None) -> None:
    counts: Counter[str] = app._subset_counts  # type: ignore[attr-defined]
    total = sum(counts.values())
    kinds = ", ".join(f"{kind} {n}" for kind, n in sorted(counts.items()))
    print(
        f"subset build: {total} references to what lies outside the subset set as plain text"
        + (f" ({kinds})" if kinds else ""),
        flush=True,
    )


def setup(app: Sphinx) -> dict[str, Any]:
    app._subset_counts = Counter()  # type: ignore[attr-defined]
    app.connect("missing-reference", missing_reference)
    app.add_post_transform(MystLinksOutside)
    app.connect("build-finished", _report)
    return {"parallel_read_safe": True, "parallel_write_safe": False}
