#!/usr/bin/env python3
"""catplan plan beside Fast Downward (and pyperplan) on the same problems, in one run.

    planner_vs_fd.py --catplan BUILD/catplan --peers ../shared/peers --out DIR [--limit 60]
                     [--series ipc,blocks,perstate,costs] [--pyperplan] [--only DOMAIN,...]
                     [--per-domain N] [--blocks 20,24,...] [--perstate 30] [--repeat 3]

Writes the problems (bench/pddl/generate.py: the IPC-style series, and seeded blocksworlds of 20 to
40 blocks), runs every planner on every problem with the same wall-time limit, one process at a
time, and measures each process's wall time and peak resident memory (wait4's ru_maxrss). Every
plan found is validated by `catplan validate` and by VAL; a plan either rejects is counted as a
failure. Prints a Markdown table per series, coverage, medians and the ratios catplan / FD, and
writes the raw rows to DIR/results.json. Each cell names the value each heuristic gave the initial
state (h0; catplan's JSON statistics, FD's "Initial heuristic value for ..." lines, FD's names
mapped to catplan's): where both planners run one heuristic, equal values say they compute it
alike.

Series:
  costs     transport problems whose drives cost the road's length (generate.COST_SIZES):
            catplan --search astar (A* summing costs, lmcut) beside FD astar(lmcut()); both are
            optimal, so the plan costs must be equal, and the table says where they are;
  ipc       the first N problems of each IPC-style domain: catplan (default configuration, lama)
            beside FD lama-first, and pyperplan (gbfs, hff) with --pyperplan;
  blocks    seeded blocksworlds (random initial and goal towers, seed 7000 + n): catplan beside
            FD lama-first;
  perstate  the same algorithm in both planners, eager greedy best-first with h_FF on a seeded
            blocksworld of --perstate blocks (catplan --search gbfs --heuristic hff, FD
            eager_greedy([ff()])): expansions, evaluations, the search's CPU time per evaluated
            state, and the memory the search added per evaluated state (peak resident memory
            minus the resident memory when the search began: catplan's statistics, FD's log);
            each planner --repeat times, in turn, and the medians reported.

FD's --overall-time-limit is CPU time; this script also stops every process at limit + 5 s of
wall time. Benchmarks only: the peers are not Debian packages and neither the product nor its
tests need them.
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
BLOCKS_DOMAIN = HERE / "pddl/domains/blocksworld.pddl"


def blocks_problem(out, n):
    path = out / "problems" / "blocks" / f"b{n}.pddl"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(generate.blocksworld((n,), random.Random(7000 + n), f"blocks-{n}"))
    return path


def write_problems(out, series, only, per_domain, blocks, perstate):
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
    if "costs" in series:
        for domain, sizes in generate.COST_SIZES.items():
            for i, size in enumerate(sizes, 1):
                path = out / "problems" / domain / f"p{i:02d}.pddl"
                path.parent.mkdir(parents=True, exist_ok=True)
                rng = random.Random(1000 * i + len(domain))
                path.write_text(generate.GENERATORS[domain](size, rng, f"{domain}-p{i:02d}"))
                problems.append(("costs", domain, f"p{i:02d}",
                                 HERE / "pddl/domains" / f"{domain}.pddl", path))
    if "blocks" in series:
        for n in blocks:
            problems.append(("blocks", "blocksworld", f"{n} blocks", BLOCKS_DOMAIN,
                             blocks_problem(out, n)))
    if "perstate" in series:
        for n in perstate:
            problems.append(("perstate", "blocksworld", f"{n} blocks", BLOCKS_DOMAIN,
                             blocks_problem(out, n)))
    return problems


def run(cmd, limit, cwd):
    """Wall seconds, peak resident MB, CPU seconds, exit code, stdout and stderr of one process
    (killed at limit + 5 s)."""
    start = time.monotonic()
    with open(cwd / "out.txt", "w") as out, open(cwd / "err.txt", "w") as err:
        proc = subprocess.Popen(cmd, cwd=cwd, stdout=out, stderr=err)
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
    read = lambda name: (cwd / name).read_text(errors="replace")  # noqa: E731
    return dict(wall=wall, mb=usage.ru_maxrss / 1024, cpu=usage.ru_utime + usage.ru_stime,
                exit=code, out=read("out.txt"), err=read("err.txt"))


def plan_steps(path):
    if not path.exists():
        return None
    return sum(1 for line in path.read_text().splitlines() if line.strip().startswith("("))


def plan_cost(path):
    """The cost on the plan's last line, as both planners write it: "; cost = 45 (general cost)"."""
    found = re.search(r"; cost = (\d+)", path.read_text()) if path.exists() else None
    return int(found.group(1)) if found else None


