#!/usr/bin/python3
"""pgm.fit on a DataFrame of 10^6 rows of integer codes (onTop2 | xOff1, yOff1, xOff2, yOff2: 625
parameters), against the same fit in C++ in process (bench_python_fit) and, when pgmpy is
importable, pgmpy's fit of the same model (MaximumLikelihoodEstimator). The C++ side is timed
three ways: from the same 64-bit codes in memory building a data set first, counted straight from
those codes (pgm/learn/count_values.hpp, as pgm.fit counts a frame of integer codes), and the fit
alone on a data set already built. Medians over repeats,
one thread each (pgm.fit also with its default, all cores), all in the same run. The targets: pgm.fit within 2x of the C++, and at least
50x faster than pgmpy.

    PYTHONPATH=build/python python3 bench/python/bench_fit.py [--timer build/bench/bench_python_fit]
"""

import argparse
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import pandas as pd

import pgm

CHILD = "onTop2"
PARENTS = ["xOff1", "yOff1", "xOff2", "yOff2"]


def stacking_codes(rows, seed):
    """Four offsets binned into 5 states and a success that depends on them, as integer codes."""
    random = np.random.default_rng(seed)
    frame = {name: random.integers(0, 5, rows, dtype=np.int64) for name in PARENTS}
    far = sum(np.abs(frame[name] - 2) for name in PARENTS)
    frame[CHILD] = (random.random(rows) < 0.95 - 0.1 * far).astype(np.int64)
    return pd.DataFrame({name: frame[name] for name in [CHILD, *PARENTS]})


def median_seconds(call, repeats):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        call()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rows", type=int, default=1_000_000)
    parser.add_argument("--repeats", type=int, default=9)
    parser.add_argument("--pgmpy-repeats", type=int, default=3)
    default_timer = Path(__file__).resolve().parents[2] / "build" / "bench" / "bench_python_fit"
    parser.add_argument("--timer", type=Path, default=default_timer, help="the built bench_python_fit")
    args = parser.parse_args()

    frame = stacking_codes(args.rows, 1)
    edges = [(p, CHILD) for p in PARENTS]
    python = median_seconds(lambda: pgm.fit(frame, edges, threads=1), args.repeats)
    python_all_cores = median_seconds(lambda: pgm.fit(frame, edges), args.repeats)

    with tempfile.TemporaryDirectory() as folder:
        codes = Path(folder) / "codes.bin"
        with codes.open("wb") as out:
            for name in frame.columns:
                frame[name].to_numpy(dtype=np.int64).tofile(out)
        timer = subprocess.run(
            [args.timer, codes, str(args.rows), str(args.repeats), *frame.columns],
            capture_output=True, text=True, check=True,
        )
    cpp, cpp_from_codes, cpp_counted = (float(x) for x in timer.stdout.split())

    print(f"{args.rows} rows, {CHILD} | {', '.join(PARENTS)}, MLE, 1 thread, medians of {args.repeats}")
    print(f"  pgm.fit (Python, DataFrame in)  {python * 1e3:9.1f} ms   (all cores, threads=0: {python_all_cores * 1e3:.1f} ms)")
    print(f"  C++, counted from the codes     {cpp_counted * 1e3:9.1f} ms   Python/C++ = {python / cpp_counted:.2f}"
          " (target <= 2)")
    print(f"  C++, data set from the codes    {cpp_from_codes * 1e3:9.1f} ms   Python/C++ = {python / cpp_from_codes:.2f}")
    print(f"  C++, fit alone (data set built) {cpp * 1e3:9.1f} ms   Python/C++ = {python / cpp:.2f} (target <= 2)")
    try:
        from pgmpy.estimators import MaximumLikelihoodEstimator
        import pgmpy.models
    except ImportError:
        print("  pgmpy: not importable, skipped")
        return 0
    model_class = getattr(pgmpy.models, "DiscreteBayesianNetwork", None) or pgmpy.models.BayesianNetwork

    def pgmpy_fit():
        model = model_class(edges)
        model.fit(frame, estimator=MaximumLikelihoodEstimator)

    theirs = median_seconds(pgmpy_fit, args.pgmpy_repeats)
    print(f"  pgmpy fit (median of {args.pgmpy_repeats})          {theirs * 1e3:9.1f} ms   "
          f"pgmpy/pgm.fit = {theirs / python:.0f} (target >= 50; all cores: {theirs / python_all_cores:.0f})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
