#!/usr/bin/env python3
"""catplan plan beside Fast Downward (and pyperplan) on the same problems, in one run.

    planner_vs_fd.py --catplan BUILD/catplan --peers ../shared/peers --out DIR [--limit 60]
                     [--series ipc,blocks] [--pyperplan] [--only DOMAIN,...]
                     [--per-domain N] [--blocks 20,24,...]

Writes the problems (bench/pddl/generate.py: the IPC-style series, and seeded blocksworlds of 20 to
40 blocks), runs every planner on every problem with the same wall-time limit, one process at a
time, and measures each process's wall time and peak resident memory (wait4's ru_maxrss). Every
plan found is validated by `catplan validate` and by VAL; a plan either rejects is counted as a
failure. Prints a Markdown table per series, coverage, medians and the ratios catplan / FD, and
writes the raw rows to DIR/results.json. Benchmarks only: the peers are not Debian packages and
neither the product nor its tests need them.
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
import time

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE / "pddl"))
import generate  # noqa: E402

BLOCKS_SIZES = list(range(20, 41, 2))


def write_problems(out, series, only, per_domain, blocks):
    """The (series, domain, problem name, domain file, problem file) of every problem."""
    problems = []
    if "ipc" in series:
        for domain, sizes in generate.SIZES.items():
            if only and domain not in only:
                continue
            for i, size in enumerate(sizes[:per_domain], 1):
                path = out / "problems" / domain / f"p{i:02d}.pddl"
                path.parent.mkdir(parents=True, exist_ok=True)
                rng = random.Random(1000 * i + len(domain))
                path.write_text(generate.GENERATORS[domain](size, rng, f"{domain}-p{i:02d}"))
                problems.append(("ipc", domain, f"p{i:02d}", HERE / "pddl/domains" / f"{domain}.pddl",
                                 path))
    if "blocks" in series:
        for n in blocks:
            path = out / "problems" / "blocks" / f"b{n}.pddl"
            path.parent.mkdir(parents=True, exist_ok=True)
            rng = random.Random(7000 + n)
            path.write_text(generate.blocksworld((n,), rng, f"blocks-{n}"))
            problems.append(("blocks", "blocksworld", f"{n} blocks",
                             HERE / "pddl/domains/blocksworld.pddl", path))
    return problems


def run(cmd, limit, cwd):
    """Wall seconds, peak resident MB, exit code, output of one process (killed at limit + 5 s)."""
    start = time.monotonic()
    with open(cwd / "log.txt", "w") as log:
        proc = subprocess.Popen(cmd, cwd=cwd, stdout=log, stderr=subprocess.STDOUT)
        deadline = start + limit + 5
        while True:
            pid, status, usage = os.wait4(proc.pid, os.WNOHANG)
            if pid != 0:
                break
            if time.monotonic() > deadline:
                proc.kill()
                pid, status, usage = os.wait4(proc.pid, 0)
                break
            time.sleep(0.005)
    wall = time.monotonic() - start
    code = os.waitstatus_to_exitcode(status)
    return wall, usage.ru_maxrss / 1024, code, (cwd / "log.txt").read_text(errors="replace")


def plan_steps(path):
    if not path.exists():
        return None
    return sum(1 for line in path.read_text().splitlines() if line.strip().startswith("("))


def validate(args, domain, problem, plan):
    cat = subprocess.run([args.catplan, "validate", str(domain), str(problem), str(plan)],
                         capture_output=True, text=True)
    val = subprocess.run([str(args.peers / "bin/validate"), str(domain), str(problem), str(plan)],
                         capture_output=True, text=True)
    return cat.returncode == 0, val.returncode == 0 and "Plan valid" in val.stdout


def planners(args):
    """(name, command builder, plan file name) per planner."""
    fd = str(args.peers / "bin/fast-downward")
    limit = f"{args.limit:g}s"
    result = [
        ("catplan", lambda d, p: [args.catplan, "plan", str(d), str(p), "--max-time",
                                  f"{args.limit:g}", "-o", "plan.txt"], "plan.txt"),
        ("FD lama-first", lambda d, p: [fd, "--overall-time-limit", limit, "--plan-file",
                                        "plan.txt", "--alias", "lama-first", str(d), str(p)],
         "plan.txt"),
    ]
    if args.pyperplan:
        result.append(("pyperplan", lambda d, p: [str(args.peers / "bin/pyperplan"), "-s", "gbfs",
                                                  "-H", "hff", str(d), str(p)], None))
    return result


def run_all(args, problems):
    rows = []
    for series, domain, name, dfile, pfile in problems:
        for planner, build, plan_name in planners(args):
            work = args.out / "runs" / planner.split()[0] / domain / name.replace(" ", "")
            work.mkdir(parents=True, exist_ok=True)
            pcopy = work / "problem.pddl"
            pcopy.write_text(pfile.read_text())
            for old in work.glob("plan.txt*"):
                old.unlink()
            wall, mb, code, log = run(build(dfile, pcopy), args.limit, work)
            plan = work / (plan_name or "problem.pddl.soln")
            steps = plan_steps(plan) if wall <= args.limit else None
            ok_cat = ok_val = False
            if steps is not None:
                ok_cat, ok_val = validate(args, dfile, pcopy, plan)
            search = re.search(r"Search time: ([0-9.]+)s", log)
            row = dict(series=series, domain=domain, problem=name, planner=planner, wall=wall,
                       mb=mb, exit=code, steps=steps, catplan_valid=ok_cat, val_valid=ok_val,
                       solved=steps is not None and ok_cat and ok_val,
                       fd_search=float(search.group(1)) if search else None)
            rows.append(row)
            print(f"{series:6} {domain:12} {name:9} {planner:14} "
                  f"{'solved' if row['solved'] else 'FAILED':6} {wall:7.2f} s {mb:7.1f} MB "
                  f"steps {steps} exit {code} valid catplan/VAL {ok_cat}/{ok_val}", flush=True)
    return rows


def cell(row):
    if row is None:
        return "–"
    if not row["solved"]:
        return "not solved" if row["steps"] is None else "INVALID PLAN"
    return f"{row['wall']:.2f} s, {row['mb']:.0f} MB, {row['steps']} steps"


def table(rows, series, names):
    out = [f"| domain | problem | {' | '.join(names)} | catplan / FD time |",
           "|---|---|" + "---|" * (len(names) + 1)]
    keys = []
    for r in rows:
        if r["series"] == series and (r["domain"], r["problem"]) not in keys:
            keys.append((r["domain"], r["problem"]))
    ratios = []
    for domain, problem in keys:
        by = {r["planner"]: r for r in rows if (r["domain"], r["problem"]) == (domain, problem)}
        cat, fd = by.get("catplan"), by.get("FD lama-first")
        ratio = "–"
        if cat and fd and cat["solved"] and fd["solved"]:
            ratios.append(cat["wall"] / fd["wall"])
            ratio = f"{ratios[-1]:.2f}"
        out.append(f"| {domain} | {problem} | " + " | ".join(cell(by.get(n)) for n in names) +
                   f" | {ratio} |")
    out.append("")
    for n in names:
        mine = [r for r in rows if r["series"] == series and r["planner"] == n]
        solved = [r for r in mine if r["solved"]]
        med = statistics.median(r["wall"] for r in solved) if solved else float("nan")
        medmb = statistics.median(r["mb"] for r in solved) if solved else float("nan")
        out.append(f"- {n}: solved {len(solved)} of {len(mine)}; median time of the solved "
                   f"{med:.2f} s, median peak memory {medmb:.0f} MB")
    if ratios:
        out.append(f"- catplan / FD whole-process time where both solved ({len(ratios)}): median "
                   f"{statistics.median(ratios):.2f}, min {min(ratios):.2f}, max {max(ratios):.2f}")
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--catplan", required=True)
    ap.add_argument("--peers", required=True, type=pathlib.Path)
    ap.add_argument("--out", required=True, type=pathlib.Path)
    ap.add_argument("--limit", type=float, default=60)
    ap.add_argument("--series", default="ipc,blocks")
    ap.add_argument("--only", default="")
    ap.add_argument("--pyperplan", action="store_true")
    ap.add_argument("--per-domain", type=int, default=4, help="the first N problems of a domain")
    ap.add_argument("--blocks", default=",".join(map(str, BLOCKS_SIZES)),
                    help="the blocksworld sizes")
    args = ap.parse_args()
    args.catplan = str(pathlib.Path(args.catplan).resolve())
    args.peers = args.peers.resolve()
    args.out = args.out.resolve()
    series = args.series.split(",")
    only = [d for d in args.only.split(",") if d]
    blocks = [int(n) for n in args.blocks.split(",") if n]
    problems = write_problems(args.out, series, only, args.per_domain, blocks)
    rows = run_all(args, problems)
    (args.out / "results.json").write_text(json.dumps(rows, indent=1))
    names = [p[0] for p in planners(args)]
    for s in series:
        print(f"\n### {s}\n")
        print(table(rows, s, names))


if __name__ == "__main__":
    main()
