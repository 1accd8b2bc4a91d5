#!/usr/bin/env python3
"""Writes cmake/catplan.order: the functions of the catplan command that its main jobs run, in
the order in which the release build links them (CATPLAN_LINK_ORDER, src/catplan/cli/CMakeLists.txt).

    tools/link_order.py [--catplan build/release/src/catplan/cli/catplan] [--out cmake/catplan.order]

The kernel maps a program's code as it first runs, a fault at a time (64 KiB around each), and
the code a short command runs is spread over the 4.6 MB of the command's code. Linked one after
another, in the order of this file, they take fewer pages: the 30-block PDDL transfer of
bench/RESULTS.md faults on a quarter fewer. The jobs, each run once under valgrind's callgrind
(Debian's valgrind, needed only to write this file), in this order: the PDDL transfers of
examples/pddl/blocks both ways, the case study's transfer, then what `make demo` and a planning
user run. A job's functions that an earlier job did not run follow that job's predecessors',
sorted by name.

The file is data, not a build input that must be exact: the linker skips a name that no longer
exists and links a function that the file does not name after the named ones. Write it again
after a change that renames or moves much of a job's code (the script first prints how many of
the present file's names the command still has).
"""
import argparse
import os
import pathlib
import re
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
BLOCKS = "examples/pddl/blocks"
CASE = "examples/colorblocksworld"


def jobs(out):
    """The commands, as argument lists after the command's path, in the order their code is laid."""
    return [
        ["transfer", f"{BLOCKS}/three_to_four.cp", "--map", "ThreeToFour", "--problem",
         f"{BLOCKS}/p01-3.pddl", "--plan", f"{BLOCKS}/p01-3.plan", "-o", f"{out}/t34.plan",
         "--problem-output", f"{out}/t34.pddl"],
        ["transfer", f"{BLOCKS}/four_to_three.cp", "--map", "FourToThree", "--problem",
         f"{BLOCKS}/p01-4.pddl", "--plan", f"{BLOCKS}/p01-4.plan", "-o", f"{out}/t43.plan",
         "--problem-output", f"{out}/t43.pddl"],
        ["transfer", "examples/colorblocks_to_kitchen/appendix_map.cp", "--map", "ColorToKitchen",
         "--problem", "CaseStudy", "--plan", f"{CASE}/paper.plan", "--rename-by-type"],
        ["validate", f"{CASE}/colorblocksworld.cp", "--domain", "Blocksworld", "--problem",
         "CaseStudy", "--plan", f"{CASE}/paper.plan"],
        ["validate", f"{BLOCKS}/blocks4.pddl", f"{BLOCKS}/p01-4.pddl", f"{BLOCKS}/p01-4.plan"],
        ["plan", f"{BLOCKS}/blocks4.pddl", f"{BLOCKS}/p01-4.pddl"],
        ["check", f"{CASE}/colorblocksworld.cp"],
        ["show", f"{CASE}/colorblocksworld.cp", "Initial"],
        ["--version"],
        ["--help"],
    ]


# callgrind names objects and functions once, "(id) name", and by id after that.
NAMED = re.compile(r"^(c?ob|c?fn)=\((\d+)\)(?: (.*))?$")


def functions_run(profile, binary):
    """The functions of `binary` that ran, in the order the profile lists them."""
    objects, functions, in_binary, out = {}, {}, False, []
    with open(profile, encoding="utf-8", errors="replace") as f:
        for line in f:
            m = NAMED.match(line.rstrip("\n"))
            if not m:
                continue
            kind, key, name = m.groups()
            if name:
                (objects if kind.endswith("ob") else functions)[key] = name
            if kind == "ob":
                in_binary = os.path.realpath(objects.get(key, "")) == binary
            elif kind == "fn" and in_binary:
                out.append(functions[key].split("'")[0])  # 'N: a recursion depth
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--catplan", default=str(ROOT / "build/release/src/catplan/cli/catplan"))
    ap.add_argument("--out", default=str(ROOT / "cmake/catplan.order"))
    a = ap.parse_args()
    binary = os.path.realpath(a.catplan)
    out = pathlib.Path(a.out)
    if out.exists():
        symbols = set(subprocess.run(["nm", "--defined-only", "--format=just-symbols", binary],
                                     capture_output=True, text=True, check=True).stdout.split())
        names = out.read_text().split()
        kept = sum(n in symbols for n in names)
        print(f"{kept} of the {len(names)} names of {out} are functions of the command")
    order, seen = [], set()
    with tempfile.TemporaryDirectory() as tmp:
        for i, job in enumerate(jobs(tmp)):
            profile = f"{tmp}/callgrind.{i}"
            r = subprocess.run(["valgrind", "--tool=callgrind", "--demangle=no",
                                f"--callgrind-out-file={profile}", binary, *job],
                               cwd=ROOT, capture_output=True, text=True)
            if r.returncode != 0:
                sys.exit(f"link_order: catplan {' '.join(job)}: exit {r.returncode}\n{r.stderr[-800:]}")
            # By name within a job: the set is what keeps its code together, and the file's
            # diff then shows what a change added or removed.
            new = sorted(set(functions_run(profile, binary)) - seen)
            seen.update(new)
            order += new
            print(f"{len(new):5d} functions first run by catplan {' '.join(job)[:70]}")
    # Names only: lld reads one symbol a line, and a name of no symbol is skipped.
    names = [n for n in order if re.fullmatch(r"[A-Za-z_][A-Za-z0-9_.$]*", n)]
    out.write_text("".join(f"{n}\n" for n in names))
    print(f"{len(names)} functions written to {out}")


if __name__ == "__main__":
    main()
