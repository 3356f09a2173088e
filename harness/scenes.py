"""Scenes: one per published table.  A scene knows its inputs, how each engine
produces the table, and the table's columns (the published table's, exactly).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

import numpy as np
import pandas as pd

from .. import legacy
from ..port import CORRECTED, PRINTED, Quirks, cognate_case1, source_case1
from .engines import run_printed

TABLE1_COLUMNS = ["input_deg", "rigid_x", "rigid_y", "src_dx", "src_dy", "src_xnew", "src_ynew",
                  "cog_dx", "cog_dy", "cog_xnew", "cog_ynew"]


@dataclass(frozen=True)
class Scene:
    name: str
    title: str
    table: str                                   # harness/published/<table>.csv
    columns: list[str]
    key: str
    inputs: str                                  # what the engines are run with, in words
    printed: Callable[[], pd.DataFrame]
    legacy: Callable[[], pd.DataFrame]
    port: Callable[[Quirks], pd.DataFrame]
    notes: list[str] = field(default_factory=list)

    def run(self, engine: str) -> pd.DataFrame:
        if engine == "printed":
            return self.printed()
        if engine == "legacy":
            return self.legacy()
        if engine == "port_printed":
            return self.port(PRINTED)
        if engine == "port_corrected":
            return self.port(CORRECTED)
        raise ValueError(f"unknown engine {engine!r}")


def _table1_frame(deg, rigid_x, rigid_y, src_dx, src_dy, cog_dx, cog_dy) -> pd.DataFrame:
    """Table I's columns; K.E.D. coordinates are rigid + deflection, as the thesis adds them."""
    frame = pd.DataFrame({"input_deg": deg, "rigid_x": rigid_x, "rigid_y": rigid_y,
                          "src_dx": src_dx, "src_dy": src_dy,
                          "src_xnew": np.asarray(rigid_x) + np.asarray(src_dx),
                          "src_ynew": np.asarray(rigid_y) + np.asarray(src_dy),
                          "cog_dx": cog_dx, "cog_dy": cog_dy,
                          "cog_xnew": np.asarray(rigid_x) + np.asarray(cog_dx),
                          "cog_ynew": np.asarray(rigid_y) + np.asarray(cog_dy)})
    return frame[TABLE1_COLUMNS]


TABLE1_DEG = np.arange(0.0, 361.0, 20.0)


def _table1_printed() -> pd.DataFrame:
    """Only what the listings WRITE: deflections; no listing prints the rigid path."""
    src = run_printed("ali1977_case1_source").set_index("deg")
    cog = run_printed("ali1977_case1_cognate").set_index("deg")
    pick = lambda frame, col: frame[col].reindex(TABLE1_DEG).to_numpy()   # noqa: E731
    nan = np.full(len(TABLE1_DEG), np.nan)
    frame = _table1_frame(TABLE1_DEG, nan, nan, pick(src, "dx"), pick(src, "dy"),
                          pick(cog, "dx"), pick(cog, "dy"))
    return frame


def _table1_legacy() -> pd.DataFrame:
    src = legacy.case1_source(step_deg=20.0)
    cog = legacy.case1_cognate(step_deg=20.0)
    return _table1_frame(src["deg"], cog["xp"], cog["yp"], src["dx"], src["dy"], cog["dx"], cog["dy"])


def _table1_port(quirks: Quirks) -> pd.DataFrame:
    src = source_case1(TABLE1_DEG, quirks=quirks)
    cog = cognate_case1(TABLE1_DEG, quirks=quirks)
    return _table1_frame(TABLE1_DEG, cog["xp"], cog["yp"], src["dx"], src["dy"], cog["dx"], cog["dy"])


ALI1977_TABLE1 = Scene(
    name="ali1977-table1",
    title="Ali (1977) Table I: mass at the path point (Case I), source four-bar and crossed cognate",
    table="ali1977_table1",
    columns=TABLE1_COLUMNS,
    key="input_deg",
    inputs=("L1=10, L2=10, L3=30, L4=25, L5=30 in; A=0.1963495408 in^2, E=1e7 psi, "
            "I=0.0030679615 in^4; W=2 lbf at the path point; PI=3.142857143 as printed. "
            "Source columns: the source listing as printed (400 rpm, ALP=1.762782545 rad = 101 deg). "
            "Cognate columns: the cognate listing (300 rpm, ALP=PI/3). Rigid-mode columns: the "
            "cognate listing's XP, YP (statements 30-31). K.E.D. columns: rigid + deflection. "
            "port_corrected: the example data of chapter IV (300 rpm, 60 deg, true pi) with every "
            "registered bug removed."),
    printed=_table1_printed,
    legacy=_table1_legacy,
    port=_table1_port,
    notes=["The printed engine shows only what the listings WRITE (the deflections); the source "
           "listing stops before printing 360 deg."],
)

SCENES: dict[str, Scene] = {s.name: s for s in [ALI1977_TABLE1]}


def get(name: str) -> Scene:
    try:
        return SCENES[name]
    except KeyError:
        raise KeyError(f"unknown scene {name!r}; known: {', '.join(SCENES)}") from None
