#!/usr/bin/env python3
"""How long catplan commands take to start: the median task-clock and page faults of short runs.

    startup.py [--runs 50] CATPLAN [CATPLAN ...] [-- ARGS ...]

Runs each CATPLAN (two builds, say, to compare them) with ARGS (default `--version`) RUNS times
under `perf stat -x, -e task-clock,page-faults`, one run of each program in turn, so that a change
of the machine's load falls on all of them alike, and prints the medians with the load average
before and after. On a short command most of the time is the dynamic loader mapping and relocating
the linked libraries; page faults are the steadier figure on a shared machine. Needs Linux perf
(Debian's linux-perf) and a kernel that lets the user count its own events.
"""
import argparse
import os
import statistics
import subprocess
import sys


def measure(command):
    """The task-clock (ms) and page faults of one run of command."""
    p = subprocess.run(["perf", "stat", "-x,", "-e", "task-clock,page-faults"] + command,
                       stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, check=False)
    figures = {}
    for line in p.stderr.splitlines():
        fields = line.split(",")
        if len(fields) > 2 and fields[2] in ("task-clock", "page-faults"):
            figures[fields[2]] = float(fields[0])
    if len(figures) != 2:
        sys.exit(f"startup.py: perf gave no figures for {' '.join(command)}:\n{p.stderr}")
    return figures["task-clock"], figures["page-faults"]


def main():
    argv = sys.argv[1:]
    args = ["--version"]
    if "--" in argv:
        args = argv[argv.index("--") + 1:]
        argv = argv[: argv.index("--")]
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=50)
    parser.add_argument("catplan", nargs="+")
    opts = parser.parse_args(argv)
    print(f"load average before: {os.getloadavg()[0]:.2f}")
    times = {c: [] for c in opts.catplan}
    faults = {c: [] for c in opts.catplan}
    for _ in range(opts.runs):
        for c in opts.catplan:
            t, f = measure([c] + args)
            times[c].append(t)
            faults[c].append(f)
    print(f"load average after: {os.getloadavg()[0]:.2f}")
    print(f"{opts.runs} runs of: catplan {' '.join(args)}")
    for c in opts.catplan:
        print(f"{statistics.median(times[c]):7.2f} ms  {statistics.median(faults[c]):5.0f} page "
              f"faults  (fastest {min(times[c]):.2f} ms)  {c}")


if __name__ == "__main__":
    main()
