#!/usr/bin/env python3
"""Plan transfer between PDDL domains beside replanning with Fast Downward, in one run.

    pddl_transfer_vs_fd.py --catplan BUILD/catplan --peers ../shared/peers --out DIR
                           [--blocks 10,20,30] [--runs 3] [--batch 32] [--limit 60]

For each seeded 4-operator blocksworld problem (examples/pddl/blocks/blocks4.pddl) of N blocks:
Fast Downward (lama-first) solves it and writes the source plan; `catplan transfer` carries that
plan along examples/pddl/blocks/four_to_three.cp into the 3-operator domain (every step repaired
with the target's own actions), writing the target IPC plan and the target problem Δ_F(I), Δ_F(G);
Fast Downward then solves that target problem from scratch. VAL checks the source plan, the
transferred plan and FD's target plan on their own domain files. Prints the median wall time of
transfer and of replanning, their ratio and the plan lengths.

With --batch K, the same source plan K times over in one directory, transferred by one catplan
process with --jobs 1 and --jobs 2: the throughput of batch transfer on one core and on two.
Benchmarks only: the peers are not Debian packages; neither the product nor its tests need them.
"""
import argparse
import pathlib
import random
import re
import shutil
import statistics
import subprocess
import sys
import time

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent
BLOCKS = ROOT / "examples/pddl/blocks"
sys.path.insert(0, str(HERE / "pddl"))
import generate  # noqa: E402


def blocks4_problem(n, seed):
    """A seeded problem of blocks4 (the domain's own predicate names)."""
    rng = random.Random(seed)
    blocks = [f"b{i}" for i in range(1, n + 1)]
    init = ["(hand-empty)"]
    for t in generate.towers(blocks, rng):
        init.append(f"(on-table {t[0]})")
        init += [f"(on {a} {b})" for b, a in zip(t, t[1:])]
        init.append(f"(clear {t[-1]})")
    goal = []
    for t in generate.towers(blocks, rng):
        goal += [f"(on {a} {b})" for b, a in zip(t, t[1:])]
    return generate.problem("blocks4", f"blocks4-{n}", [("block", blocks)], init,
                            goal or [f"(on {blocks[0]} {blocks[1]})"])


def timed(cmd, limit):
    start = time.perf_counter()
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=limit + 30)
    return time.perf_counter() - start, r


def steps(plan):
    return sum(1 for line in plan.read_text().splitlines() if line.startswith("("))


def val(peers, domain, problem, plan):
    r = subprocess.run([str(peers / "bin/validate"), str(domain), str(problem), str(plan)],
                       capture_output=True, text=True)
    return "Plan valid" in r.stdout


def fd(peers, domain, problem, plan, limit):
    return timed([str(peers / "bin/fast-downward"), "--overall-time-limit", f"{limit}s",
                  "--plan-file", str(plan), "--alias", "lama-first", str(domain), str(problem)],
                 limit)


def transfer_cmd(catplan, problem, plan, extra):
    return [str(catplan), "transfer", str(BLOCKS / "four_to_three.cp"), "--map", "FourToThree",
            "--problem", str(problem), "--plan", str(plan), "--no-timing"] + extra


def one_size(a, n, out):
    d = out / f"b{n}"
    d.mkdir(parents=True, exist_ok=True)
    problem = d / "source.pddl"
    problem.write_text(blocks4_problem(n, 7000 + n))
    source_plan, target_plan, target_problem = d / "source.plan", d / "target.plan", d / "target.pddl"
    fd_plan = d / "fd_target.plan"
    _, r = fd(a.peers, BLOCKS / "blocks4.pddl", problem, source_plan, a.limit)
    if not source_plan.exists():
        print(f"{n} blocks: FD found no source plan: {r.stdout[-300:]}", file=sys.stderr)
        return None
    transfer_s, replan_s = [], []
    for _ in range(a.runs):
        t, r = timed(transfer_cmd(a.catplan, problem, source_plan,
                                  ["-o", str(target_plan), "--problem-output", str(target_problem)]),
                     a.limit)
        if r.returncode != 0:
            print(f"{n} blocks: transfer exit {r.returncode}: {r.stdout[-400:]}{r.stderr[-400:]}",
                  file=sys.stderr)
            return None
        transfer_s.append(t)
        t, r = fd(a.peers, BLOCKS / "blocks3.pddl", target_problem, fd_plan, a.limit)
        replan_s.append(t)
    row = {
        "n": n,
        "source_steps": steps(source_plan),
        "target_steps": steps(target_plan),
        "fd_target_steps": steps(fd_plan) if fd_plan.exists() else None,
        "transfer_s": statistics.median(transfer_s),
        "replan_s": statistics.median(replan_s),
        "val_source": val(a.peers, BLOCKS / "blocks4.pddl", problem, source_plan),
        "val_transfer": val(a.peers, BLOCKS / "blocks3.pddl", target_problem, target_plan),
        "val_fd": fd_plan.exists() and val(a.peers, BLOCKS / "blocks3.pddl", target_problem, fd_plan),
    }
    if a.batch:
        plans = d / "plans"
        shutil.rmtree(plans, ignore_errors=True)
        plans.mkdir()
        for i in range(a.batch):
            shutil.copy(source_plan, plans / f"plan{i:03d}")
        for jobs in (1, 2):
            times = []
            for _ in range(a.runs):
                t, r = timed(transfer_cmd(a.catplan, problem, plans,
                                          ["--jobs", str(jobs), "--format", "jsonl"]), a.limit * 4)
                lines = r.stdout.splitlines()
                if r.returncode != 0 or len(lines) != a.batch:
                    print(f"{n} blocks: batch --jobs {jobs}: exit {r.returncode}, {len(lines)} lines",
                          file=sys.stderr)
                    return None
                times.append(t)
            row[f"batch_jobs{jobs}_s"] = statistics.median(times)
    return row


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--catplan", type=pathlib.Path, required=True)
    p.add_argument("--peers", type=pathlib.Path, required=True)
    p.add_argument("--out", type=pathlib.Path, required=True)
    p.add_argument("--blocks", default="10,20,30")
    p.add_argument("--runs", type=int, default=3)
    p.add_argument("--batch", type=int, default=0)
    p.add_argument("--limit", type=int, default=60)
    a = p.parse_args()
    rows = [r for n in map(int, a.blocks.split(",")) if (r := one_size(a, n, a.out))]
    print("| blocks | source steps (FD) | transferred steps | FD replanned steps | transfer s "
          "| FD replanning s | replanning / transfer | VAL source, transferred, replanned |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        ok = ", ".join("valid" if r[k] else "INVALID" for k in ("val_source", "val_transfer", "val_fd"))
        print(f"| {r['n']} | {r['source_steps']} | {r['target_steps']} | {r['fd_target_steps']} "
              f"| {r['transfer_s']:.3f} | {r['replan_s']:.3f} "
              f"| {r['replan_s'] / r['transfer_s']:.2f} | {ok} |")
    if a.batch:
        print(f"\n| blocks | {a.batch} plans, --jobs 1 s | --jobs 2 s | speed-up |")
        print("|---|---|---|---|")
        for r in rows:
            j1, j2 = r["batch_jobs1_s"], r["batch_jobs2_s"]
            print(f"| {r['n']} | {j1:.3f} | {j2:.3f} | {j1 / j2:.2f} |")


if __name__ == "__main__":
    main()
