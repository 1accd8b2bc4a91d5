"""An IPC plan of the 3-operator blocks world carried into the 4-operator one.

    python3 examples/python/pddl_transfer.py      (from the repository root)

No 4-operator action is a migrated `move`, so each source step is repaired with the target's
own actions; the target plan is written as Fast Downward writes plans.
"""
from pathlib import Path

import catplan

blocks = Path("examples/pddl/blocks")
m = catplan.load(str(blocks / "three_to_four.cp"))
r = catplan.transfer_pddl(m, "ThreeToFour", str(blocks / "p01-3.pddl"),
                          (blocks / "p01-3.plan").read_text())
for step in r.steps:
    action, args = step.source
    became = "; ".join(f"({a} {' '.join(xs)})" for a, xs in step.target)
    print(f"({action} {' '.join(args)}) -> {became} [{step.kind}]")
print(r.plan_text, end="")
print("valid" if r.valid else f"invalid: {r.transfer.reason or r.pddl_reason}")
