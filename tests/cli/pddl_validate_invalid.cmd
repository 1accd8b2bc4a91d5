validate tests/pddl/blocksworld-domain.pddl tests/pddl/blocksworld-p01.pddl tests/pddl/blocksworld-p01-invalid.plan
