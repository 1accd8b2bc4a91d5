#!/usr/bin/env python3
"""Runs one CLI golden case and compares what it printed with the expected transcript.

A case is tests/cli/<name>.cmd: its first line is the command line after `catplan` (run from the
repository root, with umask 022). Further lines, each optional and in any order:
  absent: PATH     a file that must not exist afterwards (no partial output); removed before the run
  stdin: PATH      the file given to catplan as its standard input (else it reads nothing)
  before: SHELL    a shell command run from the root before catplan (to make the files a case needs:
                   a file of a given mode, a symlink, a file another catplan command writes: $CATPLAN
                   is the catplan under test); its output is not compared
  after: SHELL     a shell command run from the root after catplan, whose stdout is compared too (to
                   show the files catplan wrote: their text, `stat -c '%a %F'`, a link's target)
The expectation tests/cli/<name>.expected holds stdout, then `--- stderr` and stderr, then
`--- exit N`, then, for a case with `after:` lines, `--- after` and their output.
CATPLAN_UPDATE_GOLDEN=1 rewrites the expectation instead of comparing.
"""
import difflib
import os
import pathlib
import shlex
import subprocess
import sys


def directives(lines, key):
    prefix = key + ":"
    return [l[len(prefix):].strip() for l in lines[1:] if l.startswith(prefix)]


def shell(command, root, catplan):
    env = dict(os.environ, CATPLAN=str(pathlib.Path(catplan).resolve()))
    return subprocess.run(command, shell=True, cwd=root, capture_output=True, text=True,
                          timeout=60, env=env, preexec_fn=lambda: os.umask(0o022))


def main() -> int:
    catplan, case, root = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
    lines = case.read_text(encoding="utf-8").splitlines()
    args = shlex.split(lines[0]) if lines else []
    absent = directives(lines, "absent")
    for path in absent:
        if (root / path).exists() or (root / path).is_symlink():
            (root / path).unlink()
    failures = []
    for command in directives(lines, "before"):
        r = shell(command, root, catplan)
        if r.returncode != 0:
            failures.append(f"before: {command} failed: {r.stderr}")
    stdin = directives(lines, "stdin")
    with open(root / stdin[0], "rb") if stdin else open(os.devnull, "rb") as given:
        proc = subprocess.run([catplan] + args, cwd=root, stdin=given, capture_output=True,
                              timeout=120, preexec_fn=lambda: os.umask(0o022))
    out = proc.stdout.decode("utf-8", errors="backslashreplace")
    err = proc.stderr.decode("utf-8", errors="backslashreplace")
    actual = f"{out}--- stderr\n{err}--- exit {proc.returncode}\n"
    after = directives(lines, "after")
    if after:
        actual += "--- after\n" + "".join(shell(c, root, catplan).stdout for c in after)
    expected_path = case.with_suffix(".expected")
    if os.environ.get("CATPLAN_UPDATE_GOLDEN"):
        expected_path.write_text(actual, encoding="utf-8")
        return 0
    failures += [f"file exists after the run but must not: {p}" for p in absent
                 if (root / p).exists()]
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
