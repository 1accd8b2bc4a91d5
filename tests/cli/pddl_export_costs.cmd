pddl export tests/pddl/shuttle.cp --problem shuttle-p01
