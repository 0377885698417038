"""Glossary terms link to their entry where a page first uses them, and enter the index.

The glossary page (``glossary_links_docname``, default ``glossary``) holds one Sphinx
``glossary`` directive. Each entry is one or more term lines (a term and its synonyms or
abbreviation, e.g. ``CEP`` and ``circular error probable``) followed by its indented
definition. This extension reads those term lines from the page's source when the build
starts, and then, in every other document except those under ``glossary_links_exclude``
(default: the API reference, ``reference/``), turns the first use of each entry in running
text into a ``term`` cross-reference to it, with an index entry at that place.

Matching: whole words only; a term with a capital letter (an acronym such as ``CEP`` or
``C/N0``, a name such as ``Monte Carlo``) matches with its case, a lower-case term also
with a capital first letter; a trailing plural "s" is included. The first use of an entry
is the first of any of its term lines; terms listed in
``glossary_links_ignore`` or on a comment line ``% glossary-links ignore: a, b`` of the
glossary page (ordinary words with a narrower meaning in the glossary) are never linked
automatically. (The comment keeps the list out of ``_config.yml``, whose Sphinx settings key
the book's execution cache.)

With the glossary page outside the build (a subset build), nothing is linked.

Never linked: text in titles, captions, code and literals, math, raw output, existing
references and links, the glossary itself, definition-list terms, table header cells, cell
outputs, index and target nodes, and ``only`` blocks (so that the web pages and the PDF link
the same use).

The links are ``pending_xref`` nodes of the standard domain's ``term`` role, inserted by a
transform that runs before Sphinx collects the document's index entries and objects; Sphinx
resolves them in every builder (HTML anchors, LaTeX ``\\hyperref``).
"""

from __future__ import annotations

import hashlib
import re
from pathlib import Path
from typing import Any

from docutils import nodes
from sphinx import addnodes
from sphinx.application import Sphinx
from sphinx.transforms import SphinxTransform

IGNORE_LINE = re.compile(r"^%\s*glossary-links\s+ignore:(.*)$", re.M)
FENCE = re.compile(r"^(?P<fence>`{3,}|:{3,})\s*\{glossary\}[^\n]*$")

# no link inside these: code, math, raw, links, headings, captions, definitions of terms
SKIP_NODES: tuple[type[nodes.Node], ...] = (
    nodes.literal,
    nodes.literal_block,
    nodes.FixedTextElement,
    nodes.math,
    nodes.math_block,
    nodes.raw,
    nodes.reference,
    nodes.target,
    nodes.title,
    nodes.subtitle,
    nodes.rubric,
    nodes.caption,
    nodes.term,
    nodes.field_name,
    nodes.thead,
    nodes.citation,
    nodes.footnote,
    nodes.comment,
    nodes.system_message,
    nodes.problematic,
    nodes.abbreviation,
    nodes.option_list,
    addnodes.pending_xref,
    addnodes.glossary,
    addnodes.index,
    addnodes.toctree,
    addnodes.desc_signature,
    addnodes.only,
)
SKIP_CLASSES = {"cell_output", "output", "glossary"}


def glossary_entries(source: str) -> list[list[str]]:
    """The term lines of each entry of the ``glossary`` directives in a MyST source."""
    entries: list[list[str]] = []
    fence: str | None = None
    in_entry = False
    for line in source.splitlines():
        if fence is None:
            m = FENCE.match(line.strip())
            if m:
                fence, in_entry = m.group("fence"), False
            continue
        if line.strip() == fence:
            fence = None
            continue
        if not line.strip():
            in_entry = False
            continue
        if line[0].isspace() or line.startswith(":"):  # definition text, or an option
            in_entry = False
            continue
        term = line.split(" : ", 1)[0].strip()  # "term : index key" keeps only the term
        if in_entry:
            entries[-1].append(term)
        else:
            entries.append([term])
            in_entry = True
    return entries


def term_pattern(term: str) -> re.Pattern[str]:
    """Whole-word pattern of a term, with an optional plural; spaces match any white space.

    A term with a capital letter (an acronym such as ``CEP`` or ``C/N0``, a name such as
    ``Doppler`` or ``Monte Carlo``) matches with its case; a lower-case term also matches
    with a capital first letter, as at the start of a sentence.
    """
    body = r"\s+".join(re.escape(word) for word in term.split())
    if term[:1].islower():
        body = f"[{term[0]}{term[0].upper()}]" + body[1:]
    return re.compile(rf"(?<![\w/-])(?:{body})(?:s|es)?(?![\w/]|-\w)")


