"""Ali (1977) Tables I-III: one table scene each.  A scene knows its inputs, how each engine
produces the table, and the table's columns (the published table's, exactly).
"""
from __future__ import annotations

import numpy as np
import pandas as pd

from ....legacy import ali1977
from ....port.ali1977 import CORRECTED, PRINTED, Quirks, cognate_case1, source_case1
from ....port.ali1977.case2 import COGNATE_LISTING as CASE2_COGNATE
from ....port.ali1977.case2 import LISTING as CASE2_LISTING
from ....port.ali1977.case2 import case2_cognate, case2_source
from ....port.ali1977.case3 import COGNATE_LISTING as CASE3_COGNATE
from ....port.ali1977.case3 import LISTING as CASE3_LISTING
from ....port.ali1977.case3 import case3_cognate, case3_source
from ...csv_output import write_csv
from .printed_output import run_printed
from ...listing_lines import Statement
from ...published_tables import PublishedTable
from ...table_scene import TableScene
from . import cognate_search, readings, sums
from .quantities import QUANTITIES

KED_COLUMNS = ["input_deg", "rigid_x", "rigid_y", "src_dx", "src_dy", "src_xnew", "src_ynew",
                  "cog_dx", "cog_dy", "cog_xnew", "cog_ynew"]


TABLE_DEG = np.arange(0.0, 361.0, 20.0)
NOT_PRODUCED = {"dx": np.full(len(TABLE_DEG), np.nan), "dy": np.full(len(TABLE_DEG), np.nan)}


def ked_frame(deg, rigid_x, rigid_y, src: dict, cog: dict) -> pd.DataFrame:
    """The K.E.D. tables' columns; K.E.D. coordinates are rigid + deflection, as the thesis adds them."""
    rigid_x, rigid_y = np.asarray(rigid_x, dtype=float), np.asarray(rigid_y, dtype=float)
    frame = pd.DataFrame({"input_deg": deg, "rigid_x": rigid_x, "rigid_y": rigid_y,
                          "src_dx": src["dx"], "src_dy": src["dy"],
                          "src_xnew": rigid_x + np.asarray(src["dx"]),
                          "src_ynew": rigid_y + np.asarray(src["dy"]),
                          "cog_dx": cog["dx"], "cog_dy": cog["dy"],
                          "cog_xnew": rigid_x + np.asarray(cog["dx"]),
                          "cog_ynew": rigid_y + np.asarray(cog["dy"])})
    return frame[KED_COLUMNS]


def _printed_rows(program: str | None) -> dict:
    """What a printed program WRITEs at the table's angles (NaN where it does not)."""
    if program is None:
        return NOT_PRODUCED
    frame = run_printed(program).drop_duplicates("deg").set_index("deg")
    return {q: frame[q].reindex(TABLE_DEG).to_numpy() for q in ("dx", "dy")}


def _ked_printed(source: str, cognate: str | None) -> pd.DataFrame:
    """Only what the listings WRITE: deflections; no listing prints the rigid path."""
    nan = np.full(len(TABLE_DEG), np.nan)
    return ked_frame(TABLE_DEG, nan, nan, _printed_rows(source), _printed_rows(cognate))


def _table1_legacy() -> pd.DataFrame:
    src = ali1977.case1_source(step_deg=20.0)
    cog = ali1977.case1_cognate(step_deg=20.0)
    return ked_frame(src["deg"], cog["xp"], cog["yp"], src, cog)


def _table1_port(quirks: Quirks) -> pd.DataFrame:
    src = source_case1(TABLE_DEG, quirks=quirks)
    cog = cognate_case1(TABLE_DEG, quirks=quirks)
    return ked_frame(TABLE_DEG, cog["xp"], cog["yp"], src, cog)


def _with_source_rigid(src: dict, cog: dict) -> pd.DataFrame:
    """Tables II and III: the rigid path from the source listing (its ALP=PI/3)."""
    return ked_frame(TABLE_DEG, src["xp"], src["yp"], src, cog)


def _table2_port(quirks: Quirks) -> pd.DataFrame:
    src = case2_source(TABLE_DEG, quirks=quirks & CASE2_LISTING)
    cog = case2_cognate(TABLE_DEG, quirks=quirks & CASE2_COGNATE)
    return _with_source_rigid(src, cog)


