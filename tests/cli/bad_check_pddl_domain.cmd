check tests/pddl/bad-type.pddl
