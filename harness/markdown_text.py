"""Our markdown, written one way and read one way: ``code_span`` puts code (a command line, a
FORTRAN name such as ``REAL*8`` or ``KED_*``) in a code span, ``prose`` puts plain text whose
characters must stay as written (a register entry's words, a variant's description) with the
characters markdown would read as markup escaped, keeping the code spans it holds; and
``html`` is the one way the page (report.html) turns any of it into HTML.
"""
from __future__ import annotations

import re
from functools import lru_cache
from pathlib import PurePosixPath

#: a code span: a run of backticks, its text, the same run again (CommonMark)
SPAN = re.compile(r"(?<!`)(`+)(?!`)(.+?)(?<!`)\1(?!`)", re.S)
#: what markdown would read as markup in running text (emphasis, links, raw HTML, table cells, a lone
#: backtick, an entity); ``_`` only where it can open or close emphasis (not between two letters or digits)
MARKUP = re.compile(r"[\\*\[\]<>|`]|&(?=#?\w+;)|(?<![A-Za-z0-9])_|_(?![A-Za-z0-9])")


def code_span(text: str) -> str:
    """``text`` as a markdown code span, whatever backticks it holds."""
    fence = "`" * (max((len(run) for run in re.findall("`+", text)), default=0) + 1)
    pad = " " if text.startswith("`") or text.endswith("`") else ""
    return f"{fence}{pad}{text}{pad}{fence}"


def prose(text: str) -> str:
    """Plain ``text`` for running markdown: each character markdown would read as markup (``MARKUP``)
    escaped with a backslash, the code spans it holds (```like this```) kept as code spans."""
    out, at = [], 0
    for span in SPAN.finditer(text):
        out += [MARKUP.sub(lambda m: "\\" + m.group(0), text[at:span.start()]), span.group(0)]
        at = span.end()
    return "".join(out) + MARKUP.sub(lambda m: "\\" + m.group(0), text[at:])


def html(text: str, base: PurePosixPath = PurePosixPath("."), breaks: bool = False, inline: bool = False) -> str:
    """Markdown as HTML (CommonMark and tables; raw HTML escaped; ``breaks``: a line break is kept,
    as in a scene's overview lines; ``inline``: one paragraph's content, no ``<p>``).  Images are
    left out (a section shows its figures with their captions); a relative link is made relative
    to the report's folder (``base``: the markdown's folder there)."""
    md, env = _renderer(breaks), {"base": base}
    return md.renderInline(text, env) if inline else TABLE_BREAK.sub(r"\1", md.render(text, env))


@lru_cache(maxsize=None)
def _renderer(breaks: bool):
    """The markdown-it renderer ``html`` uses, made once a process (``breaks``: keep line breaks)."""
    from markdown_it import MarkdownIt
    md = MarkdownIt("commonmark", {"html": False, "breaks": breaks}).enable("table")
    md.renderer.rules["image"] = lambda tokens, idx, options, env: ""

    def link_open(tokens, idx, options, env):
        href = tokens[idx].attrGet("href") or ""
        if href and not href.startswith(("#", "/")) and ":" not in href.split("/")[0]:
            tokens[idx].attrSet("href", (env["base"] / href).as_posix())
        return md.renderer.renderToken(tokens, idx, options, env)

    md.renderer.rules["link_open"] = link_open
    return md


#: the line break markdown-it puts after each tag of a table: nothing to a reader, 3-5 % of a page of tables
TABLE_BREAK = re.compile(r"(</?(?:table|thead|tbody|tr|th|td)>)\n")
