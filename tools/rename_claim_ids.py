"""Rename the catalog-numbered claim ids (``KZL-c16``, ``WF-c7-ratio``) to readable ones.

Usage: ``python tools/rename_claim_ids.py [--check]``

The ids of the first catalog carried its item numbers (``-c16``), which tell a reader
nothing. :data:`RENAMES` maps each old id to a slug of what the claim checks, keeping the
paper prefix and a locator part (``KZL-sec3.6-heading-with-init``). The script rewrites every
reference in the repository's tracked text files (book pages, tests, navcore including the
errata's ``claims=`` tuples and ``paper_items.json``, tools, README) with exact whole-id
matching (``KZL-c16`` never touches ``KZL-c16-covariance``), and gives each renamed claim
an ``aliases=("<old id>",)`` line after its ``id=`` so that an old id still resolves.

Lines holding ``aliases=`` are never rewritten (nor the files in :data:`KEEP`), so the
script is idempotent: run it again after merging a branch that still uses the old ids and
it renames only what is left.
``--check`` rewrites nothing and exits non-zero if an old id is still referenced.
"""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

#: old id -> new id
RENAMES: dict[str, str] = {
    # WF (Wang & Farrell): Sec. II-V
    "WF-c1-additive": "WF-eq6-model-error-acts-like-noise",
    "WF-c2-position": "WF-sec3-tip-position-vs-range",
    "WF-c3-position-ins": "WF-sec3-tip-position-vs-ins",
    "WF-c4-flexible-mode": "WF-sec3-flexible-mode-velocity",
    "WF-c5-velocity-nominal": "WF-sec3-velocity-vs-nominal",
    "WF-c6-velocity-ins": "WF-sec3-velocity-vs-ins",
    "WF-c7-ratio": "WF-eq9-velocity-position-ratio",
    "WF-c8-effective": "WF-eq9-velocity-error-dominates",
    "WF-c11-outage": "WF-eq19-outage-infinite-covariance",
    "WF-c12-wls": "WF-eq19-weighted-least-squares",
    "WF-c13-sigmaG": "WF-sec4d-sigma-g-from-gps-doppler",
    "WF-c13-sigmaL-high-res": "WF-sec4d-sigma-l-high-resolution",
    "WF-c13-sigmaL-medium-res": "WF-sec4d-sigma-l-medium-resolution",
    "WF-c14-60dB": "WF-fig1-improvement-at-100ug",
    "WF-c15-factor": "WF-sec4d-improvement-factor",
    "WF-c15-sigmaD": "WF-sec4d-fused-velocity-accuracy",
    "WF-c17-unfiltered": "WF-sec4d-unfiltered-velocity-accuracy",
    "WF-c18-gps-little": "WF-fig2-gps-adds-little",
    "WF-c19-gps-noticeable": "WF-sec4d-gps-noticeable-only-when-severe",
    "WF-c20-three-vs-one": "WF-fig2-three-vs-one-satellite",
    "WF-c21-50Hz": "WF-fig1-update-rate-50hz",
    "WF-c22-mems-sensitive": "WF-sec4d-mems-ten-times-more-sensitive",
    "WF-c23-negligible": "WF-sec5-aperture-errors-negligible",
    # KZL (Kim, Zhang & Lee): Secs. 1-3
    "KZL-c1": "KZL-sec1-satellite-aircraft-speed-ratio",
    "KZL-c3": "KZL-sec1-pointing-half-degree",
    "KZL-c26-overlap": "KZL-sec1-footprint-overlap",
    "KZL-c27-positioning": "KZL-sec1-positioning-less-strict",
    "KZL-c28-baseline-angle": "KZL-sec1-baseline-tilt-accuracy",
    "KZL-c29-baseline-length": "KZL-sec1-baseline-length-accuracy",
    "KZL-c6": "KZL-sec2.1-ins-drift-per-hour",
    "KZL-c7": "KZL-sec2.1-four-measurements",
    "KZL-c30-ins-rate": "KZL-sec2.1-ins-data-rate",
    "KZL-c31-gnss-rate": "KZL-sec2.1-gnss-output-rate",
    "KZL-c32-cascaded": "KZL-sec2.2-cascaded-nearly-uncorrelated",
    "KZL-c11-earth-rate": "KZL-sec3.1-gyro-bias-swamps-earth-rate",
    "KZL-c12-observability": "KZL-sec3.1-observability-needs-attitude",
    "KZL-c13-neglected-rates": "KZL-sec3.2-earth-transport-rates-negligible",
    "KZL-c14-sequential": "KZL-sec3.4-sequential-update",
    "KZL-c15": "KZL-sec3.5-small-rotation-euler-angles",
    "KZL-c16": "KZL-sec3.6-heading-with-init",
    "KZL-c16-covariance": "KZL-sec3.6-heading-with-init-covariance",
    "KZL-c17": "KZL-sec3.6-heading-without-init",
    "KZL-c17-covariance": "KZL-sec3.6-heading-without-init-covariance",
    "KZL-c18": "KZL-sec3.6-heading-largest-attitude-error",
    "KZL-c19-tilt": "KZL-fig4-tight-improves-roll-pitch",
    "KZL-c19-heading": "KZL-fig4-tight-improves-heading",
    "KZL-c20": "KZL-fig4-redundant-attitude",
    "KZL-c21": "KZL-fig4-dd-phases-robust",
    "KZL-c22-position": "KZL-fig5-ins-position",
    "KZL-c22-velocity": "KZL-fig5-ins-velocity",
    "KZL-c22-position-covariance": "KZL-fig5-ins-position-covariance",
    "KZL-c22-velocity-covariance": "KZL-fig5-ins-velocity-covariance",
    "KZL-c23-c24": "KZL-fig5-tight-three-bounded",
    "KZL-c25": "KZL-fig5-dd-best",
    "KZL-c33-loose-three": "KZL-fig5-loose-three-unbounded",
    "KZL-c34-baselines": "KZL-sec3.7-baseline-tradeoff",
}

