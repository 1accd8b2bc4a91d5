validate tests/pddl/blocksworld-domain.pddl tests/pddl/blocksworld-p01.pddl -
stdin: tests/pddl/blocksworld-p01.plan
