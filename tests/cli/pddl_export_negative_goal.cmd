pddl export tests/pddl/stacker.cp --problem stacker-p01
