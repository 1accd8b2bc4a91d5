plan tests/pddl/blocksworld-domain.pddl
