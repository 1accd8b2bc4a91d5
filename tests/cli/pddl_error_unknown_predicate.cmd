pddl import tests/pddl/bad-predicate.pddl