def validate(args, domain, problem, plan):
    cat = subprocess.run([args.catplan, "validate", str(domain), str(problem), str(plan)],
                         capture_output=True, text=True)
    val = subprocess.run([str(args.peers / "bin/validate"), str(domain), str(problem), str(plan)],
                         capture_output=True, text=True)
    return cat.returncode == 0, val.returncode == 0 and "Plan valid" in val.stdout


def catplan_stats(p):
    """Counts and times from catplan's JSON statistics."""
    try:
        st = json.loads(p["out"])["statistics"]
    except (ValueError, KeyError):
        return {}
    return dict(expanded=st.get("expanded"), evaluated=st.get("evaluated"),
                initial_h=st.get("initial_h") or None, search_cpu=st.get("search_cpu_seconds"),
                setup_mb=st.get("setup_memory_bytes", 0) / 2**20)


# Fast Downward's names of the heuristics catplan also has.
FD_HEURISTICS = {"ff": "hff", "landmark_sum_heuristic": "lmcount", "lmcut": "lmcut",
                 "hmax": "hmax", "add": "hadd"}


def fd_stats(p):
    """Counts and times from Fast Downward's log (the last search's, for anytime aliases)."""
    log = p["out"]

    def last(pattern, cast=float):
        found = re.findall(pattern, log)
        return cast(found[-1]) if found else None

    # The resident memory when the search began: the first line that reports the initial
    # heuristic value.
    setup = re.search(r"\[t=[0-9.e-]+s, (\d+) KB\] Initial heuristic value", log)
    # The first search's value of each heuristic on the initial state, by catplan's names.
    initial = {}
    for name, value in re.findall(r"Initial heuristic value for ([^:]+): (\w+)", log):
        name = FD_HEURISTICS.get(name, name)
        if name not in initial:
            initial[name] = int(value) if value.isdigit() else None
    return dict(expanded=last(r"Expanded (\d+) state", int), initial_h=initial or None,
                evaluated=last(r"Evaluated (\d+) state", int),
                search_cpu=last(r"Search time: ([0-9.]+)s"),
                search_mb=last(r"Peak memory: (\d+) KB", lambda kb: int(kb) / 1024),
                setup_mb=int(setup.group(1)) / 1024 if setup else None)


def pyperplan_stats(p):
    log = p["out"] + p["err"]
    expanded = re.findall(r"(\d+) Nodes expanded", log)
    return dict(expanded=int(expanded[-1]) if expanded else None)


def planners(args, series):
    """(name, command builder, plan file name or None, statistics parser) per planner."""
    fd = str(args.peers / "bin/fast-downward")
    limit = f"{args.limit:g}s"

    def catplan(*extra):
        return lambda d, p: [args.catplan, "plan", str(d), str(p), "--max-time",
                             f"{args.limit:g}", "--format", "json", "-o", "plan.txt", *extra]

    def lama_first(d, p):
        return [fd, "--overall-time-limit", limit, "--plan-file", "plan.txt", "--alias",
                "lama-first", str(d), str(p)]

    def eager_greedy_ff(d, p):
        return [fd, "--overall-time-limit", limit, "--plan-file", "plan.txt", str(d), str(p),
                "--search", "eager_greedy([ff()])"]

    def astar_lmcut(d, p):
        return [fd, "--overall-time-limit", limit, "--plan-file", "plan.txt", str(d), str(p),
                "--search", "astar(lmcut())"]

    if series == "costs":
        return [
            ("catplan astar lmcut", catplan("--search", "astar"), "plan.txt", catplan_stats),
            ("FD astar(lmcut())", astar_lmcut, "plan.txt", fd_stats),
        ]
    if series == "perstate":
        return [
            ("catplan gbfs hff", catplan("--search", "gbfs", "--heuristic", "hff"), "plan.txt",
             catplan_stats),
            ("FD eager_greedy([ff()])", eager_greedy_ff, "plan.txt", fd_stats),
        ]
    result = [
        ("catplan", catplan(), "plan.txt", catplan_stats),
        ("FD lama-first", lama_first, "plan.txt", fd_stats),
    ]
    if args.pyperplan and series == "ipc":
        result.append(("pyperplan", lambda d, p: [str(args.peers / "bin/pyperplan"), "-s", "gbfs",
                                                  "-H", "hff", str(d), str(p)], None,
                       pyperplan_stats))
    return result


