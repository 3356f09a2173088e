"""The HTML report and `linkrepro explain`: Table I, Table 5.1 and the conditioning study run into a
temporary folder (readings skipped), then Table 5.1 rerun alone, and a quick bench into its
bench/, and Rahman (1996)'s multibody scene saved as skipped (Exudyn missing); the page is checked
as a file (self-contained; every string as written) and in headless Chromium (Debian's
``chromium`` and ``chromium-driver``, driven by Selenium: nothing is downloaded): every section
rendered and holding its report.md whole, headings clear of the header, the cell's panel, units,
a keyboard walk, contrast.
Screenshots of the main views are kept in ``test-artifacts/report/`` (look at them).

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

from linkrepro.harness import describe, markdown_text, multibody, register, report, report_folder
from linkrepro.harness.bench_run import run_bench
from linkrepro.harness.run import reproduce
from linkrepro.harness.scene import Outcome
from linkrepro.harness.scenes import SCENES
from linkrepro.harness.scenes.rahman1996.arithmetic_variants import VARIANTS

SCENE, ROW, COLUMN = "ali1977-table1", "160", "src_dx"
OTHERS = ("rahman1996-table5_1", "ali1977-conditioning")
SKIPPED = "rahman1996-multibody"         # shown as skipped where Exudyn cannot be imported
LISTINGS = Path(__file__).resolve().parents[2] / "legacy"
SHOTS = Path(__file__).resolve().parents[2] / "test-artifacts" / "report"


@pytest.fixture(scope="module")
def run_dir(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("html")
    reproduce([SCENE, *OTHERS], out, measure_readings=False)
    reproduce([OTHERS[0]], out, measure_readings=False)           # a single-scene rerun
    run_bench(1, out / "bench", quick=True)
    Outcome(SKIPPED, SCENES[SKIPPED].title, [], 0.0, skipped=exudyn_missing()).save(out)
    report_folder.write(out)
    return out


def exudyn_missing() -> str:
    """Why a multibody scene is skipped where Exudyn cannot be imported (``multibody.require``'s words)."""
    with pytest.MonkeyPatch.context() as patch:
        patch.setitem(sys.modules, "exudyn", None)            # import exudyn raises ImportError
        with pytest.raises(multibody.ExudynMissing) as missing:
            multibody.require()
    return str(missing.value)


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
    """Nothing is fetched (every src a data: URI); a link leads within the page or to a file of
    the folder (a CSV a section names)."""
    refs = _Refs()
    refs.feed((run_dir / "report.html").read_text())
    assert refs.links == 0
    outside = [u for u in refs.urls if not (u.startswith("data:") or u.startswith("#") or (run_dir / u).is_file())]
    assert outside == []
    assert any(u.startswith("data:image/webp;base64,") for u in refs.urls)     # the table's figure


def test_every_figure_is_on_the_page_pixel_for_pixel(run_dir):
    """A figure is embedded smaller (lossless WebP) but every pixel as in its PNG (decoded by Pillow)."""
    import base64
    import io

    from PIL import Image

    def pixels(image) -> bytes:
        return image.convert("RGB").tobytes() + repr(image.size).encode()
    refs = _Refs()
    refs.feed((run_dir / "report.html").read_text())
    embedded = [base64.b64decode(u.split(",", 1)[1]) for u in refs.urls if u.startswith("data:image/")]
    shown = sorted(pixels(Image.open(io.BytesIO(data))) for data in embedded)
    pngs = sorted(run_dir.rglob("*.png"))
    assert len(pngs) >= 2 and shown == sorted(pixels(Image.open(png)) for png in pngs)
    assert sum(map(len, embedded)) < 0.85 * sum(png.stat().st_size for png in pngs)


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
    assert re.search(r"^\s+legacy\s.*\s0/3\s", out, re.M)        # digits as the page's marker: a misprinted sign
    kept = assumed(SCENE)                                             # the model assumptions, named
    assert kept and all(f"{e.id} {e.title}" in " ".join(out.split()) for e in kept)


def assumed(scene: str) -> list:
    """The register's model assumptions whose scenes name ``scene`` (read from the TOML)."""
    return [e for e in register.load().values() if e.kind == "model-assumption" and scene in e.scenes]


def test_each_scene_states_the_model_assumptions_its_corrected_engine_keeps(run_dir):
    """In the scene's report.md (with their effect), its section of the folder's report.md and of
    report.html; a scene that none names says none."""
    folder, page = (run_dir / "report.md").read_text(), (run_dir / "report.html").read_text()
    assert assumed(SCENE) and assumed(OTHERS[0]) and not assumed(OTHERS[1])
    for name in (SCENE, *OTHERS):
        own = (run_dir / name / "report.md").read_text()
        section = folder.split(f"## [{name}]")[1].split("\n## ")[0]
        html = page.split(f'<section id="{name}">')[1].split("</section>")[0]
        assert ("What the corrected engine still assumes" in own) == bool(assumed(name)), name
        assert ("model-assumption" in section) == ("still assumes" in html) == bool(assumed(name)), name
        for e in assumed(name):
            assert f"- **{e.id}** {markdown_text.prose(e.title)}. {markdown_text.prose(e.effect)}" in own
            assert f"{e.id} {e.title}" in section
            assert squash(f"{e.id} {e.title}. {e.effect}".replace("`", "")) in squash(text_of(html)[0])


def test_explain_unknown_row_is_a_usage_error(run_dir):
    done = subprocess.run([sys.executable, "-m", "linkrepro", "explain", SCENE, "165", COLUMN, "--out", str(run_dir)],
                          capture_output=True, text=True)
    assert done.returncode == 2 and "no row '165'" in done.stderr and "Traceback" not in done.stderr


class _Reader(HTMLParser):
    """An HTML fragment as a reader sees it: its text, its code's texts, and the markdown left in it
    (``slips``): a backtick outside code, or emphasis glued to a letter, digit, ``_`` or ``*`` (an
    asterisk or underscore of code text read as markup: REAL*8 ... 4.0*ATAN, KED_*, NEWTON_*)."""
    GLUE = re.compile(r"[\w*]")
    BLOCKS = {"p", "li", "td", "th", "tr", "div", "summary", "details", "dd", "dt", "h2", "h3", "h4", "pre",
              "figcaption"}

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.text, self.codes, self.slips = "", [], []
        self.in_code, self.hidden, self.emphasis, self.closed = 0, 0, [], None

    def handle_starttag(self, tag, attrs):
        self.hidden += tag in ("script", "style", "template")
        if tag in ("code", "pre"):
            self.in_code += 1
            self.codes.append("")
        if tag in ("em", "strong"):
            self.emphasis.append(len(self.text))
            if self.text and self.GLUE.match(self.text[-1]):
                self.slips.append(f"<{tag}> after {self.text[-30:]!r}")

    def handle_endtag(self, tag):
        self.hidden -= tag in ("script", "style", "template")
        self.in_code -= tag in ("code", "pre")
        if tag in ("em", "strong") and self.emphasis:
            self.closed = (len(self.text), tag, self.text[self.emphasis.pop():])
        if tag in self.BLOCKS:
            self.text += " "

    def handle_data(self, data):
        if self.hidden:
            return
        if self.closed and self.closed[0] == len(self.text) and self.GLUE.match(data):
            self.slips.append(f"</{self.closed[1]}> before {data[:20]!r} (emphasised {self.closed[2][-30:]!r})")
        if self.in_code:
            self.codes[-1] += data
        elif "`" in data:
            self.slips.append(f"a backtick in {data.strip()[:80]!r}")
        self.text += data


def text_of(html: str) -> tuple[str, list[str], list[str]]:
    """``html``'s text, its code's texts, its slips (``_Reader``)."""
    reader = _Reader()
    reader.feed(html)
    return reader.text, reader.codes, reader.slips


def squash(text: str) -> str:
    return " ".join(text.split())


def page_sections(run_dir: Path) -> dict[str, str]:
    """Each section of the page: its id and its HTML."""
    return dict(re.findall(r'<section id="([^"]+)">(.*?)</section>', (run_dir / "report.html").read_text(), re.S))


def test_every_section_renders_text_as_written(run_dir):
    """No section shows markdown as text or loses an asterisk of code; a skipped scene's reason is
    its words with its command as code; the bench's FORTRAN names keep their asterisks."""
    sections = page_sections(run_dir)
    assert {SCENE, *OTHERS, SKIPPED, "bench", "register"} <= set(sections)
    assert {name: text_of(html)[2] for name, html in sections.items() if text_of(html)[2]} == {}
    text, codes, _ = text_of(sections[SKIPPED])
    reason = exudyn_missing()
    assert "`" in reason and squash(reason.replace("`", "")) in squash(text)
    assert multibody.INSTALL in codes
    bench = (run_dir / "bench" / "bench.md").read_text()
    named = re.findall(r"\b[A-Z]+_\*", bench)                # the flop counts' names, KED_* ...
    assert named and set(named) <= set(text_of(sections["bench"])[1])


def test_register_words_and_variants_render_as_written():
    """Every register entry as report.md writes it (``report.render_entry``) and every arithmetic
    variant's description read back from the HTML are the register's text: nothing taken as markup
    (its backticks mark code)."""
    for entry in register.load().values():
        text, codes, slips = text_of(markdown_text.html(report.render_entry(entry)))
        assert slips == [], entry.id
        for words in (entry.title, entry.where, entry.evidence, entry.effect):
            assert squash(words.replace("`", "")) in squash(text), (entry.id, words)
        assert entry.printed in codes and entry.meant in codes, entry.id
    for variant in VARIANTS:
        text, _, slips = text_of(markdown_text.html(markdown_text.prose(variant.machine), inline=True))
        assert slips == [] and text == variant.machine.replace("`", "")


def _browser(size: tuple[int, int] = (1400, 900)):
    """A headless Chromium driven by Selenium (window ``size`` px), or a skip that says what is missing."""
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
    for arg in ("--headless=new", "--no-sandbox", "--disable-dev-shm-usage", f"--window-size={size[0]},{size[1]}"):
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
        assert describe(SCENE, COLUMN).label in shown      # the column's words (the page keeps each once)

        # a cell the printed engine does not produce: its row says so (fields left out of the page's data)
        rigid = browser.find_element(By.CSS_SELECTOR, f'td.cell[data-cell="{SCENE}|0|rigid_x"]')
        browser.execute_script("arguments[0].scrollIntoView({block: 'center'})", rigid)
        rigid.click()
        printed_row = [r.text for r in panel.find_elements(By.CSS_SELECTOR, "tr") if r.text.startswith("printed")]
        assert printed_row == ["printed not produced - not-produced"]

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


# -- the page as a person reads it, at 1280 x 900 ---------------------------------------------

@pytest.fixture
def page(run_dir):
    """The report open in Chromium at 1280 x 900; no severe console message while it was open."""
    browser = _browser((1280, 900))
    try:
        browser.get((run_dir / "report.html").as_uri())
        yield browser
        assert [e for e in browser.get_log("browser") if e["level"] == "SEVERE"] == []
    finally:
        browser.quit()


def shot(browser, name: str) -> None:
    SHOTS.mkdir(parents=True, exist_ok=True)
    browser.save_screenshot(str(SHOTS / f"{name}.png"))


def rect(browser, element) -> dict:
    return browser.execute_script("return arguments[0].getBoundingClientRect().toJSON()", element)


def test_every_section_is_rendered_and_none_is_lost_by_a_rerun(page):
    from selenium.webdriver.common.by import By
    ids = [s.get_attribute("id") for s in page.find_elements(By.CSS_SELECTOR, "main section")]
    assert {SCENE, *OTHERS, "bench", "arithmetic"} <= set(ids)
    text = page.execute_script("return document.querySelector('main').innerText")
    for raw in ("|---", "| ---", "**", "](", "![", "\n| "):
        assert raw not in text, raw                             # no markdown left as text
    bench = page.find_element(By.ID, "bench")
    assert bench.find_elements(By.CSS_SELECTOR, ".markdown table") and bench.find_elements(By.TAG_NAME, "img")
    overview = page.find_element(By.CSS_SELECTOR, f"#{OTHERS[1]} .markdown")
    assert len(overview.text.splitlines()) >= 2                 # its lines stay lines
    assert "linkrepro arithmetic --out" in page.find_element(By.ID, "arithmetic").text
    shot(page, "top")


def test_the_bench_s_subsections_are_folded_and_say_what_they_hold(page):
    """Each ### subsection of the bench is a <details>: its summary is its heading and its table's
    rows (counted here in the table), a click opens it; folded, a subsection takes its summary's
    line or two, open, its table's height more."""
    from selenium.webdriver.common.by import By
    bench = page.find_element(By.ID, "bench")
    folds = bench.find_elements(By.CSS_SELECTOR, "details.fold")
    assert len(folds) >= 3 and not any(f.get_attribute("open") for f in folds)
    line = page.execute_script("return parseFloat(getComputedStyle(arguments[0]).lineHeight)", bench)
    for fold in folds:
        rows = len(fold.find_elements(By.CSS_SELECTOR, "tbody tr"))
        summary = fold.find_element(By.TAG_NAME, "summary")
        assert summary.find_element(By.TAG_NAME, "h3").text and f"a table of {rows} row" in summary.text
        assert rect(page, fold)["height"] < 3 * line
    fold = max(folds, key=lambda f: len(f.find_elements(By.CSS_SELECTOR, "tbody tr")))      # the longest table
    page.execute_script("arguments[0].scrollIntoView({block: 'center'})", fold)
    fold.find_element(By.TAG_NAME, "summary").click()
    table = fold.find_element(By.TAG_NAME, "table")
    assert table.is_displayed() and rect(page, fold)["height"] > rect(page, table)["height"] + line
    # scrolled past its top, the table's heads stay under the page's header
    header, head = page.find_element(By.TAG_NAME, "header"), table.find_element(By.CSS_SELECTOR, "thead th")
    page.execute_script("scrollBy(0, arguments[0].getBoundingClientRect().top - arguments[1].offsetHeight + 2 * arguments[2])",
                        table, header, line)
    assert rect(page, table)["top"] < rect(page, header)["bottom"] - line
    assert abs(rect(page, head)["top"] - rect(page, header)["bottom"]) < 1.5


#: markdown's emphasis (``*words*``, ``**words**``, never inside a word) and links, as the words they show
EMPHASIS = re.compile(r"(?<![\\\w])\*\*?(?=\S)(.+?)(?<=\S)\*\*?(?![\w*])|!?\[([^\]]*)\]\([^)]*\)")


def report_fragments(markdown: str) -> tuple[list[str], list[str]]:
    """What a reader reads of a report.md, its markup taken off line by line (apart from the page's
    renderer): each heading's, paragraph's, list item's and table cell's words; and, apart, the
    lines of its part "Register entries involved" (the page shows each entry once, in its register
    section).  Images are left out, and a part of images only (the page shows the figures with
    their captions)."""
    shown, entries, part = [], [], ""
    for line in markdown.splitlines()[1:]:                    # the title is the section's heading
        if line.startswith("## "):
            if shown and shown[-1] == squash(part):
                shown.pop()                                   # the part before held images only
            part = line[3:]
        if not line.strip() or line.startswith(("![", "|---")):
            continue
        field = part == report.REGISTER_PART and line.startswith("- ")     # an entry's field: name, words
        line = re.sub(r"^(#+ |- |\d+\. )", "", line)
        cells = ([c for c in re.split(r"(?<!\\)\|", line) if c.strip()] if line.startswith("|")
                 else line.split(": ", 1) if field else [line])
        for cell in cells:
            pieces = re.split(r"(`+)(.+?)\1", cell)             # code spans kept as written
            words = "".join(p if i % 3 == 2 else "" if i % 3 == 1 else
                            re.sub(r"\\(.)", r"\1", re.sub(EMPHASIS, r"\1\2", p))
                            for i, p in enumerate(pieces))
            in_entries = part == report.REGISTER_PART and not line.startswith("Register")
            (entries if in_entries else shown).append(squash(words))
    return shown[:-1] if shown and shown[-1] == squash(part) else shown, entries


def test_each_section_holds_its_report_whole(page, run_dir):
    """Each section holds every word of its folder's report.md (scene or command; closed parts
    included), its register entries in the page's register section, links to its files and back
    to the overview; the overview links each section and the manifest."""
    from selenium.webdriver.common.by import By
    texts = page.execute_script("const t = {}; for (const s of document.querySelectorAll('main section')) "
                                "t[s.id] = s.textContent.split(/\\s+/).join(' '); return t;")
    reports = {p.parent.name: p for p in run_dir.glob("*/*.md") if p.parent.name in texts}
    assert {SCENE, *OTHERS, "bench"} <= set(reports)
    for name, path in reports.items():
        shown, entries = report_fragments(path.read_text())
        assert [f for f in shown if f not in texts[name]] == [], name
        assert [f for f in entries if f not in texts["register"]] == [], name
        links = [a.get_attribute("href") for a in page.find_elements(By.CSS_SELECTOR, f"#{name} .files a")]
        named = {link.split("/")[-1] for link in links}
        assert path.name in named and any(link.endswith("#overview") for link in links), (name, links)
        assert {p.name for p in path.parent.glob("*.csv")} <= named, name
    overview = {a.get_attribute("href").split("/")[-1] for a in page.find_elements(By.CSS_SELECTOR, "#sections a")}
    assert "manifest.json" in overview and {f"report.html#{n}" for n in reports} <= overview


def test_each_heading_is_clear_of_the_header_after_its_link_is_clicked(page):
    from selenium.webdriver.common.by import By
    links = page.find_elements(By.CSS_SELECTOR, "header nav a")
    assert len(links) == len(page.find_elements(By.CSS_SELECTOR, "main section")) + 1
    for link in links:
        assert page.execute_script("return arguments[0].getClientRects().length", link) == 1   # never wrapped
    for link in links:
        link.click()
        target = page.find_element(By.ID, link.get_attribute("href").split("#", 1)[1])
        heading = target if target.tag_name == "h2" else target.find_element(By.TAG_NAME, "h2")
        header = rect(page, page.find_element(By.TAG_NAME, "header"))
        box = rect(page, heading)
        assert box["top"] >= header["bottom"] - 0.5 and box["bottom"] <= page.execute_script("return innerHeight"), \
            (link.text, box, header)
        if link.text == SCENE:
            shot(page, "table")


def test_the_panel_fits_and_leaves_the_cell_in_view(page):
    from selenium.webdriver.common.by import By
    columns = [head for head, _ in heads(page)]
    for column in (COLUMN, columns[-1]):                       # a middle column, and the last one
        cell = page.find_element(By.CSS_SELECTOR, f'td.cell[data-cell="{SCENE}|{ROW}|{column}"]')
        page.execute_script("arguments[0].scrollIntoView({block: 'center'})", cell)
        cell.click()
        panel = page.find_element(By.ID, "panel")
        assert panel.is_displayed()
        assert page.execute_script("return arguments[0].scrollWidth <= arguments[0].clientWidth", panel)
        box, side = rect(page, cell), rect(page, panel)
        header = rect(page, page.find_element(By.TAG_NAME, "header"))
        assert box["left"] >= 0 and box["right"] <= side["left"], (column, box, side)
        # within a pixel: the page scrolls by whole pixels, the cell may sit at a fraction of one (its text's line height)
        assert box["top"] >= header["bottom"] - 1 and box["bottom"] <= page.execute_script("return innerHeight") + 1
        if column == COLUMN:
            shot(page, "panel")


def test_figures_are_shown_at_their_natural_size_and_the_overview_fits(page):
    """A figure's text is >= 9 pt at its natural size (harness/figures.py): the page never
    shrinks it, with the panel closed or open; the overview table needs no scrolling at 1280 px."""
    from selenium.webdriver.common.by import By
    sizes = "return [...document.querySelectorAll('main figure img')].map(i => [i.clientWidth, i.naturalWidth])"
    shown = page.execute_script(sizes)
    assert shown and all(w == natural for w, natural in shown), shown
    overview = page.find_element(By.CSS_SELECTOR, "table.overview")
    assert page.execute_script("return arguments[0].parentElement.scrollWidth <= arguments[0].parentElement.clientWidth",
                               overview)
    cell = page.find_element(By.CSS_SELECTOR, f'td.cell[data-cell="{SCENE}|{ROW}|{COLUMN}"]')
    page.execute_script("arguments[0].scrollIntoView({block: 'center'})", cell)
    cell.click()
    assert page.find_element(By.ID, "panel").is_displayed()
    assert all(w == natural for w, natural in page.execute_script(sizes))


def heads(browser) -> list[tuple[str, str]]:
    """The published table's column heads: (the text shown, the hover text)."""
    return browser.execute_script(f"""return [...document.querySelectorAll('#{SCENE} table.published thead th')]
        .map(th => [th.firstChild.textContent, th.title])""")


def test_columns_are_headed_short_with_their_words_and_unit_on_hover(page):
    """A head shows the column's id and unit (two short lines, not seven); its words and unit
    (quantities.describe) are its hover text."""
    from selenium.webdriver.common.by import By
    shown = heads(page)
    assert [title for _, title in shown] == [describe(SCENE, column).label for column, _ in shown]
    assert shown[3][0] == COLUMN and "(in)" in shown[3][1] and shown[0][1].endswith("(deg)"), shown
    row = page.find_element(By.CSS_SELECTOR, f"#{SCENE} table.published thead tr")
    line = page.execute_script("return parseFloat(getComputedStyle(arguments[0]).lineHeight)", row)
    assert rect(page, row)["height"] < 3 * line                  # the id and the unit, each on one line


def test_a_long_table_keeps_its_column_heads_in_view(run_dir):
    """At a short window the table scrolls inside its box, its heads stay at the box's top (and
    above the cells); the panel still opens on a cell scrolled to."""
    from selenium.webdriver.common.by import By
    browser = _browser((1280, 600))
    try:
        browser.get((run_dir / "report.html").as_uri())
        box = browser.find_element(By.CSS_SELECTOR, f"#{SCENE} .scroll")
        browser.execute_script("arguments[0].scrollIntoView(); scrollBy(0, -document.querySelector('header').offsetHeight)", box)
        assert browser.execute_script("return arguments[0].scrollHeight > arguments[0].clientHeight", box)
        head = box.find_element(By.CSS_SELECTOR, "thead th:nth-child(4)")
        browser.execute_script("arguments[0].scrollTop = arguments[0].scrollHeight", box)
        assert browser.execute_script("return arguments[0].scrollTop", box) > 0
        assert abs(rect(browser, head)["top"] - rect(browser, box)["top"]) < 1.5
        middle = rect(browser, head)
        top = browser.execute_script("return document.elementFromPoint(arguments[0], arguments[1])",
                                     middle["left"] + middle["width"] / 2, middle["top"] + middle["height"] / 2)
        assert browser.execute_script("return arguments[0].closest('th') === arguments[1]", top, head)
        shot(browser, "sticky")
        last = box.find_elements(By.CSS_SELECTOR, "td.cell")[-1]
        last.click()
        assert browser.find_element(By.ID, "panel").is_displayed()
        assert browser.execute_script("return document.elementFromPoint(...arguments) !== null",
                                      rect(browser, last)["left"] + 2, rect(browser, last)["top"] + 2)
        assert [e for e in browser.get_log("browser") if e["level"] == "SEVERE"] == []
    finally:
        browser.quit()


def test_a_copied_cell_is_its_value_and_the_digits_marker_says_what_it_means(page):
    from selenium.webdriver.common.by import By
    cell = page.find_element(By.CSS_SELECTOR, f'td.cell[data-cell="{SCENE}|{ROW}|{COLUMN}"]')
    copied = page.execute_script("""const r = document.createRange(); r.selectNodeContents(arguments[0]);
        const s = getSelection(); s.removeAllRanges(); s.addRange(r); return s.toString();""", cell)
    assert copied.strip() == "-0.655"
    marker = cell.find_element(By.CSS_SELECTOR, '.digits[data-engine="legacy"]')
    assert marker.text == "0/3" and "0 of the 3 printed digits" in marker.get_attribute("title")   # a misprinted sign
    hover = dict(part.split(": ") for part in cell.get_attribute("title").split("; "))
    assert set(hover) == {"printed", "legacy", "port_printed", "port_corrected"}
    assert all(hover[engine] == cell.get_attribute(f"data-{engine}") for engine in hover)
    assert hover["legacy"] == "explained"                        # the misprint, an entry of the register
    matched = page.find_element(By.CSS_SELECTOR, f'td.cell[data-cell="{SCENE}|0|{COLUMN}"] .digits[data-engine="legacy"]')
    assert matched.text == "3/3"                               # a match reproduces every printed digit


def test_a_keyboard_walk_reaches_a_cell_opens_and_closes_its_trail(page):
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.by import By
    from selenium.webdriver.common.keys import Keys
    for _ in range(400):
        ActionChains(page).send_keys(Keys.TAB).perform()
        if page.execute_script("return document.activeElement.matches('td.cell')"):
            break
    else:
        pytest.fail("Tab never reached a cell")
    cell = page.switch_to.active_element
    assert page.execute_script("return getComputedStyle(arguments[0]).outlineStyle", cell) != "none"   # visible focus
    ActionChains(page).send_keys(Keys.ENTER).perform()
    panel = page.find_element(By.ID, "panel")
    assert panel.is_displayed() and cell.text.split()[0] in panel.text
    shot(page, "keyboard")
    ActionChains(page).send_keys(Keys.ESCAPE).perform()
    assert not panel.is_displayed()
    assert page.execute_script("return document.activeElement === arguments[0]", cell)


def _luminance(css: str) -> float:
    channels = [float(v) / 255 for v in re.findall(r"[\d.]+", css)[:3]]
    linear = [c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4 for c in channels]
    return 0.2126 * linear[0] + 0.7152 * linear[1] + 0.0722 * linear[2]


def test_text_on_every_status_colour_has_sufficient_contrast(page):
    """WCAG AA: 4.5:1 for the value, the digits marker and the legend on each status colour."""
    from selenium.webdriver.common.by import By
    elements = page.find_elements(By.CSS_SELECTOR, ".legend span span, .legend > span")
    for status in ("match", "explained", "unresolved", "unexplained", "not-produced"):
        found = page.find_elements(By.CSS_SELECTOR, f'td.cell[data-legacy="{status}"]')
        if found:
            elements += [found[0], found[0].find_element(By.CSS_SELECTOR, '.digits[data-engine="legacy"]')]
    assert len(elements) >= 5
    for element in elements:
        style = page.execute_script("""let e = arguments[0]; const colour = getComputedStyle(e).color;
            while (e && getComputedStyle(e).backgroundColor === 'rgba(0, 0, 0, 0)') e = e.parentElement;
            return [colour, e ? getComputedStyle(e).backgroundColor : 'rgb(255, 255, 255)'];""", element)
        light, dark = sorted(map(_luminance, style), reverse=True)
        assert (light + 0.05) / (dark + 0.05) >= 4.5, (element.text, style)
