"""The figures' conventions, and the check that every figure keeps them.

A figure is drawn for the page that shows it (``out/report.html`` shows an image at its natural
size, at most the content column's width): at ``DPI`` = 96 pixels per inch, one point of
matplotlib text is one CSS point on the screen, so text of ``MIN_TEXT_PT`` or more is legible
there; a figure is at most ``MAX_WIDTH_IN`` wide (the column at a 1280 px window).

``new_figure`` makes a figure in the house style (``RC``: text sizes), ``ENGINE_STYLE`` gives
every engine a line that differs from the others in colour *and* dash or marker, and ``save``
draws the figure once, checks it (``problems``) and writes a palette PNG (a few tens of kB).

``problems`` lists what makes a figure hard to read: text under ``MIN_TEXT_PT``; two texts
(titles, labels, tick labels, legends, notes) on top of each other; a legend or a note inside
an axes over a curve or a point of its data; two legend entries drawn alike; an axis without
words, or with several units in one label ("(in, rad)"); a figure wider than the column.
``save`` warns ``FigureWarning`` for each, or raises ``FigureError`` where the environment
variable ``LINKREPRO_STRICT_FIGURES`` is set (the test suite sets it).
"""
from __future__ import annotations

import io
import os
import re
import warnings
from pathlib import Path

import numpy as np
from matplotlib import rc_context
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.collections import PathCollection
from matplotlib.figure import Figure
from matplotlib.legend import Legend
from matplotlib.lines import Line2D
from matplotlib.text import Text
from PIL import Image, PngImagePlugin

#: pixels per inch of every figure (a CSS pixel is 1/96 in)
DPI = 96
#: smallest text on the page, points
MIN_TEXT_PT = 9.0
#: widest figure, inches (1152 px: the report's content column at a 1280 px window)
MAX_WIDTH_IN = 12.0
#: colours in a written PNG (an adaptive palette; antialiased lines need a few shades each)
PALETTE = 96
RC = {"font.size": 10, "axes.titlesize": 10, "axes.labelsize": 10, "xtick.labelsize": 9,
      "ytick.labelsize": 9, "legend.fontsize": 9, "figure.titlesize": 11, "legend.frameon": True,
      "legend.framealpha": 0.9}
STRICT_ENV = "LINKREPRO_STRICT_FIGURES"
#: the PNG text chunk that holds a figure's caption
CAPTION_KEY = "Description"

#: one look per engine: no two alike in colour, dash and marker (the port's printed face draws
#: over legacy's curve bit for bit, so it is dashed with sparse markers to stay visible)
ENGINE_STYLE = {"published": dict(marker="o", ls="none", color="k", ms=4.5, zorder=4),
                "printed": dict(marker="x", ls="none", color="0.45", ms=5, zorder=3),
                "legacy": dict(ls="-", color="tab:blue", lw=2.0, zorder=1),
                "port_printed": dict(ls=(0, (4, 3)), color="tab:orange", lw=1.4, marker="|", ms=7,
                                     markevery=0.1, zorder=2),
                "port_corrected": dict(ls="-.", color="tab:green", lw=1.4, zorder=2)}


class FigureWarning(UserWarning):
    """A figure breaks a rule of ``harness/figures.py`` (hard to read); it is still written."""


class FigureError(ValueError):
    """A figure breaks a rule of ``harness/figures.py``, where ``LINKREPRO_STRICT_FIGURES`` is set."""


def new_figure(width_in: float, height_in: float) -> Figure:
    """An empty figure of the given size (in) in the house style."""
    with rc_context(RC):
        return Figure(figsize=(width_in, height_in), dpi=DPI)


def save(fig: Figure, path: Path, caption: str, **margins) -> Path:
    """Draw ``fig`` (``margins``: ``subplots_adjust``'s, where given), check it, write it to
    ``path`` as a palette PNG with ``caption`` (what it shows, in words: the report prints it
    under the figure, ``caption_of``); returns ``path``."""
    if not caption.strip():
        raise ValueError(f"{Path(path).name}: a figure needs a caption in words")
    if margins:
        fig.subplots_adjust(**margins)
    fig.set_dpi(DPI)
    canvas = FigureCanvasAgg(fig)
    with rc_context(RC):
        canvas.draw()
    found = problems(fig, canvas.get_renderer())
    if found:
        message = f"{Path(path).name}: " + "; ".join(found)
        if os.environ.get(STRICT_ENV):
            raise FigureError(message)
        warnings.warn(message, FigureWarning, stacklevel=2)
    image = Image.fromarray(np.asarray(canvas.buffer_rgba())[..., :3])
    text = PngImagePlugin.PngInfo()
    text.add_itxt(CAPTION_KEY, caption)
    buffer = io.BytesIO()
    image.quantize(PALETTE, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE).save(
        buffer, format="png", pnginfo=text)     # zlib's default level: optimize=True (level 9) takes 10x
                                                # the time for files 8 % smaller
    Path(path).write_bytes(buffer.getvalue())
    return Path(path)


