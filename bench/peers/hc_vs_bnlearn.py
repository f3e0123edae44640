#!/usr/bin/python3
"""Hill climbing (and tabu) with BIC: pgm learn-structure against R bnlearn's hc() (tabu()) on rbn()
samples of the published networks. pgm's time is the whole `pgm` process (reading the CSV
included); bnlearn's is the hc() call alone. Prints a Markdown table for docs/structure-learning.md.

    bench/peers/hc_vs_bnlearn.py BUILD_DIR [--algorithms hc,tabu] [--rows 10000,100000]

Needs Rscript and the bnlearn that cmake/peers.cmake installs into BUILD_DIR/peers/bnlearn-lib.
"""

import argparse
import json
import os
import pathlib
import subprocess
import tempfile
import time

here = pathlib.Path(__file__).resolve().parent
source = here.parent.parent


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("build")
    parser.add_argument("--algorithms", default="hc,tabu")
    parser.add_argument("--rows", default="10000,100000")
    parser.add_argument("--networks", default="alarm,insurance,child")
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    build = pathlib.Path(args.build).resolve()
    env = dict(os.environ, R_LIBS=str(build / "peers" / "bnlearn-lib"))
    r_script = here / "bnlearn_hc.R"
    print("| network | rows | algorithm | pgm s (process) | bnlearn s (call) | BIC pgm | BIC bnlearn | SHD pgm | SHD bnlearn |")
    print("|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        work = pathlib.Path(work)
        for network in args.networks.split(","):
            bif = source / "tests" / "data" / "networks" / f"{network}.bif"
            for rows in map(int, args.rows.split(",")):
                csv = work / f"{network}-{rows}.csv"
                subprocess.run(["Rscript", r_script, "sample", bif, str(rows), str(args.seed), csv], env=env, check=True)
                for algorithm in args.algorithms.split(","):
                    out = work / "learned.json"
                    start = time.perf_counter()
                    subprocess.run([build / "bin" / "pgm", "learn-structure", "--algorithm", algorithm, "--score", "bic",
                                    "--data", csv, "--out", out], check=True, capture_output=True)
                    seconds = time.perf_counter() - start
                    edges = json.loads(out.read_text())["edges"]
                    arcs = work / "arcs.csv"
                    arcs.write_text("from,to\n" + "".join(f"{a},{b}\n" for a, b in edges))
                    answer = subprocess.run(["Rscript", r_script, "compare", bif, csv, algorithm, arcs], env=env,
                                            check=True, capture_output=True, text=True).stdout.split()
                    r_seconds, r_bic, r_shd, our_bic, our_shd = answer
                    print(f"| {network} | {rows} | {algorithm} | {seconds:.2f} | {float(r_seconds):.2f} | "
                          f"{float(our_bic):.2f} | {float(r_bic):.2f} | {our_shd} | {r_shd} |", flush=True)


if __name__ == "__main__":
    main()
