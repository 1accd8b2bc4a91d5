#!/usr/bin/env python3
"""Makes the seed corpus of every fuzz harness from the inputs kept in the repository.

    make_seeds.py ROOT OUT [CATPLAN]

writes OUT/<harness>/<sha1> for each harness (lang, json, pddl_domain, pddl_problem, ipc_plan,
plan, transfer): the language files, JSON files, PDDL domains and problems and plans under
examples/ and tests/ (the IPC plans seed both ipc_plan and transfer). With the path of a catplan
binary it also adds what catplan writes from the examples: the JSON of every schema and instance
(`json export`) and the PDDL of every domain and problem that PDDL can express (`pddl export`).
Nothing is copied into the repository: the seeds follow the files.
"""
import hashlib
import pathlib
import re
import subprocess
import sys

HARNESSES = ["lang", "json", "pddl_domain", "pddl_problem", "ipc_plan", "plan", "transfer"]


def classify(path: pathlib.Path, text: str):
    """The harness a repository file seeds, or None."""
    if path.suffix == ".cp":
        return "lang"
    if path.suffix == ".json":
        return "json"
    if path.suffix == ".pddl":
        return "pddl_problem" if re.search(r"\(\s*problem\b", text) else "pddl_domain"
    if path.suffix == ".plan":
        steps = [l.strip() for l in text.splitlines() if l.strip() and l.strip()[0] not in "#;"]
        return "ipc_plan" if steps and steps[0].startswith("(") else "plan"
    return None


def catplan_outputs(catplan: str, root: pathlib.Path):
    """(harness, text) for what `catplan json export` and `pddl export` write from examples/."""
    for cp in sorted((root / "examples").rglob("*.cp")):
        rel = str(cp.relative_to(root))
        check = subprocess.run([catplan, "check", rel], cwd=root, capture_output=True, text=True)
        for line in check.stdout.splitlines():
            m = re.match(r"(schema|instance|domain|problem) (\S+?)[ :]", line)
            if not m:
                continue
            kind, name = m.groups()
            if kind in ("schema", "instance"):
                args, harness = ["json", "export", rel, name], "json"
            else:
                args = ["pddl", "export", rel, "--" + kind, name]
                harness = "pddl_domain"
            r = subprocess.run([catplan] + args, cwd=root, capture_output=True, text=True)
            if r.returncode != 0:
                continue
            parts = re.split(r"(?=\(define \(problem)", r.stdout)
            yield harness, parts[0]
            if len(parts) > 1:
                yield "pddl_problem", parts[1]


def main() -> int:
    root, out = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    catplan = sys.argv[3] if len(sys.argv) > 3 else None
    seeds = []
    for top in ("examples", "tests"):
        for path in sorted((root / top).rglob("*")):
            if not path.is_file():
                continue
            text = path.read_text(encoding="utf-8", errors="replace")
            harness = classify(path, text)
            if harness:
                seeds.append((harness, path.read_bytes()))
            if harness == "ipc_plan":
                seeds.append(("transfer", path.read_bytes()))  # IPC plans are transferred too
    if catplan:
        seeds += [(h, t.encode("utf-8")) for h, t in catplan_outputs(catplan, root)]
    counts = dict.fromkeys(HARNESSES, 0)
    for harness in HARNESSES:
        (out / harness).mkdir(parents=True, exist_ok=True)
    for harness, data in seeds:
        target = out / harness / hashlib.sha1(data).hexdigest()
        if not target.exists():
            target.write_bytes(data)
            counts[harness] += 1
    print("seeds: " + ", ".join(f"{h} {n}" for h, n in counts.items()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
