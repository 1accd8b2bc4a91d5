plan tests/pddl/bad-requirement.pddl tests/pddl/blocksworld-p01.pddl
