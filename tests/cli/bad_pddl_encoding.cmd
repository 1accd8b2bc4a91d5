pddl import tests/cli/bad/pddl/encoding.pddl
