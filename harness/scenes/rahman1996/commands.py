"""Rahman (1996)'s own command: ``linkrepro arithmetic`` (the arithmetic study: arithmetic.py,
its variants and its build, which do the work and import numpy and pandas when it runs: not
here, since the parser reads this module for ``linkrepro --help``)."""
from __future__ import annotations

from pathlib import Path

from ...command import Command
from .arithmetic_settings import OUTPUTS, RECORD, TITLE


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
