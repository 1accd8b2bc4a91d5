validate tests/pddl/blocksworld-domain.pddl tests/pddl/gripper-p01.pddl tests/pddl/gripper-p01.plan
