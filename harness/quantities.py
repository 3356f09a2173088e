"""What a column of a scene's CSVs means, in words, and its unit: ``Quantity``.

A ``Quantity`` has ``words``, ``unit`` ("in", "deg", "lbf", "lbf in", ...; "" for a pure
number or a text) and ``label`` ("words (unit)") for a table heading or an axis.  It also
describes a row's quantity in a long file (the ``dx`` of a curve, the ``src_dx`` of a diff
row): a column whose unit changes from row to row names, in ``per_row``, the column that holds
each row's quantity.

The data: each thesis's ``harness/scenes/<thesis>/quantities.py`` (its ``QUANTITIES``,
scene -> name -> Quantity), and here the columns of ``diff.csv``, which every table scene
writes (``DIFF``).  ``harness.results.describe(scene, column)`` looks one up.  Nothing here
names a thesis.
"""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Quantity:
    """A column's (or a row quantity's) meaning in words and its unit ("" for a pure number)."""
    words: str
    unit: str
    per_row: str = ""      # long files: the column naming each row's quantity, whose unit this one takes

    @property
    def label(self) -> str:
        """The heading: "words (unit)", or the words alone when there is no unit."""
        return f"{self.words} ({self.unit})" if self.unit else self.words


#: the columns of diff.csv (harness/diff.py), written by every table scene: the values are in
#: the unit of the table column each row names (``column``)
DIFF = {
    "scene": Quantity("scene", ""),
    "engine": Quantity("engine (printed, legacy, port_printed or port_corrected)", ""),
    "column": Quantity("the published table's column of the cell", ""),
    "published_text": Quantity("the cell as printed", ""),
    "published": Quantity("the cell's published value", "", per_row="column"),
    "value": Quantity("the engine's value of the cell", "", per_row="column"),
    "abs_diff": Quantity("|engine - published|", "", per_row="column"),
    "digits": Quantity("significant digits the engine shares with the published value", ""),
    "half_unit": Quantity("half a unit of the printed last digit", "", per_row="column"),
    "status": Quantity("the cell's status (match, registered, unexplained or not-produced)", ""),
    "register_ids": Quantity("the register entries (harness/deviations.toml) that explain it", ""),
    "legacy": Quantity("the legacy engine's value of the cell", "", per_row="column"),
    "diff_vs_legacy": Quantity("engine - legacy", "", per_row="column"),
}
