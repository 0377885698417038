"""Download buttons: every executed notebook as ``.ipynb``, and the whole book as a PDF.

sphinx-book-theme offers a page's ``.ipynb`` only when a launch service (Binder, JupyterHub)
is configured; this book has none. This extension writes the executed notebook next to the
page's sources, so the theme's download menu offers it with its outputs (it runs on its own
after ``pip install navcore``). MyST-NB writes ``<build>/jupyter_execute/<page>.ipynb``
*without* outputs when they come from its execution cache, so the outputs are merged in
from that cache. Cell ids, random in a notebook read from Markdown, are replaced by
``cell-<n>`` so that two builds give the same bytes. Each notebook's metadata carries the
build's provenance under ``navcore_provenance`` (commit and whether the tree was clean, the
commit's date, the lock file's hash, Python's and the core packages' versions; see
:func:`navcore.provenance.build_provenance`), taken when the book is built, not when the page
executed, and from the commit, not the clock.

If the PDF book has been built (``<build>/latex/book.pdf``, by ``nox -s pdf``), it is
copied into the HTML output and every page's download menu links it.
"""

from __future__ import annotations

import re
import shutil
from functools import cache
from pathlib import Path
from typing import Any

from sphinx.application import Sphinx

from navcore.provenance import build_provenance

PDF_NAME = "book.pdf"
METADATA_KEY = "navcore_provenance"
_ADDRESS = re.compile(r" at 0x[0-9a-fA-F]+>")


def _build_dir(app: Sphinx) -> Path:
    return Path(app.outdir).parent


def _pdf_source(app: Sphinx) -> Path:
    return _build_dir(app) / "latex" / PDF_NAME


@cache
def _provenance() -> dict[str, Any]:
    return build_provenance().as_dict()


def executed_notebook(path: Path, cache_path: str | None = None) -> Any:
    """The executed notebook: outputs merged from the execution cache if absent, stable ids, provenance."""
    import nbformat

    nb = nbformat.read(path, as_version=4)
    code = [c for c in nb.cells if c.cell_type == "code"]
    if cache_path and code and not any(c.get("outputs") for c in code):
        from jupyter_cache import get_cache

        try:
            _, nb = get_cache(cache_path).merge_match_into_notebook(nb)
        except KeyError:  # not in the cache: the notebook as MyST-NB wrote it
            pass
    for index, cell in enumerate(nb.cells):
        cell["id"] = f"cell-{index}"
        for out in cell.get("outputs", []):  # "<... at 0x7f...>" differs from run to run
            plain = out.get("data", {}).get("text/plain")
            if isinstance(plain, str):
                out["data"]["text/plain"] = _ADDRESS.sub(">", plain)
    nb.metadata[METADATA_KEY] = _provenance()
    return nb


def _add_notebook(app: Sphinx, pagename: str, templatename: str, context: dict, doctree: Any) -> None:
    if app.builder.format != "html" or doctree is None:
        return
    import nbformat

    executed = _build_dir(app) / "jupyter_execute" / f"{pagename}.ipynb"
    if not executed.exists():
        return
    config = getattr(app.env, "mystnb_config", None)
    cache_path = None
    if config is not None and config.execution_mode == "cache":
        cache_path = config.execution_cache_path
    nb = executed_notebook(executed, cache_path)
    target = Path(app.outdir) / "_sources" / f"{pagename}.ipynb"
    target.parent.mkdir(parents=True, exist_ok=True)
    target.write_text(nbformat.writes(nb) + "\n", encoding="utf-8")
    context["ipynb_source"] = f"{pagename}.ipynb"


def _add_pdf_button(app: Sphinx, pagename: str, templatename: str, context: dict, doctree: Any) -> None:
    if app.builder.format != "html" or not _pdf_source(app).exists():
        return
    for button in context.get("header_buttons", []):
        if button.get("label") == "download-buttons":
            button["buttons"].append(
                {
                    "type": "link",
                    "url": context["pathto"](PDF_NAME, 1),
                    "text": "book (PDF)",
                    "tooltip": "Download the whole book as a PDF",
                    "icon": "fas fa-book",
                    "label": "download-book-pdf-button",
                }
            )


def _copy_pdf(app: Sphinx, exception: Exception | None) -> None:
    if exception is None and app.builder.format == "html" and _pdf_source(app).exists():
        shutil.copy2(_pdf_source(app), Path(app.outdir) / PDF_NAME)


def setup(app: Sphinx) -> dict[str, Any]:
    # before sphinx-book-theme builds its header buttons (priority 501), and after
    app.connect("html-page-context", _add_notebook, priority=400)
    # again after the theme, which may copy MyST-NB's output-less notebook over it
    app.connect("html-page-context", _add_notebook, priority=900)
    app.connect("html-page-context", _add_pdf_button, priority=600)
    app.connect("build-finished", _copy_pdf)
    return {"version": "1.0", "parallel_read_safe": True, "parallel_write_safe": True}
