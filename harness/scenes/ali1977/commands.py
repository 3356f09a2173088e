"""Ali (1977)'s own command: ``linkrepro ked-bound`` (the K.E.D. error bound's calibration
sample, ``calibration.py``, which does the work and imports every Ali engine when it runs: not
here, since the parser reads this module for ``linkrepro --help``)."""
from __future__ import annotations

from pathlib import Path

from ...command import Command
from .calibration_settings import DRAWS, OUTPUTS, SEED, TITLE


def _arguments(parser) -> None:
    parser.add_argument("--draws", type=int, default=DRAWS,
                        help=f"draws of the sample, four runs each (default {DRAWS})")
    parser.add_argument("--seed", type=int, default=SEED, help=f"(default {SEED})")
    parser.add_argument("--record", action="store_true",
                        help="also write the summary the docs show (harness/scenes/ali1977/ked_bound.csv)")


COMMANDS = [Command(
    name="ked-bound",
    help="the K.E.D. engines' error bound on random geometries, sections and listing poles, Cases I-III, "
         "against the same equations in 60 digits (about 30 s of CPU for the default 5000 runs)",
    default_out=Path("out/ked-bound"),
    out_help="output folder for calibration.csv, summary.csv, calibration.md (default: out/ked-bound/)",
    outputs=OUTPUTS,
    work=f"{__package__}.calibration",
    add_arguments=_arguments,
    report_title=TITLE,
    report_markdown="calibration.md",
)]
