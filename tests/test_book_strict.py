"""The book build is strict: a failing cell, a broken reference or a missing citation fails it.

Each case builds a two-page book with the project's own ``_config.yml`` (only the
bibliography files are swapped for a one-entry temporary file) and checks the exit status of
``jupyter-book build`` with the same flags the nox session uses. The good case must succeed,
so the failures are not an artefact of the set-up.
"""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

ROOT = Path(__file__).resolve().parents[1]
JB = shutil.which("jupyter-book", path=str(Path(sys.executable).parent))

pytestmark = [
    pytest.mark.slow,
    pytest.mark.skipif(JB is None, reason="jupyter-book is not installed (install the 'book' extra)"),
]

HEADER = """---
jupytext:
  text_representation:
    extension: .md
    format_name: myst
kernelspec:
  display_name: Python 3
  language: python
  name: python3
---
"""

GOOD_BODY = """
# A page {cite}`known`

See {ref}`sec-target`.

(sec-target)=
## Target

```{code-cell} ipython3
1 + 1
```

```{bibliography}
```
"""

CASES = {
    "good": (GOOD_BODY, 0),
    "failing-cell": (GOOD_BODY.replace("1 + 1", "raise RuntimeError('deliberately broken')"), 1),
    "broken-reference": (GOOD_BODY.replace("{ref}`sec-target`", "{ref}`sec-missing`"), 1),
    "missing-citation": (GOOD_BODY.replace("{cite}`known`", "{cite}`unknown_key`"), 1),
}


def _build(tmp_path: Path, body: str) -> subprocess.CompletedProcess:
    src = tmp_path / "book"
    src.mkdir()
    (src / "index.md").write_text(HEADER + body)
    (src / "_toc.yml").write_text("format: jb-book\nroot: index\n")
    (src / "refs.bib").write_text(
        "@book{known, author={A. Author}, title={Known}, year={2000}, publisher={P}}\n"
    )
    config = yaml.safe_load((ROOT / "_config.yml").read_text())
    config["bibtex_bibfiles"] = ["refs.bib"]
    config["sphinx"]["config"].pop("html_static_path", None)
    config["sphinx"]["config"].pop("html_css_files", None)
    # the book's local Sphinx extensions, found from the copied config's folder
    for name, folder in (config["sphinx"].get("local_extensions") or {}).items():
        config["sphinx"]["local_extensions"][name] = str(ROOT / folder)
    (tmp_path / "_config.yml").write_text(yaml.safe_dump(config))
    cmd = [
        JB,
        "build",
        str(src),
        "--config",
        str(tmp_path / "_config.yml"),
        "--toc",
        str(src / "_toc.yml"),
        "--path-output",
        str(tmp_path),
        "--all",
        "-W",
        "-n",
        "--keep-going",
    ]
    return subprocess.run(cmd, capture_output=True, text=True, cwd=tmp_path, timeout=600)


@pytest.mark.parametrize("case", list(CASES))
def test_strict_build(case: str, tmp_path: Path) -> None:
    body, expected_failure = CASES[case]
    proc = _build(tmp_path, body)
    if expected_failure:
        assert proc.returncode != 0, f"{case}: the build should have failed\n{proc.stdout[-2000:]}"
    else:
        assert proc.returncode == 0, (
            f"the good book should build\n{proc.stdout[-3000:]}\n{proc.stderr[-3000:]}"
        )
