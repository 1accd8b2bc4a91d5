transfer tests/pddl/stacker.cp --map Same --problem tests/pddl/stacker-p01.pddl --plan tests/pddl/stacker-p01-invalid.plan --no-timing