def caption_of(path: Path) -> str:
    """The caption ``save`` wrote into a PNG ('' for another file)."""
    with Image.open(path) as image:
        return str(getattr(image, "text", {}).get(CAPTION_KEY, ""))


# ---- the checks ------------------------------------------------------------------------------

def _undrawn_ticks(fig: Figure) -> set[int]:
    """ids of the texts of hidden axes, and of the tick labels matplotlib keeps outside an
    axis's view: texts it does not draw.  As matplotlib decides, in the axis's scale (on a log
    axis, 1e-2 lies outside a view from 0.16 to 1e16, however wide the view is in data units)."""
    hidden = set()
    for axes in fig.axes:
        if not (axes.get_visible() and axes.axison):
            hidden |= {id(text) for text in axes.findobj(Text)}
            continue
        for axis in (axes.xaxis, axes.yaxis):
            scale = axis.get_transform()
            low, high = sorted(scale.transform(np.asarray(axis.get_view_interval(), float)))
            slack = 1e-9 * (high - low)
            ticks = axis.get_major_ticks() + axis.get_minor_ticks()
            with np.errstate(divide="ignore", invalid="ignore"):
                at = scale.transform(np.array([tick.get_loc() for tick in ticks], float))
            hidden |= {id(label) for tick, loc in zip(ticks, at)
                       if not (np.isfinite(loc) and low - slack <= loc <= high + slack)
                       for label in (tick.label1, tick.label2)}
    return hidden


def _texts(fig: Figure) -> list[tuple[str, Text]]:
    """Every drawn, non-empty text outside the legends: (its words, the artist)."""
    skip = _undrawn_ticks(fig) | {id(t) for legend in _legends(fig) for t in [*legend.get_texts(), legend.get_title()]}
    found = []
    for text in fig.findobj(Text):
        if (not text.get_visible() or not text.get_text().strip() or id(text) in skip
                or (text.axes is not None and not text.axes.get_visible())):
            continue
        found.append((repr(text.get_text()[:30]), text))
    return found


def _legends(fig: Figure) -> list[Legend]:
    return [legend for legend in fig.findobj(Legend) if legend.get_visible()]


def _box(artist, renderer):
    return artist.get_window_extent(renderer)


def _overlap(a, b, slack: float = 1.0) -> bool:
    return (a.x0 + slack < b.x1 and b.x0 + slack < a.x1 and a.y0 + slack < b.y1 and b.y0 + slack < a.y1)


def _clip(a: np.ndarray, b: np.ndarray, box) -> tuple[np.ndarray, np.ndarray]:
    """The segments a[k] -> b[k] (display px) cut to ``box`` (Liang-Barsky); those that miss it,
    or have an end that is not finite, left out."""
    ok = np.isfinite(a).all(axis=1) & np.isfinite(b).all(axis=1)
    a, b = a[ok], b[ok]
    d = b - a
    t0, t1 = np.zeros(len(a)), np.ones(len(a))
    for k, (low, high) in enumerate(((box.x0, box.x1), (box.y0, box.y1))):
        flat = d[:, k] == 0
        with np.errstate(divide="ignore", invalid="ignore"):
            ta, tb = (low - a[:, k]) / d[:, k], (high - a[:, k]) / d[:, k]
        t0 = np.where(flat, t0, np.maximum(t0, np.minimum(ta, tb)))
        t1 = np.where(flat, t1, np.minimum(t1, np.maximum(ta, tb)))
        t1[flat & ((a[:, k] < low) | (a[:, k] > high))] = -1.0
    keep = t0 <= t1
    return a[keep] + t0[keep, None] * d[keep], a[keep] + t1[keep, None] * d[keep]


