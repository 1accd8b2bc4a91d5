#!/usr/bin/env python3
"""Plan transfer between PDDL domains beside replanning with Fast Downward, in one run.

    pddl_transfer_vs_fd.py --catplan BUILD/catplan --peers ../shared/peers --out DIR
                           [--blocks 30,100] [--directions 4to3,3to4] [--runs 3]
                           [--transfer-runs 9] [--batch 32] [--limit 900] [--repeat 20]

For each direction and each seeded blocksworld problem of N blocks in the source domain:
  4to3: the 4-operator blocksworld (examples/pddl/blocks/blocks4.pddl) carried along
        examples/pddl/blocks/four_to_three.cp into the 3-operator one (every step repaired;
        pick-up and the stack after it merge into one move);
  3to4: the 3-operator blocksworld carried along three_to_four.cp into the 4-operator one (every
        move repaired into two steps).
Fast Downward (lama-first) solves the source problem and writes the source plan (not timed; kept in
DIR and used again when the problem is the same); `catplan transfer` carries that plan into the
target domain, whole process, writing the target IPC plan (-o) and the target problem Δ_F(I),
Δ_F(G) (--problem-output); Fast Downward then solves that target problem from scratch, whole
process. Both tools write their plans to files that do not exist before the run (the previous run's
are removed, untimed). VAL checks the source plan, the transferred plan and FD's target plan on
their own domain files. Prints, per direction and size, the medians of --transfer-runs runs of the
transfer and of --runs runs of replanning, the two spread over the same stretch of time (and FD's
own search time, from its log), their ratios
and the plan lengths, the start-up floor of the harness (a process that does nothing, and
`catplan --version`, timed the same way), and the load average of the machine before and after.
Each run is timed whole, wall and CPU (user + system of the process and its children): on a shared
machine the wall time of a short process depends on the load more than its CPU time does.

With --repeat R, the whole comparison runs R times over, each run printed as it ends, then a
summary per direction and size: the R ratios sorted, their median, and in how many runs the
transfer was at least 100x faster (wall and CPU). A shared machine's slower phases move single
runs of a short process far more than FD's; the median over runs is the figure to compare.

With --batch K (4to3 only), the same source plan K times over in one directory, transferred by one
catplan process with --jobs 1 and --jobs 2: the throughput of batch transfer on one core and on two.
Benchmarks only: the peers are not Debian packages; neither the product nor its tests need them.
"""
import argparse
import os
import pathlib
import random
import re
import resource
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

# direction: (source domain, map file, map, target domain, source domain name, hand predicate)
DIRECTIONS = {
    "4to3": ("blocks4.pddl", "four_to_three.cp", "FourToThree", "blocks3.pddl", "blocks4", True),
    "3to4": ("blocks3.pddl", "three_to_four.cp", "ThreeToFour", "blocks4.pddl", "blocks3", False),
}


def blocks_problem(domain, hand, n, seed):
    """A seeded problem of blocks3 or blocks4 (the domains' own predicate names)."""
    rng = random.Random(seed)
    blocks = [f"b{i}" for i in range(1, n + 1)]
    init = ["(hand-empty)"] if hand else []
    for t in generate.towers(blocks, rng):
        init.append(f"(on-table {t[0]})")
        init += [f"(on {a} {b})" for b, a in zip(t, t[1:])]
        init.append(f"(clear {t[-1]})")
    goal = []
    for t in generate.towers(blocks, rng):
        goal += [f"(on {a} {b})" for b, a in zip(t, t[1:])]
    return generate.problem(domain, f"{domain}-{n}", [("block", blocks)], init,
                            goal or [f"(on {blocks[0]} {blocks[1]})"])


