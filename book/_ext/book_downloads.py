"""Download buttons: every executed notebook as ``.ipynb``, and the whole book as a PDF.

sphinx-book-theme offers a page's ``.ipynb`` only when a launch service (Binder, JupyterHub)
is configured; this book has none. This extension copies the executed notebook that MyST-NB
writes to ``<build>/jupyter_execute/<page>.ipynb`` next to the page's sources, so the
theme's download menu offers it (with its outputs; it runs on its own after
``pip install navcore``). If the PDF book has been built (``<build>/latex/book.pdf``, by
``nox -s pdf``), it is copied into the HTML output and every page's download menu links it.
"""

from __future__ import annotations

import shutil
from pathlib import Path
from typing import Any

from sphinx.application import Sphinx

PDF_NAME = "book.pdf"


def _build_dir(app: Sphinx) -> Path:
    return Path(app.outdir).parent


def _pdf_source(app: Sphinx) -> Path:
    return _build_dir(app) / "latex" / PDF_NAME


def _add_notebook(app: Sphinx, pagename: str, templatename: str, context: dict, doctree: Any) -> None:
    if app.builder.format != "html" or doctree is None:
        return
    executed = _build_dir(app) / "jupyter_execute" / f"{pagename}.ipynb"
    if not executed.exists() or context.get("ipynb_source"):
        return
    target = Path(app.outdir) / "_sources" / f"{pagename}.ipynb"
    target.parent.mkdir(parents=True, exist_ok=True)
    shutil.copy2(executed, target)
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
    app.connect("html-page-context", _add_pdf_button, priority=600)
    app.connect("build-finished", _copy_pdf)
    return {"version": "1.0", "parallel_read_safe": True, "parallel_write_safe": True}