class Matcher:
    """Finds the first unlinked use of each glossary entry in a text."""

    def __init__(self, entries: list[list[str]], ignore: set[str]):
        self.patterns: list[tuple[int, str, re.Pattern[str]]] = []
        for index, terms in enumerate(entries):
            for term in terms:
                if term not in ignore and term.lower() not in ignore:
                    self.patterns.append((index, term, term_pattern(term)))
        # at one place, the longest term wins ("tightly coupled" before "coupled")
        self.patterns.sort(key=lambda p: -len(p[1]))

    def first(self, text: str, done: set[int]) -> tuple[int, int, int, str] | None:
        """(start, end, entry, term) of the first use of an entry not yet linked.

        Uses of entries already linked still count, so that "coupled" is not found inside a
        second "tightly coupled".
        """
        pos = 0
        while True:
            best = None
            for index, term, pattern in self.patterns:
                m = pattern.search(text, pos)
                if m and (
                    best is None or m.start() < best[0] or (m.start() == best[0] and m.end() > best[1])
                ):
                    best = (m.start(), m.end(), index, term)
            if best is None or best[2] not in done:
                return best
            pos = best[1]


def _skipped(node: nodes.Node) -> bool:
    parent = node.parent
    while parent is not None:
        if isinstance(parent, SKIP_NODES):
            return True
        if isinstance(parent, nodes.Element) and SKIP_CLASSES & set(parent.get("classes", [])):
            return True
        if isinstance(parent, nodes.entry) and isinstance(parent.parent, nodes.row):
            if isinstance(parent.parent.parent, nodes.thead):
                return True
        parent = parent.parent
    return False


def ignored_terms(source: str) -> set[str]:
    """Terms named on ``% glossary-links ignore: ...`` comment lines of the glossary source."""
    return {t.strip() for line in IGNORE_LINE.findall(source) for t in line.split(",") if t.strip()}


def _is_excluded(docname: str, env: Any) -> bool:
    config = env.config
    if docname == config.glossary_links_docname or config.glossary_links_docname not in env.found_docs:
        return True
    return any(docname.startswith(prefix) for prefix in config.glossary_links_exclude)


class GlossaryLinks(SphinxTransform):
    """Link the first use of each glossary entry in a document to the glossary."""

    default_priority = 845  # before SphinxDomains (850) collects index entries and objects

    def apply(self, **kwargs: Any) -> None:
        env = self.env
        matcher: Matcher | None = getattr(self.app, "_glossary_links_matcher", None)
        if matcher is None or not matcher.patterns or _is_excluded(env.docname, env):
            return
        done: set[int] = set()
        for text in list(self.document.findall(nodes.Text)):
            if _skipped(text):
                continue
            self._link_in(text, matcher, done)

    def _link_in(self, text: nodes.Text, matcher: Matcher, done: set[int]) -> None:
        rest = str(text)
        parent = text.parent
        position = parent.index(text)
        parent.remove(text)
        pieces: list[nodes.Node] = []
        while rest:
            hit = matcher.first(rest, done)
            if hit is None:
                break
            start, end, index, term = hit
            done.add(index)
            if start:
                pieces.append(nodes.Text(rest[:start]))
            pieces.extend(self._link(rest[start:end], term))
            rest = rest[end:]
        if rest:
            pieces.append(nodes.Text(rest))
        for offset, piece in enumerate(pieces):
            parent.insert(position + offset, piece)

    def _link(self, shown: str, term: str) -> list[nodes.Node]:
        target_id = f"index-{self.env.new_serialno('index')}"
        index = addnodes.index(entries=[("single", term, target_id, "", None)], inline=True)
        target = nodes.target("", "", ids=[target_id])
        self.document.note_explicit_target(target)
        xref = addnodes.pending_xref(
            "",
            nodes.inline(shown, shown, classes=["xref", "std", "std-term", "glossary-link"]),
            refdomain="std",
            reftype="term",
            reftarget=term,
            refexplicit=True,
            refwarn=True,
            refdoc=self.env.docname,
        )
        return [index, target, xref]


def _read_glossary(app: Sphinx) -> None:
    config = app.config
    base = Path(app.srcdir) / config.glossary_links_docname
    source = next((base.with_suffix(s) for s in (".md", ".rst") if base.with_suffix(s).exists()), None)
    text = source.read_text(encoding="utf-8") if source else ""
    app._glossary_links_source_hash = hashlib.sha256(text.encode()).hexdigest()  # type: ignore[attr-defined]
    entries = glossary_entries(text)
    ignore = set(config.glossary_links_ignore) | ignored_terms(text)
    app._glossary_links_matcher = Matcher(entries, ignore)  # type: ignore[attr-defined]


def _outdated(app: Sphinx, env: Any, added: set[str], changed: set[str], removed: set[str]) -> list[str]:
    """A changed glossary changes the links of every page: read them all again."""
    digest = app._glossary_links_source_hash  # type: ignore[attr-defined]
    if getattr(env, "glossary_links_source_hash", None) != digest:
        env.glossary_links_source_hash = digest
        return [d for d in env.found_docs if d not in added | changed]
    return []


def setup(app: Sphinx) -> dict[str, Any]:
    app.add_config_value("glossary_links_docname", "glossary", "env")
    app.add_config_value("glossary_links_exclude", ["reference/"], "env")
    app.add_config_value("glossary_links_ignore", [], "env")
    app.connect("builder-inited", _read_glossary)
    app.connect("env-get-outdated", _outdated)
    app.add_transform(GlossaryLinks)
    return {"version": "1.0", "parallel_read_safe": True, "parallel_write_safe": True, "env_version": 1}