def timed(cmd, limit):
    """Wall seconds, the run, and its CPU seconds (user + system, the process and its children)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=limit + 30)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    r.cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, r


def steps(plan):
    return sum(1 for line in plan.read_text().splitlines() if line.startswith("("))


def val(peers, domain, problem, plan):
    r = subprocess.run([str(peers / "bin/validate"), str(domain), str(problem), str(plan)],
                       capture_output=True, text=True)
    return "Plan valid" in r.stdout


def fd(peers, domain, problem, plan, limit):
    if plan.exists():
        plan.unlink()
    return timed([str(peers / "bin/fast-downward"), "--overall-time-limit", f"{limit}s",
                  "--plan-file", str(plan), "--alias", "lama-first", str(domain), str(problem)],
                 limit)


def fd_search_seconds(log):
    m = re.findall(r"Search time: ([0-9.]+)s", log)
    return float(m[-1]) if m else None


def transfer_cmd(catplan, map_file, map_name, problem, plan, extra):
    return [str(catplan), "transfer", str(BLOCKS / map_file), "--map", map_name,
            "--problem", str(problem), "--plan", str(plan), "--no-timing"] + extra


def source_plan(a, domain_file, problem_text, d):
    """FD's plan of the source problem, kept in d and used again for the same problem."""
    problem, plan = d / "source.pddl", d / "source.plan"
    if problem.exists() and problem.read_text() == problem_text and plan.exists():
        return problem, plan
    problem.write_text(problem_text)
    _, r = fd(a.peers, BLOCKS / domain_file, problem, plan, a.limit)
    if not plan.exists():
        print(f"{d.name}: FD found no source plan: {r.stdout[-300:]}", file=sys.stderr)
        return problem, None
    return problem, plan


def one_size(a, direction, n, out):
    src_dom, map_file, map_name, tgt_dom, src_name, hand = DIRECTIONS[direction]
    d = out / f"{direction}-b{n}"
    d.mkdir(parents=True, exist_ok=True)
    problem, splan = source_plan(a, src_dom, blocks_problem(src_name, hand, n, 7000 + n), d)
    if splan is None:
        return None
    target_plan, target_problem, fd_plan = d / "target.plan", d / "target.pddl", d / "fd_target.plan"
    transfer_s, transfer_cpu, replan_s, replan_cpu, search_s = [], [], [], [], []
    # The transfer's runs are spread evenly between FD's (with 25 and 5: five transfers, then one
    # FD run, five times over), so that both medians sample the same stretch of time: a shared
    # machine has phases of a second or so in which every process runs slower, and 25 transfers
    # back to back fit in one.
    for i in range(a.transfer_runs):
        # As FD's plan file is (fd()), the transfer's outputs are removed before its run, so that
        # each tool writes new files: on ext4 replacing a file costs more than writing a new one
        # (bench/RESULTS.md), and the VAL check sees this run's plan.
        for f in (target_plan, target_problem):
            f.unlink(missing_ok=True)
        t, r = timed(transfer_cmd(a.catplan, map_file, map_name, problem, splan,
                                  ["-o", str(target_plan), "--problem-output",
                                   str(target_problem)]), a.limit)
        if r.returncode != 0:
            print(f"{d.name}: transfer exit {r.returncode}: {r.stdout[-400:]}{r.stderr[-400:]}",
                  file=sys.stderr)
            return None
        transfer_s.append(t)
        transfer_cpu.append(r.cpu)
        while len(replan_s) < (i + 1) * a.runs // a.transfer_runs:
            t, r = fd(a.peers, BLOCKS / tgt_dom, target_problem, fd_plan, a.limit)
            replan_s.append(t)
            replan_cpu.append(r.cpu)
            search_s.append(fd_search_seconds(r.stdout))
    row = {
        "direction": direction,
        "n": n,
        "source_steps": steps(splan),
        "target_steps": steps(target_plan),
        "fd_target_steps": steps(fd_plan) if fd_plan.exists() else None,
        "transfer_s": statistics.median(transfer_s),
        "transfer_cpu": statistics.median(transfer_cpu),
        "replan_s": statistics.median(replan_s),
        "replan_cpu": statistics.median(replan_cpu),
        "replan_search_s": statistics.median([s for s in search_s if s is not None] or [0.0]),
        "replan_solved": fd_plan.exists(),
        "val_source": val(a.peers, BLOCKS / src_dom, problem, splan),
        "val_transfer": val(a.peers, BLOCKS / tgt_dom, target_problem, target_plan),
        "val_fd": fd_plan.exists() and val(a.peers, BLOCKS / tgt_dom, target_problem, fd_plan),
    }
    if a.batch and direction == "4to3":
        row.update(batch(a, map_file, map_name, problem, splan, d))
    return row