def run_all(args, problems):
    rows = []
    for series, domain, name, dfile, pfile in problems:
        repeat = args.repeat if series == "perstate" else 1
        for planner, build, plan_name, parse in planners(args, series) * repeat:
            work = (args.out / "runs" / series / re.sub(r"\W+", "_", planner) / domain /
                    name.replace(" ", ""))
            work.mkdir(parents=True, exist_ok=True)
            pcopy = work / "problem.pddl"
            pcopy.write_text(pfile.read_text())
            for old in list(work.glob("plan.txt*")) + list(work.glob("*.soln")):
                old.unlink()
            p = run(build(dfile, pcopy), args.limit, work)
            plan = work / (plan_name or "problem.pddl.soln")
            steps = plan_steps(plan) if p["wall"] <= args.limit + 5 else None
            ok_cat = ok_val = False
            if steps is not None:
                ok_cat, ok_val = validate(args, dfile, pcopy, plan)
            row = dict(series=series, domain=domain, problem=name, planner=planner,
                       wall=p["wall"], mb=p["mb"], cpu=p["cpu"], exit=p["exit"], steps=steps,
                       cost=plan_cost(plan) if steps is not None else None,
                       catplan_valid=ok_cat, val_valid=ok_val,
                       solved=steps is not None and ok_cat and ok_val, **parse(p))
            rows.append(row)
            print(f"{series:8} {domain:12} {name:9} {planner:24} "
                  f"{'solved' if row['solved'] else 'FAILED':6} {p['wall']:7.2f} s "
                  f"{p['mb']:7.1f} MB steps {steps} expanded {row.get('expanded')} exit "
                  f"{p['exit']} valid catplan/VAL {ok_cat}/{ok_val}", flush=True)
    return rows


def cell(row):
    if row is None:
        return "–"
    if not row["solved"]:
        if row["steps"] is not None:
            return "INVALID PLAN"
        return "not solved" if row["exit"] == 0 else f"not solved (exit {row['exit']})"
    exp = f", {row['expanded']} exp." if row.get("expanded") is not None else ""
    if row.get("initial_h"):
        exp += ", h0 " + " ".join(f"{k} {'dead end' if v is None else v}"
                                  for k, v in row["initial_h"].items())
    cost = f", cost {row['cost']}" if row["series"] == "costs" else ""
    return f"{row['wall']:.2f} s, {row['mb']:.0f} MB, {row['steps']} steps{cost}{exp}"


def table(rows, series, names):
    out = [f"| domain | problem | {' | '.join(names)} | catplan / FD time |",
           "|---|---|" + "---|" * (len(names) + 1)]
    keys = []
    for r in rows:
        if r["series"] == series and (r["domain"], r["problem"]) not in keys:
            keys.append((r["domain"], r["problem"]))
    ratios = []
    for domain, problem in keys:
        by = {r["planner"]: r for r in rows if r["series"] == series and
              (r["domain"], r["problem"]) == (domain, problem)}
        cat, fd = by.get(names[0]), by.get(names[1])
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
    if series == "costs":
        both = [(by[names[0]], by[names[1]]) for by in (
            {r["planner"]: r for r in rows if r["series"] == series and
             (r["domain"], r["problem"]) == key} for key in keys)
            if all(n in by and by[n]["solved"] for n in names)]
        same = sum(1 for a, b in both if a["cost"] == b["cost"])
        out.append(f"- plan cost the same in both (both optimal): {same} of {len(both)} solved by "
                   "both")
    if ratios:
        out.append(f"- {names[0]} / {names[1]} whole-process time where both solved "
                   f"({len(ratios)}): median {statistics.median(ratios):.2f}, min "
                   f"{min(ratios):.2f}, max {max(ratios):.2f}")
    return "\n".join(out)


