"""Layout gate on a built HTML book, measured in headless Chromium: nothing a reader must
scroll sideways to read.

Usage::

    python tools/check_layout.py _build/html                  # 1400 px and 420 px
    python tools/check_layout.py _build/html --width 420 --list

Every page of the book (not the API reference's highlighted sources, the search page or the
indexes) is loaded at each width, after MathJax has typeset it, and two things are measured:

``math``
    a display equation whose rendered width exceeds its box (``scrollWidth > clientWidth``
    of the equation's block, or of MathJax's container inside it), so that the reader sees
    it cut and must scroll it sideways;
``table``
    a table in a cell's output (``div.cell_output``) that is wider than the text column.

The book sets a display equation that is a little too wide smaller, down to 70 % of its size
(``book/_static/navcore-math.js``); the gate reports how many it set smaller, and how small.

At 1400 px nothing may overflow. At 420 px (a phone) an equation that cannot be broken into
lines of that width, or a table whose columns cannot be narrowed further, may scroll inside
its own box: each such item is listed, with the reason, in ``tools/layout_allowlist.json``
(``{"420": {"math": {"page#equation": "why"}, "table": {...}}}``). The gate fails on an
overflow not in the list and on a list entry that no longer overflows (so the list only
shrinks). Equations and tables are named by page and by their anchor (an equation's label)
or their position on the page (``math-3``, ``table-2``; a pandas Styler table's generated id,
which changes with its numbers, is not used), so that the list survives a rebuild.

Chromium is found on the PATH (``chromium``, ``chromium-browser``, ``google-chrome``); when
it is missing and the gate runs as root on Debian it is installed with apt-get, otherwise
the gate fails with the command to install it. It is driven through the DevTools protocol
(a websocket; ``tornado``, which the notebook stack installs, is the client).

Exit status 1 and one line per problem when the gate fails.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
ALLOWLIST = ROOT / "tools" / "layout_allowlist.json"
WIDTHS = (1400, 420)
# pages that are not the book's text
SKIP = re.compile(r"^(?:_modules/|_sources/|_static/|_images/|genindex|py-modindex|search\.html)")
BROWSERS = ("chromium", "chromium-browser", "google-chrome")

# measured in the page once MathJax has typeset it; returns {"math": [...], "table": [...]}
MEASURE = r"""
(async () => {
  if (window.MathJax && MathJax.startup && MathJax.startup.promise) {
    await MathJax.startup.promise;
  }
  if (document.fonts && document.fonts.ready) { await document.fonts.ready; }
  await new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)));
  const root = document.querySelector('article.bd-article') || document.body;
  const over = el => el.scrollWidth > el.clientWidth + 1;
  const out = {math: [], table: [], smaller: []};
  let i = 0;
  for (const block of root.querySelectorAll('div.math')) {
    i += 1;
    const inner = block.querySelector('mjx-container[display="true"]');
    const size = inner ? inner.dataset.navcoreSize : undefined;
    if (size !== undefined && inner.style.fontSize !== size) {
      const base = parseFloat(size) || 100;
      out.smaller.push({name: block.id || ('math-' + i), scale: parseFloat(inner.style.fontSize) / base});
    }
    if (over(block) || (inner && over(inner))) {
      const el = inner && over(inner) ? inner : block;
      out.math.push({name: block.id || ('math-' + i), scroll: el.scrollWidth, client: el.clientWidth,
                     text: (block.textContent || '').trim().slice(0, 60)});
    }
  }
  let j = 0;
  const column = root.clientWidth;
  for (const table of root.querySelectorAll('div.cell_output table')) {
    j += 1;
    const box = table.closest('div.output') || table.parentElement;
    const width = table.getBoundingClientRect().width;
    if (width > box.clientWidth + 1 || width > column + 1) {
      const head = Array.from(table.querySelectorAll('th')).map(t => t.textContent.trim()).join(' | ');
      // a pandas Styler table's id (T_ and a hash of its content) changes with its numbers: by position
      const named = table.id && !/^T_[0-9a-f]+$/.test(table.id);
      out.table.push({name: named ? table.id : ('table-' + j), scroll: Math.round(width),
                      client: box.clientWidth, text: head.slice(0, 60)});
    }
  }
  return JSON.stringify(out);
})()
"""


def find_browser() -> str:
    """The Chromium executable, installed with apt-get when missing and running as root."""
    for name in BROWSERS:
        path = shutil.which(name)
        if path:
            return path
    command = ["apt-get", "install", "-y", "--no-install-recommends", "chromium"]
    if hasattr(os, "geteuid") and os.geteuid() == 0 and shutil.which("apt-get"):
        env = {**os.environ, "DEBIAN_FRONTEND": "noninteractive"}
        subprocess.run(["apt-get", "update", "-qq"], check=True, env=env)
        subprocess.run(command, check=True, env=env)
        path = shutil.which("chromium")
        if path:
            return path
    raise SystemExit(f"check_layout: Chromium is needed; install it with:\n    sudo {' '.join(command)}")


class Browser:
    """One headless Chromium, driven over the DevTools protocol."""

    def __init__(self, executable: str):
        self.profile = tempfile.mkdtemp(prefix="navcore-layout-")
        self.proc = subprocess.Popen(
            [
                executable,
                "--headless",
                "--no-sandbox",
                "--disable-gpu",
                "--disable-background-networking",
                "--disable-component-update",
                "--disable-sync",
                "--no-first-run",
                "--hide-scrollbars",
                f"--user-data-dir={self.profile}",
                "--remote-debugging-port=0",
                "about:blank",
            ],
            stdout=subprocess.DEVNULL,
            stderr=subprocess.PIPE,
            text=True,
        )
        assert self.proc.stderr is not None
        for line in self.proc.stderr:
            m = re.search(r"DevTools listening on (ws://\S+)", line)
            if m:
                self.browser_ws = m.group(1)
                break
        else:
            raise SystemExit("check_layout: Chromium did not start its DevTools endpoint")
        self.ids = 0

    async def connect(self) -> None:
        from tornado.httpclient import HTTPRequest
        from tornado.websocket import websocket_connect

        port = re.search(r":(\d+)/", self.browser_ws).group(1)  # type: ignore[union-attr]
        self.ws = await websocket_connect(self.browser_ws, max_message_size=1 << 26)
        target = await self.call("Target.createTarget", {"url": "about:blank"})
        page_ws = f"ws://127.0.0.1:{port}/devtools/page/{target['targetId']}"
        self.page = await websocket_connect(HTTPRequest(page_ws), max_message_size=1 << 26)

    async def call(self, method: str, params: dict | None = None, ws=None) -> dict:
        ws = ws or self.ws
        self.ids += 1
        ident = self.ids
        ws.write_message(json.dumps({"id": ident, "method": method, "params": params or {}}))
        while True:
            msg = await ws.read_message()
            if msg is None:
                raise SystemExit(f"check_layout: Chromium closed the connection during {method}")
            data = json.loads(msg)
            if data.get("id") == ident:
                if "error" in data:
                    raise RuntimeError(f"{method}: {data['error']}")
                return data.get("result", {})

    async def measure(self, url: str, width: int, dark: bool = False) -> dict:
        await self.call(
            "Emulation.setDeviceMetricsOverride",
            {"width": width, "height": 1200, "deviceScaleFactor": 1, "mobile": False},
            self.page,
        )
        await self.call("Page.enable", {}, self.page)
        await self.call("Page.navigate", {"url": url}, self.page)
        # wait for the load event
        while True:
            msg = await self.page.read_message()
            if msg is None:
                raise SystemExit("check_layout: Chromium closed the page")
            if json.loads(msg).get("method") == "Page.loadEventFired":
                break
        result = await self.call(
            "Runtime.evaluate",
            {"expression": MEASURE, "awaitPromise": True, "returnByValue": True, "timeout": 60000},
            self.page,
        )
        value = result.get("result", {}).get("value")
        if value is None:
            raise RuntimeError(f"{url}: measurement failed: {result}")
        return json.loads(value)

    def close(self) -> None:
        self.proc.terminate()
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
        shutil.rmtree(self.profile, ignore_errors=True)


def pages(root: Path) -> list[Path]:
    """The book's pages: not the skipped ones, nor a page that only redirects (index.html)."""
    return [
        p
        for p in sorted(root.rglob("*.html"))
        if not SKIP.match(p.relative_to(root).as_posix())
        and 'http-equiv="Refresh"' not in p.read_text(encoding="utf-8", errors="replace")[:2000]
    ]


