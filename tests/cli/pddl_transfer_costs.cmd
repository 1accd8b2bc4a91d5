transfer tests/pddl/lift_transfer.cp --map ToFlat --problem tests/pddl/lift-p01.pddl --plan tests/pddl/lift-p01.plan --no-timing
