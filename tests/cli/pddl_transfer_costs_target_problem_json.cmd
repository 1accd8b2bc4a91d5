transfer tests/pddl/lift_transfer.cp --map FromFlat --problem tests/pddl/lift-flat-p01.pddl --plan tests/pddl/lift-p01.plan --target-problem tests/pddl/lift-p01.pddl --no-timing --format json
