"""Computed numbers pasted into the prose read as numbers, not as a program prints them.

A page pastes a computed value into a sentence with ``{glue:text}`name:.1e```; Python's
format gives ``9.5e-04``, which a browser may break after the minus sign and which is not
how a number is written in a sentence. This extension passes the text of every pasted value
(MyST-NB's ``pasted-text`` spans) through :func:`navcore.formatting.tidy_numbers`: an
exponent becomes ``9.5×10⁻⁴`` with the digits the page chose, and a negative zero loses its
sign. HTML and PDF alike.
"""

from __future__ import annotations

from typing import Any

from docutils import nodes
from sphinx.application import Sphinx
from sphinx.transforms.post_transforms import SphinxPostTransform

from navcore.formatting import tidy_numbers


class TidyPastedNumbers(SphinxPostTransform):
    """Rewrite program-style numbers in pasted values (after MyST-NB has pasted them)."""

    default_priority = 800

    def run(self, **kwargs: Any) -> None:
        for node in self.document.findall(nodes.inline):
            if "pasted-text" not in node.get("classes", []):
                continue
            for text in list(node.findall(nodes.Text)):
                tidy = tidy_numbers(str(text))
                if tidy != str(text):
                    text.parent.replace(text, nodes.Text(tidy))


def setup(app: Sphinx) -> dict[str, Any]:
    app.add_post_transform(TidyPastedNumbers)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
