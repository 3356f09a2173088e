"""Rahman (1996)'s own command: ``linkrepro arithmetic`` (the arithmetic study: arithmetic.py, its variants and its build)."""
from __future__ import annotations

from pathlib import Path

from ...command import Command
from ...readings import CompilerError
from .arithmetic import OUTPUTS, RECORD, ReferenceFailed, write


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
    run=lambda args: write(args.out, record=args.record)[3],
    add_arguments=_arguments,
    failures=(CompilerError, ReferenceFailed),
    report_title="Rahman (1996): which digits survive a change of arithmetic",
    report_markdown="arithmetic.md",
)]