def _table3_port(quirks: Quirks) -> pd.DataFrame:
    src = case3_source(TABLE_DEG, n=5, quirks=quirks & CASE3_LISTING)
    cog = case3_cognate(TABLE_DEG, n=5, quirks=quirks & CASE3_COGNATE)
    return _with_source_rigid(src, cog)


def sums_section(scene: TableScene, published: PublishedTable, diff: pd.DataFrame, target) -> str:
    """The table's printed sums X_new = X + dX against its printed terms (identities.csv)."""
    checks = sums.with_register(sums.sum_checks(scene.table, published), diff)
    write_csv(checks, target / "identities.csv", "%.9g")
    return sums.as_markdown(checks)


def cognate_section(scene: TableScene, published: PublishedTable, diff: pd.DataFrame, target) -> str:
    """The sign and frame search over the reconstructed cognate loads (cognate_search.csv)."""
    found = cognate_search.search(cognate_search.case_of(scene.table))
    write_csv(found, target / "cognate_search.csv", "%.9g")
    return cognate_search.as_markdown(found)


def _lines(file: str, printed: tuple[str, ...] = (), src: tuple[str, ...] = ()) -> tuple[Statement, ...]:
    return (tuple(Statement("printed", file + ".f", p) for p in printed)
            + tuple(Statement("src", file + ".f", p) for p in src))


def ked_statements(rigid: str, source: tuple, cognate: tuple):
    """Where a K.E.D. table's cells come from: ``rigid`` the listing whose XP, YP give the rigid
    path; ``source``, ``cognate``: (listing, {"dx"|"dy": (printed patterns, src patterns)}).
    A K.E.D. coordinate is rigid + deflection, summed by the harness as the thesis sums them."""
    by_column = {f"rigid_{axis}": _lines(rigid, (rf"^\s+{axis.upper()}P=",), (rf"{axis.upper()}PO\(IANG\)={axis.upper()}P\b",))
                 for axis in "xy"}
    for prefix, (listing, patterns) in (("src", source), ("cog", cognate)):
        for axis in "xy":
            deflection = _lines(listing, *patterns[f"d{axis}"])
            by_column[f"{prefix}_d{axis}"] = deflection
            by_column[f"{prefix}_{axis}new"] = by_column[f"rigid_{axis}"] + deflection
    return lambda row, column: by_column.get(column, ())


def _written(var: str, write: str, printed_set: bool = True, src_set: bool = False) -> tuple:
    """(printed patterns, src patterns) of a deflection ``var`` (XX, CYY, ...) set from R(k)
    and written by FORMAT ``write``; the src copy hands it over in ``<var>O(IANG)``."""
    axis = {"X": 1, "Y": 2}[var[-1]]
    setting = (rf"^\s+{var}=R\({axis}\)",)
    return ((setting if printed_set else ()) + (rf"WRITE ?\(6,{write}\)",),
            (setting if src_set else ()) + (rf"{var}O\(IANG\)={var}\b",))


CASE3_SOURCE_LINES = ((r"WRITE\(6,500\)",), (r"DEF\(I,IANG\)=R\(I\)",))
TABLE_STATEMENTS = {
    "ali1977_table1": ked_statements("ali1977_case1_cognate",
                                     ("ali1977_case1_source", {"dx": _written("XX", "200"), "dy": _written("YY", "200")}),
                                     ("ali1977_case1_cognate", {"dx": _written("CXX", "200"), "dy": _written("CYY", "200")})),
    "ali1977_table2": ked_statements("ali1977_case2_source",
                                     ("ali1977_case2_source", {"dx": _written("XX", "200"), "dy": _written("YY", "200")}),
                                     ("ali1977_case2_cognate", {"dx": _written("CXX", "200", printed_set=False, src_set=True),
                                                                "dy": _written("CYY", "200", printed_set=False, src_set=True)})),
    "ali1977_table3": ked_statements("ali1977_case3_source",
                                     ("ali1977_case3_source", {"dx": CASE3_SOURCE_LINES, "dy": CASE3_SOURCE_LINES}),
                                     ("ali1977_case3_cognate", {"dx": ((), _written("CXX", "200", src_set=True)[1]),
                                                                "dy": ((), _written("CYY", "200", src_set=True)[1])})),
}

