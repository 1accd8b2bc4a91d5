#!/usr/bin/env python3
"""The case study's plan transfer beside Fast Downward replanning its exported target, in one run.

    case_study_vs_fd.py --catplan BUILD/catplan --peers ../shared/peers --out DIR [--runs 7]

Each run, one process at a time:
  1. `catplan transfer examples/colorblocks_to_kitchen/appendix_map.cp --map ColorToKitchen
     --problem CaseStudy --plan examples/colorblocksworld/paper.plan` (whole process, wall time;
     with --format json --no-timing, to read the target plan);
  2. `catplan pddl export ... --map ColorToKitchen --problem CaseStudy -o d --problem-output p`:
     the target domain and problem Δ_F(I), Δ_F(G) as PDDL;
  3. Fast Downward lama-first on d and p (whole process, and its own "Search time");
  4. `catplan plan d p` (catplan's own planner on the same files, whole process).
Then, once: the transferred plan carried to the export (`pddl export --plan`) and FD's plan are
checked by VAL on d and p, and FD's plan is read back as a catplan plan (`pddl export --from-ipc`,
which checks it on the migrated problem). Prints medians, their ratios and the plan lengths.
Benchmarks only: the peers are not Debian packages; neither the product nor its tests need them.
"""
import argparse
import json
import pathlib
import platform
import re
import statistics
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
MAP = "examples/colorblocks_to_kitchen/appendix_map.cp"
PLAN = "examples/colorblocksworld/paper.plan"
TARGET = ["--map", "ColorToKitchen", "--problem", "CaseStudy"]


def timed(cmd, cwd=ROOT):
    start = time.perf_counter()
    r = subprocess.run(cmd, capture_output=True, text=True, cwd=cwd, timeout=120)
    return time.perf_counter() - start, r


def steps(text):
    return [line for line in text.splitlines() if line.startswith("(")]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--catplan", required=True)
    ap.add_argument("--peers", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--runs", type=int, default=7)
    a = ap.parse_args()
    catplan = str(pathlib.Path(a.catplan).resolve())
    fd = str(pathlib.Path(a.peers, "bin/fast-downward").resolve())
    val = str(pathlib.Path(a.peers, "bin/validate").resolve())
    out = pathlib.Path(a.out).resolve()
    out.mkdir(parents=True, exist_ok=True)
    d, p = out / "target-domain.pddl", out / "target-problem.pddl"
    t_transfer, t_export, t_fd, t_search, t_cp = [], [], [], [], []
    target_plan = fd_plan = None
    for _ in range(a.runs):
        t, r = timed([catplan, "transfer", MAP, "--plan", PLAN, "--format", "json",
                      "--no-timing"] + TARGET)
        if r.returncode != 0:
            sys.exit(f"transfer failed: {r.stderr}")
        t_transfer.append(t)
        target_plan = json.loads(r.stdout)["target_plan"]
        t, r = timed([catplan, "pddl", "export", MAP] + TARGET +
                     ["-o", str(d), "--problem-output", str(p)])
        if r.returncode != 0:
            sys.exit(f"export failed: {r.stderr}")
        t_export.append(t)
        (out / "sas_plan").unlink(missing_ok=True)
        t, r = timed([fd, "--alias", "lama-first", "--overall-time-limit", "60s", str(d), str(p)],
                     cwd=out)
        if r.returncode != 0:
            sys.exit(f"Fast Downward failed: {r.stdout[-2000:]}")
        t_fd.append(t)
        t_search.append(float(re.search(r"Search time: ([0-9.]+)s", r.stdout).group(1)))
        fd_plan = (out / "sas_plan").read_text()
        t, r = timed([catplan, "plan", str(d), str(p)])
        if r.returncode != 0:
            sys.exit(f"catplan plan failed: {r.stderr}")
        t_cp.append(t)
        cp_steps = len(steps(r.stdout)) - 1
    (out / "target.plan").write_text("\n".join(target_plan) + "\n")
    (out / "fd.plan").write_text(fd_plan)
    r = subprocess.run([catplan, "pddl", "export", MAP] + TARGET +
                       ["--plan", str(out / "target.plan"), "-o", str(out / "target.ipc")],
                       capture_output=True, text=True, cwd=ROOT)
    if r.returncode != 0:
        sys.exit(f"the transferred plan does not carry to the export: {r.stderr}")

    def val_ok(plan):
        return subprocess.run([val, str(d), str(p), str(plan)], capture_output=True,
                              text=True).returncode == 0
    back = subprocess.run([catplan, "pddl", "export", MAP] + TARGET +
                          ["--from-ipc", str(out / "fd.plan")],
                          capture_output=True, text=True, cwd=ROOT)
    med = statistics.median
    fd_steps = len(steps(fd_plan)) - 1  # reach-goal is not a step of the catplan plan
    print(f"runs: {a.runs}; machine: {platform.machine()}, {platform.platform()}")
    print(f"transfer (whole process): median {med(t_transfer):.3f} s, min {min(t_transfer):.3f}")
    print(f"export of the target (whole process): median {med(t_export):.3f} s")
    print(f"Fast Downward lama-first (whole process): median {med(t_fd):.3f} s, "
          f"search {med(t_search):.4f} s")
    print(f"catplan plan on the export (whole process): median {med(t_cp):.3f} s, "
          f"{cp_steps} steps (+ reach-goal)")
    print(f"replanning / transfer: {med(t_fd) / med(t_transfer):.2f}; "
          f"(export + replanning) / transfer: {(med(t_export) + med(t_fd)) / med(t_transfer):.2f}")
    print(f"plan lengths: transferred {len(target_plan)}, Fast Downward {fd_steps} "
          f"(+ reach-goal)")
    print(f"VAL on the export: transferred plan {'valid' if val_ok(out / 'target.ipc') else 'INVALID'}"
          f", Fast Downward's plan {'valid' if val_ok(out / 'fd.plan') else 'INVALID'}")
    print("FD's plan read back on the migrated problem: " +
          (back.stdout.strip().splitlines()[-2] if back.returncode == 0 else "INVALID"))
    print("FD's plan:", " ".join(steps(fd_plan)))


if __name__ == "__main__":
    main()
