plan tests/pddl/gripper-domain.pddl tests/pddl/gripper-p16.pddl --no-timing --max-time 120
