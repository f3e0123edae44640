#!/usr/bin/python3
"""The structure prior from a related task (docs/structure-learning.md): on the paper's 1-Stack →
2-Stack transfer (tasks/scenarios/2-stack-sim.json's map), how many trials of the new task hill
climbing needs to recover 2-Stack's structure, from scratch and with the 1-Stack network as a
structure prior. For each number of trials and seed: simulate 2-Stack (analytic), bin every
offset into 5 quantile bins, `pgm learn-structure --algorithm hc --score bic` with and without
`--prior-model 1-stack.bif --map ... --prior-weight W`, and compare the DAG with the task's
structure (11 variables, 6 edges): how many of its 6 edges the DAG has, in their direction, and
whether it has all 6 ("found"). (The simulator also makes onTop2 depend on onTop1 -- the first
stack must stand -- which the task's structure leaves out, so an edge onTop1 -> onTop2 is not
counted against the search.) Prints a Markdown table.

    bench/structure_prior_trials.py BUILD_DIR [--trials 20,50,...] [--seeds 10] [--weights 20,200]
"""

import argparse
import json
import pathlib
import subprocess
import tempfile

source = pathlib.Path(__file__).resolve().parent.parent
MAP = "onTop2=onTop1,xOff2~xOff1,yOff2~yOff1"


def found(learned, truth):
    return len(set(map(tuple, learned)) & set(map(tuple, truth)))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("build")
    parser.add_argument("--trials", default="20,50,100,200,500,1000,2000")
    parser.add_argument("--seeds", type=int, default=10)
    parser.add_argument("--weights", default="20,200")
    args = parser.parse_args()
    pgm = pathlib.Path(args.build).resolve() / "bin" / "pgm"
    truth = [e.split(" -> ") for e in json.loads((source / "tasks" / "2-stack.json").read_text())["structure"]]

    def run(*arguments):
        subprocess.run([pgm, *map(str, arguments)], check=True, capture_output=True)

    with tempfile.TemporaryDirectory() as work:
        work = pathlib.Path(work)
        # The prior task's network: 1-Stack's structure fitted on 10^5 simulated trials.
        run("simulate", "--task", "1-stack", "--rows", 100000, "--seed", 1, "--out", work / "prior.csv")
        run("discretize", "--in", work / "prior.csv", "--bins", 5, "--out", work / "prior-binned.csv")
        run("fit", "--data", work / "prior-binned.csv", "--edges", "xOff1->onTop1,yOff1->onTop1", "--out",
            work / "1-stack.bif")
        weights = args.weights.split(",")
        print(f"| trials | task edges found, from scratch (mean of {args.seeds} seeds) | all 6 |"
              + "".join(f" with the 1-Stack prior, w = {w} | all 6 |" for w in weights))
        print("|---|---|---|" + "---|---|" * len(weights))
        for trials in map(int, args.trials.split(",")):
            results = [[] for _ in range(len(weights) + 1)]
            for seed in range(1, args.seeds + 1):
                raw, binned = work / "raw.csv", work / "binned.csv"
                run("simulate", "--task", "2-stack", "--rows", trials, "--seed", 1000 + seed, "--out", raw)
                run("discretize", "--in", raw, "--bins", 5, "--out", binned)
                variants = [[]] + [["--prior-model", work / "1-stack.bif", "--map", MAP, "--prior-weight", w]
                                   for w in weights]
                for prior_args, into in zip(variants, results):
                    out = work / "learned.json"
                    run("learn-structure", "--algorithm", "hc", "--data", binned, "--out", out, *prior_args)
                    into.append(found(json.loads(out.read_text())["edges"], truth))
            cells = "".join(f" {sum(r) / len(r):.1f} | {sum(v == 6 for v in r)}/{args.seeds} |" for r in results)
            print(f"| {trials} |{cells}", flush=True)


if __name__ == "__main__":
    main()
