"""The HTML report and `linkrepro explain`: one run of Table I (readings skipped) into a temporary
folder; the page is checked as a file (self-contained) and in headless Chromium (Debian's
``chromium`` and ``chromium-driver``, driven by Selenium: nothing is downloaded).

The expectations come from outside the run: the register (harness/deviations.toml) says which
entry explains a cell, the listing (legacy/printed) and the scan (legacy/scan) give the line.
"""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from html.parser import HTMLParser
from pathlib import Path

import pytest

from linkrepro.harness import register
from linkrepro.harness.run import reproduce

SCENE, ROW, COLUMN = "ali1977-table1", "160", "src_dx"
LISTINGS = Path(__file__).resolve().parents[2] / "legacy"


@pytest.fixture(scope="module")
def run_dir(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("html")
    reproduce([SCENE], out, measure_readings=False)
    return out


def misprint_ids() -> set[str]:
    """The register's published-misprint entries that claim the cell (read from the TOML)."""
    return {e.id for e in register.load().values() if e.kind == "published-misprint"
            and any(c.covers(SCENE, 160, COLUMN, "legacy") for c in e.cells)}


def write_statement() -> tuple[int, str]:
    """The printed source listing's WRITE of the deflections: (line number, text)."""
    lines = (LISTINGS / "printed" / "ali1977_case1_source.f").read_text().splitlines()
    found = [(n, line.strip()) for n, line in enumerate(lines, 1) if re.match(r"\s+WRITE ?\(6,200\)", line)]
    assert len(found) == 1
    return found[0]


class _Refs(HTMLParser):
    """Every URL the page would fetch: src and href attributes, <link> elements."""

    def __init__(self):
        super().__init__()
        self.urls, self.links = [], 0

    def handle_starttag(self, tag, attrs):
        self.links += tag == "link"
        self.urls += [value for name, value in attrs if name in ("src", "href") and value]


def test_page_is_self_contained(run_dir):
    refs = _Refs()
    refs.feed((run_dir / "report.html").read_text())
    assert refs.links == 0
    outside = [u for u in refs.urls if not (u.startswith("data:") or u.startswith("#"))]
    assert outside == []
    assert any(u.startswith("data:image/png;base64,") for u in refs.urls)     # the table's figure


def test_explain_prints_the_trail(run_dir):
    number, text = write_statement()
    done = subprocess.run([sys.executable, "-m", "linkrepro", "explain", SCENE, ROW, COLUMN, "--out", str(run_dir)],
                          capture_output=True, text=True, check=True)
    out = done.stdout
    assert misprint_ids() and all(i in out for i in misprint_ids())
    assert f"legacy/printed/ali1977_case1_source.f:{number}" in out and text in out
    assert "published  -0.655" in out                                # harness/published, as printed
    for engine in ("printed", "legacy", "port_printed", "port_corrected"):
        assert re.search(rf"^\s+{engine}\s", out, re.M)


def test_explain_unknown_row_is_a_usage_error(run_dir):
    done = subprocess.run([sys.executable, "-m", "linkrepro", "explain", SCENE, "165", COLUMN, "--out", str(run_dir)],
                          capture_output=True, text=True)
    assert done.returncode == 2 and "no row '165'" in done.stderr and "Traceback" not in done.stderr


def _browser():
    """A headless Chromium driven by Selenium, or a skip that says what is missing."""
    try:
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service
    except ImportError:
        pytest.skip("selenium is not installed (pip install '.[test]')")
    binary = next((shutil.which(n) for n in ("chromium", "chromium-browser", "google-chrome") if shutil.which(n)), None)
    driver = shutil.which("chromedriver") or next((p for p in ("/usr/lib/chromium/chromedriver",) if os.path.exists(p)), None)
    if not binary or not driver:
        pytest.skip("no Chromium and chromedriver on this machine: `apt-get install chromium chromium-driver` "
                    "(make test does it on Debian) to run the browser test")
    options = webdriver.ChromeOptions()
    for arg in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", "--window-size=1400,900"):
        options.add_argument(arg)
    options.binary_location = binary
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    return webdriver.Chrome(service=Service(driver), options=options)


def test_clicking_a_misprinted_cell_shows_its_trail_in_chromium(run_dir):
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support.ui import Select

    number, text = write_statement()
    browser = _browser()
    try:
        browser.get((run_dir / "report.html").as_uri())
        cell = browser.find_element(By.CSS_SELECTOR, f'td.cell[data-cell="{SCENE}|{ROW}|{COLUMN}"]')
        assert cell.text.startswith("-0.655")
        browser.execute_script("arguments[0].scrollIntoView({block: 'center'})", cell)
        cell.click()
        panel = browser.find_element(By.ID, "panel")
        assert panel.is_displayed()
        shown = panel.text
        assert misprint_ids() and all(i in shown for i in misprint_ids())
        assert f"legacy/printed/ali1977_case1_source.f:{number}" in shown and text in shown

        # the selector recolours: row 0's source dX matches for legacy, not for the corrected port
        other = browser.find_element(By.CSS_SELECTOR, f'td.cell[data-cell="{SCENE}|0|{COLUMN}"]')
        assert other.get_attribute("data-legacy") == "match" != other.get_attribute("data-port_corrected")
        before = other.value_of_css_property("background-color")
        Select(browser.find_element(By.ID, "engine")).select_by_value("port_corrected")
        assert other.value_of_css_property("background-color") != before

        errors = [e for e in browser.get_log("browser") if e["level"] == "SEVERE"]
        assert errors == []
    finally:
        browser.quit()
