pddl import tests/pddl/bad-parens.pddl