def per_state(r):
    """(µs of search CPU, bytes of added memory) per evaluated state of one run, or None."""
    peak = r.get("search_mb") or r["mb"]  # FD: its search process's own peak
    if not r.get("evaluated") or r.get("search_cpu") is None or r.get("setup_mb") is None:
        return None
    return (1e6 * r["search_cpu"] / r["evaluated"],
            (peak - r["setup_mb"]) * 2**20 / r["evaluated"], peak)


def spread(values, fmt):
    med = statistics.median(values)
    return f"{med:{fmt}} ({min(values):{fmt}}–{max(values):{fmt}})" if len(values) > 1 \
        else f"{med:{fmt}}"


def per_state_table(rows):
    """µs of search CPU time and bytes of memory per evaluated state, both planners: the median
    over the repetitions (and their range)."""
    out = ["| problem | planner | runs solved | steps | expanded | evaluated | "
           "µs / evaluated state | peak memory | at search start | bytes / evaluated state |",
           "|---|---|---|---|---|---|---|---|---|---|"]
    keys = []
    for r in rows:
        if r["series"] == "perstate" and (r["problem"], r["planner"]) not in keys:
            keys.append((r["problem"], r["planner"]))
    medians = {}
    for problem, planner in keys:
        runs = [r for r in rows if r["series"] == "perstate" and
                (r["problem"], r["planner"]) == (problem, planner)]
        measured = [m for m in map(per_state, runs) if m]
        first = runs[0]
        us = spread([m[0] for m in measured], ".1f") if measured else "–"
        per_byte = spread([m[1] for m in measured], ".0f") if measured else "–"
        peak = spread([m[2] for m in measured], ".1f") + " MiB" if measured else "–"
        if measured:
            medians[(problem, planner)] = (statistics.median(m[0] for m in measured),
                                           statistics.median(m[1] for m in measured))
        out.append(f"| {problem} | {planner} | {sum(r['solved'] for r in runs)} of {len(runs)} | "
                   f"{first['steps']} | {first.get('expanded')} | {first.get('evaluated')} | "
                   f"{us} | {peak} | {first.get('setup_mb') or 0:.1f} MiB | {per_byte} |")
    for problem in dict.fromkeys(p for p, _ in keys):
        mine = [v for (p, _), v in medians.items() if p == problem]
        if len(mine) == 2:
            out.append(f"\n{problem}: catplan / FD per evaluated state, medians: time "
                       f"{mine[0][0] / mine[1][0]:.2f}, memory {mine[0][1] / mine[1][1]:.2f}")
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--catplan", required=True)
    ap.add_argument("--peers", required=True, type=pathlib.Path)
    ap.add_argument("--out", required=True, type=pathlib.Path)
    ap.add_argument("--limit", type=float, default=60)
    ap.add_argument("--series", default="ipc,blocks,perstate")
    ap.add_argument("--only", default="")
    ap.add_argument("--pyperplan", action="store_true", help="pyperplan too (ipc series)")
    ap.add_argument("--per-domain", type=int, default=4, help="the first N problems of a domain")
    ap.add_argument("--blocks", default=",".join(map(str, BLOCKS_SIZES)),
                    help="the blocksworld sizes")
    ap.add_argument("--perstate", default="30", help="the blocksworld sizes of the perstate series")
    ap.add_argument("--repeat", type=int, default=3, help="runs per planner in the perstate series")
    args = ap.parse_args()
    args.catplan = str(pathlib.Path(args.catplan).resolve())
    args.peers = args.peers.resolve()
    args.out = args.out.resolve()
    series = args.series.split(",")
    only = [d for d in args.only.split(",") if d]
    sizes = lambda text: [int(n) for n in text.split(",") if n]  # noqa: E731
    problems = write_problems(args.out, series, only, args.per_domain, sizes(args.blocks),
                              sizes(args.perstate))
    rows = run_all(args, problems)
    (args.out / "results.json").write_text(json.dumps(rows, indent=1))
    for s in series:
        print(f"\n### {s}\n")
        if s == "perstate":
            print(per_state_table(rows))
        else:
            print(table(rows, s, [p[0] for p in planners(args, s)]))


if __name__ == "__main__":
    main()
