"""The ``linkrepro`` command."""
from __future__ import annotations

import argparse
import sys
from pathlib import Path


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="linkrepro", description=(
        "Rebuild, port and diff the FORTRAN of three mechanism-dynamics theses."))
    sub = parser.add_subparsers(dest="command", required=True)
    rep = sub.add_parser("reproduce", help="run every engine of the scenes and write the report")
    rep.add_argument("scenes", nargs="*", help="scene names (default: all; see `linkrepro scenes`)")
    rep.add_argument("--out", default="out", type=Path, help="output folder (default: out/)")
    sub.add_parser("scenes", help="list the scenes")
    bench = sub.add_parser("bench", help="time each engine against its error")
    bench.add_argument("--repeat", type=int, default=20, help="timing repetitions (best of)")
    args = parser.parse_args(argv)

    from .scenes import SCENES
    if args.command == "scenes":
        from . import appendix, rahman1991, rahman1996_figures
        for scene in SCENES.values():
            print(f"{scene.name:22s} {scene.title}")
        print(f"{appendix.NAME:22s} {appendix.TITLE} (engine against engine)")
        print(f"{rahman1996_figures.NAME:22s} Rahman (1996) Figures 5.1-5.6 and the section 5.3 percentages")
        print(f"{rahman1991.NAME:22s} {rahman1991.TITLE}")
        return 0
    if args.command == "reproduce":
        from .run import reproduce, unexplained_count
        from . import appendix, rahman1991, rahman1996_figures
        extra = [appendix.NAME, rahman1996_figures.NAME, rahman1991.NAME]
        unknown = [s for s in args.scenes if s not in SCENES and s not in extra]
        if unknown:
            parser.error(f"unknown scene(s): {', '.join(unknown)}; known: {', '.join([*SCENES, *extra])}")
        done = reproduce(args.scenes, args.out)
        for item in done:
            print(f"{item['scene']}:")
            print(item["counts"].to_string())
        print(f"report: {args.out / 'report.md'}  ({unexplained_count(done)} unexplained cells)")
        return 0
    if args.command == "bench":
        from .bench import run_bench
        print(run_bench(args.repeat))
        return 0
    return 2


if __name__ == "__main__":
    sys.exit(main())