def _data_points(axes) -> np.ndarray:
    """The axes' curves and markers in display pixels, inside the axes: markers at their centres,
    curves sampled every 2 px or less (each segment cut to the axes first: a curve may run far
    beyond them)."""
    box = axes.get_window_extent()
    points = []
    for line in axes.lines:
        if not line.get_visible() or len(line.get_xdata()) == 0:
            continue
        xy = line.get_transform().transform(np.column_stack([line.get_xdata(), line.get_ydata()]).astype(float))
        if line.get_linestyle() in ("None", "none", "") or len(xy) < 2:
            points.append(xy[np.isfinite(xy).all(axis=1)])
            continue
        a, b = _clip(xy[:-1], xy[1:], box)
        counts = np.maximum(2, (np.hypot(*(b - a).T) / 2.0).astype(int) + 1)
        segment = np.repeat(np.arange(len(a)), counts)
        at = (np.arange(counts.sum()) - np.repeat(np.cumsum(counts) - counts, counts)) / np.repeat(counts - 1, counts)
        points.append(a[segment] + at[:, None] * (b - a)[segment])
    for collection in axes.collections:
        if isinstance(collection, PathCollection) and collection.get_visible():
            points.append(collection.get_offset_transform().transform(collection.get_offsets()))
    points = [p for p in points if len(p)]
    if not points:
        return np.empty((0, 2))
    xy = np.concatenate(points)
    inside = (xy[:, 0] >= box.x0) & (xy[:, 0] <= box.x1) & (xy[:, 1] >= box.y0) & (xy[:, 1] <= box.y1)
    return xy[inside]


def _covers(box, xy: np.ndarray, slack: float = 1.5) -> int:
    return int(((xy[:, 0] > box.x0 + slack) & (xy[:, 0] < box.x1 - slack)
                & (xy[:, 1] > box.y0 + slack) & (xy[:, 1] < box.y1 - slack)).sum())


def _look(handle) -> tuple:
    if isinstance(handle, Line2D):
        return ("line", str(handle.get_color()), str(handle.get_linestyle()), str(handle.get_marker()))
    face = getattr(handle, "get_facecolor", lambda: None)()
    return (type(handle).__name__, str(np.round(np.asarray(face, float), 3).tolist()) if face is not None else "",
            str(getattr(handle, "get_hatch", lambda: None)()))


MULTI_UNIT = re.compile(r"\(([^()]*,[^()]*)\)\s*$")


def problems(fig: Figure, renderer) -> list[str]:
    """What makes the drawn ``fig`` hard to read (see the module docstring); [] if nothing."""
    found = []
    width = fig.get_figwidth()
    if width > MAX_WIDTH_IN + 1e-9:
        found.append(f"{width:.1f} in wide (at most {MAX_WIDTH_IN:g})")
    texts = _texts(fig)
    legends = _legends(fig)
    for name, text in texts:
        if text.get_fontsize() < MIN_TEXT_PT - 1e-9:
            found.append(f"text {name} at {text.get_fontsize():g} pt")
    for legend in legends:
        for text in legend.get_texts():
            if text.get_fontsize() < MIN_TEXT_PT - 1e-9:
                found.append(f"legend text {text.get_text()[:30]!r} at {text.get_fontsize():g} pt")
    boxes = [(name, _box(text, renderer)) for name, text in texts]
    boxes += [(f"legend {k}", _box(legend, renderer)) for k, legend in enumerate(legends)]
    for i, (a, box_a) in enumerate(boxes):
        for b, box_b in boxes[i + 1:]:
            if _overlap(box_a, box_b):
                found.append(f"{a} over {b}")
    axes_list = [ax for ax in fig.axes if ax.get_visible() and ax.axison]
    data = {ax: _data_points(ax) for ax in axes_list}
    covering = [(f"legend {k}", _box(legend, renderer)) for k, legend in enumerate(legends)]
    covering += [(name, _box(text, renderer)) for name, text in texts
                 if text.axes is not None and text in text.axes.texts]       # notes, annotations
    for name, box in covering:
        for ax, xy in data.items():
            hits = _covers(box, xy)
            if hits:
                found.append(f"{name} over {hits} px of data")
                break
    for k, legend in enumerate(legends):
        looks = [_look(h) for h in legend.legend_handles]
        labels = [t.get_text() for t in legend.get_texts()]
        seen = {}
        for look, label in zip(looks, labels):
            if look[0] == "line" and look[2] in ("None", "none", "") and look[3] in ("None", "none", ""):
                continue                                # a note in the legend, drawn as nothing
            if look in seen:
                found.append(f"legend {k}: {seen[look]!r} and {label!r} look alike")
            seen.setdefault(look, label)
    for ax in axes_list:
        for which, label in (("x", ax.get_xlabel()), ("y", ax.get_ylabel())):
            shared = ax.get_shared_x_axes() if which == "x" else ax.get_shared_y_axes()
            if not label.strip() and not any(o.get_xlabel() if which == "x" else o.get_ylabel()
                                             for o in shared.get_siblings(ax) if o is not ax):
                found.append(f"an axes without a {which} label")
            if MULTI_UNIT.search(label):
                found.append(f"{which} label {label!r} names several units")
    return found
