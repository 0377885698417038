"""The PDF as the HTML shows it: references where they stand, errata boxes in the web's colour.

References.

Sphinx's LaTeX builder gathers every citation of the book into one list at the very end of
the document (``BibliographyTransform``). For this book that put the bibliography after the
last page of the API reference, with no heading, and left its own *Bibliography* chapter
empty; and it moved each function's numbered references ([1], [2], ...) of the API reference
into the same list, where nothing says which function they belong to.

This extension keeps each run of citations where it stands: the Bibliography page's list under
the page's heading, a function's references under that function. A run of sibling citations
becomes its own ``thebibliography`` (the preamble of ``_config.yml`` takes the list heading
away, so that the page's heading is the only one), and its citations become
:class:`in_place_citation` nodes, which the LaTeX writer prints exactly as a citation
(``\\bibitem[label]{key}``) but which the end-of-document gathering does not move.

Links. A link inside a reference list is printed as its address (a DOI becomes
``https://doi.org/...``) instead of as a footnote mark glued to the DOI, which read as one
more digit of it.

The introduction. Sphinx takes the root page's heading for the document's title and prints
the page's text after the table of contents without it, so the PDF's first page of text had
no title and its running footer still said "Contents". Here that text gets its heading back,
as an unnumbered chapter that enters the table of contents and the running headers.

Errata. An erratum is an admonition with the class ``warning``; the web shows it with the
theme's orange warning colours, but Sphinx's LaTeX writer prints every titled admonition as
a note. Here a titled admonition with the class ``warning`` is printed as a warning box,
whose colours ``_config.yml`` sets to the web's.
"""

from __future__ import annotations

from typing import Any

from docutils import nodes
from sphinx.application import Sphinx
from sphinx.builders.latex.nodes import thebibliography
from sphinx.transforms.post_transforms import SphinxPostTransform


class in_place_citation(nodes.General, nodes.Element):
    """A citation that the LaTeX builder prints where it stands."""


def _visit_in_place_citation(self: Any, node: nodes.Element) -> None:
    self.visit_citation(node)


def _depart_in_place_citation(self: Any, node: nodes.Element) -> None:
    self.depart_citation(node)


class CitationUrlsInline(SphinxPostTransform):
    """A link in a citation is printed as its address (no footnote mark after a DOI)."""

    default_priority = 390  # before ShowUrlsTransform (400)
    formats = ("latex",)

    def run(self, **kwargs: Any) -> None:
        for citation in self.document.findall(nodes.citation):
            for ref in list(citation.findall(nodes.reference)):
                uri = ref.get("refuri", "")
                if uri.startswith(("http://", "https://")) and ref.astext() != uri:
                    ref.children = [nodes.Text(uri)]


class CitationsInPlace(SphinxPostTransform):
    """Each run of sibling citations becomes a reference list where it stands."""

    default_priority = 740  # before Sphinx's BibliographyTransform (750)
    formats = ("latex",)

    def run(self, **kwargs: Any) -> None:
        parents: list[nodes.Element] = []
        for citation in self.document.findall(nodes.citation):
            if citation.parent not in parents:
                parents.append(citation.parent)
        for parent in parents:
            children, run = list(parent.children), []
            new_children: list[nodes.Node] = []
            for child in [*children, None]:
                if isinstance(child, nodes.citation):
                    run.append(child)
                    continue
                if run:
                    listing = thebibliography()
                    for citation in run:
                        listing += in_place_citation(
                            citation.rawsource, *citation.children, **citation.attributes
                        )
                    new_children.append(listing)
                    run = []
                if child is not None:
                    new_children.append(child)
            parent.children = []
            parent.extend(new_children)


def _latex_escape(text: str) -> str:
    specials = {"&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#", "_": r"\_", "{": r"\{", "}": r"\}"}
    return "".join(specials.get(c, c) for c in text)


class IntroductionHeading(SphinxPostTransform):
    """The root page's text starts with its own heading, as an unnumbered chapter."""

    default_priority = 800
    formats = ("latex",)

    def run(self, **kwargs: Any) -> None:
        root = self.config.root_doc
        title = self.env.titles.get(root)
        first = next(iter(self.document.findall(nodes.section)), None)
        if title is None or first is None or not first.children:
            return
        if not isinstance(first[0], nodes.title) or first[0].astext() != title.astext():
            return  # not the assembled book (whose first section is the root page's)
        text = _latex_escape(title.astext())
        heading = (
            rf"\chapter*{{{text}}}\addcontentsline{{toc}}{{chapter}}{{{text}}}\markboth{{{text}}}{{{text}}}"
        )
        first.insert(1, nodes.raw("", heading + "\n", format="latex"))


def _visit_admonition(self: Any, node: nodes.Element) -> None:
    kind = "warning" if "warning" in node.get("classes", []) else "note"
    self.body.append("\n" + r"\begin{sphinxadmonition}{" + kind + "}")
    self.no_latex_floats += 1
    if self.table:
        self.table.has_problematic = True


def _depart_admonition(self: Any, node: nodes.Element) -> None:
    self.body.append(r"\end{sphinxadmonition}" + "\n")
    self.no_latex_floats -= 1


def setup(app: Sphinx) -> dict[str, Any]:
    app.add_node(in_place_citation, latex=(_visit_in_place_citation, _depart_in_place_citation))
    app.add_node(nodes.admonition, override=True, latex=(_visit_admonition, _depart_admonition))
    app.add_post_transform(CitationUrlsInline)
    app.add_post_transform(CitationsInPlace)
    app.add_post_transform(IntroductionHeading)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