def start_floor(a):
    """Medians (wall s, CPU s) of a process that does nothing (/bin/true) and of `catplan
    --version`, timed as the transfer is, runs interleaved: what no transfer can go below here."""
    runs = {"true": [], "version": []}
    for _ in range(a.transfer_runs):
        for key, cmd in (("true", ["/bin/true"]), ("version", [str(a.catplan), "--version"])):
            t, r = timed(cmd, a.limit)
            runs[key].append((t, r.cpu))
    return {key: (statistics.median(t for t, _ in v), statistics.median(c for _, c in v))
            for key, v in runs.items()}


def batch(a, map_file, map_name, problem, splan, d):
    plans = d / "plans"
    shutil.rmtree(plans, ignore_errors=True)
    plans.mkdir()
    for i in range(a.batch):
        shutil.copy(splan, plans / f"plan{i:03d}")
    out = {}
    for jobs in (1, 2):
        times = []
        for _ in range(a.runs):
            t, r = timed(transfer_cmd(a.catplan, map_file, map_name, problem, plans,
                                      ["--jobs", str(jobs), "--format", "jsonl"]), a.limit * 4)
            lines = r.stdout.splitlines()
            if r.returncode != 0 or len(lines) != a.batch:
                print(f"batch --jobs {jobs}: exit {r.returncode}, {len(lines)} lines",
                      file=sys.stderr)
                return {}
            times.append(t)
        out[f"batch_jobs{jobs}_s"] = statistics.median(times)
    return out


def measure(a):
    """One run of the whole comparison: the rows, the start-up floor and the load around them."""
    load_before = os.getloadavg()
    floors = [start_floor(a)]
    rows = [r for direction in a.directions.split(",") for n in map(int, a.blocks.split(","))
            if (r := one_size(a, direction, n, a.out))]
    floors.append(start_floor(a))
    floor = {k: tuple(statistics.mean(f[k][i] for f in floors) for i in (0, 1)) for k in floors[0]}
    return rows, floor, load_before, os.getloadavg()


