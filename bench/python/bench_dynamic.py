#!/usr/bin/python3
"""Filtering an episode: pgm.DynamicNetwork.filter against pgmpy's DBNInference.forward_inference,
from Python, in one process, on docs/dynamic.md's two-variable model with the observed variable b
alternating over episodes of 10, 100 and 1,000 steps. pgm filters every step (all marginals);
pgmpy is asked for the last step's a only, on the model with numbered states (its inference
fails on state names, docs/dynamic.md), and built once outside the timing, as pgm's model is.
Both answers are compared. Medians of wall-clock time over repeated calls, one thread; writes
docs/results/dynamic_filter.csv and docs/dynamic.md's table from it.

    PYTHONPATH=build/python:PGMPY /usr/bin/python3 bench/python/bench_dynamic.py
    /usr/bin/python3 bench/python/bench_dynamic.py --render   # the table from the CSV only
"""

import csv
import logging
import re
import statistics
import sys
import tempfile
import time
from pathlib import Path


ROOT = Path(__file__).resolve().parents[2]
CSV = ROOT / "docs" / "results" / "dynamic_filter.csv"
PAGE = ROOT / "docs" / "dynamic.md"
BEGIN = "<!-- dynamic table: docs/results/dynamic_filter.csv, by bench/python/bench_dynamic.py -->"
END = "<!-- end of the dynamic table -->"


def render():
    with open(CSV, newline="") as f:
        rows = list(csv.DictReader(f))
    table = [
        "| steps | pgm (every step) | per step | pgmpy (the last step) | pgmpy / pgm |",
        "|---|---|---|---|---|",
    ]
    for r in rows:
        table.append(
            f"| {int(r['steps']):,} | {r['pgm_ms']} ms | {r['pgm_us_per_step']} µs | {r['pgmpy_ms']} ms "
            f"| {r['ratio']}× |"
        )
    text = PAGE.read_text()
    start, end = text.index(BEGIN) + len(BEGIN), text.index(END)
    PAGE.write_text(text[:start] + "\n" + "\n".join(table) + "\n" + text[end:])


def median_seconds(call, repeats):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        call()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def main():
    if sys.argv[1:] == ["--render"]:
        render()
        return
    import pandas as pd
    from pgmpy.inference import DBNInference

    import pgm

    logging.getLogger("pgmpy").setLevel(logging.ERROR)
    text = re.search(r"```json\n(.*?)```", (ROOT / "docs" / "dynamic.md").read_text(), re.S).group(1)
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "tower.json"
        path.write_text(text)
        model = pgm.read_network(path)
    theirs = DBNInference(model.to_pgmpy(state_names=False))
    rows = []
    for steps in (10, 100, 1000):
        observed = ["high", "low"] * (steps // 2)
        episode = pd.DataFrame({"b": observed})
        evidence = {("b", t): model.states("b").index(s) for t, s in enumerate(observed)}
        last = ("a", steps - 1)
        ours = model.filter(episode)
        answer = ours[(ours.t == steps - 1) & (ours.variable == "a")].probability.to_numpy()
        difference = float(abs(theirs.forward_inference([last], evidence)[last].values - answer).max())
        repeats = 20 if steps < 1000 else 3
        pgm_s = median_seconds(lambda: model.filter(episode), repeats * 5)
        pgmpy_s = median_seconds(lambda: theirs.forward_inference([last], evidence), repeats)
        rows.append(
            {
                "steps": steps,
                "pgm_ms": f"{pgm_s * 1e3:.3f}",
                "pgm_us_per_step": f"{pgm_s * 1e6 / steps:.2f}",
                "pgmpy_ms": f"{pgmpy_s * 1e3:.3f}",
                "ratio": f"{pgmpy_s / pgm_s:.1f}",
                "largest_difference": f"{difference:.2e}",
            }
        )
        print(rows[-1], file=sys.stderr)
    CSV.parent.mkdir(parents=True, exist_ok=True)
    with open(CSV, "w", newline="") as out:
        writer = csv.DictWriter(out, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    render()
    print(f"wrote {CSV} and the table of {PAGE}")


if __name__ == "__main__":
    main()
