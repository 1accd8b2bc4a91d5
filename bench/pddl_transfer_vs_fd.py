#!/usr/bin/env python3
"""PDDL plan transfer beside replanning with Fast Downward, in one run.

    pddl_transfer_vs_fd.py --catplan BUILD/catplan --peers ../shared/peers --out DIR
                           [--blocks 30,100] [--repetitions 5] [--limit 120]

For each size n and each direction between the 4-operator and the 3-operator blocks world
(examples/pddl/blocks: FourToThree and ThreeToFour), writes a seeded random source problem of n
blocks, has Fast Downward (lama-first) find the source plan, then times, as whole processes:
  - `catplan transfer MAP --map M --problem SRC.pddl --plan sas_plan -o target.plan
    --problem-output target.pddl` (parse, import, transfer with repair, target plan checked);
  - Fast Downward lama-first replanning target.pddl (the exported target problem) from scratch.
Every transferred plan is checked by VAL on the target domain and the exported problem, and so
is FD's replanned plan. Prints a Markdown table with medians and the ratio replanning / transfer,
and writes the raw rows to DIR/results.json. Benchmarks only: the peers are not Debian packages
and neither the product nor its tests need them.
"""
import argparse
import json
import pathlib
import random
import statistics
import subprocess
import sys

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent
BLOCKS = ROOT / "examples/pddl/blocks"
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE / "pddl"))
from planner_vs_fd import plan_steps, run  # noqa: E402
import generate  # noqa: E402

# (name, map file, map name, source domain, target domain)
DIRECTIONS = [
    ("4 ops -> 3 ops", "four_to_three.cp", "FourToThree", "blocks4", "blocks3"),
    ("3 ops -> 4 ops", "three_to_four.cp", "ThreeToFour", "blocks3", "blocks4"),
]


def blocks_problem(domain, n, rng):
    """A problem of `domain` (blocks3 or blocks4): n blocks in random towers, random goal towers."""
    blocks = [f"b{i}" for i in range(1, n + 1)]

    def facts(towers):
        out = []
        for t in towers:
            out.append(f"(on-table {t[0]})")
            out += [f"(on {a} {b})" for b, a in zip(t, t[1:])]
            out.append(f"(clear {t[-1]})")
        return out

    init = facts(generate.towers(blocks, rng))
    if domain == "blocks4":
        init.append("(hand-empty)")
    goal = [f for f in facts(generate.towers(blocks, rng)) if f.startswith("(on ")]
    if not goal:
        goal = [f"(on {blocks[0]} {blocks[1]})"]
    return generate.problem(domain, f"{domain}-{n}", [("block", blocks)], init, goal)


def fd(args, domain, problem, plan, cwd):
    return run([str(args.peers / "bin/fast-downward"), "--overall-time-limit", f"{args.limit:g}s",
                "--plan-file", str(plan), "--alias", "lama-first", str(domain), str(problem)],
               args.limit, cwd)


def val(args, domain, problem, plan):
    r = subprocess.run([str(args.peers / "bin/validate"), str(domain), str(problem), str(plan)],
                       capture_output=True, text=True)
    return r.returncode == 0 and "Plan valid" in r.stdout


def one(args, n, direction):
    name, map_file, map_name, source, target = direction
    cwd = args.out / f"{source}-{target}-{n}"
    cwd.mkdir(parents=True, exist_ok=True)
    src = cwd / "source.pddl"
    src.write_text(blocks_problem(source, n, random.Random(9000 + n)))
    wall, _, code, log = fd(args, BLOCKS / f"{source}.pddl", src, cwd / "sas_plan", cwd)
    row = {"n": n, "direction": name, "source_fd_s": wall, "source_steps": plan_steps(cwd / "sas_plan")}
    if code != 0:
        row["error"] = f"FD found no source plan (exit {code})"
        return row
    transfer = [args.catplan, "transfer", str(BLOCKS / map_file), "--map", map_name, "--problem",
                str(src), "--plan", str(cwd / "sas_plan"), "-o", str(cwd / "target.plan"),
                "--problem-output", str(cwd / "target.pddl")]
    times = []
    for _ in range(args.repetitions):
        wall, rss, code, log = run(transfer, args.limit, cwd)
        if code != 0:
            row["error"] = f"catplan transfer exit {code}: {log[-400:]}"
            return row
        times.append(wall)
    row.update(transfer_s=statistics.median(times), transfer_mb=rss,
               target_steps=plan_steps(cwd / "target.plan"),
               transfer_val=val(args, BLOCKS / f"{target}.pddl", cwd / "target.pddl",
                                cwd / "target.plan"))
    times = []
    for _ in range(args.fd_repetitions):
        wall, rss, code, log = fd(args, BLOCKS / f"{target}.pddl", cwd / "target.pddl",
                                  cwd / "replan.plan", cwd)
        times.append(wall)
    row.update(replan_s=statistics.median(times), replan_mb=rss, replan_code=code,
               replan_steps=plan_steps(cwd / "replan.plan"),
               replan_val=code == 0 and val(args, BLOCKS / f"{target}.pddl", cwd / "target.pddl",
                                            cwd / "replan.plan"))
    return row


def table(rows):
    print("| blocks | direction | source plan (FD) | catplan transfer | target plan | VAL | "
          "FD lama-first replanning | replanned plan | VAL | replanning / transfer |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        if "error" in r:
            print(f"| {r['n']} | {r['direction']} | {r.get('source_steps')} steps | "
                  f"{r['error']} | | | | | | |")
            continue
        ok = lambda b: "valid" if b else "INVALID"  # noqa: E731
        print(f"| {r['n']} | {r['direction']} | {r['source_steps']} steps | "
              f"{r['transfer_s'] * 1000:.0f} ms, {r['transfer_mb']:.0f} MB | "
              f"{r['target_steps']} steps | {ok(r['transfer_val'])} | "
              f"{r['replan_s'] * 1000:.0f} ms, {r['replan_mb']:.0f} MB | {r['replan_steps']} steps | "
              f"{ok(r['replan_val'])} | {r['replan_s'] / r['transfer_s']:.1f}x |")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--catplan", required=True)
    p.add_argument("--peers", type=pathlib.Path, required=True)
    p.add_argument("--out", type=pathlib.Path, required=True)
    p.add_argument("--blocks", default="30,100")
    p.add_argument("--repetitions", type=int, default=5)
    p.add_argument("--fd-repetitions", type=int, default=3)
    p.add_argument("--limit", type=float, default=120)
    args = p.parse_args()
    args.catplan = str(pathlib.Path(args.catplan).resolve())
    args.peers = args.peers.resolve()
    args.out = args.out.resolve()
    rows = [one(args, int(n), d) for n in args.blocks.split(",") for d in DIRECTIONS]
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "results.json").write_text(json.dumps(rows, indent=2))
    table(rows)


if __name__ == "__main__":
    main()