def print_run(a, rows, floor, load_before, load_after):
    print(f"load average (1, 5, 15 min) before: {load_before[0]:.2f} {load_before[1]:.2f} "
          f"{load_before[2]:.2f}; after: {load_after[0]:.2f} {load_after[1]:.2f} {load_after[2]:.2f}")
    print("| direction | blocks | source steps (FD) | transferred steps | FD replanned steps "
          "| transfer s (CPU s) | FD replanning s (CPU s; its search s) "
          "| replanning / transfer: wall, CPU | VAL source, transferred, replanned |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        ok = ", ".join("valid" if r[k] else "INVALID" for k in ("val_source", "val_transfer", "val_fd"))
        bound = "" if r["replan_solved"] else " (FD hit its limit: a lower bound)"
        print(f"| {r['direction']} | {r['n']} | {r['source_steps']} | {r['target_steps']} "
              f"| {r['fd_target_steps']} | {r['transfer_s']:.3f} ({r['transfer_cpu']:.3f}) "
              f"| {r['replan_s']:.3f} ({r['replan_cpu']:.3f}; {r['replan_search_s']:.3f}) "
              f"| {wall_ratio(r):.0f}x, {cpu_ratio(r):.0f}x{bound} | {ok} |")
    print(f"\nstart-up in this harness (medians of {a.transfer_runs} runs, before and after the rows, "
          f"averaged): a process that does nothing (/bin/true) {floor['true'][0] * 1e3:.1f} ms wall "
          f"({floor['true'][1] * 1e3:.1f} ms CPU); `catplan --version` "
          f"{floor['version'][0] * 1e3:.1f} ms wall ({floor['version'][1] * 1e3:.1f} ms CPU)")
    for r in rows:
        if r["replan_s"] < 100 * r["transfer_s"]:
            print(f"{r['direction']} {r['n']}: 100x needs the whole transfer in "
                  f"{r['replan_s'] * 10:.1f} ms of wall time; it took {r['transfer_s'] * 1e3:.1f}")
    batched = [r for r in rows if "batch_jobs1_s" in r]
    if batched:
        print(f"\n| blocks | {a.batch} plans, --jobs 1 s | --jobs 2 s | speed-up |")
        print("|---|---|---|---|")
        for r in batched:
            j1, j2 = r["batch_jobs1_s"], r["batch_jobs2_s"]
            print(f"| {r['n']} | {j1:.3f} | {j2:.3f} | {j1 / j2:.2f} |")


def wall_ratio(r):
    return r["replan_s"] / r["transfer_s"]


def cpu_ratio(r):
    return r["replan_cpu"] / max(r["transfer_cpu"], 1e-3)


def print_summary(runs):
    """Over the runs of --repeat: each direction and size's ratios, their median, and in how many
    runs the transfer was at least 100x faster (a shared machine's slow phases move single runs;
    the median over runs is the figure to compare)."""
    print(f"\nover {len(runs)} runs (each a row above; ratios sorted):")
    print("| direction | blocks | wall ratios | median wall | runs at 100x wall "
          "| CPU ratios, min to max | median CPU | runs at 100x CPU |")
    print("|---|---|---|---|---|---|---|---|")
    keys = sorted({(r["direction"], r["n"]) for rows, _ in runs for r in rows})
    for key in keys:
        rs = [r for rows, _ in runs for r in rows if (r["direction"], r["n"]) == key]
        wall = sorted(wall_ratio(r) for r in rs)
        cpu = sorted(cpu_ratio(r) for r in rs)
        print(f"| {key[0]} | {key[1]} | {', '.join(f'{w:.0f}' for w in wall)} "
              f"| {statistics.median(wall):.0f}x | {sum(w >= 100 for w in wall)} of {len(wall)} "
              f"| {cpu[0]:.0f} to {cpu[-1]:.0f} | {statistics.median(cpu):.0f}x "
              f"| {sum(c >= 100 for c in cpu)} of {len(cpu)} |")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--catplan", type=pathlib.Path, required=True)
    p.add_argument("--peers", type=pathlib.Path, required=True)
    p.add_argument("--out", type=pathlib.Path, required=True)
    p.add_argument("--blocks", default="30,100")
    p.add_argument("--directions", default="4to3,3to4")
    p.add_argument("--runs", type=int, default=3)
    p.add_argument("--transfer-runs", type=int, default=9)
    p.add_argument("--batch", type=int, default=0)
    p.add_argument("--limit", type=int, default=900)
    p.add_argument("--repeat", type=int, default=1,
                   help="run the whole comparison this many times, then summarise the ratios")
    a = p.parse_args()
    if a.runs < 1 or a.transfer_runs < 1 or a.repeat < 1:
        p.error("--runs, --transfer-runs and --repeat must be at least 1")
    runs = []
    for k in range(a.repeat):
        if a.repeat > 1:
            print(f"{'' if k == 0 else chr(10)}run {k + 1} of {a.repeat}, "
                  f"{time.strftime('%H:%M:%S', time.gmtime())} UTC", flush=True)
        rows, floor, load_before, load_after = measure(a)
        print_run(a, rows, floor, load_before, load_after)
        runs.append((rows, floor))
        sys.stdout.flush()
    if a.repeat > 1:
        print_summary(runs)


if __name__ == "__main__":
    main()