#: shorthand mentions in prose that are not whole ids
PHRASES: dict[str, str] = {
    "WF-c2/WF-c3": "WF-sec3-tip-position-vs-range and WF-sec3-tip-position-vs-ins",
    "(WF-c13-*)": "(WF-sec4d-sigma-l-high-resolution, WF-sec4d-sigma-l-medium-resolution)",
}

#: files that hold old ids on purpose (this map, and the test that old ids still resolve)
#: The files that quote old ids on purpose: this script and its tests.
KEEP = ("tools/rename_claim_ids.py", "tests/test_render_claims.py", "tests/test_tools_inprocess.py")

SUFFIXES = (".py", ".md", ".json", ".rst", ".txt", ".yml", ".yaml", ".toml", ".cfg", ".ipynb")
_ID_CHARS = "A-Za-z0-9._+-"


def _pattern(old: str) -> re.Pattern[str]:
    """``old`` as a whole id: not inside a longer id (``-``/``.`` followed by a letter or a
    digit continues an id; a full stop ending a sentence does not)."""
    return re.compile(rf"(?<![{_ID_CHARS}]){re.escape(old)}(?![A-Za-z0-9_+]|[-.][A-Za-z0-9])")


_PATTERNS = [(_pattern(old), new) for old, new in sorted(RENAMES.items(), key=lambda kv: -len(kv[0]))]
_ALIASES_LINE = re.compile(r"^\s*aliases\s*=")
_ID_LINE = re.compile(r'^(?P<indent>\s*)id="(?P<id>[^"]+)",\s*$')


def rewrite_text(text: str, *, add_aliases: bool = False) -> str:
    """``text`` with every old id replaced by its new one (lines with ``aliases=`` kept).

    With ``add_aliases`` (Python modules defining claims) an ``id="<old>",`` line becomes
    ``id="<new>",`` followed by ``aliases=("<old>",),`` at the same indentation.
    """
    out = []
    for line in text.splitlines(keepends=True):
        if _ALIASES_LINE.match(line):
            out.append(line)
            continue
        m = _ID_LINE.match(line.rstrip("\r\n"))
        if add_aliases and m and m["id"] in RENAMES:
            end = line[len(line.rstrip("\r\n")) :]
            out.append(f'{m["indent"]}id="{RENAMES[m["id"]]}",{end}')
            out.append(f'{m["indent"]}aliases=("{m["id"]}",),{end or chr(10)}')
            continue
        for phrase, new in PHRASES.items():
            line = line.replace(phrase, new)
        for pattern, new in _PATTERNS:
            line = pattern.sub(new, line)
        out.append(line)
    return "".join(out)


def _files() -> list[Path]:
    listed = subprocess.run(
        ["git", "ls-files"], cwd=ROOT, capture_output=True, text=True, check=True
    ).stdout.splitlines()
    return [ROOT / f for f in listed if f.endswith(SUFFIXES) and f not in KEEP and (ROOT / f).is_file()]


def _check_map() -> None:
    new_ids = list(RENAMES.values())
    if len(set(new_ids)) != len(new_ids):
        raise SystemExit("two old ids map to the same new id")
    if set(new_ids) & set(RENAMES):
        raise SystemExit("a new id is also an old id")
    bad = [n for n in new_ids if not re.fullmatch(r"(WF|KZL)-[a-z0-9.]+(-[a-z0-9]+)+", n)]
    if bad:
        raise SystemExit(f"new ids must be lower-case words joined by hyphens: {bad}")


def main(argv: list[str]) -> int:
    _check_map()
    check = "--check" in argv
    changed, left = [], []
    for path in _files():
        text = path.read_text(encoding="utf-8")
        is_claim_module = path.suffix == ".py" and path.parent.name == "papers"
        new = rewrite_text(text, add_aliases=is_claim_module)
        if new != text:
            (left if check else changed).append(path.relative_to(ROOT))
            if not check:
                path.write_text(new, encoding="utf-8")
    if check:
        for p in left:
            print(f"old claim id still referenced: {p}")
        return 1 if left else 0
    for p in changed:
        print(f"rewrote {p}")
    print(f"{len(changed)} files changed")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
