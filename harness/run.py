"""``linkrepro reproduce``: run every engine of each scene, diff, write the report."""
from __future__ import annotations

import time
from pathlib import Path

import pandas as pd

from . import appendix, bench, rahman1991, rahman1996_figures, readings, register as register_mod
from .diff import diff_scene, summary
from .engines import ENGINES, PrintedProgramError
from .published_tables import PublishedTable
from .report import plot_scene, scene_report
from .scenes import SCENES, get


def run_scene(name: str, out_dir: Path, measure_readings: bool = True) -> dict:
    """Run one scene; write DIR/<scene>/...; return its summary counts and timings."""
    scene = get(name)
    register = register_mod.load()
    published = PublishedTable.load(scene.table)
    target = out_dir / scene.name
    target.mkdir(parents=True, exist_ok=True)
    published.text.to_csv(target / "published.csv", index=False)

    results, timings, failures = {}, {}, []
    for engine in ENGINES:
        start = time.perf_counter()
        try:
            frame = scene.run(engine)
        except PrintedProgramError as exc:
            failures.append(f"engine {engine} failed: {exc}")
            continue
        timings[engine] = time.perf_counter() - start
        frame.to_csv(target / f"{engine}.csv", index=False, float_format="%.9g")
        results[engine] = frame

    diff = diff_scene(scene, published, results, register)
    diff.to_csv(target / "diff.csv", index=False, float_format="%.9g")
    plots = plot_scene(scene, published, results, target)
    extra = "\n".join(f"**{f}**" for f in failures)
    measured = readings.measure(scene.table) if measure_readings else None
    if measured is not None and not measured.empty:
        extra += "\n\n" + readings.as_markdown(measured)
    (target / "report.md").write_text(scene_report(scene, diff, timings, register, plots, extra))
    return {"scene": scene.name, "title": scene.title, "counts": summary(diff), "timings": timings,
            "failures": failures}


def reproduce(names: list[str] | None, out_dir: Path) -> list[dict]:
    """Run the named scenes (all by default) and write DIR/report.md over them; with all
    scenes (or ali1977-table3) also the Case III speed-against-error sweep."""
    measure_convergence = not names or "ali1977-table3" in names
    special = (appendix.NAME, rahman1996_figures.NAME, rahman1991.NAME)
    names = names or list(SCENES) + list(special)
    out_dir.mkdir(parents=True, exist_ok=True)
    start = time.perf_counter()
    done = [run_scene(name, out_dir) for name in names if name not in special]
    curves = appendix.run(out_dir) if appendix.NAME in names else None
    figures = rahman1996_figures.run(out_dir) if rahman1996_figures.NAME in names else None
    example = rahman1991.run(out_dir) if rahman1991.NAME in names else None
    total = time.perf_counter() - start
    lines = ["# linkrepro: reproduction report", "",
             "Each published cell, for each engine: `match` (within half a unit of the printed last "
             "digit), `registered` (explained in harness/deviations.toml), `unexplained`, or "
             "`not-produced` (the engine does not give it).", ""]
    for item in done:
        lines += [f"## [{item['scene']}]({item['scene']}/report.md)", "", item["title"], "",
                  "| engine | " + " | ".join(item["counts"].columns) + " | seconds |",
                  "|---|" + "---|" * (len(item["counts"].columns) + 1)]
        for engine, row in item["counts"].iterrows():
            secs = item["timings"].get(engine, float("nan"))
            lines.append(f"| {engine} | " + " | ".join(str(v) for v in row) + f" | {secs:.4f} |")
        lines += [f"\n**{f}**" for f in item["failures"]] + [""]
    if measure_convergence:
        data = bench.case3_data(repeat=1)
        data.to_csv(out_dir / "case3_convergence.csv", index=False, float_format="%.6g")
        bench.plot_case3(data, out_dir / "case3_convergence.png")
        (out_dir / "case3_convergence.md").write_text(
            "# Case III: speed against error\n" + "\n".join(bench.case3_sweep(1, data))
            + "\n\n![case3 convergence](case3_convergence.png)\n")
        lines += ["## [Case III: speed against error](case3_convergence.md)", "",
                  "Sub-elements n and angle step against the converged distributed-mass answer, and which "
                  "mass model each table needs (timings from this one run).", ""]
    if curves is not None:
        lines += [f"## [{curves['scene']}]({curves['scene']}/report.md)", "", curves["title"], "",
                  f"{curves['curves']} of 36 curves, engine against engine (no published numbers); largest "
                  f"|port - legacy| {curves['max_engine_gap']:.3g}; {', '.join(curves['missing']) or 'every curve from both engines'}.", ""]
    if figures is not None:
        lines += [f"## [{figures['scene']}]({figures['scene']}/report.md)", "", figures["title"],
                  "(recomputed from every engine beside the printed text).", ""]
    if example is not None:
        verdicts = example["claims"].groupby(["engine", "verdict"]).size().unstack(fill_value=0)
        lines += [f"## [{example['scene']}]({example['scene']}/report.md)", "", example["title"], "",
                  "No numeric table is printed; each claim of section 3.2, per engine "
                  "(see the scene report and register D085-D094):", "",
                  "| engine | " + " | ".join(verdicts.columns) + " |", "|---|" + "---|" * len(verdicts.columns)]
        lines += [f"| {engine} | " + " | ".join(str(v) for v in row) + " |" for engine, row in verdicts.iterrows()]
        lines.append("")
    lines.append(f"Total wall time of this reproduce run: {total:.2f} s.")
    (out_dir / "report.md").write_text("\n".join(lines) + "\n")
    return done


def unexplained_count(done: list[dict]) -> int:
    return int(sum(item["counts"].get("unexplained", pd.Series(dtype=int)).sum() for item in done))
