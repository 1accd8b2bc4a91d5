#!/usr/bin/env python3
"""Transfer with costed repairs (least cost per step, reused by shape) beside Fast Downward.

    costed_transfer_vs_fd.py --catplan BUILD/catplan [--peers ../shared/peers] --out DIR
                             [--cities 60,300,1000] [--runs 5] [--limit 300]

For each N: a chain of N cities in the roads domain (tests/pddl/roads-domain.pddl), each road's
length drawn (seeded) from 2, 3, 5 and 60, and the plan that drives the truck from the first city
to the last. `catplan transfer` carries it along ToCharters (tests/pddl/roads_to_transit.cp) into
the charters domain, where a drive is repaired by a departure and an arrival, which cost the road's
length, or by a charter, which costs 50: each repair is searched with A* and LM-cut, or reused
from an earlier one of the same shape, values and all. Whole process, medians of --runs runs,
wall and CPU (user + system). The script reads the transfer's JSON for the repairs searched and
reused and the target plan's cost (and checks that each repair is the least on its focus).

With --peers, VAL checks the transferred plan on charters-domain.pddl and the target problem
the transfer writes (--problem-output), and Fast Downward's astar(lmcut()) solves that problem,
whole process (one run): the least cost of the target problem, which the transfer, keeping the
source plan's route, does not claim (a charter from the first city to the last costs 50).
Benchmarks only: the peers are not Debian packages; neither the product nor its tests need them.
"""
import argparse
import json
import os
import pathlib
import random
import re
import statistics
import subprocess
import sys

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent
PDDL = ROOT / "tests/pddl"
sys.path.insert(0, str(HERE))
from pddl_transfer_vs_fd import timed  # noqa: E402  (whole process, wall and CPU)
LENGTHS = (2, 3, 5, 60)


def chain(n, seed):
    """The problem text and the plan text of a seeded chain of n cities."""
    rng = random.Random(seed)
    lengths = [rng.choice(LENGTHS) for _ in range(n - 1)]
    cities = [f"c{i}" for i in range(n)]
    init = ["(at t1 c0)"] + [f"(road c{i} c{i + 1})" for i in range(n - 1)]
    init += [f"(= (road-length c{i} c{i + 1}) {d})" for i, d in enumerate(lengths)]
    init.append("(= (total-cost) 0)")
    problem = (f"(define (problem chain-{n})\n  (:domain roads)\n"
               f"  (:objects {' '.join(cities)} - city t1 - truck)\n"
               f"  (:init {' '.join(init)})\n  (:goal (at t1 c{n - 1}))\n"
               "  (:metric minimize (total-cost)))\n")
    plan = "".join(f"(drive t1 c{i} c{i + 1})\n" for i in range(n - 1))
    return problem, plan + f"; cost = {sum(lengths)} (general cost)\n"


def repairs(report):
    """(searched, reused, all least) of the transfer's JSON report."""
    rs = [s["repair"] for s in report["steps"] if s.get("carried_out_by") == "repaired"]
    reused = sum(1 for r in rs if r.get("reused_from") is not None)
    return len(rs) - reused, reused, all(r.get("least_cost") for r in rs)


def one_size(a, n, out):
    d = out / f"chain-{n}"
    d.mkdir(parents=True, exist_ok=True)
    problem_text, plan_text = chain(n, seed=n)
    problem, plan = d / "source.pddl", d / "source.plan"
    problem.write_text(problem_text)
    plan.write_text(plan_text)
    target_plan, target_problem = d / "target.plan", d / "target.pddl"
    cmd = [str(a.catplan), "transfer", str(PDDL / "roads_to_transit.cp"), "--map", "ToCharters",
           "--problem", str(problem), "--plan", str(plan), "--no-timing", "--format", "json",
           "-o", str(target_plan), "--problem-output", str(target_problem)]
    walls, cpus = [], []
    for _ in range(a.runs):
        wall, r = timed(cmd, a.limit)
        if r.returncode != 0:
            sys.exit(f"chain {n}: the transfer exited {r.returncode}: {r.stderr[-500:]}")
        walls.append(wall)
        cpus.append(r.cpu)
    report = json.loads(r.stdout)
    searched, reused, least = repairs(report)
    cost = re.search(r"; cost = (\d+)", target_plan.read_text())
    target_steps = sum(1 for x in target_plan.read_text().splitlines() if x.startswith("("))
    row = {"cities": n, "steps": n - 1, "target_steps": target_steps,
           "searched": searched, "reused": reused, "all_least": least,
           "source_cost": int(re.search(r"; cost = (\d+)", plan_text).group(1)),
           "target_cost": int(cost.group(1)) if cost else None,
           "wall": statistics.median(walls), "cpu": statistics.median(cpus)}
    if a.peers:
        v = subprocess.run([str(a.peers / "bin/validate"), str(PDDL / "charters-domain.pddl"),
                            str(target_problem), str(target_plan)], capture_output=True, text=True)
        row["val"] = "valid" if "Plan valid" in v.stdout else "INVALID"
        fd_plan = d / "fd.plan"
        if fd_plan.exists():
            fd_plan.unlink()
        wall, r = timed([str(a.peers / "bin/fast-downward"), "--overall-time-limit",
                         f"{a.limit}s", "--plan-file", str(fd_plan),
                         str(PDDL / "charters-domain.pddl"), str(target_problem),
                         "--search", "astar(lmcut())"], a.limit)
        fd_cost = re.search(r"; cost = (\d+)", fd_plan.read_text()) if fd_plan.exists() else None
        row["fd_wall"], row["fd_cpu"] = wall, r.cpu
        row["fd_cost"] = int(fd_cost.group(1)) if fd_cost else None
    return row


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--catplan", type=pathlib.Path, required=True)
    p.add_argument("--peers", type=pathlib.Path)
    p.add_argument("--out", type=pathlib.Path, required=True)
    p.add_argument("--cities", default="60,300,1000")
    p.add_argument("--runs", type=int, default=5)
    p.add_argument("--limit", type=int, default=300)
    a = p.parse_args()
    a.catplan = a.catplan.resolve()
    print(f"load average before: {os.getloadavg()[0]:.2f}")
    head = ("| cities | source steps | target steps | repairs searched, reused | each the least "
            "| source cost | target cost | transfer s (CPU s) |")
    rule = "|---|---|---|---|---|---|---|---|"
    if a.peers:
        head += " VAL (transferred) | FD astar(lmcut()) s (CPU s) | FD least cost |"
        rule += "---|---|---|"
    print(head)
    print(rule)
    for n in (int(x) for x in a.cities.split(",")):
        r = one_size(a, n, a.out)
        line = (f"| {r['cities']} | {r['steps']} | {r['target_steps']} | {r['searched']}, "
                f"{r['reused']} | {'yes' if r['all_least'] else 'no'} | {r['source_cost']} | "
                f"{r['target_cost']} | {r['wall']:.3f} ({r['cpu']:.3f}) |")
        if a.peers:
            line += f" {r['val']} | {r['fd_wall']:.3f} ({r['fd_cpu']:.3f}) | {r['fd_cost']} |"
        print(line, flush=True)
    print(f"load average after: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
