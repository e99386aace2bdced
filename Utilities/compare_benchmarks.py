#!/usr/bin/env python3
"""Runs the benchmarks of two builds side by side and prints how long each took, as a ratio.

    compare_benchmarks.py BEFORE_BUILD AFTER_BUILD [--rounds N] [--only NAME ...]

Each benchmark runs from both builds in turn, N rounds (default 2), alternating which build goes
first, so that a shared, noisy machine slows both alike; the ratio is after / before of the
median wall-clock times (below 1: faster). Rendering benchmarks run under xvfb-run. A build is a
folder holding bin/Benchmark*, for example one made from an earlier commit with
`git worktree add ../before REV && make -C ../before build`.
"""

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Testing", "Data")
XVFB = ["xvfb-run", "-a", "-s", "-screen 0 1920x1080x24"]

# Each benchmark with the arguments measured: sizes that take seconds to a minute, not the
# full tables of their docs.
BENCHMARKS = {
    "BenchmarkAperturePrecompute": [DATA],
    "BenchmarkOcclusionQueryVisibility": [DATA, "--max-level", "3"],
    "BenchmarkEnvironmentLighting": [DATA],
    "BenchmarkApertureLightingMapper": [DATA, "--quick"],
    "BenchmarkDynamicVisibility": [DATA, "--quick"],
    "BenchmarkTerrain": [DATA, "{scratch}", "--quick"],
}


def run(build, name, arguments, scratch):
    command = XVFB + [os.path.join(build, "bin", name)]
    command += [a.replace("{scratch}", scratch) for a in arguments]
    start = time.monotonic()
    result = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            encoding="utf-8", errors="replace")
    if result.returncode != 0:
        sys.exit(f"{name} failed in {build}:\n{result.stderr[-2000:]}")
    return time.monotonic() - start


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("before")
    parser.add_argument("after")
    parser.add_argument("--rounds", type=int, default=2)
    parser.add_argument("--only", nargs="*")
    args = parser.parse_args()
    print("| benchmark | before (s) | after (s) | after / before |")
    print("|---|---|---|---|")
    with tempfile.TemporaryDirectory() as scratch:
        for name, arguments in BENCHMARKS.items():
            if args.only and name not in args.only:
                continue
            times = {args.before: [], args.after: []}
            for r in range(args.rounds):
                order = [args.before, args.after] if r % 2 == 0 else [args.after, args.before]
                for build in order:
                    times[build].append(run(build, name, arguments, scratch))
            before = statistics.median(times[args.before])
            after = statistics.median(times[args.after])
            label = ' '.join(arguments[1:]).replace('{scratch}', 'SCRATCH')
            print(f"| {name} {label} | {before:.1f} | {after:.1f} | "
                  f"{after / before:.3f} |", flush=True)


if __name__ == "__main__":
    main()
