pddl import tests/pddl/lift-domain.pddl
