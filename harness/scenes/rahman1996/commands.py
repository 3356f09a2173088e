"""Rahman (1996)'s own command: ``linkrepro arithmetic`` (the arithmetic study: arithmetic.py,
its variants and its build, which do the work and import numpy and pandas: not here, since the
parser reads this module for ``linkrepro --help``)."""
from __future__ import annotations

from pathlib import Path

from ...command import Command

TITLE = "Rahman (1996): which digits survive a change of arithmetic"
OUTPUTS = ("arithmetic.csv", "arithmetic_cells.csv", "arithmetic.md")
#: which arithmetics reach each published cell's printed digit, as ``--record`` last wrote it
RECORD = Path(__file__).with_name("arithmetic_reached.csv")


def _arguments(parser) -> None:
    parser.add_argument("--record", action="store_true",
                        help=f"also write which arithmetics reach each cell's printed digit to the committed "
                             f"record the table scenes read (harness/scenes/rahman1996/{RECORD.name})")


COMMANDS = [Command(
    name="arithmetic",
    help="rebuild the Rahman (1996) FORTRAN under the arithmetics of 1996 machines (needs gfortran; "
         "about 20 s of CPU): which printed digits survive a change of compiler",
    default_out=Path("out/arithmetic"),
    out_help="output folder for arithmetic.md, arithmetic.csv, arithmetic_cells.csv "
             "(default: out/arithmetic/, which reproduce's report links)",
    outputs=OUTPUTS,
    work=f"{__package__}.arithmetic",
    add_arguments=_arguments,
    report_title=TITLE,
    report_markdown="arithmetic.md",
)]
