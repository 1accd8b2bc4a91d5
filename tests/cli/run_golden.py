#!/usr/bin/env python3
"""Runs one CLI golden case and compares what it printed with the expected transcript.

A case is tests/cli/<name>.cmd: its first line is the command line after `catplan` (run from the
repository root); further lines `absent: PATH` name files that must not exist afterwards (no partial
output). The expectation tests/cli/<name>.expected holds stdout, then `--- stderr` and stderr, then
`--- exit N`. CATPLAN_UPDATE_GOLDEN=1 rewrites the expectation instead of comparing.
"""
import difflib
import os
import pathlib
import shlex
import subprocess
import sys


def main() -> int:
    catplan, case, root = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
    lines = case.read_text(encoding="utf-8").splitlines()
    args = shlex.split(lines[0])
    absent = [l.split(":", 1)[1].strip() for l in lines[1:] if l.startswith("absent:")]
    for path in absent:
        if (root / path).exists():
            (root / path).unlink()
    proc = subprocess.run([catplan] + args, cwd=root, capture_output=True, text=True, timeout=120)
    actual = f"{proc.stdout}--- stderr\n{proc.stderr}--- exit {proc.returncode}\n"
    expected_path = case.with_suffix(".expected")
    if os.environ.get("CATPLAN_UPDATE_GOLDEN"):
        expected_path.write_text(actual, encoding="utf-8")
        return 0
    failures = [f"file exists after the run but must not: {p}" for p in absent if (root / p).exists()]
    expected = expected_path.read_text(encoding="utf-8") if expected_path.exists() else ""
    if actual != expected:
        diff = difflib.unified_diff(expected.splitlines(True), actual.splitlines(True),
                                    str(expected_path), "actual")
        failures.append("".join(diff))
    for f in failures:
        print(f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
