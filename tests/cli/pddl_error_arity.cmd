pddl import tests/pddl/bad-arity.pddl