async def _measure_all(root: Path, widths: tuple[int, ...]) -> dict[int, dict[str, list[tuple[str, dict]]]]:
    browser = Browser(find_browser())
    found: dict[int, dict[str, list[tuple[str, dict]]]] = {
        w: {"math": [], "table": [], "smaller": []} for w in widths
    }
    try:
        await browser.connect()
        for page in pages(root):
            rel = page.relative_to(root).as_posix()
            for width in widths:
                got = await browser.measure(page.resolve().as_uri(), width)
                for kind in ("math", "table", "smaller"):
                    for item in got.get(kind, []):
                        found[width][kind].append((f"{rel}#{item['name']}", item))
    finally:
        browser.close()
    return found


def measure(root: Path, widths: tuple[int, ...] = WIDTHS) -> dict[int, dict[str, list[tuple[str, dict]]]]:
    """Overflowing display equations and output tables of every page, per width."""
    return asyncio.run(_measure_all(root, widths))


def check(root: Path, widths: tuple[int, ...] = WIDTHS, list_all: bool = False) -> list[str]:
    allow = json.loads(ALLOWLIST.read_text(encoding="utf-8")) if ALLOWLIST.exists() else {}
    found = measure(root, widths)
    problems = []
    for width in widths:
        smaller = found[width].get("smaller", [])
        if smaller:
            least = min(item["scale"] for _, item in smaller)
            print(
                f"check_layout: {width} px: {len(smaller)} display equation(s) set smaller to fit "
                f"(smallest at {100 * least:.0f} %)",
                file=sys.stderr,
            )
            if list_all:
                for name, item in smaller:
                    print(f"{width} px: smaller {name} at {100 * item['scale']:.0f} %")
        for kind in ("math", "table"):
            allowed = allow.get(str(width), {}).get(kind, {})
            names = set()
            for name, item in found[width][kind]:
                names.add(name)
                size = f"{item['scroll']} px in a {item['client']} px box"
                line = f"{width} px: {kind} {name} is {size}: {item['text']}"
                if list_all:
                    print(line)
                if name not in allowed:
                    problems.append(line)
            problems += [
                f"{width} px: {kind} {name} is in the allowlist but no longer overflows: remove it"
                for name in sorted(set(allowed) - names)
            ]
            print(
                f"check_layout: {width} px: {len(found[width][kind])} overflowing {kind} "
                f"({len(allowed)} allowed)",
                file=sys.stderr,
            )
    return problems


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("html", type=Path, help="the built HTML book (_build/html)")
    parser.add_argument("--width", type=int, action="append", help="px (default: 1400 and 420)")
    parser.add_argument("--list", action="store_true", help="print every overflow, allowed or not")
    args = parser.parse_args(argv)
    widths = tuple(args.width) if args.width else WIDTHS
    problems = check(args.html, widths, args.list)
    for line in problems:
        print(line)
    print(f"check_layout: {len(problems)} problem(s)", file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    raise SystemExit(main())
