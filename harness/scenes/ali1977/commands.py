"""Ali (1977)'s own command: ``linkrepro ked-bound`` (the K.E.D. error bound's calibration
sample, ``calibration.py``)."""
from __future__ import annotations

from pathlib import Path

from ...command import Command
from . import calibration


def _arguments(parser) -> None:
    parser.add_argument("--draws", type=int, default=calibration.DRAWS,
                        help=f"draws of the sample, four runs each (default {calibration.DRAWS})")
    parser.add_argument("--seed", type=int, default=calibration.SEED, help=f"(default {calibration.SEED})")
    parser.add_argument("--record", action="store_true",
                        help="also write the summary the docs show (harness/scenes/ali1977/ked_bound.csv)")


COMMANDS = [Command(
    name="ked-bound",
    help="the K.E.D. engines' error bound on random geometries, sections and listing poles, Cases I-III, "
         "against the same equations in 60 digits (about 30 s of CPU for the default 5000 runs)",
    default_out=Path("out/ked-bound"),
    out_help="output folder for calibration.csv, summary.csv, calibration.md (default: out/ked-bound/)",
    outputs=calibration.OUTPUTS,
    run=lambda args: calibration.write(args.out, args.seed, args.draws, args.record),
    add_arguments=_arguments,
    report_title=calibration.TITLE,
    report_markdown="calibration.md",
)]
