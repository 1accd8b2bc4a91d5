pddl import tests/pddl/bad-type.pddl
