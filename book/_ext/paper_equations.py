"""Number the book's display equations with the paper's own equation numbers.

A display equation labelled ``eq-<paper>-<number>`` (paper in wf, sp, atc10, kzl; the
number as the paper prints it, dots between levels, appendix letters in lower case) is shown
as ``(<number>)``: ``(eq-wf-13)`` as (13), ``(eq-atc10-2.4.2)`` as (2.4.2),
``(eq-atc10-a.18)`` as (A.18). An equation the book derives itself is labelled
``eq-<paper>-x-<name>`` and is shown as (N1), (N2), ... in the order of its page, so that a
reader never mistakes it for one of the paper's. Every other labelled equation gets the same
N-numbering.

HTML: Sphinx takes equation numbers (for the equation and for every ``{eq}`` reference to
it) from ``env.toc_fignumbers`` when ``math_numfig`` is on; this extension overwrites them
after Sphinx has assigned its sequential ones. LaTeX: the equation gets ``\\tag{...}``, so
``\\ref`` and the printed number are the paper's.
"""

from __future__ import annotations

from typing import Any

from docutils import nodes
from sphinx.application import Sphinx
from sphinx.environment import BuildEnvironment

from navcore.traceability import paper_equation_number as paper_number

# one rule for the book, the index and the tests: navcore.traceability.paper_equation_number


def _collect(app: Sphinx, doctree: nodes.document) -> None:
    env = app.env
    tags: dict[str, str] = {}
    derived = 0
    for node in doctree.findall(nodes.math_block):
        label = node.get("label")
        if not label or not node.get("ids"):
            continue
        tag = paper_number(label)
        if tag is None:
            derived += 1
            tag = f"N{derived}"
        node["paper_tag"] = tag
        for node_id in node["ids"]:
            tags[node_id] = tag
    if not hasattr(env, "paper_equation_tags"):
        env.paper_equation_tags = {}
    env.paper_equation_tags[env.docname] = tags


def _purge(app: Sphinx, env: BuildEnvironment, docname: str) -> None:
    getattr(env, "paper_equation_tags", {}).pop(docname, None)


def _merge(app: Sphinx, env: BuildEnvironment, docnames: set[str], other: BuildEnvironment) -> None:
    if not hasattr(env, "paper_equation_tags"):
        env.paper_equation_tags = {}
    env.paper_equation_tags.update(getattr(other, "paper_equation_tags", {}))


def _renumber(app: Sphinx, env: BuildEnvironment) -> list[str]:
    """Replace Sphinx's sequential equation numbers by the paper's (after they are assigned)."""
    for docname, tags in getattr(env, "paper_equation_tags", {}).items():
        numbers = env.toc_fignumbers.setdefault(docname, {}).setdefault("displaymath", {})
        for node_id, tag in tags.items():
            numbers[node_id] = (tag,)
    return []


def _latex_visit_math_block(original):
    def visit(self, node: nodes.Element) -> None:
        try:
            original(self, node)
        finally:  # Sphinx's visitor ends with SkipNode: tag what it appended, then re-raise
            tag = node.get("paper_tag")
            if tag and not node.get("nowrap") and self.body and r"\label{" in self.body[-1]:
                self.body[-1] = self.body[-1].replace("\\label{", f"\\tag{{{tag}}}\\label{{", 1)

    return visit


def setup(app: Sphinx) -> dict[str, Any]:
    from sphinx.writers.latex import LaTeXTranslator

    app.connect("doctree-read", _collect)
    app.connect("env-purge-doc", _purge)
    app.connect("env-merge-info", _merge)
    # after the toctree collector (priority 500) has assigned Sphinx's own figure numbers
    app.connect("env-get-updated", _renumber, priority=900)
    if not getattr(LaTeXTranslator.visit_math_block, "_paper_equations", False):
        patched = _latex_visit_math_block(LaTeXTranslator.visit_math_block)
        patched._paper_equations = True
        LaTeXTranslator.visit_math_block = patched
    return {"version": "1.0", "parallel_read_safe": True, "parallel_write_safe": True}
