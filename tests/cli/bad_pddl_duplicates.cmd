pddl import tests/cli/bad/pddl/duplicates.pddl
