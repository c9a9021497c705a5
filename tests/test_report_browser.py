"""Guards issue 18's acceptance for the HTML report in a real headless browser (Debian's
chromium, installed by ``make test``'s set-up so that CI runs this rather than skipping): the
page of a model that is not the paper rig loads without console errors, every figure is present
and visible (an SVG of real size), and at a narrow (phone, 390 px) and a wide (1400 px) window no
text overflows its box (a table cell, paragraph, caption or heading whose content is wider than
the box). Screenshots at both widths are written and must be real images. The overflow check is
a script added to a copy of the report (the report itself has no script)."""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from rotordyn.cli import main

MODELS = Path(__file__).parent / "data" / "models"
CHROMIUM = shutil.which("chromium")
if CHROMIUM is None and os.environ.get("CI"):
    pytest.fail("chromium is missing: `make test` installs it (Makefile, testdeps)",
                pytrace=False)
pytestmark = pytest.mark.skipif(CHROMIUM is None, reason="no Chromium installed "
                                                         "(make test installs it)")

CHECK = """<style>html{width:WIDTHpx}</style><script>
// WIDTH: the layout width under test (headless Chromium's window is at least 500 px wide, so a
// narrower one is set on the page itself)
window.addEventListener('load', () => {
  const W = WIDTH, bad = [];
  const scrolls = el => { for (let a = el.parentElement; a; a = a.parentElement) {
      const ox = getComputedStyle(a).overflowX;
      if (ox === 'auto' || ox === 'scroll') return true; } return false; };
  for (const el of document.querySelectorAll('td, th, p, figcaption, h1, h2, summary, pre, svg')) {
    const ox = getComputedStyle(el).overflowX;
    if (el.scrollWidth > el.clientWidth + 1 && ox !== 'auto' && ox !== 'scroll')
      bad.push(el.tagName + ' wider than its box: ' + el.textContent.slice(0, 60));
    if (!scrolls(el) && el.getBoundingClientRect().right > W + 1)
      bad.push(el.tagName + ' beyond the page: ' + el.textContent.slice(0, 60));
  }
  const svgs = [...document.querySelectorAll('figure svg')];
  const small = svgs.filter(s => { const r = s.getBoundingClientRect();
                                   return r.width < 100 || r.height < 60; });
  document.body.setAttribute('data-overflow', JSON.stringify(bad));
  document.body.setAttribute('data-figures', String(svgs.length));
  document.body.setAttribute('data-small', String(small.length));
});
</script>"""


@pytest.fixture(scope="module")
def page(tmp_path_factory):
    d = tmp_path_factory.mktemp("report")
    html = d / "r.html"
    assert main(["report", str(MODELS / "compressor_tilting_pad.toml"), "--out", str(d),
                 "--html", str(html), "--operating-speed-hz", "140", "170"]) == 0
    text = html.read_text(encoding="utf-8")
    return d, html, text, text.count("<svg")


def _chromium(*args, timeout=180):
    return subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu",
                           "--hide-scrollbars", "--enable-logging=stderr", "--v=0", *args],
                          capture_output=True, text=True, timeout=timeout)


@pytest.mark.parametrize("width", [390, 1400])
def test_report_in_a_browser(page, width):
    """Loads, figures present and visible, nothing overflows at ``width``."""
    d, html, text, n_svg = page
    probe = d / f"probe_{width}.html"
    probe.write_text(text.replace("</body>", CHECK.replace("WIDTH", str(width)) + "</body>"),
                     encoding="utf-8")
    p = _chromium(f"--window-size={max(width, 500)},2000", "--virtual-time-budget=10000",
                  "--dump-dom", probe.as_uri())
    assert p.returncode == 0, p.stderr[-2000:]
    assert "Uncaught" not in p.stderr and "ERROR:CONSOLE" not in p.stderr, p.stderr[-2000:]
    body = re.search(r"<body([^>]*)>", p.stdout).group(1)
    attrs = dict(re.findall(r'(data-[a-z]+)="([^"]*)"', body))
    import html as h

    overflow = json.loads(h.unescape(attrs["data-overflow"]))
    assert overflow == [], overflow
    # drawing, static, critical speed map, bearing coefficients, Campbell, Bode per station,
    # log dec: every one of them in the page and visible
    assert int(attrs["data-figures"]) == n_svg >= 7
    assert "2b. Bearing coefficients over speed" in text
    assert attrs["data-small"] == "0"
    shot = d / f"shot_{width}.png"
    p = _chromium(f"--window-size={width},2000", f"--screenshot={shot}", html.as_uri())
    assert p.returncode == 0 and shot.stat().st_size > 20000, p.stderr[-2000:]
