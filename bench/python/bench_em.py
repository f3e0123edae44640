#!/usr/bin/python3
"""EM with a latent variable, the case pgmpy's ExpectationMaximization supports: a latent class H
(2 states) over five indicators of 3 states each, ROWS rows sampled from known tables. Both run a
fixed number of iterations (pgm: max_iterations, tolerance 0; pgmpy: max_iter, atol 0), one
thread, from their own seeded random starts; the figure is the time per iteration, the median over
repeats, both in the same process. pgmpy is imported from PYTHONPATH (../shared/peers unpacked
by cmake into build/peers, see docs/peers.md); without it only pgm is timed.

    PYTHONPATH=build/python:build/peers/pgmpy-head:build/peers/pylib /usr/bin/python3 bench/python/bench_em.py
"""

import argparse

import numpy as np
import pandas as pd
from bench_fit import median_seconds

import pgm

INDICATORS = ["X1", "X2", "X3", "X4", "X5"]


def latent_class_rows(rows, seed):
    """Rows of the five indicators; H, which drew them, is left out."""
    random = np.random.default_rng(seed)
    h = random.random(rows) < 0.4
    frame = {}
    for k, name in enumerate(INDICATORS):
        high = np.array([0.1, 0.2 + 0.05 * k, 0.7 - 0.05 * k])
        low = high[::-1]
        draw = random.random(rows)
        cumulative = np.where(h[:, None], np.cumsum(high)[None, :], np.cumsum(low)[None, :])
        frame[name] = (draw[:, None] > cumulative).sum(axis=1).astype(np.int64)
    return pd.DataFrame(frame)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rows", type=int, default=10_000)
    parser.add_argument("--iterations", type=int, default=10)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--pgmpy-repeats", type=int, default=1)
    args = parser.parse_args()

    frame = latent_class_rows(args.rows, 1)
    edges = [("H", name) for name in INDICATORS]

    def ours():
        return pgm.fit(frame, edges, missing="em", latent={"H": 2}, max_iterations=args.iterations, tolerance=0,
                       seed=3, threads=1)

    per_iteration = median_seconds(ours, args.repeats) / args.iterations
    print(f"latent class model, H (2 states) -> {len(INDICATORS)} indicators of 3 states, {args.rows} rows, "
          f"{args.iterations} iterations, 1 thread")
    print(f"  pgm.fit(missing='em')    {per_iteration * 1e3:10.3f} ms per iteration   ({ours().notes[0]})")
    try:
        from pgmpy.estimators import ExpectationMaximization
        from pgmpy.models import BayesianNetwork
    except ImportError as error:
        print(f"  pgmpy: not importable ({error}); put it on PYTHONPATH to compare")
        return

    def theirs():
        model = BayesianNetwork(edges, latents={"H"})
        estimator = ExpectationMaximization(model, frame)
        return estimator.get_parameters(latent_card={"H": 2}, max_iter=args.iterations, atol=0, n_jobs=1, seed=3,
                                        show_progress=False)

    pgmpy_per_iteration = median_seconds(theirs, args.pgmpy_repeats) / args.iterations
    print(f"  pgmpy ExpectationMaximization {pgmpy_per_iteration * 1e3:10.3f} ms per iteration   "
          f"pgmpy / pgm = {pgmpy_per_iteration / per_iteration:.0f}x (target >= 50x)")


if __name__ == "__main__":
    main()