#: the process the Ali (1977) tables and curves share (the longest group: it starts first)
GROUP, START = "ali1977", 0
COMMON_INPUTS = ("L1=10, L2=10, L3=30, L4=25, L5=30 in; A=0.1963495408 in^2, E=1e7 psi, "
                 "I=0.0030679615 in^4; PI=3.142857143 as printed. ")

ALI1977_TABLE1 = TableScene(
    name="ali1977-table1",
    title="Ali (1977) Table I: mass at the path point (Case I), source four-bar and crossed cognate",
    group=GROUP,
    start=START,
    table="ali1977_table1",
    columns=KED_COLUMNS,
    statements=TABLE_STATEMENTS["ali1977_table1"],
    key="input_deg",
    inputs=(COMMON_INPUTS + "W=2 lbf at the path point. "
            "Source columns: the source listing as printed (400 rpm, ALP=1.762782545 rad = 101 deg). "
            "Cognate columns: the cognate listing (300 rpm, ALP=PI/3). Rigid-mode columns: the "
            "cognate listing's XP, YP (statements 30-31). K.E.D. columns: rigid + deflection. "
            "port_corrected: the example data of chapter IV (300 rpm, 60 deg, true pi) with every "
            "registered bug removed."),
    printed=lambda: _ked_printed("ali1977_case1_source", "ali1977_case1_cognate"),
    legacy=_table1_legacy,
    port=_table1_port,
    quirks=(PRINTED, CORRECTED),
    sections=(sums_section,),
    notes=["The printed engine shows only what the listings WRITE (the deflections); the source "
           "listing stops before printing 360 deg."],
    quantities=QUANTITIES["ali1977-table1"],
    readings=readings,
)

ALI1977_TABLE2 = TableScene(
    name="ali1977-table2",
    title="Ali (1977) Table II: mass at each joint (Case II), source four-bar and crossed cognate",
    group=GROUP,
    start=START,
    table="ali1977_table2",
    columns=KED_COLUMNS,
    statements=TABLE_STATEMENTS["ali1977_table2"],
    key="input_deg",
    inputs=(COMMON_INPUTS + "300 rpm, ALP=PI/3; each link's weight 0.098 lbf/in^3 * A * length "
            "lumped at a joint (Appendix C). Rigid and source columns: the Case II source listing. "
            "Cognate columns: the Case II cognate listing with the missing page (statements 241-281) "
            "reconstructed from the source listing's loads, see D037."),
    printed=lambda: _ked_printed("ali1977_case2_source", None),
    legacy=lambda: _with_source_rigid(ali1977.case2_source(step_deg=20.0), ali1977.case2_cognate(step_deg=20.0)),
    port=_table2_port,
    quirks=(PRINTED, CORRECTED),
    sections=(sums_section, cognate_section),
    notes=["Cognate columns: the Case II cognate listing with its missing page RECONSTRUCTED (D037); "
           "the printed engine cannot give them (the printed program never sets them)."],
    quantities=QUANTITIES["ali1977-table2"],
    readings=readings,
)

ALI1977_TABLE3 = TableScene(
    name="ali1977-table3",
    title="Ali (1977) Table III: distributed mass model (Case III, n = 5), source four-bar and cognate",
    group=GROUP,
    start=START,
    table="ali1977_table3",
    columns=KED_COLUMNS,
    statements=TABLE_STATEMENTS["ali1977_table3"],
    key="input_deg",
    inputs=(COMMON_INPUTS + "300 rpm, ALP=PI/3; the extender's weight at 5 nodes (Appendix D). "
            "Rigid and source columns: the Case III source listing (the only program Appendix D "
            "prints). port_corrected: the coupled 5-segment model. Cognate columns: a "
            "reconstruction, D037."),
    printed=lambda: _ked_printed("ali1977_case3_source", None),
    legacy=lambda: _with_source_rigid(ali1977.case3_source(step_deg=20.0), ali1977.case3_cognate(step_deg=20.0)),
    port=_table3_port,
    quirks=(PRINTED, CORRECTED),
    sections=(sums_section, cognate_section),
    notes=["Cognate columns: a RECONSTRUCTION (no listing exists, D037), in src/ and in the port; "
           "it does not reproduce them."],
    quantities=QUANTITIES["ali1977-table3"],
    readings=readings,
)

TABLES = [ALI1977_TABLE1, ALI1977_TABLE2, ALI1977_TABLE3]
