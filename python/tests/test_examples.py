"""The examples in examples/python run and print what their comments promise."""

import subprocess
import sys


def run(source_dir, name):
    r = subprocess.run([sys.executable, str(source_dir / "examples/python" / name)],
                       cwd=source_dir, capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    return r.stdout.splitlines()


def test_case_study(source_dir):
    out = run(source_dir, "case_study.py")
    assert out[0] == "1. unstack(E, D) -> unstack(bread2, bread1)"
    assert out[-2:] == ["valid", "goal satisfaction: 52/52"]
    assert len(out) == 10


def test_perception(source_dir):
    out = run(source_dir, "perception.py")
    assert "the paper's initial state: True" in out
    kitchen = next(line for line in out if line.startswith("kitchen plan:"))
    assert kitchen.startswith("kitchen plan: unstack(bread2, bread1); putdown(bread2)")
    assert out[-1] == "valid (52/52)"


def test_pddl_transfer(source_dir):
    out = run(source_dir, "pddl_transfer.py")
    assert out[0] == "(move-to-table a b) -> (unstack a b); (put-down a) [repaired]"
    assert out[3:5] == ["(unstack a b)", "(put-down a)"]
    assert out[-2:] == ["; cost = 6 (unit cost)", "valid"]
