plan tests/pddl/gripper-domain.pddl tests/pddl/gripper-p01.pddl --no-timing
